"""A free flight's interval between two control updates in one compiled call: the
wingbeat schedule's advance (its two filters and the wings' rows,
:mod:`birdsim.flight.fast_wingbeat`) and the steps that follow the rows
(:mod:`birdsim.flight.fast_loop`), the two kernels run unchanged one after the other.

What is saved is the Python between them: the schedule's torso rows (``set_root``: in
free flight the root is not prescribed, and the steps read only the wings' columns), the
``Prescription`` and the step wrapper's copies of its columns.  The Prescription
returned carries the same wings' rows, parameters and pitch; its root entries are the
model's rest pose (``qpos0``) and zeros, not the table's pitch (only the posed mode
prescribes the torso, and it never comes here).

Where either piece does not apply (switched off, no numba, a filter of time constant 0,
a wing the compiled rows do not know, the reference step loop, a leg motion, a flock's
lockstep replacing ``step_many``) the two calls run as before; where the rows or the
pitch are not finite nothing is stepped and the schedule's own path runs on the same
filtered parameters (naming the joint).  ``tests/test_fast_interval.py`` holds the fused
call bitwise to the two calls.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from birdsim.flight import fast_loop, fast_wingbeat
from birdsim.flight.wingbeat import Prescription
from birdsim.physics.jit import numba

#: the schedule's advance and the steps in one call (False: the two calls)
ENABLED = True


def _interval(
    target, target_left, offset, shoulder_target,
    x1, x2, u, ex, gex, tau, tau2, y1, y2, v, ey, gey, sig, sig2, t_rel, dt, n, times,
    present, index, scale, const, affine, omega, plans, axes, kmat, kkmat, qpos0,
    right, left, shoulder, qpos, qvel, qacc, pitch_index,
    m, d, dqpos, dqvel, applied, passive, bias, xfrc, M, com_t, xpos_t, xmat_t, pq1,
    pq0, pv0, w0, w1, site_ids, body_ids, site_xpos, site_xmat, areas, fold, wind,
    fl, ints, frame, state, weight, h, mass, project, every, rec_q, rec_v, rec_out, stats,
    tail, t0, rec_t,
):  # fmt: skip
    """The schedule's filter inputs into ``u`` and ``v`` from the wings' targets, the
    offset and the shoulders' target (``WingbeatSchedule.inputs``, its operations),
    ``fast_wingbeat``'s kernel (its flags), then, where its rows and the pitch column
    of ``right`` are finite, ``fast_loop``'s steps on the rows' columns ``pq0:pq1`` of
    qpos and ``pv0:`` of qvel and qacc (the tail's last force and angle of attack into
    ``tail`` (4,)), the samples' times into ``rec_t`` and the time after the steps into
    its last entry (``t0`` plus one ``h`` per step, added one after the other as the
    reference's loop adds them), and bit 8 (stepped) and 16 (qpos, qvel finite) set in
    the flags returned."""
    k = target.shape[0]
    for j in range(k):
        u[j] = 0.5 * (target[j] + target_left[j])
        v[j] = 0.5 * (target[j] - target_left[j])
        v[k + j] = offset[j]
    for j in range(shoulder_target.shape[0]):
        v[2 * k + j] = shoulder_target[j]
        v[2 * k + shoulder_target.shape[0] + j] = shoulder_target[j]
    flags = _rows(
        x1, x2, u, ex, gex, tau, tau2, y1, y2, v, ey, gey, sig, sig2, t_rel, dt, n, times,
        present, index, scale, const, affine, omega, plans, axes, kmat, kkmat, qpos0,
        right, left, shoulder, qpos, qvel, qacc,
    )  # fmt: skip
    if not flags & 4:
        return flags
    for i in range(right.shape[1]):
        if not math.isfinite(right[0, i, pitch_index]):
            return flags
    out = _steps(
        m, d, dqpos, dqvel, applied, passive, bias, xfrc, M, com_t, xpos_t, xmat_t,
        qpos[:, pq0:pq1], qvel[:, pv0:], qacc[:, pv0:], pq0, pv0, w0, w1, site_ids,
        body_ids, site_xpos, site_xmat, areas, fold, wind, fl, ints, frame, state, weight,
        h, mass, project, every, rec_q, rec_v, rec_out, stats,
    )  # fmt: skip
    for i in range(4):
        tail[i] = out[i]
    time = t0
    j = 0
    for k in range(qpos.shape[0]):
        if k % every == 0:
            rec_t[j] = time
            j += 1
        time += h
    rec_t[j] = time
    return flags | 8 | (16 if _finite(dqpos, dqvel) else 0)


if numba is not None and fast_wingbeat.kernel is not None and fast_loop.run_steps is not None:
    _rows, _steps, _finite = fast_wingbeat.kernel, fast_loop.run_steps, fast_loop.all_finite
    kernel = numba.njit(cache=True)(_interval)
else:  # pragma: no cover
    kernel = None


def interval(
    fb,
    target: np.ndarray,
    times: np.ndarray,
    t_now: float,
    dt: float,
    target_left: np.ndarray | None,
    offset: np.ndarray | None,
    wind: np.ndarray,
    record: list | None,
    every: int,
) -> Prescription:
    """``fb.schedule.advance(target, times, t_now, dt, target_left, offset)`` and then
    ``fb.step_many`` of its prescription (``wind``, samples every ``every`` steps into
    ``record``), in one compiled call where it applies.  Returns the prescription."""
    plan = _usable(fb)
    made = None
    if plan is not None:
        schedule = fb.schedule
        inputs = _inputs(schedule, target, target_left, offset)
        if inputs is not None:  # u and v, filled by the kernel
            times = np.asarray(times, dtype=float)
            rel = times - t_now
            made = fast_wingbeat.arguments(schedule, inputs[-2], inputs[-1], times, rel, dt)
    if made is None:
        pres = fb.schedule.advance(target, times, t_now, dt, target_left, offset)
        fb.step_many(pres, wind, record, every)
        return pres
    rows_args, rows = made
    n = times.shape[0]
    args, outs = fast_loop.arguments(fb, plan, wind, n, every)
    tail, rec_t = np.zeros(4), np.empty(outs[0].shape[0] + 1)
    installed = mujoco.get_mjcb_passive()
    mujoco.set_mjcb_passive(None)
    try:
        flags = kernel(
            *inputs[:4], *rows_args, *rows, schedule.pitch_index, *args[:12], plan.Pq.stop, *args[12:],
            *outs, tail, fb.time, rec_t,
        )  # fmt: skip
    finally:
        mujoco.set_mjcb_passive(installed)
    right3, left3, shoulder3, qpos, qvel, qacc = rows
    if not flags & 8:  # not finite: the schedule's path (it raises naming the joint)
        r, lft = tuple(right3), tuple(left3)
        if flags & 4:
            pres = schedule._finish(qpos, qvel, qacc, *r, None if flags & 2 else lft)
        else:
            pres = schedule.prescribe(times, *r, left=lft, shoulder=tuple(shoulder3))
        fb.step_many(pres, wind, record, every)
        return pres
    times_list, t_end = rec_t[:-1].tolist(), float(rec_t[-1])
    fast_loop.finish(fb, plan, args, outs, tail, record, times_list, t_end, bool(flags & 16))
    k, params = schedule.pitch_index, right3[0]
    left = None if flags & 2 else np.array(left3[0])
    return Prescription(qpos, qvel, qacc, params, params[:, k].copy(), left)


def _inputs(schedule, target, target_left, offset) -> tuple | None:
    """(right, left, offset, shoulder target) as floats and ``u``, ``v`` (made empty) for
    the kernel's ``WingbeatSchedule.inputs``, or None where a shape is not the schedule's
    (its numpy path then runs and says so)."""
    right = np.asarray(target, dtype=float)
    left = right if target_left is None else np.asarray(target_left, dtype=float)
    n = len(schedule.names)
    off = np.zeros(n) if offset is None else np.asarray(offset, dtype=float)
    sh = np.asarray(schedule.shoulder_target, dtype=float)
    if right.shape != (n,) or left.shape != (n,) or off.shape != (n,) or sh.ndim != 1:
        return None
    return right, left, off, sh, np.empty(n), np.empty(2 * n + 2 * sh.shape[0])


def _usable(fb):
    """The step loop's plan where the fused call applies to ``fb``, else None."""
    if not ENABLED or kernel is None or fb.config.leg_motion is not None:
        return None
    if "step_many" in fb.__dict__:  # a flock's lockstep steps every bird together
        return None
    return fast_loop.plan(fb)


__all__ = ["ENABLED", "interval", "kernel"]
