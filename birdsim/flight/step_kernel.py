"""The free body's per-step arithmetic in one compiled call (attitude free).

:meth:`birdsim.flight.simulate.FreeBird.step_many` does, between ``mj_step1`` and
``mj_step2``, the momentum projection, the partitioned dynamics and the integration of
the external momenta (its docstring and the module docstring of
:mod:`birdsim.flight.simulate` give the formulas).  With the attitude free (the root's
six DOF first, the wings' after them) :func:`free_step` does all of it in one call of
compiled code instead of some sixty small numpy operations; the same formulas, with
``M_FF`` factorised by Cholesky (it is the mass matrix's block: symmetric positive
definite) instead of inverted.  The numbers agree with the numpy path to round-off
(``tests/test_step_kernel.py``; flights to < 1e-9, docs/performance.md).  The posed
mode keeps the numpy path (its four presets stay bit for bit).

Without numba (:data:`birdsim.physics.jit.numba` None) :data:`AVAILABLE` is False and
the numpy path runs.
"""

from __future__ import annotations

import numpy as np

from birdsim.physics.jit import numba

AVAILABLE = numba is not None


def _free_step(
    M: np.ndarray,
    qpos: np.ndarray,
    qvel: np.ndarray,
    passive: np.ndarray,
    bias: np.ndarray,
    applied: np.ndarray,
    com: np.ndarray,
    xpos: np.ndarray,
    xmat: np.ndarray,
    a_p: np.ndarray,
    state: np.ndarray,
    weight: np.ndarray,
    h: float,
    mass: float,
    project: bool,
    out: np.ndarray,
) -> None:
    """One step's arithmetic.  ``state`` (9,): the whole bird's P, X and L, moved on by
    one step; ``out`` (15,): f_ext (3), m_ext (3, world), |dx| max, |dv| max, the
    largest |entry| of the root's applied force (0.0), and the moment m_ext in torso
    axes (3) and 3 spare entries.  ``xmat`` (9,): the torso's rotation, row major."""
    nv = M.shape[0]
    arm0 = com[0] - xpos[0]
    arm1 = com[1] - xpos[1]
    arm2 = com[2] - xpos[2]
    # Cholesky of M_FF (6 x 6): L L^T
    c = np.zeros((6, 6))
    for i in range(6):
        for j in range(i + 1):
            s = M[i, j]
            for k in range(j):
                s -= c[i, k] * c[j, k]
            if i == j:
                c[i, i] = np.sqrt(s)
            else:
                c[i, j] = s / c[j, j]
    dmax = 0.0
    vmax = 0.0
    if project:
        for i in range(3):
            dx = state[3 + i] - com[i]
            qpos[i] += dx
            if abs(dx) > dmax:
                dmax = abs(dx)
        p_lin = np.zeros(3)
        p_rot = np.zeros(3)
        for i in range(3):
            s = 0.0
            r = 0.0
            for j in range(nv):
                s += M[i, j] * qvel[j]
                r += M[3 + i, j] * qvel[j]
            p_lin[i] = s
            p_rot[i] = r
        dp = np.zeros(6)
        for i in range(3):
            dp[i] = state[i] - p_lin[i]
        # l_now = R p_rot - arm x p_lin; the rotational correction R^T (L - l_now + arm x dP)
        l0 = xmat[0] * p_rot[0] + xmat[1] * p_rot[1] + xmat[2] * p_rot[2]
        l1 = xmat[3] * p_rot[0] + xmat[4] * p_rot[1] + xmat[5] * p_rot[2]
        l2 = xmat[6] * p_rot[0] + xmat[7] * p_rot[1] + xmat[8] * p_rot[2]
        l0 -= arm1 * p_lin[2] - arm2 * p_lin[1]
        l1 -= arm2 * p_lin[0] - arm0 * p_lin[2]
        l2 -= arm0 * p_lin[1] - arm1 * p_lin[0]
        t0 = state[6] - l0 + (arm1 * dp[2] - arm2 * dp[1])
        t1 = state[7] - l1 + (arm2 * dp[0] - arm0 * dp[2])
        t2 = state[8] - l2 + (arm0 * dp[1] - arm1 * dp[0])
        dp[3] = xmat[0] * t0 + xmat[3] * t1 + xmat[6] * t2
        dp[4] = xmat[1] * t0 + xmat[4] * t1 + xmat[7] * t2
        dp[5] = xmat[2] * t0 + xmat[5] * t1 + xmat[8] * t2
        dv = _chol_solve(c, dp)
        for i in range(6):
            qvel[i] += dv[i]
            if abs(dv[i]) > vmax:
                vmax = abs(dv[i])
    # a_F = M_FF^-1 (f_F - M_FP a_P); tau_P = M_PF a_F + M_PP a_P - f_P
    rhs = np.zeros(6)
    for i in range(6):
        s = passive[i] - bias[i]
        for j in range(6, nv):
            s -= M[i, j] * a_p[j - 6]
        rhs[i] = s
    a_f = _chol_solve(c, rhs)
    for i in range(6):
        applied[i] = 0.0
    for i in range(6, nv):
        s = 0.0
        for j in range(6):
            s += M[i, j] * a_f[j]
        for j in range(6, nv):
            s += M[i, j] * a_p[j - 6]
        applied[i] = s - (passive[i] - bias[i])
    amax = 0.0
    for i in range(6):
        if abs(applied[i]) > amax:
            amax = abs(applied[i])
    # external force (aero + weight) and the aero moment about the centre of mass (world)
    f0 = passive[0] + weight[0]
    f1 = passive[1] + weight[1]
    f2 = passive[2] + weight[2]
    m0 = xmat[0] * passive[3] + xmat[1] * passive[4] + xmat[2] * passive[5]
    m1 = xmat[3] * passive[3] + xmat[4] * passive[4] + xmat[5] * passive[5]
    m2 = xmat[6] * passive[3] + xmat[7] * passive[4] + xmat[8] * passive[5]
    m0 -= arm1 * passive[2] - arm2 * passive[1]
    m1 -= arm2 * passive[0] - arm0 * passive[2]
    m2 -= arm0 * passive[1] - arm1 * passive[0]
    out[0], out[1], out[2] = f0, f1, f2
    out[3], out[4], out[5] = m0, m1, m2
    out[6], out[7], out[8] = dmax, vmax, amax
    # the moment in torso axes (R^T m_ext)
    out[9] = xmat[0] * m0 + xmat[3] * m1 + xmat[6] * m2
    out[10] = xmat[1] * m0 + xmat[4] * m1 + xmat[7] * m2
    out[11] = xmat[2] * m0 + xmat[5] * m1 + xmat[8] * m2
    # P, X, L moved on by one step (semi-implicit, as the numpy path)
    state[0] += h * f0
    state[1] += h * f1
    state[2] += h * f2
    for i in range(3):
        state[3 + i] += h * state[i] / mass
    state[6] += h * m0
    state[7] += h * m1
    state[8] += h * m2


def _chol_solve(c: np.ndarray, b: np.ndarray) -> np.ndarray:
    n = b.shape[0]
    y = np.zeros(n)
    for i in range(n):
        s = b[i]
        for k in range(i):
            s -= c[i, k] * y[k]
        y[i] = s / c[i, i]
    x = np.zeros(n)
    for i in range(n - 1, -1, -1):
        s = y[i]
        for k in range(i + 1, n):
            s -= c[k, i] * x[k]
        x[i] = s / c[i, i]
    return x


if AVAILABLE:
    _chol_solve = numba.njit(cache=True, nogil=True)(_chol_solve)
    free_step = numba.njit(cache=True, nogil=True)(_free_step)
else:  # pragma: no cover
    free_step = None


def free_loop(fb, pres, Pq, P, W, record: list | None, every: int, weight: np.ndarray) -> tuple:
    """:meth:`FreeBird.step_many`'s loop with :func:`free_step` (attitude free, the
    root's DOF first): returns (max |dx|, max |dv|) of the projection.  ``Pq``, ``P``,
    ``W``: the prescribed qpos and DOF and the wings' DOF (slices)."""
    import mujoco

    m, d, h, M = fb.m, fb.d, fb.h, fb._M
    qpos, qvel, applied, xfrc = d.qpos, d.qvel, d.qfrc_applied, d.xfrc_applied
    passive, bias = d.qfrc_passive, d.qfrc_bias
    com_t, xpos_t, xmat_t = d.subtree_com[fb.torso], d.xpos[fb.torso], d.xmat[fb.torso]
    pres_q, pres_v, pres_a = pres.qpos[:, Pq], pres.qvel[:, P], pres.qacc[:, P]
    step1, step2, full_m = mujoco.mj_step1, mujoco.mj_step2, mujoco.mj_fullM
    project = bool(fb.config.momentum_projection)
    mass = fb.total_mass
    state = np.concatenate([fb.P, fb.X, fb.L])
    out = np.zeros(12)
    seed = np.array([1.0, -1.0, -1.0])
    cb = fb.cb
    dmax = vmax = 0.0
    time = fb.time
    try:
        for k in range(pres_q.shape[0]):
            qpos[Pq] = pres_q[k]
            qvel[P] = pres_v[k]
            step1(m, d)
            full_m(m, d, M)
            free_step(
                M,
                qpos,
                qvel,
                passive,
                bias,
                applied,
                com_t,
                xpos_t,
                xmat_t,
                pres_a[k],
                state,
                weight,
                h,
                mass,
                project,
                out,
            )
            if out[6] > dmax:
                dmax = float(out[6])
            if out[7] > vmax:
                vmax = float(out[7])
            if out[8] != 0.0 or xfrc.any():
                fb.root_applied_max = max(
                    fb.root_applied_max, float(out[8]), float(np.max(np.abs(xfrc)))
                )
            if record is not None and k % every == 0:
                power = float(applied[W] @ qvel[W])  # both wings' joints
                moment = seed * out[9:12]
                tail = seed * cb.tail_force_body
                record.append((time, qpos.copy(), qvel.copy(), moment, out[:3].copy(), power, tail))
            step2(m, d)
            time += h
    finally:
        fb.P, fb.X, fb.L = state[:3].copy(), state[3:6].copy(), state[6:].copy()
        fb.time = time
    return dmax, vmax


__all__ = ["AVAILABLE", "free_loop", "free_step"]
