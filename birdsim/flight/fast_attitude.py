"""The attitude loop's control update after its Jacobians are known, in one compiled call:
:meth:`birdsim.flight.attitude.AttitudeLoop.update`'s inputs' bounds, the integral's
bound and step, the moment demand and its allocation (the pitch row's split,
:func:`birdsim.flight.attitude_pitch.pitch_allocation`, and the least squares of the
other rows), bit for bit the reference's numbers (reduced units, seed body axes).

The reference runs some hundred numpy calls per control update on vectors of 3 and 7
entries.  Here every operation is the reference's in its order, without fused
multiply-adds (numba's default): the elementwise arithmetic, Python's ``min`` / ``max``
where the reference uses them, numpy's ``clip`` / ``maximum`` / ``minimum``; the dot
products and the matrix-vector products through numba's ``np.dot`` (the BLAS ``ddot``
and ``dgemv`` numpy's ``@`` calls: measured bitwise equal on 20 000 random problems of
each of the loop's shapes); the unbounded solves by the compiled
:data:`birdsim.flight.bounded_lsq.kernel` the reference calls too.  Where a solve is not
within its bounds (the reference then calls ``scipy.optimize.lsq_linear``) or an input
is not finite, the call reports it, changes nothing, and the reference runs the update
(``tests/test_fast_attitude.py``: flights bitwise equal, straight and turning, with a
gust that drives inputs to their bounds).
"""

from __future__ import annotations

import math

import numpy as np

from birdsim.flight import attitude_pitch, bounded_lsq
from birdsim.physics.jit import numba

#: the update's allocation compiled (False: the reference's numpy and Python)
ENABLED = True


def _pymin(a, b):
    """Python's ``min(a, b)``: ``a`` unless ``b < a``."""
    return b if b < a else a


def _pymax(a, b):
    """Python's ``max(a, b)``: ``a`` unless ``b > a``."""
    return b if b > a else a


def _npmax(a, b):
    """numpy's ``maximum`` of two floats (a NaN propagates)."""
    if a != a:
        return a
    if b != b:
        return b
    return a if a >= b else b


def _npmin(a, b):
    """numpy's ``minimum`` of two floats (a NaN propagates)."""
    if a != a:
        return a
    if b != b:
        return b
    return a if a <= b else b


def _clip(x, lo, hi):
    """numpy's ``clip`` of a float: ``min(max(x, lo), hi)``, a NaN of ``x`` kept."""
    if x != x:
        return x
    x = x if x > lo else lo
    return x if (x != x or x < hi) else hi


def _norm(v):
    """:func:`birdsim.flight.bounded_lsq.vector_norm`: ``sqrt(v . v)``."""
    return math.sqrt(np.dot(v, v))


def _bounds(params, plan_index, plan_lower, plan_upper, plan_bound, lo, hi):
    """``AttitudeLoop.bounds``: per input ``min(bound, max(0, 2 min(p - lower, upper -
    p)))`` for an amplitude, else its bound; ``lo = -hi``."""
    for j in range(plan_index.shape[0]):
        b = plan_bound[j]
        i = plan_index[j]
        if i >= 0:
            p = params[i]
            b = _pymin(b, _pymax(0.0, 2.0 * _pymin(p - plan_lower[j], plan_upper[j] - p)))
        hi[j] = b
        lo[j] = -b


def _integral_limit(
    omega_a, jac, lo, hi, inertia, limit_rad, authority, lateral, cap_rad, groups, lim
):
    """``AttitudeLoop.integral_limit`` (:func:`birdsim.flight.attitude.integral_bound`,
    then straight flight's lateral cap) into ``lim`` (3,).  ``groups``: (2, 2, 4) rows
    and columns of the two allocations, -1 padded."""
    for r in range(3):
        lim[r] = limit_rad * (omega_a[r] * omega_a[r])
    if authority[0] or authority[1] or authority[2]:
        half = (hi - lo) / 2
        auth = np.zeros(3)
        for g in range(groups.shape[0]):
            nc = 0
            for c in range(groups.shape[2]):
                if groups[g, 1, c] >= 0:
                    nc += 1
            cols = groups[g, 1, :nc]
            h = np.empty(nc)
            for c in range(nc):
                h[c] = half[cols[c]]
            for k in range(groups.shape[2]):
                r = groups[g, 0, k]
                if r < 0:
                    continue
                a = np.empty(nc)
                for c in range(nc):
                    a[c] = abs(jac[r, cols[c]])
                auth[r] = np.dot(a, h)
        for r in range(3):
            if authority[r]:
                lim[r] = _npmax(lim[r], auth[r] / inertia[r])
    if lateral:
        for r in (0, 2):
            lim[r] = _npmin(lim[r], cap_rad * (omega_a[r] * omega_a[r]))


def _row_lsq(a, b, lo, hi, sqrt_lam, out):
    """``attitude_pitch._lsq`` within its bounds: ``out`` the solution times the scale;
    False where the unbounded solution leaves the bounds (the reference's ``lsq_linear``)."""
    n = a.shape[0]
    scale = np.empty(n)
    for i in range(n):
        scale[i] = (hi[i] - lo[i]) / 2 if hi[i] > lo[i] else 1.0
    sa = a * scale
    top = np.abs(sa).max()
    reg = sqrt_lam * _pymax(top, 1e-12)
    a_aug = np.zeros((n + 1, n))
    a_aug[0, :] = sa
    for i in range(n):
        a_aug[1 + i, i] = reg
    b_aug = np.zeros(n + 1)
    b_aug[0] = b
    x = np.empty(n)
    if bounded_lsq.kernel(a_aug, b_aug, lo / scale, hi / scale, x) != 1:
        return False
    for i in range(n):
        out[i] = x[i] * scale[i]
    return True


def _pitch(row, demand, slow, lo, hi, sqrt_lam, wings, tail, u):
    """``attitude_pitch.pitch_allocation`` into ``u``: (status 1 or 0 for the reference,
    the moment missed, whether the tail's bound bound)."""
    nw = 0
    for c in wings:
        if hi[c] > lo[c]:
            nw += 1
    w = np.empty(nw, dtype=np.int64)
    k = 0
    for c in wings:
        if hi[c] > lo[c]:
            w[k] = c
            k += 1
    active = False
    more = np.empty(nw)
    if nw:
        if not _row_lsq(row[w], slow, lo[w], hi[w], sqrt_lam, more):
            return 0, 0.0, False
        for i in range(nw):
            u[w[i]] = more[i]
    rest = demand - np.dot(row, u)
    if hi[tail] > lo[tail] and abs(row[tail]) > 1e-12:
        u[tail] = rest / row[tail]
        if not (lo[tail] <= u[tail] and u[tail] <= hi[tail]):
            u[tail] = _pymin(_pymax(u[tail], lo[tail]), hi[tail])
            active = True
        rest -= row[tail] * u[tail]
    if nw:
        uw = u[w]
        if not _row_lsq(row[w], rest, lo[w] - uw, hi[w] - uw, sqrt_lam, more):
            return 0, 0.0, False
        for i in range(nw):
            u[w[i]] += more[i]
    return 1, abs(demand - np.dot(row, u)), active


def _update(
    params, plan_index, plan_lower, plan_upper, plan_bound,
    omega_a, kp, kd, ki, inertia, limit_rad, authority, lateral, cap_rad, groups,
    integral, frozen, dt, err, rates, rate_cmd, acc_cmd, turn, m0, jac, residual, damping,
    split, a_lp, has_slow, slow, sqrt_lam, wings, tail, u, out,
):  # fmt: skip
    """The update's bounds, integral, demand and allocation (see the module): 1 with
    ``integral`` (3,) moved on, ``u`` (inputs) written and ``out`` = (the pitch's slow
    demand, saturated 1.0 / 0.0); 0 (nothing kept) where the reference must run."""
    n_in = plan_index.shape[0]
    lo, hi = np.empty(n_in), np.empty(n_in)
    _bounds(params, plan_index, plan_lower, plan_upper, plan_bound, lo, hi)
    lim = np.empty(3)
    _integral_limit(
        omega_a, jac, lo, hi, inertia, limit_rad, authority, lateral, cap_rad, groups, lim
    )
    new_int = integral.copy()
    if not frozen:  # np.clip(integral + dt ki err, -lim, lim)
        for r in range(3):
            new_int[r] = _clip(integral[r] + dt * ki[r] * err[r], -lim[r], lim[r])
    rate_err = rate_cmd - rates
    demand = inertia * (acc_cmd + kp * err + kd * rate_err + new_int) - m0
    demand = demand - np.dot(residual, rates - turn)
    demand = demand + damping * (rate_err + rates - turn)
    for i in range(n_in):
        u[i] = 0.0
    miss, active = 0.0, False
    first = 0
    new_slow = slow
    if split:
        new_slow = demand[1] if not has_slow else slow + a_lp * (demand[1] - slow)
        up = np.zeros(n_in)
        state, miss, active = _pitch(jac[1], demand[1], new_slow, lo, hi, sqrt_lam, wings, tail, up)
        if state != 1:
            return 0
        for c in range(groups.shape[2]):
            col = groups[0, 1, c]
            if col >= 0:
                u[col] = up[col]
        first = 1
    for g in range(first, groups.shape[0]):
        nr = 0
        for k in range(groups.shape[2]):
            if groups[g, 0, k] >= 0:
                nr += 1
        rows = groups[g, 0, :nr]
        nc = 0
        for k in range(groups.shape[2]):
            c = groups[g, 1, k]
            if c >= 0 and hi[c] > lo[c]:
                nc += 1
        cols = np.empty(nc, dtype=np.int64)
        j = 0
        for k in range(groups.shape[2]):
            c = groups[g, 1, k]
            if c >= 0 and hi[c] > lo[c]:
                cols[j] = c
                j += 1
        d_rows = demand[rows]
        if nc == 0:
            miss += _norm(d_rows)
            continue
        scale = (hi[cols] - lo[cols]) / 2
        a = np.empty((nr, nc))
        for i in range(nr):
            for j in range(nc):
                a[i, j] = jac[rows[i], cols[j]] * scale[j]
        reg = sqrt_lam * _pymax(np.abs(a).max(), 1e-12)
        a_aug = np.zeros((nr + nc, nc))
        a_aug[:nr, :] = a
        for j in range(nc):
            a_aug[nr + j, j] = reg
        b_aug = np.zeros(nr + nc)
        b_aug[:nr] = d_rows
        x = np.empty(nc)
        if bounded_lsq.kernel(a_aug, b_aug, lo[cols] / scale, hi[cols] / scale, x) != 1:
            return 0
        for j in range(nc):
            u[cols[j]] = x[j] * scale[j]
        if nr == 1:  # numpy's (1, n) @ (n,) is a dot product (BLAS ddot, not dgemv)
            miss += _norm(np.dot(a[0], x) - d_rows)
        else:
            miss += _norm(np.dot(a, x) - d_rows)
    for r in range(3):
        integral[r] = new_int[r]
    out[0] = new_slow
    out[1] = 1.0 if (active and miss > 0.1 * _norm(demand) + 1e-12) else 0.0
    return 1


if numba is not None and bounded_lsq.kernel is not None:
    _pymin = numba.njit(cache=True)(_pymin)
    _pymax = numba.njit(cache=True)(_pymax)
    _npmax = numba.njit(cache=True)(_npmax)
    _npmin = numba.njit(cache=True)(_npmin)
    _clip = numba.njit(cache=True)(_clip)
    _norm = numba.njit(cache=True)(_norm)
    _bounds = numba.njit(cache=True)(_bounds)
    _integral_limit = numba.njit(cache=True)(_integral_limit)
    _row_lsq = numba.njit(cache=True)(_row_lsq)
    _pitch = numba.njit(cache=True)(_pitch)
    kernel = numba.njit(cache=True)(_update)
else:  # pragma: no cover
    kernel = None


def _plan(loop, groups: tuple) -> tuple:
    """The loop's constants as the kernel takes them, made once per loop: its bounds plan
    (index, lower, upper, bound per input), the allocations' ``groups`` ((rows, columns)
    of the pitch's and the lateral one) as a (2, 2, 4) array (-1 padded), the shoulders'
    inputs and the tail elevation's."""
    hit = loop.__dict__.get("_fast_attitude_plan")
    if hit is not None:
        return hit
    loop.bounds(np.zeros(len(loop.fb.kin.param_names)))  # makes loop._bounds_plan
    plan = loop._bounds_plan
    table = -np.ones((2, 2, 4), dtype=np.int64)
    for g, (rows, cols) in enumerate(groups):
        table[g, 0, : len(rows)] = rows
        table[g, 1, : len(cols)] = cols
    out = (
        np.array([p[0] for p in plan], dtype=np.int64),
        np.array([p[1] for p in plan], dtype=float),
        np.array([p[2] for p in plan], dtype=float),
        np.array([p[3] for p in plan], dtype=float),
        table,
        np.array(attitude_pitch._WINGS, dtype=np.int64),
        int(attitude_pitch._TAIL),
    )
    loop._fast_attitude_plan = out
    return out


def _gains(loop, gains) -> tuple:
    """(omega_a, kp, kd, ki, inertia) as the kernel takes them, made again only when the
    loop's placed gains or its inertia are other objects."""
    hit = loop.__dict__.get("_fast_attitude_gains")
    if hit is not None and hit[0] is gains and hit[1] is loop.inertia:
        return hit[2]
    f = np.ascontiguousarray
    out = tuple(f(a, dtype=float) for a in (gains.omega_a, gains.kp, gains.kd, gains.ki))
    out += (f(loop.inertia, dtype=float),)
    loop._fast_attitude_gains = (gains, loop.inertia, out)
    return out


def allocate(loop, groups, params, gains, m0, jac, residual, damping, err, rates, dt,
             rate_cmd, acc_cmd, turn, limit_rad, authority, split, a_lp, lam) -> bool:  # fmt: skip
    """The update of ``loop`` (an AttitudeLoop; ``groups`` its allocations' (rows, columns),
    the pitch's first) after its plant is known, compiled: True
    with ``loop.integral``, ``loop.u``, ``loop.saturated`` (and the pitch's slow demand
    where ``split``) set as the reference sets them; False (nothing changed) where it
    does not apply or the reference must run (a bound binds in a solve, an input not
    finite)."""
    if not (ENABLED and bounded_lsq.ENABLED) or kernel is None:
        return False  # the reference's lsq_linear for every solve: the reference runs
    index, lower, upper, bound, groups, wings, tail = _plan(loop, groups)
    omega_a, kp, kd, ki, inertia = _gains(loop, gains)
    f = np.ascontiguousarray
    zero = np.zeros(3)
    slow = loop.__dict__.get("_slow")
    lateral = loop.lateral_integral_rad is not None
    u = np.empty(len(index))
    out = np.empty(2)
    integral = np.array(loop.integral, dtype=float)
    state = kernel(
        f(params, dtype=float), index, lower, upper, bound, omega_a, kp, kd, ki, inertia,
        float(limit_rad), authority,
        lateral, float(loop.lateral_integral_rad) if lateral else 0.0, groups,
        integral, bool(loop.saturated), float(dt), f(err, dtype=float), f(rates, dtype=float),
        zero if rate_cmd is None else f(rate_cmd, dtype=float),
        zero if acc_cmd is None else f(acc_cmd, dtype=float), f(turn, dtype=float),
        f(m0, dtype=float), f(jac, dtype=float), f(residual, dtype=float), f(damping, dtype=float),
        bool(split), float(a_lp), slow is not None, 0.0 if slow is None else float(slow),
        math.sqrt(lam), wings, tail, u, out,
    )  # fmt: skip
    if state != 1:
        return False
    loop.integral = integral
    if split:
        loop._slow = float(out[0])
    loop.u = u
    loop.saturated = bool(out[1])
    return True


__all__ = ["ENABLED", "allocate", "kernel"]
