"""Kinematic driver: the core's joint angles, rates and accelerations -> MuJoCo qpos,
qvel and qacc of the bird built by :mod:`birdsim.mujoco.model`.

Joint names are the core's (``kinematics.JOINTS``): ``heave`` (slide), ``sweep``,
``stroke``, ``flap``, ``twist`` (composed into the shoulder ball joint in that order),
``wrist_flap``, ``wrist_twist`` (hinges).  Both wings get the same values; the left
wing's joint axes are the mirror images (see :mod:`birdsim.mujoco.model`), so the left
wing is the mirror image of the right one.  Joints a model does not use stay at 0.

Ball joints: ``qpos`` is the quaternion of the composed rotation
``A_1 A_2 ... A_n`` (intrinsic: each an active rotation by +q_k about its MuJoCo axis
a_k), ``qvel`` the angular velocity in the CHILD frame,
``w = sum_k v_k qd_k`` with ``v_k = (A_{k+1}..A_n)^T a_k``, and ``qacc`` its time
derivative ``sum_k (v_k qdd_k - qd_k W_k x v_k)`` with ``W_k = sum_{j>k} v_j qd_j``.

The root (free joint): position and velocity given in seed earth axes and converted
with C = diag(1,-1,-1); orientation = body pitch theta (nose up) about MuJoCo -y;
its angular velocity (body frame) is the pitch rate about -y.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from birdsim.errors import BirdsimError
from birdsim.mujoco.ball import ball_state
from birdsim.mujoco.model import SIDES, hinge_axis
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import JOINTS, get_model, validate_params

#: The core joints composed into the shoulder ball joint, outermost first.
SHOULDER = ("sweep", "stroke", "flap", "twist")
HINGES = ("wrist_flap", "wrist_twist")
#: m5's hinges (only its MJCF has them: mujoco/fold.py)
FOLD_HINGES = ("elbow", "wrist_sweep")
#: m5's supination turns the hand about the same axis as the wrist twist, right after
#: it: MuJoCo moves both with the ``X_wrist_twist`` hinge (the sum of the two angles; two
#: collinear hinges in one body would make the mass matrix singular)
SAME_AXIS = {"supination": "wrist_twist"}
_JOINT = mujoco.mjtObj.mjOBJ_JOINT
CORE_JOINTS = ("heave",) + SHOULDER + HINGES + FOLD_HINGES + tuple(SAME_AXIS)


@dataclass(frozen=True)
class Trajectory:
    """Full-model generalised coordinates over time: qpos (T, nq), qvel and qacc (T, nv)."""

    time: np.ndarray
    qpos: np.ndarray
    qvel: np.ndarray
    qacc: np.ndarray


def _as_series(value: object, t: int, name: str, check: bool = True) -> np.ndarray:
    """``value`` as ``t`` samples; ``check=False`` leaves the finiteness of a float array
    of that shape to the caller (wing_arrays checks its outputs once)."""
    if type(value) is np.ndarray and value.dtype == np.float64 and value.shape == (t,):
        if check and not np.isfinite(value).all():
            raise BirdsimError(
                f"joint {name} is not finite; allowed: finite angles (rad) or heave (length)"
            )
        return value  # read only by the callers (they copy into qpos/qvel/qacc)
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise BirdsimError(f"joint {name}={value!r} is not a number") from None
    if a.ndim > 1 or (a.ndim == 1 and a.shape[0] != t):
        raise BirdsimError(f"joint {name} has shape {a.shape}; allowed: a number or ({t},) samples")
    if not np.all(np.isfinite(a)):
        raise BirdsimError(
            f"joint {name} is not finite; allowed: finite angles (rad) or heave (length)"
        )
    return np.broadcast_to(a, (t,)).astype(float)


def _check_names(joint_values: Mapping[str, object], arg: str) -> None:
    for k in joint_values:
        if k not in CORE_JOINTS:
            raise BirdsimError(f"{arg} names joint {k!r}; allowed: {', '.join(CORE_JOINTS)}")


_PLANS: dict[int, tuple[mujoco.MjModel, dict]] = {}


def _plan(m: mujoco.MjModel) -> dict:
    """Per side: the heave's qpos/dof address, the shoulder's axes and addresses, and
    every hinge's (None where the model lacks it), looked up once per model."""
    hit = _PLANS.get(id(m))
    if hit is not None and hit[0] is m:
        return hit[1]
    plan = {}
    for side in SIDES:
        heave = m.joint(f"{side}_heave").id
        sh = m.joint(f"{side}_shoulder").id
        hinges = []
        for j in HINGES + FOLD_HINGES:
            jid = mujoco.mj_name2id(m, _JOINT, f"{side}_{j}")
            if j in FOLD_HINGES and jid < 0:
                hinges.append((j, None))
            else:
                jid = m.joint(f"{side}_{j}").id
                hinges.append((j, (int(m.jnt_qposadr[jid]), int(m.jnt_dofadr[jid]))))
        plan[side] = (
            int(m.jnt_qposadr[heave]),
            int(m.jnt_dofadr[heave]),
            [hinge_axis(side, JOINTS[j].axis) for j in SHOULDER],
            (int(m.jnt_qposadr[sh]), int(m.jnt_dofadr[sh])),
            hinges,
        )
    if len(_PLANS) > 64:
        _PLANS.clear()
    _PLANS[id(m)] = (m, plan)
    return plan


def wing_arrays(
    m: mujoco.MjModel,
    angles: Mapping[str, object],
    rates: Mapping[str, object] | None = None,
    accelerations: Mapping[str, object] | None = None,
    *,
    samples: int = 1,
    left: tuple[Mapping[str, object], Mapping[str, object], Mapping[str, object]] | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """qpos (T, nq), qvel and qacc (T, nv) with the wing joints set (root entries: rest
    pose / zero).  Missing joints, rates or accelerations are 0.

    ``left``: (angles, rates, accelerations) of the LEFT wing's core joints when it does
    not move like the right one (a differential wingbeat); the left wing is then the
    mirror image of a right wing moving with these values.  None: both wings the same."""
    sides = {"r": (angles, rates, accelerations)}
    sides["l"] = left if left is not None else sides["r"]
    for a_, r_, c_ in sides.values():
        for arg, vals in (
            ("joint_angles", a_),
            ("joint_rates", r_ or {}),
            ("joint_accelerations", c_ or {}),
        ):
            _check_names(vals, arg)
    t = samples
    plan = _plan(m)
    zeros = np.zeros(t)

    def get(d: Mapping[str, object] | None, k: str, check: bool = False) -> np.ndarray:
        d = d or {}
        out = _as_series(d[k], t, k, check) if k in d else zeros
        for extra, into in SAME_AXIS.items():
            if into == k and extra in d:
                out = out + _as_series(d[extra], t, extra, check)  # type: ignore[index]
        return out

    qpos = np.tile(m.qpos0, (t, 1))
    qvel = np.zeros((t, m.nv))
    qacc = np.zeros((t, m.nv))
    for side in SIDES:
        angles, rates, accelerations = sides[side]
        hq, hd, axes, (sq, sd), hinges = plan[side]
        qpos[:, hq] = get(angles, "heave")
        qvel[:, hd] = get(rates, "heave")
        qacc[:, hd] = get(accelerations, "heave")
        with np.errstate(invalid="ignore"):  # a non-finite input is named below
            quat, omega, alpha = ball_state(
                axes,
                [get(angles, j) for j in SHOULDER],
                [get(rates, j) for j in SHOULDER],
                [get(accelerations, j) for j in SHOULDER],
            )
        qpos[:, sq : sq + 4] = quat
        qvel[:, sd : sd + 3] = omega
        qacc[:, sd : sd + 3] = alpha
        for j, adr in hinges:
            if adr is None:  # a model without m5's joints
                if (j in (angles or {}) and np.any(get(angles, j, True))) or (
                    j in (rates or {}) and np.any(get(rates, j, True))
                ):
                    raise BirdsimError(
                        f"joint {j} is not in this model; allowed: m5's MJCF (build_model('m5'))"
                    )
                continue
            qpos[:, adr[0]] = get(angles, j)
            qvel[:, adr[1]] = get(rates, j)
            qacc[:, adr[1]] = get(accelerations, j)
    if not (np.isfinite(qpos).all() and np.isfinite(qvel).all() and np.isfinite(qacc).all()):
        for values in sides.values():  # name the joint whose series is not finite
            for d in values:
                for k, v in (d or {}).items():
                    _as_series(v, t, k)
    return qpos, qvel, qacc


def _vec3(value: object, name: str) -> np.ndarray:
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise BirdsimError(
            f"{name}={value!r} is not a vector; allowed: three finite numbers"
        ) from None
    if a.shape != (3,) or not np.all(np.isfinite(a)):
        raise BirdsimError(
            f"{name}={value!r} is invalid; allowed: three finite numbers (seed axes X, Y, Z)"
        )
    return a


def set_root(
    m: mujoco.MjModel,
    qpos: np.ndarray,
    qvel: np.ndarray,
    *,
    pitch: float | np.ndarray,
    position_seed: object | None = None,
    velocity_seed: object | None = None,
    pitch_rate: float | np.ndarray = 0.0,
) -> None:
    """Write the root (free joint) into ``qpos``/``qvel`` (arrays (..., nq) / (..., nv)).

    ``position_seed``/``velocity_seed``: torso position and velocity in seed earth axes
    (X forward, Y right, Z down; altitude h is Z = -h); None keeps the position already
    in ``qpos`` and sets the velocity to zero.
    """
    pitch = np.asarray(pitch, dtype=float)
    if not np.isfinite(pitch).all():
        raise BirdsimError(f"pitch={pitch!r} is not finite; allowed: an angle in radians")
    if position_seed is not None:
        qpos[..., 0:3] = np.asarray(position_seed, dtype=float) * np.array([1.0, -1.0, -1.0])
    half = 0.5 * pitch
    qpos[..., 3] = np.cos(half)
    qpos[..., 4] = 0.0
    qpos[..., 5] = -np.sin(half)
    qpos[..., 6] = 0.0
    qvel[..., 0:3] = (
        0.0
        if velocity_seed is None
        else np.asarray(velocity_seed, dtype=float) * np.array([1.0, -1.0, -1.0])
    )
    qvel[..., 3] = 0.0
    qvel[..., 4] = -np.asarray(pitch_rate, dtype=float)
    qvel[..., 5] = 0.0


def set_pose(
    m: mujoco.MjModel,
    d: mujoco.MjData,
    joint_angles: Mapping[str, float],
    joint_rates: Mapping[str, float] | None = None,
    *,
    pitch: float,
    position_seed: Sequence[float] | None = None,
    velocity_seed: Sequence[float] | None = (0.0, 0.0, 0.0),
    pitch_rate: float = 0.0,
    forward: bool = True,
) -> None:
    """Write one instant of the bird into ``d.qpos``/``d.qvel`` (both wings mirrored).

    ``joint_angles``/``joint_rates``: core joint names (heave, sweep, stroke, flap,
    twist, wrist_flap, wrist_twist) -> angle (rad; heave: length, positive down) and
    rate (per unit time); missing joints are 0.  ``pitch``: body pitch (rad, nose up).
    ``position_seed``: torso position in seed earth axes (X forward, Y right, Z down;
    altitude h is Z = -h); None keeps the current position.  ``velocity_seed``: torso
    velocity in seed earth axes.  Calls ``mj_forward`` unless ``forward=False``.
    """
    if position_seed is not None:
        position_seed = _vec3(position_seed, "position_seed")
    if velocity_seed is not None:
        velocity_seed = _vec3(velocity_seed, "velocity_seed")
    qpos, qvel, _ = wing_arrays(m, joint_angles, joint_rates, samples=1)
    qpos[0, :3] = d.qpos[:3]
    set_root(
        m,
        qpos[0],
        qvel[0],
        pitch=pitch,
        position_seed=position_seed,
        velocity_seed=velocity_seed,
        pitch_rate=pitch_rate,
    )
    d.qpos[:] = qpos[0]
    d.qvel[:] = qvel[0]
    if forward:
        mujoco.mj_forward(m, d)


def joint_series(
    model_name: str,
    params: Mapping[str, object],
    times: np.ndarray,
    bird: Bird | None = None,
    *,
    check_bounds: bool = True,
) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray], dict[str, np.ndarray]]:
    """Angles, rates and accelerations (each (T,)) of every joint the model moves, at
    ``times``: exactly the core's ``KinematicModel.joint_motion`` sinusoids.

    ``params`` values may be floats or (T,) arrays (a parameter schedule); a schedule
    is treated as quasi-steady (the derivatives of the parameters themselves are not
    added), which is exact for constant parameters.
    """
    bird = bird or Bird()
    km = get_model(model_name)
    p = validate_params(km, params, check_bounds=check_bounds)
    times = np.asarray(times, dtype=float)
    if times.ndim != 1:
        raise BirdsimError(f"times has shape {times.shape}; allowed: a 1-D array of times")
    if not np.all(np.isfinite(times)):
        raise BirdsimError(
            f"times={float(times[~np.isfinite(times)][0])} is not finite; allowed: finite times"
        )
    p = {k: np.broadcast_to(v, times.shape) for k, v in p.items()}
    angles, rates, accs = {}, {}, {}
    for name, motion in km.joint_motion(p, bird).items():
        q, qd, qdd = motion.at(bird.omega * times, bird.omega)
        angles[name], rates[name], accs[name] = (
            np.broadcast_to(x, times.shape) for x in (q, qd, qdd)
        )
    return angles, rates, accs


def trajectory(
    m: mujoco.MjModel,
    model_name: str,
    params: Mapping[str, object],
    times: np.ndarray,
    bird: Bird | None = None,
    *,
    position_seed: Sequence[float] = (0.0, 0.0, -2.0),
    velocity_seed: Sequence[float] = (0.0, 0.0, 0.0),
    check_bounds: bool = True,
) -> Trajectory:
    """qpos/qvel/qacc over ``times`` for a parameter set (or schedule) of ``model_name``.

    The torso is at ``position_seed`` moving at the constant ``velocity_seed`` (seed
    earth axes) with the pitch of the parameters; the root acceleration is zero.
    """
    times = np.asarray(times, dtype=float)
    angles, rates, accs = joint_series(model_name, params, times, bird, check_bounds=check_bounds)
    qpos, qvel, qacc = wing_arrays(m, angles, rates, accs, samples=times.shape[0])
    pos = _vec3(position_seed, "position_seed")
    vel = _vec3(velocity_seed, "velocity_seed")
    pitch = np.broadcast_to(np.asarray(params["pitch"], dtype=float), times.shape)
    set_root(m, qpos, qvel, pitch=pitch, position_seed=pos, velocity_seed=vel)
    qpos[:, 0:3] += times[:, None] * vel * np.array([1.0, -1.0, -1.0])
    return Trajectory(times, qpos, qvel, qacc)
