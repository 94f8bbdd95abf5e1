"""The bird on its feet: free flight's partitioned dynamics with the legs free and the
feet in contact (issue 25; docs/legs.md).

Reduced units (semispans, omega = 1, mass ratio, reduced gravity), MuJoCo world axes
(x forward, y left, z up), the arena of :mod:`birdsim.mujoco.arena` (floor and perch).

Partition: FREE = the root's six DOF and both legs' slides (MuJoCo integrates them
under gravity, the air, the feet's contact and the legs' muscle forces); PRESCRIBED =
the wing joints, held at a pose (standing, the push, touchdown) by computed torque as
in flight.  Per step: the wings are set to their pose, ``mj_step1``, ``a_F = M_FF^-1
(f_F - M_FP a_P)`` with ``f = passive - bias + legs``, ``tau_P`` into the wings'
``qfrc_applied``, the legs' muscle force into theirs (a force between the torso and the
leg: internal to the bird), the root's ``qfrc_applied`` exactly zero, ``mj_step2``
(contact solved by MuJoCo).  No momentum projection in contact: the projection of free
flight integrates the air and the weight only and would cancel the ground's reaction;
the wings are still here, so the reset it corrects is zero.  Flight after lift-off
restarts the projection from the state MuJoCo reached.

The feet's force is the root's translational row of ``qfrc_constraint`` (only the feet
touch anything, and a joint limit acts on its own DOF only): the world force of the
ground or perch on the bird.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import mujoco
import numpy as np

from birdsim.errors import BirdsimError
from birdsim.mujoco.callback import AeroCallback
from birdsim.mujoco.driver import wing_arrays
from birdsim.mujoco.legs import LegGeometry, foot_geoms, leg_dofs, leg_geometry
from birdsim.mujoco.model import build_model, pitch_quat
from birdsim.mujoco.perches import Scene
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.physics.units import reduced_bird

#: Static compression of the standing legs as a fraction of the leg length: sets the
#: legs' stiffness, k = (m g / 2) / (0.1 L) per leg (natural frequency sqrt(g / 0.1 L)).
STANDING_SAG = 0.07
#: Damping ratio of the legs' spring-damper (critical: landing absorbs without bouncing).
LEG_DAMPING_RATIO = 1.0
#: Time constant of the hips' PD muscle (critically damped), in wingbeats.
HIP_BEATS = 0.25
#: MuJoCo's noslip iterations (contact phases only).
NOSLIP_ITERATIONS = 10
#: Time steps per wingbeat (free flight's).
STEPS_PER_BEAT = 128
TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class LegMuscle:
    """The legs as muscles: a spring-damper about a reference length plus an active
    force (per leg, reduced units; positive extends the leg)."""

    stiffness: float
    damping: float
    q_stand: float  # leg coordinate standing (sole at leg_length below the hip)
    weight: float  # the whole bird's weight

    @classmethod
    def of(cls, geom: LegGeometry, mass: float, gravity: float) -> "LegMuscle":
        weight = mass * gravity
        k = 0.5 * weight / (STANDING_SAG * geom.length)
        c = 2.0 * LEG_DAMPING_RATIO * math.sqrt(k * 0.5 * mass)
        return cls(k, c, geom.q_stand, weight)

    @property
    def q_ref_stand(self) -> float:
        """Spring reference that carries half the weight per leg at ``q_stand``."""
        return self.q_stand + 0.5 * self.weight / self.stiffness

    def spring(self, q: np.ndarray, qd: np.ndarray, q_ref: float) -> np.ndarray:
        """The spring's force; the damper is the leg joint's ``dof_damping``, which
        MuJoCo's Euler integrates implicitly (explicit, the light leg against the
        damper of the whole bird chattered on the perch: m_leg / c is one time step)."""
        return self.stiffness * (q_ref - q)


#: A prescribed wing motion: reduced time -> (qpos, qvel, qacc) full rows.
WingPath = Callable[[float], tuple[np.ndarray, np.ndarray, np.ndarray]]
#: The wings' rest pose while standing (core joint angles, rad): swept back along the
#: body (sweep positive = tips back) and a little down.  m3 has no fold: a drawing choice.
REST_WINGS = {"sweep": 1.35, "flap": 0.1}
#: The folding wing's rest pose (m5): the swept-back arm's elbow flexed so that the forearm
#: (which carries the arm panel) lies forward along it and the wrist flexed so that the
#: hand lies back along the body, a Z fold (a drawing choice: the wrist ends 0.07 ahead
#: of the shoulder, the whole bird's centre of mass 0.015 semispan further forward than
#: with the wing extended and swept back).
FOLDED_WINGS = {**REST_WINGS, "elbow": -2.8, "wrist_sweep": 2.8}


def rest_wings(model_name: str) -> dict:
    """The wings' rest pose for ``model_name``: folded where the model has the folding
    wing (an elbow and a wrist that flexes in the wing plane), else swept back."""
    names = {j.name for j in get_model(model_name).joints}
    return dict(FOLDED_WINGS if {"elbow", "wrist_sweep"} <= names else REST_WINGS)


#: A leg law: (reduced time since the phase began, leg q (2,), leg qdot (2,)) -> force (2,)
LegLaw = Callable[[float, np.ndarray, np.ndarray], np.ndarray]


class ContactBird:
    """The MuJoCo bird with legs in the arena, contact on (reduced units).

    Use ``with ContactBird(...) as cb:`` (installs the aero callback).  ``bird`` in its
    own units; the simulation runs its reduced bird; ``perches`` the scene (default the
    presets' one perch)."""

    def __init__(
        self, model_name: str, bird: Bird, *, aero: bool = True, perches: Scene | None = None
    ):
        self.kin = get_model(model_name)
        self.bird = bird
        self.red = red = reduced_bird(bird)
        m = build_model(self.kin.name, red, scene=True, legs=True, perches=perches)
        m.opt.timestep = red.period / STEPS_PER_BEAT
        m.opt.gravity[:] = (0.0, 0.0, -red.gravity)
        m.opt.wind[:] = 0.0
        # MuJoCo's soft friction creeps under a steady moment: a bird on a round perch is
        # an inverted pendulum held by its feet's grip, and the creep grew (e-folding in
        # about 2.5 wingbeats); the noslip pass removes the creep of the friction rows
        m.opt.noslip_iterations = NOSLIP_ITERATIONS
        m.opt.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
        self.m, self.d = m, mujoco.MjData(m)
        self.h = float(m.opt.timestep)
        self.torso = m.body("torso").id
        self.mass = float(m.body_subtreemass[self.torso])
        self.weight = self.mass * red.gravity
        self.geom = leg_geometry(red)
        self.muscle = LegMuscle.of(self.geom, self.mass, red.gravity)
        self.legs = leg_dofs(m)
        self.hips = leg_dofs(m, "hip")
        self.leg_q = np.array([m.jnt_qposadr[m.joint(f"{s}_leg").id] for s in ("r", "l")])
        self.hip_q = np.array([m.jnt_qposadr[m.joint(f"{s}_hip").id] for s in ("r", "l")])
        self.feet = foot_geoms(m)
        self._M = np.zeros((m.nv, m.nv))
        self.set_leg_damping(True)
        # the hips: a PD muscle about ``hip_ref`` (rad), the body's pitch inertia turned
        # at HIP_BEATS (damper implicit, as the legs')
        mujoco.mj_forward(m, self.d)
        mujoco.mj_fullM(m, self.d, self._M)
        w_h = 1.0 / (HIP_BEATS * TWO_PI)
        self.hip_stiffness = 0.5 * float(self._M[4, 4]) * w_h**2  # per hip
        m.dof_damping[self.hips] = 2.0 * 0.5 * float(self._M[4, 4]) * w_h
        self.hip_ref = 0.0
        rot = 6
        self.free = np.concatenate([np.arange(rot), self.hips, self.legs])
        own = set(self.legs) | set(self.hips)
        self.pres = np.array([i for i in range(rot, m.nv) if i not in own])
        self.cb = AeroCallback(m, self.kin.name, red, tail=True)
        self.cb.enabled = aero
        self.time = 0.0
        self.hold_qpos = m.qpos0.copy()
        #: a wing motion (reduced time -> full qpos, qvel, qacc rows), or None: held
        self.wing_path: WingPath | None = None
        #: largest |entry| of the root's applied force over every step (0.0 exactly)
        self.root_applied_max = 0.0
        #: the feet's total normal force at the end of the last step (what a leg law may
        #: read: inside a step, between ``mj_step1`` and ``mj_step2``, MuJoCo's
        #: ``efc_force`` is not yet solved and holds whatever its arena memory held,
        #: which made the landing's contact differ from run to run)
        self.felt_normal = 0.0

    def __enter__(self) -> "ContactBird":
        if mujoco.get_mjcb_passive() is not None:
            raise BirdsimError(
                "a MuJoCo passive callback is already installed; allowed: one simulation at a time"
            )
        mujoco.set_mjcb_passive(self.cb)
        return self

    def __exit__(self, *exc: object) -> None:
        mujoco.set_mjcb_passive(None)

    def set_leg_damping(self, on: bool) -> None:
        """The legs' damper on (standing, landing) or relaxed (the push)."""
        self.m.dof_damping[self.legs] = self.muscle.damping if on else 0.0

    # ---- state -----------------------------------------------------------------------

    def hip_for(self, pitch: float) -> float:
        """The hip angle that puts the feet (legs at standing length) right under the
        whole bird's centre of mass at body ``pitch`` (no moment on the grip)."""
        m = self.m
        d = mujoco.MjData(m)
        d.qpos[:] = self.hold_qpos
        d.qpos[3:7] = pitch_quat(pitch)
        d.qpos[self.leg_q] = self.muscle.q_stand
        a = pitch
        for _ in range(6):
            d.qpos[self.hip_q] = a
            mujoco.mj_kinematics(m, d)
            mujoco.mj_comPos(m, d)
            err = float(d.geom_xpos[self.feet, 0].mean() - d.subtree_com[self.torso, 0])
            reach = self.geom.length - self.geom.foot_radius
            a += math.asin(max(-1.0, min(1.0, err / reach)))
        return a

    def place_standing(self, foot_top: np.ndarray, pitch: float = 0.0) -> None:
        """Put the bird at rest with its soles on ``foot_top`` (world x, y, z of the
        surface under the feet; the feet's mean x there), legs at their standing
        length under the centre of mass (:meth:`hip_for`), torso at ``pitch`` (nose
        up, rad)."""
        d, m = self.d, self.m
        hip = self.hip_for(pitch)
        d.qpos[:] = self.hold_qpos
        d.qvel[:] = 0.0
        d.qpos[3:7] = pitch_quat(pitch)
        d.qpos[self.leg_q] = self.muscle.q_stand
        d.qpos[self.hip_q] = hip
        self.hip_ref = hip
        d.qpos[:3] = 0.0
        mujoco.mj_forward(m, d)
        feet = d.geom_xpos[self.feet].mean(axis=0)
        top = np.asarray(foot_top, dtype=float)
        d.qpos[0] = top[0] - feet[0]
        d.qpos[1] = top[1] - feet[1]
        d.qpos[2] = top[2] + self.geom.foot_radius - feet[2]
        mujoco.mj_forward(m, d)

    def foot_force(self) -> np.ndarray:
        """World force of the ground/perch on the bird (after a step)."""
        return self.d.qfrc_constraint[:3].copy()

    def foot_normal(self) -> float:
        """Total normal force on the feet (sum over the feet's contacts), valid after a
        step only (inside one, in a leg law, read :attr:`felt_normal`)."""
        d, m = self.d, self.m
        total, f6 = 0.0, np.zeros(6)
        for i in range(d.ncon):
            c = d.contact[i]
            if c.geom1 in self.feet or c.geom2 in self.feet:
                mujoco.mj_contactForce(m, d, i, f6)
                total += f6[0]
        return total

    def on_feet(self) -> bool:
        d = self.d
        return any(
            d.contact[i].geom1 in self.feet or d.contact[i].geom2 in self.feet
            for i in range(d.ncon)
        ) and bool(np.any(d.qfrc_constraint[:3]))

    def body_pitch(self) -> float:
        """The torso's pitch (rad, nose up; :func:`~birdsim.mujoco.model.pitch_quat`)."""
        w, x, y, z = self.d.qpos[3:7]
        return -math.asin(max(-1.0, min(1.0, 2.0 * (w * y - z * x))))

    def com(self) -> tuple[np.ndarray, np.ndarray]:
        """Whole bird's centre of mass and its velocity (world)."""
        mujoco.mj_fwdPosition(self.m, self.d)
        mujoco.mj_fullM(self.m, self.d, self._M)
        v = (self._M[:3] @ self.d.qvel) / self.mass
        return self.d.subtree_com[self.torso].copy(), v

    # ---- stepping --------------------------------------------------------------------

    def step(self, law: LegLaw, t_phase: float) -> None:
        """One step: the wings held at ``hold_qpos`` (or moved by ``wing_path``, a
        callable of the time giving full qpos, qvel, qacc rows), the legs driven by
        ``law``."""
        m, d, M = self.m, self.d, self._M
        F, P = self.free, self.pres
        pq = self._pres_qpos()
        if self.wing_path is None:
            d.qpos[pq] = self.hold_qpos[pq]
            d.qvel[P] = 0.0
            a_p = np.zeros(len(P))
        else:
            q, v, a = self.wing_path(self.time)
            d.qpos[pq], d.qvel[P], a_p = q[pq], v[P], a[P]
        mujoco.mj_step1(m, d)
        mujoco.mj_fullM(m, d, M)
        legs = law(t_phase, d.qpos[self.leg_q], d.qvel[self.legs])
        hips = self.hip_stiffness * (self.hip_ref - d.qpos[self.hip_q])
        f = d.qfrc_passive - d.qfrc_bias
        f[self.legs] += legs
        f[self.hips] += hips
        a_f = np.linalg.solve(M[np.ix_(F, F)], f[F] - M[np.ix_(F, P)] @ a_p)
        d.qfrc_applied[:] = 0.0
        d.qfrc_applied[P] = M[np.ix_(P, F)] @ a_f + M[np.ix_(P, P)] @ a_p - f[P]
        d.qfrc_applied[self.legs] = legs
        d.qfrc_applied[self.hips] = hips
        self.root_applied_max = max(self.root_applied_max, float(np.abs(d.qfrc_applied[:6]).max()))
        mujoco.mj_step2(m, d)
        self.felt_normal = self.foot_normal()
        self.time += self.h
        if not (np.all(np.isfinite(d.qpos)) and np.all(np.isfinite(d.qvel))):
            raise BirdsimError(f"the contact simulation diverged at t={self.time:.3f}")

    def wing_blend(self, start: dict, end: dict, t0: float, duration: float) -> WingPath:
        """A wing motion from the core joint angles ``start`` to ``end`` (dicts of
        joint name -> angle) over ``duration`` from ``t0`` (reduced time), a cosine blend
        (rates and accelerations exact); held at ``end`` after."""
        m = self.m
        names = set(start) | set(end)
        a0 = {n: float(start.get(n, 0.0)) for n in names}
        da = {n: float(end.get(n, 0.0)) - a0[n] for n in names}

        def path(t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            u = min(max((t - t0) / duration, 0.0), 1.0)
            inside = 0.0 < u < 1.0
            s = 0.5 * (1.0 - math.cos(math.pi * u))
            ds = 0.5 * math.pi / duration * math.sin(math.pi * u) if inside else 0.0
            dds = 0.5 * (math.pi / duration) ** 2 * math.cos(math.pi * u) if inside else 0.0
            q, v, a = wing_arrays(
                m,
                {n: a0[n] + s * da[n] for n in names},
                {n: ds * da[n] for n in names},
                {n: dds * da[n] for n in names},
            )
            return q[0], v[0], a[0]

        return path

    def _pres_qpos(self) -> np.ndarray:
        if not hasattr(self, "_pq"):
            m, q = self.m, []
            for j in range(m.njnt):
                name = m.joint(j).name
                if name == "root" or name.endswith(("_leg", "_hip")):
                    continue
                n = {1: 4, 2: 1, 3: 1}[int(m.jnt_type[j])]
                q += range(int(m.jnt_qposadr[j]), int(m.jnt_qposadr[j]) + n)
            self._pq = np.array(q)
        return self._pq

    def standing_law(self) -> LegLaw:
        mu = self.muscle
        return lambda t, q, qd: mu.spring(q, qd, mu.q_ref_stand)


def beats_to_steps(beats: float) -> int:
    return int(round(beats * STEPS_PER_BEAT))


__all__ = ["FOLDED_WINGS", "REST_WINGS", "ContactBird", "LegMuscle", "beats_to_steps", "rest_wings"]
