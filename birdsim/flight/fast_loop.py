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
from birdsim.mujoco import aero_kernel, capi
from birdsim.physics.jit import numba

#: the compiled loop is used where :func:`usable` (False: always the reference path)
ENABLED = True


def usable(fb, F, P) -> bool:
    """Whether :func:`run` can step ``fb`` (a FreeBird; F, P its free and prescribed
    DOF as slices)."""
    return (
        ENABLED
        and step_kernel.AVAILABLE
        and capi.AVAILABLE
        and fb.part.free_rotation
        and F == slice(0, 6)
        and P == slice(6, fb.m.nv)
        and aero_kernel.supported(fb.cb)
    )


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
            m, d, passive, site_ids, body_ids, site_xpos, site_xmat, areas, wind, fl, ints,
            frame, tail_out,
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


if numba is not None and capi.AVAILABLE and step_kernel.AVAILABLE:
    run_steps = numba.njit(cache=True)(_run_steps)
else:  # pragma: no cover
    run_steps = None


def run(fb, pres, Pq, P, W, record: list | None, every: int, weight: np.ndarray) -> tuple:
    """:meth:`FreeBird.step_many` compiled: ``len(pres.qpos)`` steps, samples appended
    to ``record`` as the reference appends them; returns (max |dx|, max |dv|) of the
    projection."""
    m, d, cb = fb.m, fb.d, fb.cb
    pres_q = np.ascontiguousarray(pres.qpos[:, Pq])
    pres_v = np.ascontiguousarray(pres.qvel[:, P])
    pres_a = np.ascontiguousarray(pres.qacc[:, P])
    n = pres_q.shape[0]
    samples = (n + every - 1) // every
    rec_q = np.empty((samples, m.nq))
    rec_v = np.empty((samples, m.nv))
    rec_out = np.empty((samples, 10))
    fl, ints, frame = aero_kernel.parameters(cb)
    state = np.concatenate([fb.P, fb.X, fb.L])
    stats = np.array([0.0, 0.0, fb.root_applied_max])
    installed = mujoco.get_mjcb_passive()
    mujoco.set_mjcb_passive(None)
    try:
        tail = run_steps(
            m._address, d._address, d.qpos, d.qvel, d.qfrc_applied, d.qfrc_passive,
            d.qfrc_bias, d.xfrc_applied, fb._M, d.subtree_com[fb.torso], d.xpos[fb.torso],
            d.xmat[fb.torso], pres_q, pres_v, pres_a, Pq.start, P.start, W.start, W.stop,
            cb.site_ids, cb.body_ids, d.site_xpos, d.site_xmat, cb.areas[:, 0].copy(),
            m.opt.wind, fl, ints, frame, state, weight, fb.h, fb.total_mass,
            bool(fb.config.momentum_projection), every, rec_q, rec_v, rec_out, stats,
        )  # fmt: skip
    finally:
        mujoco.set_mjcb_passive(installed)
    fb.P, fb.X, fb.L = state[:3].copy(), state[3:6].copy(), state[6:].copy()
    t0 = fb.time
    fb.time = t0 + 0.0
    for _ in range(n):  # the reference's time, summed step by step
        fb.time += fb.h
    fb.root_applied_max = float(stats[2])
    if ints[aero_kernel.TAIL]:
        cb.tail_force_body = tail[:3].copy()
        cb.tail_alpha = float(tail[3])
    if record is not None:
        time = t0
        for j in range(samples):
            r = rec_out[j]
            record.append((time, rec_q[j], rec_v[j], r[0:3], r[3:6], float(r[6]), r[7:10]))
            for _ in range(every):
                time += fb.h
    return float(stats[0]), float(stats[1])


__all__ = ["ENABLED", "run", "run_steps", "usable"]
