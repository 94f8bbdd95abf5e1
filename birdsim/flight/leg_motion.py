"""The legs' motion in flight (issue 25): prescribed like the wings, a cosine blend of
the hips' and the legs' coordinates over a fraction of a wingbeat -- the tuck after
lift-off and the reach before touchdown (docs/legs.md).

In free flight every joint but the root is prescribed and held by computed torque (the
wings' and the legs' muscles: internal forces); without a :class:`LegMotion` the legs
stay at the MJCF's ``qpos0`` (tucked).  Reduced time; the leg coordinate is the slide
along the leg (0 tucked, positive extends), the hip the hinge about the torso's y
(positive swings the foot back).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

SIDES = ("r", "l")


def blend(t: np.ndarray, t0: float, duration: float) -> tuple[np.ndarray, ...]:
    """The cosine blend s(t) from 0 at ``t0`` to 1 at ``t0 + duration`` and its first
    and second time derivatives (0 outside)."""
    u = np.clip((np.asarray(t, dtype=float) - t0) / duration, 0.0, 1.0)
    inside = (u > 0.0) & (u < 1.0)
    w = math.pi / duration
    s = 0.5 * (1.0 - np.cos(math.pi * u))
    ds = np.where(inside, 0.5 * w * np.sin(math.pi * u), 0.0)
    dds = np.where(inside, 0.5 * w * w * np.cos(math.pi * u), 0.0)
    return s, ds, dds


@dataclass(frozen=True)
class LegMotion:
    """Both legs from (``leg_from``, ``hip_from``) to (``leg_to``, ``hip_to``) over
    ``duration`` from ``t0`` (reduced time), held before and after."""

    t0: float
    duration: float
    leg_from: float
    leg_to: float
    hip_from: float
    hip_to: float

    def at(self, t: np.ndarray) -> tuple[np.ndarray, ...]:
        """(leg, leg rate, leg acceleration, hip, hip rate, hip acceleration) at ``t``."""
        s, ds, dds = blend(t, self.t0, self.duration)
        dl, dh = self.leg_to - self.leg_from, self.hip_to - self.hip_from
        return (
            self.leg_from + s * dl,
            ds * dl,
            dds * dl,
            self.hip_from + s * dh,
            ds * dh,
            dds * dh,
        )

    def apply(self, m: mujoco.MjModel, pres: object, times: np.ndarray) -> None:
        """Write the legs' rows of a :class:`~birdsim.flight.wingbeat.Prescription`
        (qpos, qvel, qacc at ``times``) in place."""
        _write(m, pres, self.at(np.asarray(times, dtype=float)))


@dataclass(frozen=True)
class LegPlan:
    """Motions one after the other (a take-off's tuck, a landing's reach): at each
    time the last one that has begun (the first before any has)."""

    parts: tuple[LegMotion, ...]

    def apply(self, m: mujoco.MjModel, pres: object, times: np.ndarray) -> None:
        t = np.asarray(times, dtype=float)
        out = [np.array(v, dtype=float) for v in self.parts[0].at(t)]
        for part in self.parts[1:]:
            began = t >= part.t0
            for o, v in zip(out, part.at(t)):
                o[began] = np.broadcast_to(v, t.shape)[began]
        _write(m, pres, tuple(out))


def _write(m: mujoco.MjModel, pres: object, values: tuple) -> None:
    """The legs' rows (both sides alike) of ``pres`` from (leg, rate, acceleration, hip,
    rate, acceleration)."""
    leg, leg_v, leg_a, hip, hip_v, hip_a = values
    for side in SIDES:
        for name, q, v, a in (("leg", leg, leg_v, leg_a), ("hip", hip, hip_v, hip_a)):
            j = m.joint(f"{side}_{name}").id
            pres.qpos[:, m.jnt_qposadr[j]] = q
            pres.qvel[:, m.jnt_dofadr[j]] = v
            pres.qacc[:, m.jnt_dofadr[j]] = a


__all__ = ["LegMotion", "LegPlan", "blend"]
