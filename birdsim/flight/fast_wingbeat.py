"""The wingbeat schedule's advance in one compiled call: the two filters
(:mod:`birdsim.flight.fast_schedule`) and the wings' rows made of them
(:mod:`birdsim.flight.fast_prescription`), with the choices
:meth:`birdsim.flight.wingbeat.WingbeatSchedule.prescribe` makes between them (the
shoulders' offsets used where one is not zero; the left wing's rows the right's where
they are equal and no offset is used), bit for bit the two calls' numbers.

The two kernels run unchanged, one after the other, inside one call: what is saved is
the Python between them (some twenty numpy calls and two dispatches of many arguments
per control update).  The exponentials stay numpy's, made as ``fast_schedule.advance``
makes them; the torso's rows (``driver.set_root``: numpy's cosine and sine of the pitch)
stay the schedule's.  Where either piece does not apply (switched off, no numba, a
filter of time constant 0, a wing the compiled rows do not know) nothing is done and the
two calls run; where the rows are not finite the schedule's own path runs on the same
filtered parameters (and names the joint).  ``tests/test_fast_schedule.py`` holds the
fused call bitwise to the two calls.
"""

from __future__ import annotations

import numpy as np

from birdsim.flight import fast_prescription, fast_schedule
from birdsim.physics.jit import numba

#: the filters and the rows in one call (False: fast_schedule's call, then wing_rows')
ENABLED = True


def _advance_rows(
    x1, x2, u, ex, gex, tau, tau2, y1, y2, v, ey, gey, sig, sig2, t_rel, dt, n, times,
    present, index, scale, const, affine, omega, plans, axes, kmat, kkmat, qpos0,
    right, left, shoulder, qpos, qvel, qacc,
):  # fmt: skip
    """``fast_schedule``'s filters into right, left, shoulder (3, T, .), then
    ``fast_prescription``'s rows into qpos (filled with qpos0 first), qvel, qacc (zeroed
    first).  Returns bit 1: a shoulder offset is not zero (used); bit 2: the left wing's
    rows equal the right's and no offset is used (the schedule's left is None); bit 4:
    every row finite."""
    fast_schedule.kernel(
        x1, x2, u, ex, gex, tau, tau2, y1, y2, v, ey, gey, sig, sig2, t_rel, dt, n,
        right, left, shoulder,
    )  # fmt: skip
    T = times.shape[0]
    use_sh = False
    for d in range(3):
        for i in range(T):
            for j in range(shoulder.shape[2]):
                if shoulder[d, i, j] != 0.0:
                    use_sh = True
    same = not use_sh
    if same:
        for d in range(3):
            for i in range(T):
                for j in range(n):
                    if not (left[d, i, j] == right[d, i, j]):
                        same = False
    for i in range(T):
        for j in range(qpos.shape[1]):
            qpos[i, j] = qpos0[j]
        for j in range(qvel.shape[1]):
            qvel[i, j] = 0.0
            qacc[i, j] = 0.0
    if use_sh:
        sh, shd, shdd = shoulder[0], shoulder[1], shoulder[2]
    else:  # the schedule's zeros (T, 4)
        sh, shd, shdd = np.zeros((T, 4)), np.zeros((T, 4)), np.zeros((T, 4))
    if same:  # the right wing's rows for both (the same numbers)
        lp, ldp, lddp = right[0], right[1], right[2]
    else:
        lp, ldp, lddp = left[0], left[1], left[2]
    fast_prescription.prescribe_kernel(
        times, right[0], right[1], right[2], lp, ldp, lddp, sh, shd, shdd, use_sh, present,
        index, scale, const, affine, omega, plans, axes, kmat, kkmat, qpos, qvel, qacc,
    )  # fmt: skip
    ok = fast_prescription.all_finite(qpos, qvel, qacc)
    return (1 if use_sh else 0) + (2 if same else 0) + (4 if ok else 0)


if (
    numba is not None
    and fast_schedule.kernel is not None
    and fast_prescription.prescribe_kernel is not None
):
    kernel = numba.njit(cache=True)(_advance_rows)
else:  # pragma: no cover
    kernel = None


def advance(schedule, u: np.ndarray, v: np.ndarray, times: np.ndarray, rel: np.ndarray, dt: float):
    """(right, left, shoulder, qpos, qvel, qacc, flags) for
    :meth:`WingbeatSchedule.advance` (its filters moved on by ``dt``), or None (nothing
    done) where the fused call does not apply; ``flags`` as :func:`_advance_rows` returns
    them."""
    made = arguments(schedule, u, v, times, rel, dt)
    if made is None:
        return None
    args, outs = made
    flags = kernel(*args, *outs)
    return (*outs, flags)


def _fixed(schedule) -> tuple | None:
    """The arguments of :func:`_advance_rows` that stay for ``schedule`` (its filters'
    time constants, the coefficients' form, the bird's omega, the wings' geometry,
    ``qpos0``), made again when its filters, model or bird are other objects or the time
    constants changed; None where the fused call does not apply."""
    mean_filter, input_filter = schedule.filter, schedule.input_filter
    tau, sig = mean_filter.tau, input_filter.tau
    key = (mean_filter, input_filter, schedule.m, schedule.kin, schedule.bird)
    hit = schedule.__dict__.get("_fast_wingbeat_fixed")
    if hit is not None and all(a is b for a, b in zip(hit[0], key)) and hit[1] == (tau, sig):
        return hit[2]
    out = None
    if tau != 0.0 and sig != 0.0:
        m = schedule.m
        sp = fast_prescription.spec(schedule.kin, schedule.bird)
        geo = fast_prescription.geometry(m)
        if sp is not None and geo is not None:
            tail = (*sp, float(schedule.bird.omega), *geo, m.qpos0)
            out = (tau, tau**2, sig, sig**2, len(schedule.names), m.nq, m.nv, tail)
    schedule.__dict__["_fast_wingbeat_fixed"] = (key, (tau, sig), out)
    return out


def arguments(
    schedule, u: np.ndarray, v: np.ndarray, times: np.ndarray, rel: np.ndarray, dt: float
) -> tuple[tuple, tuple] | None:
    """:func:`_advance_rows`' arguments up to ``qpos0`` and its outputs (right, left,
    shoulder, qpos, qvel, qacc; made new) for :func:`advance`, or None where the fused
    call does not apply."""
    if not (ENABLED and fast_schedule.ENABLED and fast_prescription.ENABLED) or kernel is None:
        return None
    fixed = _fixed(schedule)
    if fixed is None:
        return None
    tau, tau2, sig, sig2, n, nq, nv, tail = fixed
    mean_filter, input_filter = schedule.filter, schedule.input_filter
    ex, ey, gex, gey = fast_schedule.exponentials(tau, sig, rel, dt)
    T = rel.shape[0]
    right, left = np.empty((3, T, n)), np.empty((3, T, n))
    shoulder = np.empty((3, T, v.shape[0] - 2 * n))
    qpos, qvel, qacc = np.empty((T, nq)), np.empty((T, nv)), np.empty((T, nv))
    args = (
        mean_filter.x1, mean_filter.x2, u, ex, gex, tau, tau2,
        input_filter.x1, input_filter.x2, v, ey, gey, sig, sig2, rel, float(dt), n,
        np.ascontiguousarray(times, dtype=float), *tail,
    )  # fmt: skip
    return args, (right, left, shoulder, qpos, qvel, qacc)


__all__ = ["ENABLED", "advance", "arguments", "kernel"]
