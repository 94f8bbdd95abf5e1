"""Legs and feet of the MuJoCo bird (issue 25): one telescoping leg per side, a foot
that grips, and the contact filter that lets only the feet touch the world.

Per side (prefix ``r_`` right, at MuJoCo -y; ``l_`` left) a body ``X_leg`` hangs from the
torso at the hip, on a hinge ``X_hip`` about the torso's y (positive swings the foot
back: with the hip angle equal to the body's pitch the leg is vertical) and a slide
``X_leg`` along the leg (positive = the leg extends, the foot moves away from the hip).  ``q = 0`` is the leg TUCKED under the
body (the MJCF's qpos0, so a flight that prescribes the wings from ``qpos0`` carries its
legs folded); standing, the sole is ``bird.leg_length`` below the hip
(:attr:`LegGeometry.q_stand`).  Each leg body carries ``bird.leg_mass_fraction`` of
the bird's mass, taken out of the torso so the whole bird weighs ``bird.mass``.

The foot ``X_foot`` is a small sphere with MuJoCo's elliptic-cone contact of dimension
6: sliding friction 1, torsional and rolling friction ``toe_span / 2`` (a length: the
contact resists a moment up to the normal force times half the toe span, as a foot
whose toes wrap the perch over that span would).  That grip is what keeps a bird on a
round perch upright without a hidden torque.  With legs every other bird geom has
``contype = conaffinity = 0``: wings, tail and body never touch the perch or the floor.

Visual: a shank (capsule from the foot up, hidden in the torso when tucked) and three
toes per foot, massless and contact-free, in the dressed bird's group 2.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from birdsim.physics.bird import Bird

#: Side (MuJoCo y) of each leg: right wing at -y.
LEG_SIDES = ("r", "l")
#: Hip below the torso origin and out from the centreline, in semispans (inside the
#: drawn torso ellipsoid, half height 0.13 s).
HIP_DOWN = 0.06
HIP_OUT = 0.05
#: Hip hinge range (rad) either way.
HIP_RANGE = 1.6
#: Tucked length (hip to foot centre) as a fraction of the leg length.
TUCK_FRACTION = 0.35
#: Foot sphere radius as a fraction of the leg length.
FOOT_RADIUS_FRACTION = 0.1
#: Largest extension beyond standing, fraction of the standing stroke (the jump's room).
OVER_EXTENSION = 0.3
#: The feet's contact: solref time constant in steps of period/128 (MuJoCo's stable
#: minimum is 2 time steps) and damping ratio 1.
CONTACT_TIMECONST_BEATS = 16.0 / 128.0
#: The feet's contact impedance (MuJoCo solimp: dmin, dmax, width, midpoint, power).
FOOT_SOLIMP = (0.99, 0.9999, 0.001, 0.5, 2.0)


@dataclass(frozen=True)
class LegGeometry:
    """One leg in the bird's length unit (torso frame: x forward, y left, z up)."""

    length: float  # hip to sole, standing
    hip: tuple[float, float, float]  # right hip (the left one mirrored in y)
    tuck: float  # hip to foot centre at q = 0
    foot_radius: float
    mass: float  # one leg
    toe_span: float

    @property
    def q_stand(self) -> float:
        """Slide coordinate with the sole ``length`` below the hip."""
        return self.length - self.tuck - self.foot_radius

    @property
    def q_max(self) -> float:
        return (1.0 + OVER_EXTENSION) * self.q_stand

    def sole_below_origin(self, q: float) -> float:
        """How far the sole is below the torso origin at leg coordinate ``q`` (torso
        level)."""
        return -self.hip[2] + self.tuck + q + self.foot_radius


def leg_geometry(bird: Bird) -> LegGeometry:
    """The legs of ``bird`` (its own length unit)."""
    s, L = bird.semispan, bird.leg_length
    return LegGeometry(
        length=L,
        hip=(0.0, -HIP_OUT * s, -HIP_DOWN * s),
        tuck=TUCK_FRACTION * L,
        foot_radius=FOOT_RADIUS_FRACTION * L,
        mass=bird.leg_mass_fraction * bird.mass,
        toe_span=bird.toe_span,
    )


def add_legs(spec: mujoco.MjSpec, torso: mujoco.MjsBody, bird: Bird, visuals: bool) -> None:
    """Add both legs and feet to ``torso`` (its mass must already be set: the legs'
    mass is taken out of it) and filter the contacts to the feet."""
    g = leg_geometry(bird)
    torso.mass = torso.mass - 2.0 * g.mass
    r = g.foot_radius
    timeconst = CONTACT_TIMECONST_BEATS * bird.period
    for side in LEG_SIDES:
        sy = 1.0 if side == "r" else -1.0
        hip = np.array(g.hip) * np.array([1.0, sy, 1.0])
        leg = torso.add_body(name=f"{side}_leg", pos=hip)
        leg.add_joint(  # the hip: positive swings the foot back (the leg stays vertical
            # in the world when the hip angle equals the body's nose-up pitch)
            name=f"{side}_hip",
            type=mujoco.mjtJoint.mjJNT_HINGE,
            axis=[0.0, 1.0, 0.0],
            range=[-HIP_RANGE, HIP_RANGE],
        )
        leg.add_joint(
            name=f"{side}_leg",
            type=mujoco.mjtJoint.mjJNT_SLIDE,
            axis=[0.0, 0.0, -1.0],
            range=[0.0, g.q_max],
        )
        leg.explicitinertial = True
        leg.mass = g.mass
        leg.ipos = [0.0, 0.0, -g.tuck]
        rod = g.mass * g.length**2 / 12.0
        leg.inertia = [rod, rod, 0.1 * rod]
        foot = leg.add_geom(
            name=f"{side}_foot",
            type=mujoco.mjtGeom.mjGEOM_SPHERE,
            size=[r, 0.0, 0.0],
            pos=[0.0, 0.0, -g.tuck],
            mass=0.0,
        )
        foot.contype, foot.conaffinity = 2, 1  # against the arena's 1 / 2
        foot.condim = 6
        foot.friction = [1.0, 0.5 * g.toe_span, 0.5 * g.toe_span]
        foot.solref = [timeconst, 1.0]
        # impedance near 1: the friction (grip) constraints barely creep under a steady
        # moment (MuJoCo's soft friction creeps at a speed proportional to (1 - d) / d)
        foot.solimp = list(FOOT_SOLIMP)
        foot.group = 1
        if visuals:
            _dress_leg(leg, side, g)
    feet = {f"{side}_foot" for side in LEG_SIDES}
    for geom in spec.geoms:  # only the feet of the bird collide (class "bird": 2 / 1)
        if geom.name not in feet and geom.contype == 2:
            geom.contype, geom.conaffinity = 0, 0


def _dress_leg(leg: mujoco.MjsBody, side: str, g: LegGeometry) -> None:
    """Shank and toes for the eye (massless, contact-free, group 2)."""
    vis = dict(contype=0, conaffinity=0, group=2, mass=0.0, rgba=[0.78, 0.36, 0.36, 1.0])
    foot_z = -g.tuck
    leg.add_geom(
        name=f"vis_{side}_shank",
        type=mujoco.mjtGeom.mjGEOM_CAPSULE,
        fromto=[0.0, 0.0, foot_z, 0.0, 0.0, foot_z + g.length - g.foot_radius],
        size=[0.35 * g.foot_radius, 0.0, 0.0],
        **vis,
    )
    half = 0.5 * g.toe_span
    for k, (dx, dy) in enumerate(((1.0, 0.0), (0.8, 0.35), (-0.7, 0.0))):
        leg.add_geom(
            name=f"vis_{side}_toe{k}",
            type=mujoco.mjtGeom.mjGEOM_CAPSULE,
            fromto=[0.0, 0.0, foot_z, dx * half, dy * half, foot_z - 0.3 * g.foot_radius],
            size=[0.2 * g.foot_radius, 0.0, 0.0],
            **vis,
        )


def leg_dofs(m: mujoco.MjModel, joint: str = "leg") -> np.ndarray:
    """The legs' slide DOF addresses (right, left), or the hips' (``joint="hip"``);
    empty for a model without legs."""
    out = []
    for side in LEG_SIDES:
        j = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, f"{side}_{joint}")
        if j >= 0:
            out.append(int(m.jnt_dofadr[j]))
    return np.array(out, dtype=int)


def foot_geoms(m: mujoco.MjModel) -> np.ndarray:
    return np.array(
        [mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, f"{s}_foot") for s in LEG_SIDES],
        dtype=int,
    )


__all__ = ["LegGeometry", "add_legs", "foot_geoms", "leg_dofs", "leg_geometry"]
