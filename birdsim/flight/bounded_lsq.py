"""Bounded linear least squares for the attitude loop's allocation, without
:func:`scipy.optimize.lsq_linear`'s per-call overhead where it is not needed.

``lsq_linear`` (dense ``A``, the default method) first solves the unbounded problem with
``np.linalg.lstsq(A, b, rcond=-1)`` and returns that solution, with an all-zero active
mask, when it lies within the bounds (``lb <= x <= ub``): :func:`bounded_lsq` does
exactly that (the same call: the same numbers) and calls ``lsq_linear`` only otherwise.
The allocation is within its bounds in most control steps of a cruise, where the
argument checks, gradient and norm ``lsq_linear`` adds cost about as much as the solve.

The unbounded solve calls numpy's LAPACK routine (``gelsd``) as ``np.linalg.lstsq``
calls it (``numpy.linalg._umath_linalg.lstsq``, the same arguments: the same numbers,
half the time of the wrapper); where that private routine is missing, or its answer is
not finite (the wrapper would raise), ``np.linalg.lstsq`` itself runs.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import lsq_linear

try:  # numpy's own gufunc behind np.linalg.lstsq (numpy 1.x and 2.x)
    from numpy.linalg import _umath_linalg as _lapack

    _GELSD = _lapack.lstsq
except (ImportError, AttributeError):  # pragma: no cover
    _GELSD = None

#: solve within the bounds directly where possible (False: always lsq_linear)
ENABLED = True


def bounded_lsq(
    a: np.ndarray, b: np.ndarray, lb: np.ndarray, ub: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """``argmin |a x - b|`` with ``lb <= x <= ub``: (x, active mask as lsq_linear's:
    -1 / 1 where a lower / upper bound is active, 0 elsewhere)."""
    if ENABLED and (lb < ub).all():
        x = _lstsq(a, b)
        if ((x >= lb) & (x <= ub)).all():
            return x, np.zeros(x.shape[0])
    res = lsq_linear(a, b, bounds=(lb, ub))
    return res.x, res.active_mask


def _lstsq(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``np.linalg.lstsq(a, b, rcond=-1)[0]`` for a float (m, n) ``a`` and (m,) ``b``."""
    if (
        _GELSD is not None
        and a.dtype == np.float64
        and b.dtype == np.float64
        and a.ndim == 2
        and b.ndim == 1
        and a.shape[0] == b.shape[0] > 0
    ):
        with np.errstate(all="ignore"):
            x = _GELSD(a, b[:, None], -1.0, signature="ddd->ddid")[0][:, 0]
        if np.isfinite(x).all():
            return x.copy()
    return np.linalg.lstsq(a, b, rcond=-1)[0]


__all__ = ["bounded_lsq"]
