"""Gusts: a wind of constant velocity over an interval of a flight.

``--gust T0:DURATION:WX:WY:WZ`` (times in wingbeats after the start, velocities in the
bird's velocity unit, MuJoCo's world axes: x forward, y to the bird's LEFT, z up), or
today's four numbers ``T0:DURATION:WX:WZ`` (no side wind).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from birdsim.errors import BirdsimError, limits_text, magnitude_ok

FORMS = "T0:DURATION:WX:WY:WZ (five numbers) or T0:DURATION:WX:WZ (four)"


class GustError(BirdsimError):
    """A malformed --gust."""


@dataclass(frozen=True)
class Gust:
    """Wind ``(wx, wy, wz)`` (the bird's velocity units; x forward, y left, z up) from
    ``t0`` for ``duration`` wingbeats after the start.  (Positional order t0, duration,
    wx, wz, wy keeps the four-number form's meaning.)"""

    t0: float
    duration: float
    wx: float
    wz: float
    wy: float = 0.0

    def __post_init__(self) -> None:
        for name in ("t0", "duration", "wx", "wy", "wz"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and magnitude_ok(v)):
                raise GustError(
                    f"gust {name}={v!r} is invalid; allowed: a finite number, {limits_text()}"
                )
        if self.t0 < 0 or self.duration < 0:
            raise GustError(
                f"--gust T0={self.t0:g}, DURATION={self.duration:g}; allowed: times >= 0 (wingbeats)"
            )


def parse_gust(text: str) -> Gust:
    """``"T0:DURATION:WX:WY:WZ"`` or ``"T0:DURATION:WX:WZ"`` -> Gust; one clear line otherwise."""
    parts = str(text).split(":")
    if len(parts) not in (4, 5):
        raise GustError(f"--gust {text!r} has {len(parts)} field(s); allowed: {FORMS}")
    try:
        vals = [float(p) for p in parts]
    except ValueError:
        raise GustError(
            f"--gust {text!r} is not numbers; allowed: {FORMS}, e.g. 4:1:0:0.15:0"
        ) from None
    if not all(math.isfinite(v) for v in vals):
        raise GustError(f"--gust {text!r} is not finite; allowed: {FORMS}, finite numbers")
    t0, duration, wx, wy, wz = vals if len(vals) == 5 else (*vals[:3], 0.0, vals[3])
    try:
        return Gust(t0, duration, wx, wz, wy)
    except GustError as exc:
        raise GustError(f"--gust {text!r}: {exc}") from None


def wind_at(gusts: Sequence[Gust], t_beats: float, speed_scale: float = 1.0) -> np.ndarray:
    """The summed gust wind at ``t_beats`` (world x, y, z; reduced: divided by
    ``speed_scale``)."""
    w = np.zeros(3)
    for g in gusts:
        if g.t0 <= t_beats < g.t0 + g.duration:
            w += np.array([g.wx, g.wy, g.wz]) / speed_scale
    return w


__all__ = ["Gust", "GustError", "parse_gust", "wind_at"]
