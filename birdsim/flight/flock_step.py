"""Every bird of a flock stepped in one MuJoCo model (:mod:`birdsim.flight.flock_model`):
one ``mj_step1`` / ``mj_step2`` per step for the whole flock, the aerodynamics of every
bird's sites in the same compiled call (:func:`birdsim.mujoco.aero_kernel.apply_aero`
over each bird's block: its site, body and coordinate ids moved by the bird's offsets),
each bird's projection and partitioned dynamics on its own block of the mass matrix
(:func:`birdsim.flight.step_kernel.free_step`).

:func:`run_flock_steps` is :func:`birdsim.flight.fast_loop.run_steps` for B birds: per
step the prescription's rows of every bird, ``mj_step1``, every bird's aerodynamics,
every bird's ``free_step`` and log sample, ``mj_step2``; each bird's arithmetic is the
one-bird loop's.  :class:`SharedFlock` runs it for the lockstep
(:mod:`birdsim.flight.flock_lockstep`): each bird's ``step_many`` hands its interval's
prescription over and the last bird steps them all.
"""

from __future__ import annotations

import mujoco
import numpy as np

from birdsim.flight import fast_loop, step_kernel
from birdsim.flight.flock_model import DataMap, build_flock_model, copy_in
from birdsim.mujoco import aero_kernel, capi
from birdsim.physics.jit import numba

#: step a steered flock's birds in one MuJoCo model (False: each bird its own model)
SHARED_MODEL = True


def _fill_block(Mcsr, rowadr, rownnz, colind, v0, M):
    """Bird's dense mass matrix (nv x nv) from the shared model's sparse rows (lower
    triangle, CSR) ``v0 .. v0 + nv``: what ``mj_fullM`` gives on its one-bird model."""
    nv = M.shape[0]
    for i in range(nv):
        for j in range(nv):
            M[i, j] = 0.0
    for i in range(nv):
        r = v0 + i
        for a in range(rowadr[r], rowadr[r] + rownnz[r]):
            j = colind[a] - v0
            M[i, j] = Mcsr[a]
            M[j, i] = Mcsr[a]


def _run_flock_steps(
    m, d, qpos, qvel, applied, passive, bias, xfrc, Mcsr, rowadr, rownnz, colind, M, q0, v0,
    torso, body0, nbody, com, xpos, xmat, pres_q, pres_v, pres_a, pq0, pv0, w0, w1, site_ids,
    body_ids, site_xpos, site_xmat, areas, fold, wind, fl, ints, frame, state, weight, h,
    mass, project, every, rec_q, rec_v, rec_out, stats, tail_out,
):  # fmt: skip
    """``pres_q.shape[1]`` steps of ``B = pres_q.shape[0]`` birds; per bird as
    :func:`birdsim.flight.fast_loop.run_steps` (``rec_*``, ``stats``, ``tail_out`` with
    a leading bird axis)."""
    B = pres_q.shape[0]
    nq_p, nv_p = pres_q.shape[2], pres_v.shape[2]
    nv, nq = M.shape[1], rec_q.shape[2]
    out = np.zeros((B, 12))
    j = 0
    for k in range(pres_q.shape[1]):
        for b in range(B):
            for i in range(nq_p):
                qpos[q0[b] + pq0 + i] = pres_q[b, k, i]
            for i in range(nv_p):
                qvel[v0[b] + pv0 + i] = pres_v[b, k, i]
        capi.mj_step1(m, d)
        for b in range(B):
            aero_kernel.apply_aero(
                m, d, passive, site_ids[b], body_ids[b], site_xpos, site_xmat, areas[b],
                fold[b], qpos, wind, fl[b], ints[b], frame[b], tail_out[b],
            )  # fmt: skip
        for b in range(B):
            qs, vs = q0[b], v0[b]
            _fill_block(Mcsr, rowadr, rownnz, colind, vs, M[b])
            t = torso[b]
            step_kernel.free_step(
                M[b], qpos[qs : qs + nq], qvel[vs : vs + nv], passive[vs : vs + nv],
                bias[vs : vs + nv], applied[vs : vs + nv], com[t], xpos[t], xmat[t],
                pres_a[b, k], state[b], weight[b], h, mass[b], project, out[b],
            )  # fmt: skip
            o = out[b]
            if o[6] > stats[b, 0]:
                stats[b, 0] = o[6]
            if o[7] > stats[b, 1]:
                stats[b, 1] = o[7]
            amax = o[8]
            for c in range(6):  # the world's row and the bird's bodies
                if abs(xfrc[0, c]) > amax:
                    amax = abs(xfrc[0, c])
            for i in range(1 + body0[b], 1 + body0[b] + nbody - 1):
                for c in range(6):
                    if abs(xfrc[i, c]) > amax:
                        amax = abs(xfrc[i, c])
            if amax > stats[b, 2]:
                stats[b, 2] = amax
            if k % every == 0:
                for i in range(nq):
                    rec_q[b, j, i] = qpos[qs + i]
                for i in range(nv):
                    rec_v[b, j, i] = qvel[vs + i]
                power = 0.0
                for i in range(w0, w1):
                    power += applied[vs + i] * qvel[vs + i]
                r = rec_out[b, j]
                r[0], r[1], r[2] = o[9], -o[10], -o[11]
                r[3], r[4], r[5] = o[0], o[1], o[2]
                r[6] = power
                r[7], r[8], r[9] = tail_out[b, 0], -tail_out[b, 1], -tail_out[b, 2]
        if k % every == 0:
            j += 1
        capi.mj_step2(m, d)


if numba is not None and capi.AVAILABLE and step_kernel.AVAILABLE:
    _fill_block = numba.njit(cache=True, inline="always")(_fill_block)
    run_flock_steps = numba.njit(cache=True)(_run_flock_steps)
else:  # pragma: no cover
    run_flock_steps = None


class SharedFlock:
    """The birds' FreeBirds (one-bird models: their controllers) over one shared model:
    :meth:`step` steps every bird's pending interval in one compiled call."""

    def __init__(self, fbs: list) -> None:
        self.fbs = fbs
        self.m, self.blocks = build_flock_model([(fb.kin.name, fb.red, fb.m) for fb in fbs])
        self.d = mujoco.MjData(self.m)
        one = fbs[0].m
        self.map = DataMap(self.m, one, len(fbs))
        plans = [fast_loop._plan(fb) for fb in fbs]
        p = plans[0]
        self.Pq, self.P, self.W = p.Pq, p.P, p.W
        B, m = len(fbs), self.m
        self.q0 = np.array([b.qpos for b in self.blocks], dtype=np.int64)
        self.v0 = np.array([b.dof for b in self.blocks], dtype=np.int64)
        self.body0 = np.array([b.body for b in self.blocks], dtype=np.int64)
        self.torso = np.array([fb.torso + b.body for fb, b in zip(fbs, self.blocks)])
        self.site_ids = np.stack([fb.cb.site_ids + b.site for fb, b in zip(fbs, self.blocks)])
        self.body_ids = np.stack([fb.cb.body_ids + b.body for fb, b in zip(fbs, self.blocks)])
        self.areas = np.stack([np.ascontiguousarray(fb.cb.areas[:, 0]) for fb in fbs])
        folds = []
        for fb, b in zip(fbs, self.blocks):
            f = aero_kernel.fold_addresses(fb.cb)
            folds.append(np.where(f >= 0, f + b.qpos, -1))
        self.fold = np.stack(folds).astype(np.int64)
        self.mass = np.array([fb.total_mass for fb in fbs])
        self.M = np.zeros((B, one.nv, one.nv))
        self.csr = (self.d.M, m.M_rowadr, m.M_rownnz, m.M_colind)
        self.pending: list = [None] * B

    @staticmethod
    def usable(fbs: list) -> bool:
        """Every bird stepped by the compiled one-bird loop, no legs, one projection."""
        return (
            run_flock_steps is not None
            and all(fast_loop.usable(fb) for fb in fbs)
            and not any(fb.config.legs or fb.config.leg_motion is not None for fb in fbs)
            and len({fb.config.momentum_projection for fb in fbs}) == 1
        )

    def _aero(self) -> tuple:
        fl, ints, frames = [], [], []
        for fb, b in zip(self.fbs, self.blocks):
            f, i, fr = fast_loop._plan(fb).aero_arguments(fb.cb)
            i = i.copy()
            for k in (aero_kernel.TORSO_SITE, aero_kernel.TAIL_SITE):
                i[k] = i[k] + b.site if i[k] >= 0 else i[k]
            for k in (aero_kernel.TORSO_BODY, aero_kernel.TAIL_BODY):
                i[k] = i[k] + b.body
            fl.append(f)
            ints.append(i)
            frames.append(fr)
        return np.stack(fl), np.stack(ints), np.stack(frames)

    def step(self) -> None:
        """Step every bird's pending (pres, wind, record, every) in one call."""
        fbs, D, pend = self.fbs, self.d, self.pending
        wind = np.array(pend[0][1], dtype=float)
        every = pend[0][3]
        for i, (fb, b) in enumerate(zip(fbs, self.blocks)):
            if not np.array_equal(pend[i][1], wind) or pend[i][3] != every:
                raise ValueError(f"bird {i}: its wind or log interval differs from bird 0's")
            fb.m.opt.wind[:] = wind
            copy_in(D, fb.d, b)
        self.m.opt.wind[:] = wind
        pres_q = np.ascontiguousarray(np.stack([p[0].qpos[:, self.Pq] for p in pend]))
        pres_v = np.ascontiguousarray(np.stack([p[0].qvel[:, self.P] for p in pend]))
        pres_a = np.ascontiguousarray(np.stack([p[0].qacc[:, self.P] for p in pend]))
        B, n = pres_q.shape[:2]
        samples = (n + every - 1) // every
        rec_q = np.empty((B, samples, self.m.nq // B))
        rec_v = np.empty((B, samples, self.m.nv // B))
        rec_out = np.empty((B, samples, 10))
        state = np.stack([np.concatenate([fb.P, fb.X, fb.L]) for fb in fbs])
        stats = np.array([[0.0, 0.0, fb.root_applied_max] for fb in fbs])
        weight = np.stack([fast_loop._plan(fb).weight(fb) for fb in fbs])
        tail_out = np.zeros((B, 4))
        fl, ints, frames = self._aero()
        run_flock_steps(
            self.m._address, D._address, D.qpos, D.qvel, D.qfrc_applied, D.qfrc_passive,
            D.qfrc_bias, D.xfrc_applied, *self.csr, self.M, self.q0, self.v0, self.torso,
            self.body0, fbs[0].m.nbody, D.subtree_com, D.xpos, D.xmat, pres_q, pres_v, pres_a,
            self.Pq.start, self.P.start, self.W.start, self.W.stop, self.site_ids,
            self.body_ids, D.site_xpos, D.site_xmat, self.areas, self.fold, self.m.opt.wind,
            fl, ints, frames, state, weight, fbs[0].h, self.mass,
            bool(fbs[0].config.momentum_projection), every, rec_q, rec_v, rec_out, stats,
            tail_out,
        )  # fmt: skip
        for i, (fb, b) in enumerate(zip(fbs, self.blocks)):
            self.map.copy_out(D, fb.d, b)
            _finish(fb, pend[i], n, every, state[i], stats[i], tail_out[i], ints[i], rec_q[i],
                    rec_v[i], rec_out[i])  # fmt: skip
        self.pending = [None] * B


def _finish(fb, pending, n, every, state, stats, tail, ints, rec_q, rec_v, rec_out) -> None:
    """A bird's interval after the shared call, as :func:`birdsim.flight.fast_loop.step`
    finishes one: its momenta, time, checks, tail force and log samples."""
    record = pending[2]
    fb.P, fb.X, fb.L = state[:3].copy(), state[3:6].copy(), state[6:].copy()
    times, fb.time = fast_loop.sample_times(fb.time, fb.h, n, every)  # summed step by step
    fb.root_applied_max = float(stats[2])
    if ints[aero_kernel.TAIL]:
        fb.cb.tail_force_body = tail[:3].copy()
        fb.cb.tail_alpha = float(tail[3])
    if record is not None:
        power = rec_out[:, 6].tolist()
        moment, force, tail_f = rec_out[:, 0:3], rec_out[:, 3:6], rec_out[:, 7:10]
        record.extend(zip(times, rec_q, rec_v, moment, force, power, tail_f))
    if fb.config.momentum_projection and n:
        fb.projection_max = max(fb.projection_max, float(stats[0]), float(stats[1]) * fb.h)
    fb._check_finite()


__all__ = ["SHARED_MODEL", "SharedFlock", "run_flock_steps"]
