"""Free flight in MuJoCo: the torso is a free body, the wings are prescribed relative to it.

The model is the usual MJCF (:mod:`birdsim.mujoco.model`) built for the REDUCED bird
(:func:`birdsim.physics.units.reduced_bird`: rho = omega = semispan = chord = 1, mass =
the mass ratio, gravity in semispan omega^2), so one table and one MJCF serve every
bird with the same reduced bird.  Axes: MuJoCo world, x forward, y left, z UP.

Partition (:class:`Partition`, from joint names): the FREE coordinates F are the root
joint's six DOF (attitude ``"free"``) -- or only its translation (attitude ``"posed"``,
the former two-dimensional mode and still the default: the torso orientation is then
prescribed at the table's pitch and held by a hidden root torque); the
PRESCRIBED coordinates P are every wing joint (and, posed, the root's rotation).

Per step (semi-implicit Euler, ``mj_step1`` / ``mj_step2``, one callback call per step):

1. the prescribed coordinates are set to the exact prescription at this instant (the
   wing joints are relative to the torso, so the wings follow the body);
2. ``mj_step1``: kinematics, mass matrix M, bias forces (Coriolis, gravity) and the
   passive forces, i.e. the aerodynamics of :mod:`birdsim.mujoco.callback`;
3. momentum projection (optional, :attr:`SimConfig.momentum_projection`): the whole
   bird's linear momentum P and centre of mass X -- and, with the attitude free, its
   angular momentum L about the centre of mass -- are integrated alongside from the
   external forces MuJoCo computed (aero + weight; aero moment about the centre of
   mass); the root's velocity is corrected by ``M_FF^-1 dp`` so that the bird's momenta
   are exactly P and L, and its translation so that the centre of mass is X.  Its size
   is logged (``projection_max``);
4. partitioned dynamics: ``a_F = M_FF^-1 (f_F - M_FP a_P)`` (f = passive - bias),
   ``tau_P = M_PF a_F + M_PP a_P - f_P`` (computed torque: the bird's muscles) into
   ``qfrc_applied[P]``; ``qfrc_applied[F] = 0`` exactly with the attitude free: the
   body feels only gravity, the air and the reaction of its flapping wings.  ``mj_step2``
   integrates (the root's quaternion by MuJoCo; never written during flight).

Wind: ``m.opt.wind`` = the gust only (the body really moves through still air); the
callback uses the velocity relative to it.  Contacts are off in free flight (the wings
would strike the perch; a perched start or end is a path state, not a contact).
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from birdsim.errors import BirdsimError
from birdsim.flight import fast_loop, step_kernel
from birdsim.flight.partition import Partition, _as_slice, partition
from birdsim.flight.wingbeat import Prescription, WingbeatSchedule
from birdsim.mujoco.callback import AeroCallback
from birdsim.mujoco.model import build_model, pitch_quat
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.physics.units import reduced_bird


class FlightError(BirdsimError):
    """A simulation that cannot go on (non-finite state)."""


_MODELS: dict[tuple, tuple] = {}


def _bird_model(name: str, red: Bird, legs: bool) -> mujoco.MjModel:
    """A copy of the bird model (no scene) for ``name``, the reduced bird ``red`` (that
    object) and ``legs``: compiled once, then copied (0.5 ms against a 22 ms compile)."""
    key = (name, id(red), bool(legs))
    hit = _MODELS.get(key)
    if hit is None or hit[0] is not red:
        if len(_MODELS) > 16:
            _MODELS.clear()
        hit = _MODELS[key] = (red, build_model(name, red, scene=False, legs=legs))
    return copy.deepcopy(hit[1])


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
    #: "free": the root's six DOF are integrated by MuJoCo (no root force or torque);
    #: "posed": the torso's orientation prescribed at the table pitch (the default until
    #: the attitude loop holds the presets: docs/free-body.md)
    attitude: str = "posed"
    #: legs and feet in the model (issue 25), tucked and prescribed in flight
    legs: bool = False
    #: with legs: their prescribed motion (birdsim.flight.leg_motion.LegMotion); None: tucked
    leg_motion: Any = None

    def __post_init__(self) -> None:
        if self.attitude not in ("free", "posed"):
            raise BirdsimError(f"attitude={self.attitude!r}; allowed: free, posed")
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


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.array(
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    )


class FreeBird:
    """The MuJoCo bird in free flight (reduced units) and its stepping.

    Use ``with FreeBird(...) as fb:`` (installs the aero callback; the callback is
    process-wide).  ``aero=False`` / ``gravity=False`` switch either off (tests).
    ``fb.cb.tail`` holds the tail's controls (:class:`birdsim.mujoco.tail.TailControls`).
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
        m = _bird_model(self.kin.name, self.red, config.legs)
        m.opt.timestep = self.red.period / config.steps_per_beat
        m.opt.gravity[:] = (0.0, 0.0, -self.red.gravity if gravity else 0.0)
        m.opt.wind[:] = 0.0
        m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONTACT)
        self.m = m
        self.d = mujoco.MjData(m)
        self.h = float(m.opt.timestep)
        self.torso = m.body("torso").id
        self.total_mass = float(m.body_subtreemass[self.torso])
        self.part = partition(m, config.attitude)
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
        self.cb = AeroCallback(m, self.kin.name, self.red, tail=config.attitude == "free")
        self.cb.enabled = aero
        self.time = 0.0
        self.P = np.zeros(3)  # whole-bird linear momentum (world)
        self.X = np.zeros(3)  # whole-bird centre of mass (world)
        self.L = np.zeros(3)  # whole-bird angular momentum about the centre of mass (world)
        self.projection_max = 0.0
        #: largest |entry| of the root's applied generalised force and of any body's
        #: applied Cartesian wrench over every step so far (0.0 exactly, attitude free)
        self.root_applied_max = 0.0
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

    def start(
        self,
        position: np.ndarray,
        velocity: np.ndarray,
        prescription: Prescription,
        *,
        pitch: float | None = None,
        omega_body: np.ndarray | None = None,
    ) -> None:
        """Place the torso origin at ``position`` (world x, y, z) with the prescribed
        pose of ``prescription``'s first instant, and give the whole bird the linear
        momentum of ``velocity`` (its centre of mass moves at ``velocity``).

        Attitude free: the torso starts at ``pitch`` (default: the prescription's
        table pitch), level in roll and yaw, and the whole bird's angular momentum about
        its centre of mass is that of the body turning at ``omega_body`` (MuJoCo body
        axes; default 0) with the wings moving as prescribed."""
        d, m, part = self.d, self.m, self.part
        if self.config.leg_motion is not None:
            self.config.leg_motion.apply(m, prescription, np.array([self.time]))
        d.qpos[:] = prescription.qpos[0]
        d.qvel[:] = prescription.qvel[0]
        if part.free_rotation:
            th = float(prescription.pitch[0] if pitch is None else pitch)
            d.qpos[3:7] = pitch_quat(th)
            d.qvel[3:6] = 0.0
        d.qpos[:3] = position
        d.qvel[:3] = 0.0
        mujoco.mj_fwdPosition(m, d)
        mujoco.mj_fullM(m, d, self._M)
        f = part.free_dofs
        # the root's velocity that gives the whole bird the wanted momenta
        target = np.zeros(len(f))
        target[:3] = self.total_mass * np.asarray(velocity, dtype=float)
        if part.free_rotation and omega_body is not None:
            target[3:] = self._M[3:6, 3:6] @ np.asarray(omega_body, dtype=float)
        p_wings = self._M[f][:, part.pres_dofs] @ d.qvel[part.pres_dofs]
        d.qvel[f] = np.linalg.solve(self._M[np.ix_(f, f)], target - p_wings)
        mujoco.mj_fwdPosition(m, d)
        mujoco.mj_fullM(m, d, self._M)
        self.P = self._M[:3] @ d.qvel
        self.X = d.subtree_com[self.torso].copy()
        self.L = self._angmom_com(self._M[3:6] @ d.qvel, self.P)
        mujoco.mj_forward(m, d)

    def _angmom_com(self, p_rot: np.ndarray, p_lin: np.ndarray) -> np.ndarray:
        """Angular momentum about the whole bird's centre of mass (world) from the root's
        rotational generalised momentum (about the torso origin, torso axes)."""
        d = self.d
        R = d.xmat[self.torso].reshape(3, 3)
        arm = d.subtree_com[self.torso] - d.xpos[self.torso]
        return R @ p_rot - _cross(arm, p_lin)

    def step_many(
        self, pres: Prescription, wind: np.ndarray, record: list | None = None, every: int = 1
    ) -> None:
        """Advance ``len(pres.qpos)`` steps following ``pres`` (its row k is the
        prescription at ``self.time + k h``) with the wind ``wind`` (world, reduced
        units; held over these steps).  Every ``every``-th step (before stepping) a
        sample is appended to ``record``: (time, qpos, qvel, moment (3, seed body axes
        x fwd / y right / z down, about the centre of mass: the aerodynamic moment with
        the attitude free, the hidden holding moment when posed), external force = aero
        + weight (world), mechanical power of the wing joints)."""
        if self.config.leg_motion is not None:
            times = self.time + self.h * np.arange(pres.qpos.shape[0])
            self.config.leg_motion.apply(self.m, pres, times)
        if fast_loop.step(self, pres, wind, record, every):  # every step compiled (fast_loop)
            return
        m, d, h = self.m, self.d, self.h
        m.opt.wind[:] = wind
        M = self._M
        mass = self.total_mass
        weight = mass * np.array(m.opt.gravity)
        qpos, qvel, qfrc_applied, qfrc_passive, qfrc_bias, com = (
            d.qpos,
            d.qvel,
            d.qfrc_applied,
            d.qfrc_passive,
            d.qfrc_bias,
            d.subtree_com,
        )
        part = self.part
        F, P, Pq, W = (
            _as_slice(a) for a in (part.free_dofs, part.pres_dofs, part.pres_qpos, part.wing_dofs)
        )
        if all(isinstance(x, slice) for x in (F, P)):  # views, no copies (the usual case)
            FF, FP, PF, PP = (F, F), (F, P), (P, F), (P, P)
        else:
            FF, FP, PF, PP = np.ix_(F, F), np.ix_(F, P), np.ix_(P, F), np.ix_(P, P)
        free_rot = part.free_rotation
        torso = self.torso
        step1, step2, full_m = mujoco.mj_step1, mujoco.mj_step2, mujoco.mj_fullM
        inv = np.linalg.inv
        project = self.config.momentum_projection
        xmat, xpos, xfrc = d.xmat, d.xpos, d.xfrc_applied
        n = pres.qpos.shape[0]
        nf = len(part.free_dofs)
        if free_rot and step_kernel.AVAILABLE and F == slice(0, 6) and P == slice(6, m.nv):
            # the same arithmetic compiled (birdsim.flight.step_kernel)
            dmax, vmax = step_kernel.free_loop(self, pres, Pq, P, W, record, every, weight)
            if project and n:
                self.projection_max = max(self.projection_max, dmax, vmax * h)
            self._check_finite()
            return
        # the rows of the prescription (views for slices) and the blocks of M (views)
        pres_q, pres_v, pres_a = pres.qpos[:, Pq], pres.qvel[:, P], pres.qacc[:, P]
        m_ff, m_fp, m_pf, m_pp = M[FF], M[FP], M[PF], M[PP]
        m_lin, m_rot = M[:3], M[3:6]
        com_t, xpos_t, r_t = com[torso], xpos[torso], xmat[torso].reshape(3, 3)
        # |dx| and |dv| of every step, reduced at the end (max is exact in any order)
        dxs, dvs = np.zeros((n, 3)), np.zeros((n, nf))
        cb = self.cb
        P_, X_, L_, time = self.P, self.X, self.L, self.time
        try:
            for k in range(n):
                qpos[Pq] = pres_q[k]
                qvel[P] = pres_v[k]
                step1(m, d)
                full_m(m, d, M)
                arm = com_t - xpos_t if free_rot else None
                m_inv = inv(m_ff)  # one factorisation for the projection and a_F
                if project:
                    dx = X_ - com_t
                    qpos[:3] += dx
                    p_lin = m_lin @ qvel
                    if free_rot:
                        dp = np.empty(nf)
                        dp[:3] = P_ - p_lin
                        l_now = r_t @ (m_rot @ qvel) - _cross(arm, p_lin)
                        dp[3:] = r_t.T @ (L_ - l_now + _cross(arm, dp[:3]))
                    else:
                        dp = P_ - p_lin
                    dv = m_inv @ dp
                    qvel[F] += dv
                    dxs[k] = dx
                    dvs[k] = dv
                f = qfrc_passive - qfrc_bias
                a_p = pres_a[k]
                a_f = m_inv @ (f[F] - m_fp @ a_p)
                tau_p = m_pf @ a_f + m_pp @ a_p - f[P]
                qfrc_applied[F] = 0.0
                qfrc_applied[P] = tau_p
                f_ext = qfrc_passive[:3] + weight
                if free_rot:
                    # the aero moment about the whole bird's centre of mass (world)
                    m_ext = r_t @ qfrc_passive[3:6] - _cross(arm, qfrc_passive[:3])
                    if qfrc_applied[F].any() or xfrc.any():
                        self.root_applied_max = max(
                            self.root_applied_max,
                            float(np.max(np.abs(qfrc_applied[F]))),
                            float(np.max(np.abs(xfrc))),
                        )
                if record is not None and k % every == 0:
                    power = float(qfrc_applied[W] @ qvel[W])  # both wings' joints
                    if free_rot:
                        moment = C_SEED * (r_t.T @ m_ext)
                    else:  # the hidden torque that holds the posed orientation
                        moment = C_SEED * qfrc_applied[3:6]
                    tail = C_SEED * cb.tail_force_body
                    record.append((time, qpos.copy(), qvel.copy(), moment, f_ext, power, tail))
                step2(m, d)
                P_ = P_ + h * f_ext
                X_ = X_ + h * P_ / mass
                if free_rot:
                    L_ = L_ + h * m_ext
                time += h
        finally:
            self.P, self.X, self.L, self.time = P_, X_, L_, time
        if project and n:
            self.projection_max = max(
                self.projection_max,
                float(np.max(np.abs(dxs))),
                float(np.max(np.abs(dvs))) * h,
            )
        self._check_finite()

    def _check_finite(self) -> None:
        if not (np.all(np.isfinite(self.d.qpos)) and np.all(np.isfinite(self.d.qvel))):
            raise FlightError(
                f"the simulation diverged at t={self.time:.3f} (reduced time): non-finite state"
            )

    def com(self) -> tuple[np.ndarray, np.ndarray]:
        """Centre of mass and its velocity of the whole bird at the current state
        (recomputed from qpos/qvel)."""
        mujoco.mj_fwdPosition(self.m, self.d)
        mujoco.mj_fullM(self.m, self.d, self._M)
        return self.d.subtree_com[self.torso].copy(), (self._M[:3] @ self.d.qvel) / self.total_mass


#: MuJoCo body axes (x fwd, y left, z up) -> seed body axes (x fwd, y right, z down)
C_SEED = np.array([1.0, -1.0, -1.0])


def beat_period(bird: Bird) -> float:
    """One wingbeat in reduced time: 2 pi."""
    return 2.0 * math.pi


__all__ = ["C_SEED", "FlightError", "FreeBird", "Partition", "SimConfig", "partition"]
