"""What the wings' and tail's inputs do to the free body, measured in MuJoCo (reduced
units, seed body axes x fwd / y right / z down, about the centre of mass): the inputs of
the attitude loop (:data:`INPUTS`), the wingbeat-mean moment's Jacobian with respect to
them (:func:`measured_jacobian`) and with respect to the body rates
(:func:`measured_rate_derivatives`: the flapping's damping and cross terms), each on a
second MjData with the body held at a pitch and an airspeed, the wings beating a given
wingbeat over :data:`JAC_SAMPLES` phases.  Used by :class:`birdsim.flight.attitude.AttitudeLoop`."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator

import mujoco
import numpy as np

from birdsim.flight import fast_hold
from birdsim.mujoco.model import pitch_quat
from birdsim.mujoco.tail import ELEVATION_MAX, ROLL_MAX, TailControls

#: The inputs: (name, kind, bound in rad).  The wing inputs and their signs are those of
#: ``birdsim.physics.moments.CONTROL_INPUTS`` (the differential stroke plane rolls the
#: bird most strongly, the differential flap and twist yaw it, the symmetric sweep
#: pitches it), plus the tail's.  kind: "diff" (right +u/2, left -u/2 on the
#: wing parameter), "sweep" (symmetric sweep offset of both shoulders), "tail".
SHOULDER_BOUND = 0.3
INPUTS = (
    ("flap_amp", "diff", 0.15),
    ("twist_amp", "diff", 0.15),
    ("sweep", "shoulder", SHOULDER_BOUND),
    ("tail_elevation", "tail", ELEVATION_MAX),
    ("tail_roll", "tail", ROLL_MAX),
    ("stroke_plane", "diff", 0.15),
    ("dihedral", "shoulder", SHOULDER_BOUND),
)
#: Phases per wingbeat of a Jacobian measurement and the input step (rad).
JAC_SAMPLES = 16
JAC_STEP = 0.02
_ONES = np.ones(3)


def _hold(
    m: mujoco.MjModel,
    d: mujoco.MjData,
    qpos: np.ndarray,
    qvel: np.ndarray,
    quat: np.ndarray,
    speed: float,
    omega_mj: np.ndarray,
) -> None:
    """Pose the model at one prescription row with the body held: at (0, 0, 6), turned by
    ``quat``, moving at ``speed`` along world x and turning at ``omega_mj`` (MuJoCo body
    axes); positions and velocities forward (the callback's passive forces need no more)."""
    if fast_hold.hold(m, d, qpos, qvel, quat, speed, omega_mj):  # compiled, the same numbers
        return
    d.qpos[:] = qpos
    d.qvel[:] = qvel
    d.qpos[:3] = (0.0, 0.0, 6.0)
    d.qpos[3:7] = quat
    d.qvel[:3] = (speed, 0.0, 0.0)
    d.qvel[3:6] = omega_mj
    mujoco.mj_fwdPosition(m, d)
    mujoco.mj_fwdVelocity(m, d)


def measured_jacobian(
    fb, params: np.ndarray, pitch: float, speed: float, omega_body: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """(M_0 (3,), J (3, k)): the wingbeat-mean moment (seed body axes) with every input
    at zero and its one-sided derivatives, measured in MuJoCo (see the module); the body
    turning at ``omega_body`` (seed body axes; a steady turn's rates: the outer wing's
    faster air is in M_0), else not rotating."""

    m, cb, sched = fb.m, fb.cb, fb.schedule
    d = getattr(fb, "_jac_data", None)
    if d is None:  # a second MjData, kept for the next measurement
        d = fb._jac_data = mujoco.MjData(m)
    n = JAC_SAMPLES
    times = np.arange(n) * (fb.red.period / n)
    names = sched.names
    wind = m.opt.wind.copy()
    saved = cb.tail_controls
    m.opt.wind[:] = 0.0
    quat = pitch_quat(pitch)
    omega_mj = np.zeros(3) if omega_body is None else np.asarray(omega_body) * (1.0, -1.0, -1.0)
    k_in = len(INPUTS) + 1
    # every input's wingbeat in one prescription (per sample: the same numbers as one
    # prescription per input)
    split = [split_inputs(names, params, _unit(i)) for i in range(k_in)]
    z = np.zeros((n * k_in, len(names)))
    sw = np.repeat([np.concatenate([sp[2], sp[2]]) for sp in split], n, axis=0)
    pres = sched.prescribe(
        np.tile(times, k_in),
        np.repeat([sp[0] for sp in split], n, axis=0),
        z,
        z,
        left=(np.repeat([sp[1] for sp in split], n, axis=0), z, z),
        shoulder=(sw, np.zeros_like(sw), np.zeros_like(sw)),
    )
    out = []
    try:
        for i in range(k_in):
            cb.tail_controls = split[i][3]
            acc, rows = np.zeros(3), slice(i * n, (i + 1) * n)
            if fast_hold.hold_rows(m, d, pres.qpos[rows], pres.qvel[rows], quat, speed,
                                   omega_mj, _ONES, np.empty((n, 3)), acc=acc):  # fmt: skip
                out.append(acc / n * np.array([1.0, -1.0, -1.0]))  # compiled, the same sum
                continue
            for k in range(i * n, (i + 1) * n):
                _hold(m, d, pres.qpos[k], pres.qvel[k], quat, speed, omega_mj)
                acc += d.qfrc_passive[3:6]
            out.append(acc / n * np.array([1.0, -1.0, -1.0]))
    finally:
        m.opt.wind[:] = wind
        cb.tail_controls = saved
    m0 = out[0]
    jac = np.stack([(o - m0) / JAC_STEP for o in out[1:]], axis=1)
    return m0, jac


def measured_with_rocking(
    fb,
    params: np.ndarray,
    pitch: float,
    speed: float,
    inertia: np.ndarray,
    omega_body: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(M_0 (3,), J (3, k), D (3, 3)) as :func:`measured_jacobian` and
    :func:`measured_rate_derivatives` measure them on the held body, plus what the body's
    rocking within the wingbeat does to the means.  A free body counter-rotates within
    each wingbeat (the wings' relative angular momentum h, the moment's swing about its
    mean), and the flapping's rate derivatives change with the phase, so the rocking's
    rate times them has a mean: measured in flight, the rocking that a differential flap
    amplitude itself causes cancelled nine tenths of its yaw moment.  Per input, the
    rocking ``w(t)`` is the periodic solution of ``I w' - D w = (M(t) - mean M) - h'(t)``
    (``I`` the principal moments ``inertia``, seed axes; ``D`` the mean rate derivative;
    solved per wingbeat harmonic), and ``mean_t D(t) w(t)`` is added to the mean moment.
    Seed body axes, about the torso origin; the same phases and steps as the held
    measurement."""
    m, cb, sched = fb.m, fb.cb, fb.schedule
    d = getattr(fb, "_jac_data", None)
    if d is None:
        d = fb._jac_data = mujoco.MjData(m)
    n = JAC_SAMPLES
    times = np.arange(n) * (fb.red.period / n)
    names = sched.names
    c = np.array([1.0, -1.0, -1.0])
    base = np.zeros(3) if omega_body is None else np.asarray(omega_body, dtype=float)
    k_in = len(INPUTS) + 1
    split = [split_inputs(names, params, _unit(i)) for i in range(k_in)]
    # the inputs' sets, then the base wingbeat turning a step faster about each axis
    sets = [(sp, base) for sp in split] + [
        (split[0], base + RATE_STEP * np.eye(3)[a]) for a in range(3)
    ]
    z = np.zeros((n * len(sets), len(names)))
    sw = np.repeat([np.concatenate([sp[2], sp[2]]) for sp, _ in sets], n, axis=0)
    pres = sched.prescribe(
        np.tile(times, len(sets)),
        np.repeat([sp[0] for sp, _ in sets], n, axis=0),
        z,
        z,
        left=(np.repeat([sp[1] for sp, _ in sets], n, axis=0), z, z),
        shoulder=(sw, np.zeros_like(sw), np.zeros_like(sw)),
    )
    wind = m.opt.wind.copy()
    saved = cb.tail_controls
    m.opt.wind[:] = 0.0
    quat = pitch_quat(pitch)
    mom = np.zeros((len(sets), n, 3))
    h = np.zeros((len(sets), n, 3))
    vec, res = np.zeros(m.nv), np.zeros(m.nv)
    try:
        for i, (sp, omega) in enumerate(sets):
            cb.tail_controls = sp[3]
            rows = slice(i * n, (i + 1) * n)  # compiled, the same numbers:
            if fast_hold.hold_rows(m, d, pres.qpos[rows], pres.qvel[rows], quat, speed,
                                   omega * c, c, mom[i], h[i]):  # fmt: skip
                continue
            for k in range(n):
                row = i * n + k
                _hold(m, d, pres.qpos[row], pres.qvel[row], quat, speed, omega * c)
                mom[i, k] = d.qfrc_passive[3:6] * c
                vec[:] = d.qvel
                vec[:6] = 0.0  # the wings' motion relative to the torso
                mujoco.mj_mulM(m, d, res, vec)
                h[i, k] = res[3:6] * c
    finally:
        m.opt.wind[:] = wind
        cb.tail_controls = saved
    d_phase = np.stack([(mom[k_in + a] - mom[0]) / RATE_STEP for a in range(3)], axis=2)
    d_mean = d_phase.mean(axis=0)  # (3, 3)
    # the periodic rocking per set: harmonics j = 1 .. n/2 - 1 of the wingbeat (omega = 1
    # per time unit in reduced units: one wingbeat = 2 pi)
    spec_m = np.fft.rfft(mom[:k_in], axis=1)
    spec_h = np.fft.rfft(h[:k_in], axis=1)
    spec_w = np.zeros_like(spec_m)
    w0 = 2.0 * np.pi / fb.red.period
    for j in range(1, n // 2):
        a = 1j * j * w0 * np.diag(inertia) - d_mean
        rhs = spec_m[:, j, :] - 1j * j * w0 * spec_h[:, j, :]
        spec_w[:, j, :] = np.linalg.solve(a, rhs.T).T
    rocking = np.fft.irfft(spec_w, n=n, axis=1)  # (k_in, n, 3)
    rectified = np.einsum("kab,ikb->ia", d_phase, rocking) / n
    means = mom[:k_in].mean(axis=1) + rectified
    m0 = means[0]
    jac = np.stack([(o - m0) / JAC_STEP for o in means[1:]], axis=1)
    return m0, jac, d_mean


#: Step of the rate derivatives (:func:`measured_rate_derivatives`, rad per time unit).
RATE_STEP = 0.01


def measured_rate_derivatives(
    fb, params: np.ndarray, pitch: float, speed: float, omega_body: np.ndarray | None = None
) -> np.ndarray:
    """(3, 3): the wingbeat-mean moment's derivatives (seed body axes, about the centre of
    mass) with respect to the body rates p, q, r (seed body axes), measured like
    :func:`measured_jacobian` (the same wingbeat, every input at zero; one-sided steps of
    :data:`RATE_STEP` from the body turning at ``omega_body``).  The
    flapping's damping (cruise, seed bird: dMx/dp -0.39, dMz/dr -0.05 weight x semispan
    per rad per time unit) and its cross terms (dMx/dr +0.31: the outer wing's faster
    air) act at once on the body: the attitude loop cancels them
    (:meth:`AttitudeLoop.update`)."""
    base = np.zeros(3) if omega_body is None else np.asarray(omega_body, dtype=float)
    states = [base] + [base + RATE_STEP * np.eye(3)[i] for i in range(3)]
    out = held_mean_moments(fb, params, pitch, speed, states)
    return np.stack([(o - out[0]) / RATE_STEP for o in out[1:]], axis=1)


def held_mean_moments(
    fb,
    params: np.ndarray,
    pitch: float,
    speed: float,
    omegas: list[np.ndarray],
    inputs: np.ndarray | None = None,
) -> list[np.ndarray]:
    """The wingbeat-mean moment (3,) (seed body axes, about the centre of mass) of the
    held body (pitch ``pitch``, airspeed ``speed``) beating ``params`` with the inputs
    ``inputs`` (:data:`INPUTS`; default every input at zero), over :data:`JAC_SAMPLES`
    phases, once per body rate in ``omegas`` (seed body axes): the measurement
    :func:`measured_rate_derivatives`, :mod:`birdsim.flight.attitude_stiffness` and
    :mod:`birdsim.flight.attitude_refresh` share."""
    n, c = JAC_SAMPLES, SEED_AXES
    quat = pitch_quat(pitch)
    out = []
    with held_body(fb, params, inputs) as (m, d, pres):
        for omega in omegas:
            acc = np.zeros(3)
            for k in range(n):
                _hold(m, d, pres.qpos[k], pres.qvel[k], quat, speed, omega * c)
                acc += d.qfrc_passive[3:6]
            out.append(acc / n * c)
    return out


SEED_AXES = np.array([1.0, -1.0, -1.0])
"""The signs taking MuJoCo's body axes to the seed's (x forward, y right, z down) and
back."""


@contextlib.contextmanager
def held_body(
    fb, params: np.ndarray, inputs: np.ndarray | None
) -> Iterator[tuple[mujoco.MjModel, mujoco.MjData, object]]:
    """(the model, a scratch MjData, the prescription of :data:`JAC_SAMPLES` phases of
    one wingbeat of ``params`` with ``inputs``) for holding the body in still air with
    the tail at the inputs' controls; the wind and the tail's controls restored on
    exit."""
    m, cb = fb.m, fb.cb
    d = getattr(fb, "_jac_data", None)
    if d is None:
        d = fb._jac_data = mujoco.MjData(m)
    pres, tail = held_prescription(fb, params, inputs, JAC_SAMPLES)
    wind, saved = m.opt.wind.copy(), cb.tail_controls
    m.opt.wind[:] = 0.0
    cb.tail_controls = tail
    try:
        yield m, d, pres
    finally:
        m.opt.wind[:] = wind
        cb.tail_controls = saved


def held_prescription(
    fb, params: np.ndarray, inputs: np.ndarray | None, n: int
) -> tuple[object, TailControls]:
    """(the prescription of ``n`` phases of one wingbeat of ``params`` with the inputs
    ``inputs`` (:data:`INPUTS`; None: every input at zero), the tail's controls): what
    the held body beats in :func:`held_mean_moments`."""
    sched = fb.schedule
    times = np.arange(n) * (fb.red.period / n)
    names = sched.names
    u = np.zeros(len(INPUTS)) if inputs is None else np.asarray(inputs, dtype=float)
    right, left, sh, tail = split_inputs(names, params, u)
    z = np.zeros((n, len(names)))
    sw = np.repeat([np.concatenate([sh, sh])], n, axis=0)
    pres = sched.prescribe(
        times,
        np.repeat([right], n, axis=0),
        z,
        z,
        left=(np.repeat([left], n, axis=0), z, z),
        shoulder=(sw, np.zeros_like(sw), np.zeros_like(sw)),
    )
    return pres, tail


def _unit(i: int) -> np.ndarray:
    """The inputs with input ``i - 1`` at :data:`JAC_STEP` (``i = 0``: all zero)."""
    u = np.zeros(len(INPUTS))
    if i:
        u[i - 1] = JAC_STEP
    return u


#: :func:`split_inputs`' plan per parameter names: per input (what it moves, where)
_SPLIT_PLANS: dict[tuple[str, ...], tuple[tuple[int, int], ...]] = {}
_DIFF, _SHOULDER, _ELEVATION, _ROLL, _NONE = range(5)


def _split_plan(names: tuple[str, ...]) -> tuple[tuple[int, int], ...]:
    """Per input of :data:`INPUTS`: (kind code, the parameter's or shoulder's index)."""
    plan = _SPLIT_PLANS.get(names)
    if plan is None:
        rows = []
        for name, kind, _ in INPUTS:
            if kind == "diff" and name in names:
                rows.append((_DIFF, names.index(name)))
            elif kind == "shoulder":
                rows.append((_SHOULDER, 0 if name == "sweep" else 1))
            elif name == "tail_elevation":
                rows.append((_ELEVATION, -1))
            elif name == "tail_roll":
                rows.append((_ROLL, -1))
            else:
                rows.append((_NONE, -1))
        plan = _SPLIT_PLANS[tuple(names)] = tuple(rows)
    return plan


def split_inputs(
    names: tuple[str, ...], params: np.ndarray, u: np.ndarray
) -> tuple[np.ndarray, np.ndarray, float, TailControls]:
    """(right params, left params, shoulder offsets (sweep, dihedral), tail controls) for
    inputs ``u`` (per input of :data:`INPUTS`, as floats: the same numbers as numpy's)."""
    right = np.array(params, dtype=float)
    left = right.copy()
    shoulder = np.zeros(2)
    elevation = roll = 0.0
    values = np.asarray(u, dtype=float).tolist()
    for (kind, j), ui in zip(_split_plan(names), values):
        if kind == _DIFF:
            right[j] += 0.5 * ui
            left[j] -= 0.5 * ui
        elif kind == _SHOULDER:
            shoulder[j] = ui
        elif kind == _ELEVATION:
            elevation = ui
        elif kind == _ROLL:
            roll = ui
    return right, left, shoulder, TailControls(elevation, 1.0, roll)


__all__ = [
    "INPUTS",
    "JAC_SAMPLES",
    "JAC_STEP",
    "RATE_STEP",
    "SHOULDER_BOUND",
    "held_mean_moments",
    "held_prescription",
    "measured_jacobian",
    "measured_rate_derivatives",
    "measured_with_rocking",
    "split_inputs",
]
