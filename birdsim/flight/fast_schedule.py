"""The wingbeat schedule's two filters in one compiled call:
:meth:`birdsim.flight.wingbeat.WingbeatSchedule.advance`'s smoothing of the table's
wingbeat and of the attitude inputs, and the right and left wings' parameters made of
them, bit for bit the reference's numbers.

The reference (:meth:`birdsim.flight.wingbeat.CascadeFilter.advance`) runs some thirty
numpy calls per control update on (16, n) arrays.  The exponentials stay numpy's
(``np.exp`` on the same arrays as the reference: numpy's SIMD exponential differs from the
C library's in the last bit), every other operation is the reference's elementwise
operation in its order (``(e2 + e1 t / tau) ex``, ``(f1 - f2) / tau``, ``(f2 - 2 f1) /
tau**2``, right ``(mean + diff) + offset``, left ``(mean - diff) + offset``), without fused
multiply-adds (numba's default): the same bits (``tests/test_fast_schedule.py``).
"""

from __future__ import annotations

import numpy as np

from birdsim.physics.jit import numba

#: the filters compiled (False: the reference's numpy, :class:`CascadeFilter`)
ENABLED = True


def _cascade(x1, x2, u, t, ex, gex, dt, tau, tau2, p, dp, ddp):
    """One CascadeFilter.advance into p, dp, ddp (T, n); the state moved on by dt."""
    for j in range(u.shape[0]):
        e1 = x1[j] - u[j]
        e2 = x2[j] - u[j]
        for i in range(t.shape[0]):
            f1 = e1 * ex[i]
            f2 = (e2 + e1 * t[i] / tau) * ex[i]
            p[i, j] = u[j] + f2
            dp[i, j] = (f1 - f2) / tau
            ddp[i, j] = (f2 - 2.0 * f1) / tau2
        x1[j] = u[j] + e1 * gex
        x2[j] = u[j] + (e2 + e1 * dt / tau) * gex


def _advance(
    x1, x2, u, ex, gex, tau, tau2, y1, y2, v, ey, gey, sig, sig2, t, dt, n, right, left, shoulder
):
    """Both filters (the table's wingbeat x, the inputs y), then the wings' rows: right
    ``(x + y[:n]) + y[n:2n]``, left ``(x - y[:n]) + y[n:2n]``, the shoulders ``y[2n:]``;
    each of right, left, shoulder a (3, T, .) array of p, p', p''."""
    T = t.shape[0]
    mp, mdp, mddp = np.empty((T, n)), np.empty((T, n)), np.empty((T, n))
    k = v.shape[0]
    ip, idp, iddp = np.empty((T, k)), np.empty((T, k)), np.empty((T, k))
    _cascade(x1, x2, u, t, ex, gex, dt, tau, tau2, mp, mdp, mddp)
    _cascade(y1, y2, v, t, ey, gey, dt, sig, sig2, ip, idp, iddp)
    for d in range(3):
        if d == 0:
            a, b = mp, ip
        elif d == 1:
            a, b = mdp, idp
        else:
            a, b = mddp, iddp
        for i in range(T):
            for j in range(n):
                right[d, i, j] = a[i, j] + b[i, j] + b[i, n + j]
                left[d, i, j] = a[i, j] - b[i, j] + b[i, n + j]
            for j in range(k - 2 * n):
                shoulder[d, i, j] = b[i, 2 * n + j]


if numba is not None:
    _cascade = numba.njit(cache=True)(_cascade)
    kernel = numba.njit(cache=True)(_advance)
else:  # pragma: no cover
    kernel = None


#: :func:`exponentials`' answers by their arguments (a flight's intervals repeat a few
#: dozen ``rel`` arrays: the steps' offsets from the interval's start, as summed)
_EXPONENTIALS: dict = {}
MEMO_SIZE = 64


def exponentials(
    tau: float, sig: float, rel: np.ndarray, dt: float
) -> tuple[np.ndarray, np.ndarray, float, float]:
    """(exp(-rel / tau), exp(-rel / sig), exp(-dt / tau), exp(-dt / sig)): the
    reference's exponents (numpy's division, Python's for dt) in one ``np.exp`` call
    (numpy's exponential of an entry does not depend on the array around it: checked on
    100 000 values at every offset and length up to 17).  An earlier call's arrays where
    the arguments have its bits (kept for :data:`MEMO_SIZE` argument sets; the callers
    only read them)."""
    key = (tau, sig, dt, rel.dtype.char, rel.tobytes())
    hit = _EXPONENTIALS.get(key)
    if hit is not None:
        return hit
    T = rel.shape[0]
    arg = np.empty(2 * T + 2)
    neg = -rel
    np.divide(neg, tau, out=arg[:T])
    np.divide(neg, sig, out=arg[T : 2 * T])
    arg[2 * T], arg[2 * T + 1] = -dt / tau, -dt / sig
    e = np.exp(arg)
    out = e[:T], e[T : 2 * T], float(e[2 * T]), float(e[2 * T + 1])
    if len(_EXPONENTIALS) >= MEMO_SIZE:
        _EXPONENTIALS.clear()
    _EXPONENTIALS[key] = out
    return out


def advance(
    mean_filter, input_filter, u: np.ndarray, v: np.ndarray, rel: np.ndarray, dt: float, n: int
) -> tuple[tuple, tuple, tuple] | None:
    """(right, left, shoulder) as :meth:`WingbeatSchedule.advance` makes them from its
    filters (``mean_filter`` on the table's wingbeat ``u``, ``input_filter`` on the inputs
    ``v``, both at ``rel`` (T,) after now, then moved on by ``dt``), each a tuple (p, p',
    p''); None (nothing done) where it does not apply (switched off, no numba, a filter
    with time constant 0)."""
    if not ENABLED or kernel is None or mean_filter.tau == 0.0 or input_filter.tau == 0.0:
        return None
    tau, sig = mean_filter.tau, input_filter.tau
    T = rel.shape[0]
    ex, ey, gex, gey = exponentials(tau, sig, rel, dt)
    right, left = np.empty((3, T, n)), np.empty((3, T, n))
    shoulder = np.empty((3, T, v.shape[0] - 2 * n))
    kernel(
        mean_filter.x1, mean_filter.x2, u, ex, gex, tau, tau**2,
        input_filter.x1, input_filter.x2, v, ey, gey, sig, sig**2,
        rel, float(dt), n, right, left, shoulder,
    )  # fmt: skip
    return tuple(right), tuple(left), tuple(shoulder)


__all__ = ["ENABLED", "advance", "exponentials", "kernel"]
