"""Cross-check: the mean force MuJoCo transmits to the held body against the analytic mean.

The torso is held at the pitch of the parameter set (gravity off, contacts off, the
freestream as ``opt.wind = (-V, 0, 0)``) and the wings follow the analytic kinematics
exactly (:mod:`.driver`).  Two independent MuJoCo measurements of the force the body
must be held with:

* inverse: ``mj_inverse`` at the N analytic samples (uniform on [0, T)), the root's
  ``qfrc_inverse`` (world-frame force on the free joint);
* forward: ``mj_step`` with the torso welded to the world (equality ``hold``, anchored
  at the torso origin), the wings driven by the joint torques that realise the
  prescribed motion (the wing rows of their inverse dynamics, applied through
  ``qfrc_applied``; the wing state re-set to the prescribed one every step), the weld's
  generalised force on the root (``qfrc_constraint``, from MuJoCo's constraint solver)
  recorded at every step of the last wingbeat.  See :func:`crosscheck` for the two
  ways of holding the torso.

Each measurement is run twice, aero callback on and off, and the aerodynamic force is
``-(hold_on - hold_off)``: the wings' inertial forces cancel exactly instead of only
averaging to ~0 over the samples (``inertial_residual_seed`` reports what is left of
them in the aero-off run).  The result, converted to seed axes, is compared with
``evaluate_cycle(...).whole_bird_mean`` (two mirrored wings + body drag) on the same
sample times; the mean mechanical power of both wings is compared too
(``-qfrc_aero . qvel`` over the wing joints against ``2 P``).
"""

from __future__ import annotations

from collections.abc import Mapping
from contextlib import nullcontext
from dataclasses import dataclass, field

import mujoco
import numpy as np

from birdsim.errors import BirdsimError, check_number
from birdsim.mujoco.callback import aero_forces
from birdsim.mujoco.driver import trajectory
from birdsim.mujoco.model import HOLD_TIMECONST_STEPS, build_model
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.kinematics import get_model

C = np.array([1.0, -1.0, -1.0])
#: Where the held torso sits (seed earth axes; the height is irrelevant with gravity
#: and contacts off).
HOLD_POSITION_SEED = (0.0, 0.0, -2.0)
#: The weld's impedance when the torso is re-set each step: MuJoCo's largest (0.9999);
#: a soft constraint delivers d/(d + (1-d)) of the rigid force, ~1e-4 short.
HOLD_IMPEDANCE = 0.9999


@dataclass(frozen=True)
class CrossCheck:
    """Analytic and MuJoCo mean forces (seed earth axes, whole bird) of one wingbeat."""

    model: str
    params: dict[str, float]
    speed: float
    samples: int
    analytic_seed: np.ndarray  # (3,) whole_bird_mean on the N samples
    inverse_seed: np.ndarray  # (3,) from mj_inverse
    analytic_power: float  # whole bird, 2 P
    inverse_power: float
    inertial_residual_seed: np.ndarray  # mean root force of the aero-off run (mj_inverse)
    forward_seed: np.ndarray | None = None  # (3,) from the welded forward simulation
    forward_analytic_seed: np.ndarray | None = None  # analytic mean on the forward samples
    time: np.ndarray = field(default=None, repr=False)  # (N,)
    analytic_history_seed: np.ndarray = field(default=None, repr=False)  # (N, 3) whole bird
    inverse_history_seed: np.ndarray = field(default=None, repr=False)  # (N, 3)

    @staticmethod
    def _rel(a: np.ndarray, b: np.ndarray) -> float:
        return float(np.linalg.norm(a - b) / max(np.linalg.norm(b), 1e-12))

    @property
    def inverse_rel_error(self) -> float:
        """|F_inverse - F_analytic| / |F_analytic| (3-vectors)."""
        return self._rel(self.inverse_seed, self.analytic_seed)

    @property
    def forward_rel_error(self) -> float | None:
        """|F_forward - F_analytic(forward samples)| / |F_analytic(forward samples)|."""
        if self.forward_seed is None:
            return None
        return self._rel(self.forward_seed, self.forward_analytic_seed)

    @property
    def power_rel_error(self) -> float:
        return abs(self.inverse_power - self.analytic_power) / max(abs(self.analytic_power), 1e-12)

    def as_dict(self) -> dict:
        vec = lambda v: None if v is None else dict(zip(("Fx", "Fy", "Fz"), map(float, v)))  # noqa: E731
        return {
            "model": self.model,
            "params": self.params,
            "speed": self.speed,
            "samples": self.samples,
            "force": "whole bird (2 wings + body drag), seed earth axes (Fz < 0 is up)",
            "analytic": vec(self.analytic_seed),
            "inverse": vec(self.inverse_seed),
            "inverse_rel_error": self.inverse_rel_error,
            "forward": vec(self.forward_seed),
            "forward_analytic": vec(self.forward_analytic_seed),
            "forward_rel_error": self.forward_rel_error,
            "analytic_power": self.analytic_power,
            "inverse_power": self.inverse_power,
            "power_rel_error": self.power_rel_error,
            "inertial_residual": vec(self.inertial_residual_seed),
        }


def held_model(
    model_name: str,
    params: Mapping[str, float],
    speed: float,
    bird: Bird,
    timestep: float | None = None,
) -> mujoco.MjModel:
    """The bird built at the parameter set's pitch, gravity and contacts off, the
    freestream in ``opt.wind``; ``timestep`` also sets the weld's time constant."""
    m = build_model(model_name, bird, scene=False, body_pitch=float(params["pitch"]))
    m.opt.gravity[:] = 0.0
    m.opt.wind[:] = (-float(speed), 0.0, 0.0)
    m.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_CONTACT
    if timestep is not None:
        m.opt.timestep = timestep
        m.eq_solref[m.equality("hold").id] = (HOLD_TIMECONST_STEPS * timestep, 1.0)
    return m


def _inverse_run(m, d, traj, aero_cb) -> tuple[np.ndarray, np.ndarray]:
    """Root force (N, 3) world and wing generalised aero-free torques (N, nv-6)."""
    n = traj.time.shape[0]
    root = np.zeros((n, 3))
    wing = np.zeros((n, m.nv - 6))
    for i in range(n):
        d.qpos[:] = traj.qpos[i]
        d.qvel[:] = traj.qvel[i]
        d.qacc[:] = traj.qacc[i]
        mujoco.mj_inverse(m, d)
        root[i] = d.qfrc_inverse[:3]
        wing[i] = d.qfrc_inverse[6:]
    return root, wing


def _check_inputs(model_name: str, speed: float, samples: int, cycles: int, substeps: int) -> None:
    get_model(model_name)
    check_number("speed", speed, "a finite number >= 0", minimum=0.0)
    for name, v, lo in (("samples", samples, 2), ("cycles", cycles, 1), ("substeps", substeps, 1)):
        if not isinstance(v, int) or isinstance(v, bool) or v < lo:
            raise BirdsimError(f"{name}={v!r} is invalid; allowed: an integer >= {lo}")


def crosscheck(
    model_name: str,
    params: Mapping[str, float],
    speed: float,
    bird: Bird | None = None,
    *,
    samples: int = 64,
    forward: str | None = "held",
    cycles: int | None = None,
    substeps: int | None = None,
) -> CrossCheck:
    """Compare MuJoCo's mean holding force with the analytic whole-bird mean.

    ``samples`` N per wingbeat for ``mj_inverse`` (the analytic grid).  ``forward``:

    * ``"held"`` (default): every step starts from the prescribed state with the torso
      exactly at its pose and at rest (1 wingbeat, N steps: the analytic samples); the
      weld's force comes from MuJoCo's constraint solver.  A soft constraint of
      impedance d = 0.9999 delivers ~1e-4 less than the rigid force: the expected
      relative error.
    * ``"free"``: the torso moves under the weld (a genuine simulation over ``cycles``
      wingbeats, default 2, of ``samples * substeps`` steps each, default 8, last one
      averaged); its compliance makes the error ~1e-5..1e-3, falling with the timestep.
    * ``None``: skip the forward measurement.

    The forward mean is compared with the analytic mean on its own step times.
    Parameters outside the optimiser's bounds are accepted (dissertation examples).
    """
    bird = bird or Bird()
    if forward not in ("held", "free", None):
        raise BirdsimError(f"forward={forward!r} is invalid; allowed: 'held', 'free' or None")
    free = forward == "free"
    cycles = cycles if cycles is not None else (2 if free else 1)
    substeps = substeps if substeps is not None else (8 if free else 1)
    _check_inputs(model_name, speed, samples, cycles, substeps)
    cyc = evaluate_cycle(model_name, params, speed, bird=bird, n=samples, check_bounds=False)
    params = {k: float(v) for k, v in params.items()}
    period = bird.period

    def whole(c):
        w = c.whole_bird_mean
        return np.array([float(w.Fx), float(w.Fy), float(w.Fz)])

    # analytic whole-bird history: 2 x right wing (Fy of the mirror cancels) + body drag
    hist = cyc.force_earth * np.array([2.0, 0.0, 2.0])
    hist[:, 0] += float(cyc.body_drag_x)

    m = held_model(model_name, params, speed, bird)
    d = mujoco.MjData(m)
    traj = trajectory(
        m, model_name, params, cyc.time, bird, position_seed=HOLD_POSITION_SEED, check_bounds=False
    )
    off_root, off_wing = _inverse_run(m, d, traj, None)
    with aero_forces(m, model_name, bird):
        on_root, on_wing = _inverse_run(m, d, traj, True)
    aero_hist = -(on_root - off_root) * C
    # aero generalised force on the wing joints is -(on - off); power = -F . v_flap
    power = ((on_wing - off_wing) * traj.qvel[:, 6:]).sum(axis=1)

    fwd = fwd_an = None
    if forward is not None:
        fwd, fwd_an = _forward(
            model_name, params, speed, bird, samples * substeps, cycles, period, reset_root=not free
        )

    return CrossCheck(
        model=model_name,
        params=params,
        speed=float(speed),
        samples=samples,
        analytic_seed=whole(cyc),
        inverse_seed=aero_hist.mean(axis=0),
        analytic_power=float(cyc.whole_bird_mean.P),
        inverse_power=float(power.mean()),
        inertial_residual_seed=off_root.mean(axis=0) * C,
        forward_seed=fwd,
        forward_analytic_seed=fwd_an,
        time=cyc.time,
        analytic_history_seed=hist,
        inverse_history_seed=aero_hist,
    )


def _forward(
    model_name, params, speed, bird, steps, cycles, period, reset_root: bool
) -> tuple[np.ndarray, np.ndarray]:
    """Mean aero force (seed) from the welded forward simulation and the analytic mean
    on the same ``steps`` sample times."""
    dt = period / steps
    m = held_model(model_name, params, speed, bird, timestep=dt)
    hold = m.equality("hold").id
    if reset_root:
        m.eq_solimp[hold] = (HOLD_IMPEDANCE, HOLD_IMPEDANCE, 0.001, 0.5, 2.0)
    times = np.arange(cycles * steps) * dt
    traj = trajectory(
        m, model_name, params, times, bird, position_seed=HOLD_POSITION_SEED, check_bounds=False
    )
    d_inv = mujoco.MjData(m)

    def run(aero: bool) -> np.ndarray:
        d = mujoco.MjData(m)
        d.eq_active[hold] = 1
        d.qpos[:] = traj.qpos[0]
        d.qvel[:] = traj.qvel[0]
        held = np.zeros((steps, 3))
        ctx = aero_forces(m, model_name, bird) if aero else nullcontext()
        with ctx:
            for i in range(cycles * steps):
                # wing torques that realise the prescribed motion with the body held
                d_inv.qpos[:] = traj.qpos[i]
                d_inv.qvel[:] = traj.qvel[i]
                d_inv.qacc[:] = traj.qacc[i]
                mujoco.mj_inverse(m, d_inv)
                d.qfrc_applied[6:] = d_inv.qfrc_inverse[6:]
                if reset_root:
                    d.qpos[:] = traj.qpos[i]
                    d.qvel[:] = traj.qvel[i]
                else:
                    d.qpos[7:] = traj.qpos[i, 7:]
                    d.qvel[6:] = traj.qvel[i, 6:]
                mujoco.mj_step(m, d)
                if i >= (cycles - 1) * steps:
                    held[i - (cycles - 1) * steps] = d.qfrc_constraint[:3]
        return held.mean(axis=0)

    aero = -(run(True) - run(False)) * C
    cyc = evaluate_cycle(model_name, params, speed, bird=bird, n=steps, check_bounds=False)
    w = cyc.whole_bird_mean
    return aero, np.array([float(w.Fx), float(w.Fy), float(w.Fz)])
