"""m5's dressed hand folds: the primaries fan closed as the wrist flexes (issue 24).

m5's MJCF dresses each hand with one geom per primary, ``vis_<side>_hand_primary_<k>``
(k = 0 innermost .. :data:`~birdsim.mujoco.visual.PRIMARIES` - 1 outermost,
:func:`birdsim.mujoco.visual.add_panel_dress` with ``fan``); every other model keeps
one mesh per colour and is untouched.  Per instant, :class:`PrimaryFan` turns each
primary in the hand's plane (about the hand body's z axis) about its root, the middle
of its inner edge, towards the outermost primary's direction by

    ``f(q) * delta_k``,  ``f(q) = clip(q / FAN_SHUT_FLEXION, 0, 1)``,

with ``q`` the wrist's flexion (the joint ``<side>_wrist_sweep``, positive = the hand's
tip back) and ``delta_k`` the angle from primary k's direction to the outermost one's:
linear in the fold, closed (every primary along the outermost) at
:data:`FAN_SHUT_FLEXION`, the rest pose again when the wing extends.  A drawing: the
geoms are massless and contact-free (group 2) and turned on the renderer's own copy of
the model, so no force, inertia or figure changes.  The aerodynamics' hand area has its
own law (:func:`birdsim.physics.m5.area_factor`, ``1 - lambda sin^2(q / 2)``).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from birdsim.mujoco.sites import SIDES, span_sign
from birdsim.mujoco.visual import panel_planform
from birdsim.physics.bird import Bird
from birdsim.physics.m5 import FOLD_PARAMS

#: The wrist flexion (rad) at which the fan is shut: a DRAWING CHOICE, the largest elbow
#: flexion m5's bounds allow (``fold_amp`` <= pi/3; the wrist follows it one to one with
#: the pigeon's ``fold_coupling`` 1); the fan closes linearly up to it.
FAN_SHUT_FLEXION = next(p.upper for p in FOLD_PARAMS if p.name == "fold_amp")
#: The joint whose angle folds the hand (m5's MJCF, birdsim.mujoco.fold).
FOLD_JOINT = "wrist_sweep"


def fan_fraction(q: float | np.ndarray) -> float | np.ndarray:
    """How far the fan is closed (0 open .. 1 shut) at wrist flexion ``q`` (rad)."""
    return np.clip(np.asarray(q, dtype=float) / FAN_SHUT_FLEXION, 0.0, 1.0)


def primary_fan(span: float, chord: float, sign: float) -> tuple[np.ndarray, np.ndarray]:
    """The primaries of a hand panel of ``span`` x ``chord`` whose span runs along
    ``sign`` * y of its body: roots (K, 2) in the body's (x, y) and the angles (K,)
    about the body's z axis that turn each primary onto the outermost one's direction
    (0 for the outermost)."""
    pieces = [p for p in panel_planform("hand", span, chord) if p.kind.startswith("primaries")]
    roots, theta = [], []
    for p in pieces:  # polygon: inner a, inner b, outer b, arc..., outer a (visual._feather)
        poly = p.polygon
        root, tip = 0.5 * (poly[0] + poly[1]), 0.5 * (poly[2] + poly[-1])
        d = tip - root  # (u, x)
        roots.append([root[1], sign * root[0]])
        theta.append(math.atan2(sign * d[0], d[1]))
    theta = np.asarray(theta)
    delta = np.angle(np.exp(1j * (theta[-1] - theta)))  # wrapped to (-pi, pi]
    return np.asarray(roots), delta


def _zquat(angle: float) -> np.ndarray:
    return np.array([math.cos(angle / 2), 0.0, 0.0, math.sin(angle / 2)])


class PrimaryFan:
    """Turns the primary geoms of an m5 model ``m`` (this copy of it) by the wrist
    flexion in a ``qpos``; :meth:`for_model` gives None for a model without them."""

    def __init__(self, m: mujoco.MjModel, bird: Bird):
        self.m = m
        hand_span = bird.semispan * bird.hand_span_fraction
        hand_chord = bird.panels("m5")[1].chord
        self.sides = []  # (qpos address, geom ids, roots (K, 3), deltas (K,))
        for side in SIDES:
            roots, delta = primary_fan(hand_span, hand_chord, span_sign(side))
            ids = [
                mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, f"vis_{side}_hand_primary_{k}")
                for k in range(len(delta))
            ]
            j = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, f"{side}_{FOLD_JOINT}")
            if j < 0 or min(ids) < 0:
                continue
            r3 = np.column_stack([roots, np.zeros(len(roots))])
            self.sides.append((int(m.jnt_qposadr[j]), ids, r3, delta))
        self.pos0 = {g: m.geom_pos[g].copy() for _, ids, _, _ in self.sides for g in ids}
        self.quat0 = {g: m.geom_quat[g].copy() for g in self.pos0}
        for g in self.pos0:  # MuJoCo skips geom_pos/quat of a geom in its body's frame
            m.geom_sameframe[g] = 0

    @classmethod
    def for_model(cls, m: mujoco.MjModel, bird: Bird) -> PrimaryFan | None:
        fan = cls(m, bird)
        return fan if fan.sides else None

    def pose(self, qpos: np.ndarray) -> None:
        """Turn every primary for the wrist flexions in ``qpos`` (before mj_kinematics)."""
        for adr, ids, roots, delta in self.sides:
            f = float(fan_fraction(qpos[adr]))
            for g, r, dk in zip(ids, roots, delta):
                a = f * float(dk)
                if a == 0.0:  # extended: exactly the rest pose (as built)
                    self.m.geom_pos[g], self.m.geom_quat[g] = self.pos0[g], self.quat0[g]
                    continue
                c, s = math.cos(a), math.sin(a)
                rot = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
                self.m.geom_pos[g] = r + rot @ (self.pos0[g] - r)
                out = np.zeros(4)
                mujoco.mju_mulQuat(out, _zquat(a), self.quat0[g])
                self.m.geom_quat[g] = out


__all__ = ["FAN_SHUT_FLEXION", "FOLD_JOINT", "PrimaryFan", "fan_fraction", "primary_fan"]
