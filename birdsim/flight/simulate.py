"""Free flight in MuJoCo: the torso's translation is free, everything else prescribed.

The model is the usual MJCF (:mod:`birdsim.mujoco.model`) built for the REDUCED bird
(:func:`birdsim.physics.units.reduced_bird`: rho = omega = semispan = chord = 1, mass =
the mass ratio, gravity in semispan omega^2), so one table and one MJCF serve every
bird with the same reduced bird.  Axes: MuJoCo world, x forward, y left, z UP.

Per step (semi-implicit Euler, ``mj_step1`` / ``mj_step2``, one callback call per step):

1. the prescribed coordinates (torso orientation: pitch from the table, roll = yaw = 0;
   every wing joint) are set to the exact prescription at this instant;
2. ``mj_step1``: kinematics, mass matrix M, bias forces (Coriolis, gravity) and the
   passive forces, i.e. the blade-element aerodynamics of :mod:`birdsim.mujoco.callback`;
3. momentum projection: the whole bird's linear momentum P and centre of mass X are
   integrated alongside from the external forces MuJoCo computed (the translational rows
   of ``qfrc_passive`` = the total aerodynamic force, plus the weight); the torso's
   translation is shifted so that the bird's momentum and centre of mass are exactly
   P and X.  Semi-implicit Euler with a configuration-dependent coupling between the
   flapping wings and the torso does not conserve momentum exactly (an O(h^2) error per
   unit time, ~1e-6 semispan of drift per wingbeat at period/512); the projection
   removes it, and its size is logged (``projection_max``);
4. partitioned dynamics: with the prescribed accelerations a_P, the free translational
   accelerations are ``a_F = M_FF^-1 (f_F - M_FP a_P)`` (f = passive - bias); the
   generalised forces that realise a_P are ``tau_P = M_PF a_F + M_PP a_P - f_P``
   (computed torque), written to ``qfrc_applied``; ``mj_step2`` integrates.  The root's
   rotational entries of tau_P are the moment that holds the prescribed pitch: what a
   tail would have to supply.

Wind: ``m.opt.wind`` = the gust only (the body really moves through still air); the
callback uses the velocity relative to it.  Contacts are off in free flight (the wings
would strike the perch; a perched start or end is a path state, not a contact).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from birdsim.errors import BirdsimError
from birdsim.flight.wingbeat import Prescription, WingbeatSchedule
from birdsim.mujoco.callback import AeroCallback
from birdsim.mujoco.model import build_model
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.physics.units import reduced_bird


class FlightError(BirdsimError):
    """A simulation that cannot go on (non-finite state)."""


@dataclass(frozen=True)
class SimConfig:
    """Time stepping of free flight (counts per wingbeat)."""

    steps_per_beat: int = 128
    control_per_beat: int = 8
    log_per_beat: int = 64
    smoothing_beats: float = 0.25
    #: keep the whole bird's momentum and centre of mass on the separately integrated
    #: external impulse (aero + weight); False leaves MuJoCo's integration alone (tests
    #: measure its own O(h^2) momentum error with it off)
    momentum_projection: bool = True

    def __post_init__(self) -> None:
        for name in ("steps_per_beat", "control_per_beat", "log_per_beat"):
            v = getattr(self, name)
            if not (isinstance(v, int) and v >= 1):
                raise BirdsimError(f"{name}={v!r}; allowed: a positive integer")
        if self.steps_per_beat % self.control_per_beat or self.steps_per_beat % self.log_per_beat:
            raise BirdsimError(
                f"steps_per_beat={self.steps_per_beat} must be a multiple of control_per_beat={self.control_per_beat} "
                f"and log_per_beat={self.log_per_beat}"
            )
        if self.log_per_beat < 32:
            raise BirdsimError(
                f"log_per_beat={self.log_per_beat}; allowed: at least 32 samples per wingbeat"
            )


class FreeBird:
    """The MuJoCo bird in free flight (reduced units) and its stepping.

    Use ``with FreeBird(...) as fb:`` (installs the aero callback; the callback is
    process-wide).  ``aero=False`` / ``gravity=False`` switch either off (tests).
    """

    def __init__(
        self,
        model_name: str,
        bird: Bird,
        initial_params: np.ndarray,
        *,
        config: SimConfig = SimConfig(),
        aero: bool = True,
        gravity: bool = True,
    ):
        self.kin = get_model(model_name)
        self.bird = bird
        self.red = reduced_bird(bird)
        self.config = config
        m = build_model(self.kin.name, self.red, scene=False)
        m.opt.timestep = self.red.period / config.steps_per_beat
        m.opt.gravity[:] = (0.0, 0.0, -self.red.gravity if gravity else 0.0)
        m.opt.wind[:] = 0.0
        m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONTACT)
        self.m = m
        self.d = mujoco.MjData(m)
        self.h = float(m.opt.timestep)
        self.torso = m.body("torso").id
        self.total_mass = float(m.body_subtreemass[self.torso])
        mujoco.mj_forward(m, self.d)
        check = np.zeros((m.nv, m.nv))
        mujoco.mj_fullM(m, self.d, check)
        if not np.allclose(check[:3, :3], self.total_mass * np.eye(3), rtol=1e-12, atol=0):
            raise BirdsimError(
                "the root's translational mass block is not (mass) I; allowed: a model built by birdsim.mujoco.model"
            )
        self.schedule = WingbeatSchedule(
            m,
            self.kin,
            self.red,
            initial_params,
            smoothing=config.smoothing_beats * self.red.period,
        )
        self.cb = AeroCallback(m, self.kin.name, self.red)
        self.cb.enabled = aero
        self.time = 0.0
        self.P = np.zeros(3)  # whole-bird linear momentum (world)
        self.X = np.zeros(3)  # whole-bird centre of mass (world)
        self.projection_max = 0.0
        self._M = np.zeros((m.nv, m.nv))
        self._installed = False

    # ---- callback --------------------------------------------------------------------

    def __enter__(self) -> "FreeBird":
        if mujoco.get_mjcb_passive() is not None:
            raise BirdsimError(
                "a MuJoCo passive callback is already installed; allowed: one simulation at a time"
            )
        mujoco.set_mjcb_passive(self.cb)
        self._installed = True
        return self

    def __exit__(self, *exc: object) -> None:
        mujoco.set_mjcb_passive(None)
        self._installed = False

    # ---- state -----------------------------------------------------------------------

    def start(self, position: np.ndarray, velocity: np.ndarray, prescription: Prescription) -> None:
        """Place the torso origin at ``position`` (world x, y, z) with the prescribed
        pose of ``prescription``'s first instant, and give the whole bird the linear
        momentum of ``velocity`` (its centre of mass moves at ``velocity``)."""
        d, m = self.d, self.m
        d.qpos[:] = prescription.qpos[0]
        d.qvel[:] = prescription.qvel[0]
        d.qpos[:3] = position
        d.qvel[:3] = 0.0
        mujoco.mj_fwdPosition(m, d)
        mujoco.mj_fullM(m, d, self._M)
        p_wings = self._M[:3] @ d.qvel
        d.qvel[:3] = np.asarray(velocity, dtype=float) - p_wings / self.total_mass
        self.P = self.total_mass * np.asarray(velocity, dtype=float)
        self.X = d.subtree_com[self.torso].copy()
        mujoco.mj_forward(m, d)

    def step_many(
        self, pres: Prescription, wind: np.ndarray, record: list | None = None, every: int = 1
    ) -> None:
        """Advance ``len(pres.qpos)`` steps following ``pres`` (its row k is the
        prescription at ``self.time + k h``) with the wind ``wind`` (world, reduced
        units; held over these steps).  Every ``every``-th step (before stepping) a
        sample is appended to ``record``: (time, qpos, qvel, pitch moment nose up,
        external force = aero + weight (world), mechanical power of the wing joints)."""
        m, d, h = self.m, self.d, self.h
        m.opt.wind[:] = wind
        M = self._M
        mass = self.total_mass
        grav = np.array(m.opt.gravity)
        qpos, qvel, qfrc_applied, qfrc_passive, qfrc_bias, com = (
            d.qpos,
            d.qvel,
            d.qfrc_applied,
            d.qfrc_passive,
            d.qfrc_bias,
            d.subtree_com,
        )
        torso = self.torso
        a = np.empty(m.nv)
        step1, step2, full_m = mujoco.mj_step1, mujoco.mj_step2, mujoco.mj_fullM
        proj = self.projection_max
        project = self.config.momentum_projection
        for k in range(pres.qpos.shape[0]):
            qpos[3:] = pres.qpos[k, 3:]
            qvel[3:] = pres.qvel[k, 3:]
            step1(m, d)
            full_m(m, d, M)
            # momentum projection (translation only: M, bias and the aero forces do not
            # depend on where the bird is; its velocity changes by O(h^2))
            if project:
                dx = self.X - com[torso]
                qpos[:3] += dx
                qvel[:3] += (self.P - M[:3] @ qvel) / mass
                proj = max(proj, abs(dx[0]), abs(dx[1]), abs(dx[2]))
            f = qfrc_passive - qfrc_bias
            a[3:] = pres.qacc[k, 3:]
            # the translational block of M is (whole mass) I for a free root
            a[:3] = (f[:3] - M[:3, 3:] @ a[3:]) / mass
            tau = M @ a - f
            tau[:3] = 0.0
            qfrc_applied[:] = tau
            f_ext = qfrc_passive[:3] + mass * grav
            if record is not None and k % every == 0:
                power = float(tau[6:] @ qvel[6:])  # both wings' joints, on the air and the wings
                record.append((self.time, qpos.copy(), qvel.copy(), -float(tau[4]), f_ext, power))
            step2(m, d)
            self.P = self.P + h * f_ext
            self.X = self.X + h * self.P / mass
            self.time += h
        self.projection_max = proj
        if not (np.all(np.isfinite(qpos)) and np.all(np.isfinite(qvel))):
            raise FlightError(
                f"the simulation diverged at t={self.time:.3f} (reduced time): non-finite state"
            )

    def com(self) -> tuple[np.ndarray, np.ndarray]:
        """Centre of mass and its velocity of the whole bird at the current state
        (recomputed from qpos/qvel)."""
        mujoco.mj_fwdPosition(self.m, self.d)
        mujoco.mj_fullM(self.m, self.d, self._M)
        return self.d.subtree_com[self.torso].copy(), (self._M[:3] @ self.d.qvel) / self.total_mass


def beat_period(bird: Bird) -> float:
    """One wingbeat in reduced time: 2 pi."""
    return 2.0 * math.pi


__all__ = ["FlightError", "FreeBird", "SimConfig"]
