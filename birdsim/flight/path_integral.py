"""The path loop's integral term (reduced units): its bounds and its step per control
update, as :func:`birdsim.flight.freeflight.fly` runs them.

The step is numpy's ``(integral + dt * e_pos).clip(-limit, limit)`` with the clip's
ufunc called directly (``ndarray.clip`` adds a Python wrapper that only sorts out
integer bounds and absent ones: the same ufunc, the same numbers), and the band test on
floats (``max |e| < band`` is ``all |e| < band``, a NaN failing both).
"""

from __future__ import annotations

import numpy as np

try:  # the ufunc ndarray.clip calls (numpy >= 2); else the method
    from numpy._core.umath import clip as _clip
except ImportError:  # pragma: no cover
    _clip = np.clip

#: The integral term's acceleration is bounded by this fraction of gravity (the
#: table-vs-flight mismatch it trims is ~4 % of the weight in cruise) or, attitude free,
#: by this multiple of the mismatch the trimmed start measured where that is larger (the
#: free pigeon's hover: 14 % of the weight; docs/free-body.md, "ninth stage").
INTEGRAL_LIMIT, FREE_BIAS_MARGIN = 0.1, 1.5
#: The integral only runs while the estimated position error is below this (semispans).
INTEGRAL_BAND = 0.1
#: ... and in a turn (a path flown in its track frame) below this: a side gust in the
#: circle moves the height and the along-track position by 0.05-0.15 through the lateral
#: transient (the banked force's magnitude and direction, docs/turning.md, "tenth pass"),
#: and with the straight band the integral wound up during it and overshot the height
#: afterwards (the path loop's triple pole answering a step where the gust is an impulse).
#: Measured (``scripts/turn_gust_study.py --phases 16``, the distance 8 wingbeats after
#: the gust, mean / largest; its height part's mean): band 0.1 0.229 / 0.354, 0.078;
#: 0.05 0.225 / 0.339, 0.065; 0.04 0.208 / 0.353, 0.060; 0.03 0.210 / 0.358, 0.058;
#: 0.02 0.214 / 0.356, 0.060; 0.01 0.210 / 0.356, 0.057.  0.03 kept: the study's four
#: gusts all nearer (0.04: the one from 25.25 0.200 against 0.194) and the calm s-turn
#: 0.0956 (0.04: 0.0979; band 0.1: 0.0965).
TURN_INTEGRAL_BAND = 0.03


def within_band(
    e_pos: np.ndarray, band: float = INTEGRAL_BAND, side: np.ndarray | None = None
) -> bool:
    """Whether every entry of the estimated position error ``e_pos`` (semispans; along
    the path and height) is within ``band`` in magnitude (False where one is not finite)
    and, given straight flight's lateral window ``side`` (rows (y, vy), semispans and
    reduced velocity, newest last), its newest side offset too.

    Why the side offset: ``e_pos`` has no lateral part, so a side gust's transient (the
    banked flight's lift short of the weight for 5-6 wingbeats, the height 0.02-0.04 low)
    ran the integral the whole time and wound its height part up from 0.13 to 1.21
    (pigeon, 30 % +y gust), which held the path out of 0.05 semispan by height after the
    side offset had come back (docs/free-body.md, "the side offset in the band")."""
    off = [] if side is None or not len(side) else [float(side[-1][0])]
    return all(abs(e) < band for e in e_pos.tolist() + off)


def integral_step(
    integral: np.ndarray, dt: float, e_pos: np.ndarray, limit: float | np.ndarray
) -> np.ndarray:
    """``(integral + dt * e_pos).clip(-limit, limit)``: the integral after one control
    interval ``dt`` (reduced time) of the position error ``e_pos`` (semispans)."""
    return _clip(integral + dt * e_pos, -limit, limit)


__all__ = [
    "FREE_BIAS_MARGIN",
    "INTEGRAL_BAND",
    "INTEGRAL_LIMIT",
    "TURN_INTEGRAL_BAND",
    "integral_step",
    "within_band",
]
