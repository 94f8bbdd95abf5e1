"""Free flight's steps between two control updates in one compiled call (attitude free).

:meth:`birdsim.flight.simulate.FreeBird.step_many` with the attitude free runs, per step,
the prescription's rows into ``qpos``/``qvel``, ``mj_step1`` (with the aero callback in
it), ``mj_fullM``, the compiled projection and partitioned dynamics
(:func:`birdsim.flight.step_kernel.free_step`), the log sample and ``mj_step2``; the
reference path makes these calls from Python (``step_kernel.free_loop``).
:func:`run_steps` makes the same calls from numba, MuJoCo's C functions through
:mod:`birdsim.mujoco.capi`, and the aerodynamics computed after ``mj_step1``
(:func:`birdsim.mujoco.aero_kernel.apply_aero`; the Python callback is uninstalled for
the call and put back after it).  The formulas and their order are the reference's;
the differences are round-off (the tail's force summed in another order, the wings'
power summed naively instead of by BLAS): ``tests/test_fast_flight.py`` flies both.

:func:`usable` says when it applies (numba and libmujoco found, the attitude free with
the root's six DOF first, a callback :func:`birdsim.mujoco.aero_kernel.supported`
computes); :data:`ENABLED` switches it off (the reference path then runs).
"""

from __future__ import annotations

import mujoco
import numpy as np

from birdsim.flight import step_kernel
from birdsim.flight.partition import _as_slice
from birdsim.mujoco import aero_kernel, capi
from birdsim.physics.jit import numba

#: the compiled loop is used where :func:`usable` (False: always the reference path)
ENABLED = True


def _run_steps(
    m,
    d,
    qpos,
    qvel,
    applied,
    passive,
    bias,
    xfrc,
    M,
    com_t,
    xpos_t,
    xmat_t,
    pres_q,
    pres_v,
    pres_a,
    pq0,
    pv0,
    w0,
    w1,
    site_ids,
    body_ids,
    site_xpos,
    site_xmat,
    areas,
    fold,
    wind,
    fl,
    ints,
    frame,
    state,
    weight,
    h,
    mass,
    project,
    every,
    rec_q,
    rec_v,
    rec_out,
    stats,
):
    """``pres_q.shape[0]`` steps.  ``rec_out`` (samples, 10): moment (seed body axes),
    f_ext (world), power, tail force (seed body axes) per log sample; ``stats`` (3,):
    max |dx|, max |dv|, max |root applied| (running maxima, updated).  Returns (12,):
    the tail's last force (torso axes) and angle of attack in its first 4 entries."""
    out = np.zeros(12)
    tail_out = np.zeros(4)
    nq_p = pres_q.shape[1]
    nv_p = pres_v.shape[1]
    nv = qvel.shape[0]
    j = 0
    for k in range(pres_q.shape[0]):
        for i in range(nq_p):
            qpos[pq0 + i] = pres_q[k, i]
        for i in range(nv_p):
            qvel[pv0 + i] = pres_v[k, i]
        capi.mj_step1(m, d)
        aero_kernel.apply_aero(
            m, d, passive, site_ids, body_ids, site_xpos, site_xmat, areas, fold, qpos, wind,
            fl, ints, frame, tail_out,
        )  # fmt: skip
        capi.mj_fullM(m, d, M.ctypes.data)
        step_kernel.free_step(
            M, qpos, qvel, passive, bias, applied, com_t, xpos_t, xmat_t, pres_a[k], state,
            weight, h, mass, project, out,
        )  # fmt: skip
        if out[6] > stats[0]:
            stats[0] = out[6]
        if out[7] > stats[1]:
            stats[1] = out[7]
        amax = out[8]
        for i in range(xfrc.shape[0]):
            for c in range(6):
                if abs(xfrc[i, c]) > amax:
                    amax = abs(xfrc[i, c])
        if amax > stats[2]:
            stats[2] = amax
        if k % every == 0:
            for i in range(qpos.shape[0]):
                rec_q[j, i] = qpos[i]
            for i in range(nv):
                rec_v[j, i] = qvel[i]
            power = 0.0
            for i in range(w0, w1):
                power += applied[i] * qvel[i]
            rec_out[j, 0] = out[9]
            rec_out[j, 1] = -out[10]
            rec_out[j, 2] = -out[11]
            rec_out[j, 3] = out[0]
            rec_out[j, 4] = out[1]
            rec_out[j, 5] = out[2]
            rec_out[j, 6] = power
            rec_out[j, 7] = tail_out[0]
            rec_out[j, 8] = -tail_out[1]
            rec_out[j, 9] = -tail_out[2]
            j += 1
        capi.mj_step2(m, d)
    for i in range(4):
        out[i] = tail_out[i]
    return out


def _all_finite(qpos, qvel):
    """Whether every entry of ``qpos`` and ``qvel`` is finite (FreeBird._check_finite)."""
    for i in range(qpos.shape[0]):
        if not np.isfinite(qpos[i]):
            return False
    for i in range(qvel.shape[0]):
        if not np.isfinite(qvel[i]):
            return False
    return True


if numba is not None and capi.AVAILABLE and step_kernel.AVAILABLE:
    run_steps = numba.njit(cache=True)(_run_steps)
    all_finite = numba.njit(cache=True)(_all_finite)
else:  # pragma: no cover
    run_steps = None
    all_finite = _all_finite


class _Plan:
    """The compiled loop's fixed arguments for one FreeBird (views of its MjData, the
    callback's sites), made once."""

    def __init__(self, fb) -> None:
        m, d, cb = fb.m, fb.d, fb.cb
        part = fb.part
        self.F, self.P, self.Pq, self.W = (
            _as_slice(a) for a in (part.free_dofs, part.pres_dofs, part.pres_qpos, part.wing_dofs)
        )
        self.static = (
            m._address, d._address, d.qpos, d.qvel, d.qfrc_applied, d.qfrc_passive,
            d.qfrc_bias, d.xfrc_applied, fb._M, d.subtree_com[fb.torso], d.xpos[fb.torso],
            d.xmat[fb.torso],
        )  # fmt: skip
        self.sites = (
            np.ascontiguousarray(cb.site_ids), np.ascontiguousarray(cb.body_ids), d.site_xpos,
            d.site_xmat, np.ascontiguousarray(cb.areas[:, 0]), aero_kernel.fold_addresses(cb),
            m.opt.wind,
        )  # fmt: skip
        self.gravity = m.opt.gravity  # its view, kept (as the wind's)
        #: :func:`arguments`' fixed head (the static views, the slices' bounds, the sites)
        slices = all(isinstance(s, slice) for s in (self.Pq, self.P, self.W))
        bounds = (self.Pq.start, self.P.start, self.W.start, self.W.stop) if slices else ()
        self.head = (*self.static, *bounds, *self.sites)
        self.shape = (m.nq, m.nv)
        self.aero_for: tuple | None = None
        self.aero: tuple = ()
        self._weight: tuple | None = None

    def weight(self, fb) -> np.ndarray:
        """``fb.total_mass * gravity`` (world), made again only when either changes."""
        key = (fb.total_mass, *self.gravity.tolist())
        if self._weight is None or self._weight[0] != key:
            self._weight = (key, fb.total_mass * np.array(self.gravity))
        return self._weight[1]

    def aero_arguments(self, cb) -> tuple:
        key = (cb.tail_controls, cb.enabled, cb.body_drag)
        if self.aero_for is None or any(a is not b for a, b in zip(key, self.aero_for)):
            self.aero = aero_kernel.parameters(cb)
            self.aero_for = key
        return self.aero


def _plan(fb) -> _Plan | None:
    plan = fb.__dict__.get("_fast_plan", False)
    if plan is False:
        plan = _Plan(fb) if run_steps is not None else None
        if plan is not None and not _static_ok(fb, plan):
            plan = None
        fb.__dict__["_fast_plan"] = plan
    return plan


def _static_ok(fb, plan: _Plan) -> bool:
    return (
        step_kernel.AVAILABLE
        and capi.AVAILABLE
        and fb.part.free_rotation
        and plan.F == slice(0, 6)
        and plan.P == slice(6, fb.m.nv)
        and isinstance(plan.Pq, slice)
        and isinstance(plan.W, slice)
    )


def step(fb, pres, wind: np.ndarray, record: list | None, every: int) -> bool:
    """:meth:`FreeBird.step_many` compiled, when :func:`usable`: ``len(pres.qpos)``
    steps, samples appended to ``record`` as the reference appends them.  False (nothing
    done) where it does not apply."""
    plan = _plan(fb) if ENABLED else None
    if plan is None or not aero_kernel.supported(fb.cb):
        return False
    Pq, P = plan.Pq, plan.P
    pres_q = np.ascontiguousarray(pres.qpos[:, Pq])
    pres_v = np.ascontiguousarray(pres.qvel[:, P])
    pres_a = np.ascontiguousarray(pres.qacc[:, P])
    n = pres_q.shape[0]
    args, outs = arguments(fb, plan, wind, n, every)
    installed = mujoco.get_mjcb_passive()
    mujoco.set_mjcb_passive(None)
    try:
        tail = run_steps(
            *args[:12], pres_q, pres_v, pres_a, *args[12:], *outs
        )  # fmt: skip
    finally:
        mujoco.set_mjcb_passive(installed)
    times, t_end = sample_times(fb.time, fb.h, n, every)
    finish(fb, plan, args, outs, tail, record, times, t_end)
    return True


def sample_times(time: float, h: float, n: int, every: int) -> tuple[list[float], float]:
    """(the times of the samples of ``n`` steps of ``h`` from ``time``, every ``every``-th
    step's; the time after them): the reference's time summed step by step
    (``np.add.accumulate`` adds in order, as the reference's loop, one step after the
    other: the same bits)."""
    steps = np.full(n + 1, h)
    steps[0] = time
    sums = np.add.accumulate(steps)
    return sums[:n:every].tolist(), float(sums[n])


def arguments(fb, plan: _Plan, wind: np.ndarray, n: int, every: int) -> tuple[tuple, tuple]:
    """:func:`run_steps`' arguments for ``n`` steps of ``fb`` under ``wind`` (written into
    ``m.opt.wind``): those before the prescription's three arrays, those after them up to
    ``every``, and the outputs (rec_q, rec_v, rec_out, stats), made new."""
    plan.sites[-1][:] = wind  # m.opt.wind (its view, kept: MjOption makes a new one per read)
    weight = plan.weight(fb)
    samples = (n + every - 1) // every
    fl, ints, frame = plan.aero_arguments(fb.cb)
    state = np.empty(9)  # np.concatenate([fb.P, fb.X, fb.L]), its copies made directly
    state[:3], state[3:6], state[6:] = fb.P, fb.X, fb.L
    stats = np.array([0.0, 0.0, fb.root_applied_max])
    args = plan.head + (
        fl, ints, frame, state, weight, fb.h, fb.total_mass,
        bool(fb.config.momentum_projection), every,
    )  # fmt: skip
    nq, nv = plan.shape
    outs = (np.empty((samples, nq)), np.empty((samples, nv)), np.empty((samples, 10)), stats)
    return args, outs


def finish(
    fb,
    plan: _Plan,
    args: tuple,
    outs: tuple,
    tail: np.ndarray,
    record,
    times: list[float],
    t_end: float,
    finite: bool | None = None,
) -> None:
    """After :func:`run_steps` made its steps with :func:`arguments`' ``args`` and
    ``outs``: the bird's momenta, time (``t_end``), maxima and tail force, the samples
    (at ``times``) appended to ``record`` as the reference appends them; raises where the
    state is not finite (``finite``: already checked, None: checked here)."""
    cb, h = fb.cb, fb.h
    rec_q, rec_v, rec_out, stats = outs
    state = args[-6]
    fb.P, fb.X, fb.L = state[:3].copy(), state[3:6].copy(), state[6:].copy()
    fb.time = t_end
    fb.root_applied_max = float(stats[2])
    if args[-8][aero_kernel.TAIL]:  # ints
        cb.tail_force_body = tail[:3].copy()
        cb.tail_alpha = float(tail[3])
    if record is not None:
        power = rec_out[:, 6].tolist()
        moment, force, tail_f = rec_out[:, 0:3], rec_out[:, 3:6], rec_out[:, 7:10]
        record.extend(
            zip(times, rec_q, rec_v, moment, force, power, tail_f)
        )  # one tuple per sample, as the reference appends them
        # the same samples as arrays, for this record at this length (flight_arrays)
        fb.__dict__["last_samples"] = (record, len(record), times, rec_q, rec_v, rec_out)
    if fb.config.momentum_projection and times:
        fb.projection_max = max(fb.projection_max, float(stats[0]), float(stats[1]) * h)
    if finite is None:
        finite = all_finite(plan.static[2], plan.static[3])
    if not finite:
        fb._check_finite()  # raises, naming the time


def plan(fb) -> _Plan | None:
    """The compiled loop's fixed arguments for ``fb`` where :func:`usable`, else None."""
    p = _plan(fb) if ENABLED else None
    return p if p is not None and aero_kernel.supported(fb.cb) else None


def usable(fb, F=None, P=None) -> bool:
    """Whether :func:`step` steps ``fb`` (a FreeBird) in compiled code."""
    return ENABLED and _plan(fb) is not None and aero_kernel.supported(fb.cb)


__all__ = ["ENABLED", "arguments", "finish", "plan", "run_steps", "sample_times", "step", "usable"]
