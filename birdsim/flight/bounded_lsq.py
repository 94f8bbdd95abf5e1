"""Bounded linear least squares for the attitude loop's allocation, without
:func:`scipy.optimize.lsq_linear`'s per-call overhead where it is not needed.

``lsq_linear`` (dense ``A``, the default method) first solves the unbounded problem with
``np.linalg.lstsq(A, b, rcond=-1)`` and returns that solution, with an all-zero active
mask, when it lies within the bounds (``lb <= x <= ub``): :func:`bounded_lsq` does
exactly that (the same call: the same numbers) and calls ``lsq_linear`` only otherwise.
The allocation is within its bounds in most control steps of a cruise, where the
argument checks, gradient and norm ``lsq_linear`` adds cost about as much as the solve.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import lsq_linear

#: solve within the bounds directly where possible (False: always lsq_linear)
ENABLED = True


def bounded_lsq(
    a: np.ndarray, b: np.ndarray, lb: np.ndarray, ub: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """``argmin |a x - b|`` with ``lb <= x <= ub``: (x, active mask as lsq_linear's:
    -1 / 1 where a lower / upper bound is active, 0 elsewhere)."""
    if ENABLED and np.all(lb < ub):
        x = np.linalg.lstsq(a, b, rcond=-1)[0]
        if np.all((x >= lb) & (x <= ub)):
            return x, np.zeros(x.shape[0])
    res = lsq_linear(a, b, bounds=(lb, ub))
    return res.x, res.active_mask


__all__ = ["bounded_lsq"]
