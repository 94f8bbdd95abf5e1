"""The path loop's error estimate (:meth:`birdsim.flight.controller.ErrorWindow.estimate`)
over a full window in one compiled call, bit for bit numpy's numbers.

The reference takes four means of the last wingbeat's samples (some twenty numpy calls
per control update).  numpy's ``mean`` is ``add.reduce`` divided by the count: along the
first axis of a C-ordered (n, 2) array the rows are added one after another; along a
contiguous 1-D array numpy sums pairwise (``pairwise_sum`` in numpy's
``loops_utils.h``: eight running sums over blocks of eight below 129 entries, combined
``((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))``, the rest added in order; halves
above).  :func:`estimate_kernel` does those sums in that order and the estimate's
arithmetic in the reference's order (``tests/test_fast_schedule.py``: bitwise).
"""

from __future__ import annotations

import numpy as np

from birdsim.physics.jit import numba

#: the compiled estimate (False: the reference's numpy)
ENABLED = True


def _pairwise(a, lo, n):
    """numpy's pairwise sum of ``a[lo:lo + n]`` (contiguous float64)."""
    if n < 8:
        res = 0.0
        for i in range(n):
            res += a[lo + i]
        return res
    if n <= 128:
        r0, r1, r2, r3 = a[lo], a[lo + 1], a[lo + 2], a[lo + 3]
        r4, r5, r6, r7 = a[lo + 4], a[lo + 5], a[lo + 6], a[lo + 7]
        i = 8
        while i < n - (n % 8):
            r0 += a[lo + i]
            r1 += a[lo + i + 1]
            r2 += a[lo + i + 2]
            r3 += a[lo + i + 3]
            r4 += a[lo + i + 4]
            r5 += a[lo + i + 5]
            r6 += a[lo + i + 6]
            r7 += a[lo + i + 7]
            i += 8
        res = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
        while i < n:
            res += a[lo + i]
            i += 1
        return res
    n2 = n // 2
    n2 -= n2 % 8
    return _pairwise(a, lo, n2) + _pairwise(a, lo + n2, n - n2)


def _estimate(ep_rows, ev_rows, vx_rows, count, n, half, period, out):
    """``out`` = (position error estimate (2), velocity error estimate (2), airspeed)
    from the ``count`` samples' rows, the window the last ``n`` (``n + 1`` for the
    velocity's and the airspeed's slopes)."""
    for j in range(2):
        sp = 0.0
        sv = 0.0
        for i in range(count - n, count):
            sp += ep_rows[i, j]
            sv += ev_rows[i, j]
        ep = sp / n
        ev = sv / n
        ea = (ev_rows[count - 1, j] - ev_rows[count - n - 1, j]) / period
        out[j] = ep + half * ev
        out[2 + j] = ev + half * ea
    mean_vx = (0.0 + _pairwise(vx_rows, count - n, n)) / n  # add.reduce starts at 0.0
    out[4] = mean_vx + half * (vx_rows[count - 1] - vx_rows[count - n - 1]) / period


if numba is not None:
    _pairwise = numba.njit(cache=True)(_pairwise)
    estimate_kernel = numba.njit(cache=True)(_estimate)
else:  # pragma: no cover
    estimate_kernel = None


def estimate(rows: list, count: int, n: int, half: float, period: float) -> tuple | None:
    """:meth:`ErrorWindow.estimate` from its rows (ep (N, 2), ev (N, 2), vx (N,)) when
    ``count`` samples fill the window (``count > n``); None otherwise (the reference)."""
    if not ENABLED or estimate_kernel is None or count <= n or n < 1:
        return None
    out = np.empty(5)
    estimate_kernel(rows[0], rows[1], rows[2], count, n, half, period, out)
    return out[0:2], out[2:4], float(out[4])


__all__ = ["ENABLED", "estimate", "estimate_kernel"]
