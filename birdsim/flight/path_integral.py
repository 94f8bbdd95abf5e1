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


def within_band(e_pos: np.ndarray, band: float = INTEGRAL_BAND) -> bool:
    """Whether every entry of the estimated position error ``e_pos`` (semispans) is
    within ``band`` in magnitude (False where one is not finite)."""
    return all(abs(e) < band for e in e_pos.tolist())


def integral_step(
    integral: np.ndarray, dt: float, e_pos: np.ndarray, limit: float | np.ndarray
) -> np.ndarray:
    """``(integral + dt * e_pos).clip(-limit, limit)``: the integral after one control
    interval ``dt`` (reduced time) of the position error ``e_pos`` (semispans)."""
    return _clip(integral + dt * e_pos, -limit, limit)


__all__ = ["FREE_BIAS_MARGIN", "INTEGRAL_BAND", "INTEGRAL_LIMIT", "integral_step", "within_band"]
