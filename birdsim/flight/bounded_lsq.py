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

With numba, the unbounded solve and the bounds check run in one compiled call
(:data:`kernel`: numba's ``np.linalg.lstsq``, the same LAPACK ``gelsd`` with ``rcond=-1``
through scipy's LAPACK; 13 us against 27 us for the gufunc in its ``errstate`` on the
allocation's sizes).  Measured bitwise equal to numpy's on 15 000 random problems of the
allocation's shapes (3x2 to 6x4, regularisation rows down to 1e-6), and tested
(``tests/test_fast_flight.py``); a non-finite input leaves the kernel to the numpy path
(which raises as ``np.linalg.lstsq`` does).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import lsq_linear

from birdsim.physics.jit import numba

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
    if ENABLED and kernel is not None and a.dtype == b.dtype == np.float64 and a.ndim == 2:
        x = np.empty(a.shape[1])
        lo, hi = np.asarray(lb, dtype=float), np.asarray(ub, dtype=float)
        state = kernel(np.ascontiguousarray(a), np.ascontiguousarray(b), lo, hi, x)
        if state == 1:  # solved within the bounds
            return x, np.zeros(x.shape[0])
        if state == 0:  # outside them: lsq_linear
            res = lsq_linear(a, b, bounds=(lb, ub))
            return res.x, res.active_mask
    if ENABLED and (lb < ub).all():
        x = _lstsq(a, b)
        if ((x >= lb) & (x <= ub)).all():
            return x, np.zeros(x.shape[0])
    res = lsq_linear(a, b, bounds=(lb, ub))
    return res.x, res.active_mask


def _solve_within(a, b, lb, ub, x):
    """-1: not applicable (non-finite input, a bound not below its upper one); 1: the
    unbounded solution ``x`` (written) lies within the bounds; 0: it does not."""
    for i in range(lb.shape[0]):
        if not lb[i] < ub[i]:
            return -1
    for i in range(a.shape[0]):
        if not np.isfinite(b[i]):
            return -1
        for j in range(a.shape[1]):
            if not np.isfinite(a[i, j]):
                return -1
    sol = np.linalg.lstsq(a, b, -1.0)[0]
    inside = 1
    for i in range(x.shape[0]):
        x[i] = sol[i]
        if not np.isfinite(sol[i]):
            return -1
        if not (sol[i] >= lb[i] and sol[i] <= ub[i]):
            inside = 0
    return inside


#: the compiled unbounded solve and bounds check (None without numba)
kernel = numba.njit(cache=True)(_solve_within) if numba is not None else None


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


def vector_norm(v: np.ndarray) -> float:
    """``np.linalg.norm`` of a float vector as it computes it (sqrt of the dot product)."""
    return math.sqrt(v.dot(v))


__all__ = ["bounded_lsq", "vector_norm"]
