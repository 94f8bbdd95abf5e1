"""Forward-mode dual numbers through the wingbeat chain: the exact derivatives of the
cycle means with respect to every wingbeat parameter, compiled by numba.

Each quantity is an array ``[value, d/dp_1, ..., d/dp_d]``.  Every joint's sinusoid is
affine in the parameters (:func:`birdsim.physics.kernel.joint_derivatives`), so the
derivatives of the joint angles are exact; rotations, the polar and the power carry
them with the product and chain rules.  Called through
:func:`birdsim.physics.kernel.means_and_gradients`; conventions as in
:mod:`birdsim.physics.kernel` (the same chain encoding and rotations).
"""

from __future__ import annotations

import math

import numpy as np

from birdsim.physics.jit import jit as _jit
from birdsim.physics.jit import jit_inline as _jit_inline
from birdsim.physics.kernel_shaft import _positive_part

# ---- forward-mode dual numbers: value in [0], d/d(param i) in [1 + i] ----------------


@_jit
def _drot(V, axis, c, s, sg):
    """Rotate the dual 3-vector V (3 x D) in place by the passive rotation (c, sg*s)."""
    if axis == 1:
        i1, i2, e = 0, 2, sg
    elif axis == 0:
        i1, i2, e = 1, 2, -sg
    else:
        i1, i2, e = 0, 1, -sg
    a0, b0, c0, s0 = V[i1, 0], V[i2, 0], c[0], e * s[0]
    for i in range(1, V.shape[1]):
        ai, bi, ci, si = V[i1, i], V[i2, i], c[i], e * s[i]
        V[i1, i] = c0 * ai + ci * a0 - (s0 * bi + si * b0)
        V[i2, i] = s0 * ai + si * a0 + c0 * bi + ci * b0
    V[i1, 0] = c0 * a0 - s0 * b0
    V[i2, 0] = s0 * a0 + c0 * b0


@_jit
def _dpolar(polar, coeffs, vx, vz, area, rho, gx, gz):
    """Dual version of :func:`_polar_force`: panel-axes force of an element into gx, gz."""
    D = vx.shape[0]
    x, z = vx[0], vz[0]
    if polar == 0:
        lift2, cd0, cdm = 2.0 * coeffs[0], coeffs[1], coeffs[2]
        x2, z2 = x * x, z * z
        u2 = x2 + z2
        u = math.sqrt(u2)
        h = 0.5 * rho * area
        A = h / u if u > 0.0 else 0.0
        drag = cd0 * u2 + cdm * z2
        Cx = lift2 * z2 - drag
        Cz = lift2 * x2 + drag
        for i in range(1, D):
            xi, zi = vx[i], vz[i]
            u2i = 2.0 * (x * xi + z * zi)
            Ai = -h * (u2i / (2.0 * u)) / u2 if u > 0.0 else 0.0
            dragi = cd0 * u2i + cdm * 2.0 * z * zi
            Cxi = lift2 * 2.0 * z * zi - dragi
            Czi = lift2 * 2.0 * x * xi + dragi
            gx[i] = Ai * x * Cx + A * xi * Cx + A * x * Cxi
            gz[i] = -(Ai * z * Cz + A * zi * Cz + A * z * Czi)
        gx[0] = A * x * Cx
        gz[0] = -A * z * Cz
        return
    alpha = math.atan2(z, x)
    a = (alpha + 0.5 * math.pi) % math.pi - 0.5 * math.pi
    k1, k2 = 180.0 / math.pi, math.pi / 180.0
    deg = abs(a) * k1
    sg = 1.0 if a > 0.0 else (-1.0 if a < 0.0 else (0.0 if a == 0.0 else a))
    arg1 = (2.13 * deg - 7.20) * k2
    arg2 = (2.04 * deg - 9.82) * k2
    cl = sg * (0.225 + 1.58 * math.sin(arg1))
    cd = 1.92 - 1.55 * math.cos(arg2)
    u2 = x * x + z * z
    qa = 0.5 * rho * u2 * area
    ca, sa = math.cos(alpha), math.sin(alpha)
    fx0 = -cd * ca + cl * sa
    fz0 = -cd * sa - cl * ca
    for i in range(1, D):
        xi, zi = vx[i], vz[i]
        al_i = (x * zi - z * xi) / u2 if u2 > 0.0 else 0.0
        deg_i = sg * al_i * k1
        cl_i = sg * 1.58 * math.cos(arg1) * 2.13 * k2 * deg_i
        cd_i = 1.55 * math.sin(arg2) * 2.04 * k2 * deg_i
        qa_i = rho * area * (x * xi + z * zi)
        ca_i, sa_i = -sa * al_i, ca * al_i
        gx[i] = qa_i * fx0 + qa * (-cd_i * ca - cd * ca_i + cl_i * sa + cl * sa_i)
        gz[i] = qa_i * fz0 + qa * (-cd_i * sa - cd * sa_i - cl_i * ca - cl * ca_i)
    gx[0] = qa * fx0
    gz[0] = qa * fz0


@_jit
def _scale_by_area(gx, gz, cq, half_loss):
    """Multiply the dual force (gx, gz) by the dual area factor ``1 - h (1 - cos q)``
    (``cq`` the dual cos q, ``h`` = lambda / 2; m5's folding hand): product rule."""
    f0 = 1.0 - half_loss * (1.0 - cq[0])
    for i in range(1, gx.shape[0]):
        fi = half_loss * cq[i]
        gx[i] = f0 * gx[i] + fi * gx[0]
        gz[i] = f0 * gz[i] + fi * gz[0]
    gx[0] *= f0
    gz[0] *= f0


@_jit_inline
def _kinetic(hk, vf, mass):
    """Add ``1/2 mass |vf|^2`` (value, then its derivatives) to the dual ``hk`` (D)."""
    ke = 0.0
    for cc in range(3):
        ke += vf[cc, 0] * vf[cc, 0]
    hk[0] += 0.5 * mass * ke
    for i in range(1, hk.shape[0]):
        ke = 0.0
        for cc in range(3):
            ke += vf[cc, 0] * vf[cc, i]
        hk[i] += mass * ke


@_jit_inline
def _dual_row(pitch_b, speed_b, climb_b, ip, bias_b, const, dbias, J, D, nd):
    """A row's start, in dual numbers of width D (value, then nd parameter derivatives,
    then any further columns): the joints' value/cos/sin/rate arrays with the constant
    joints filled, the body pitch's cos and sin, and the freestream A in body axes."""
    cq = np.zeros((J, D))
    sq = np.zeros((J, D))
    qv = np.zeros((J, D))
    qd = np.zeros((J, D))
    CP = np.zeros(D)
    SP = np.zeros(D)
    CP[0], SP[0] = math.cos(pitch_b), math.sin(pitch_b)
    CP[1 + ip], SP[1 + ip] = -SP[0], CP[0]
    rx, rz = speed_b, -climb_b
    A = np.zeros((3, D))
    for i in range(D):
        A[0, i] = CP[i] * rx - SP[i] * rz
        A[2, i] = SP[i] * rx + CP[i] * rz
    for j in range(J):
        if const[j]:
            q = bias_b[j]
            c, s = math.cos(q), math.sin(q)
            qv[j, 0], cq[j, 0], sq[j, 0] = q, c, s
            for i in range(1, nd + 1):
                qv[j, i] = dbias[j, i - 1]
                cq[j, i] = -s * dbias[j, i - 1]
                sq[j, i] = c * dbias[j, i - 1]
    return cq, sq, qv, qd, CP, SP, A


@_jit_inline
def _dual_joints(
    ct_t, st_t, cph, sph, amp_b, bias_b, const, damp, dphase, dbias, omega, nd, qv, cq, sq, qd
):
    """The oscillating joints' angles (value, cos, sin) and rates at one phase, in dual
    numbers over the nd parameters."""
    for j in range(amp_b.shape[0]):
        if not const[j]:
            sarg = st_t * cph[j] + ct_t * sph[j]
            carg = ct_t * cph[j] - st_t * sph[j]
            am = amp_b[j]
            q = am * sarg + bias_b[j]
            c, s = math.cos(q), math.sin(q)
            qv[j, 0], cq[j, 0], sq[j, 0] = q, c, s
            qd[j, 0] = (am * omega) * carg
            for i in range(1, nd + 1):
                dq = damp[j, i - 1] * sarg + am * carg * dphase[j, i - 1] + dbias[j, i - 1]
                qv[j, i] = dq
                cq[j, i] = -s * dq
                sq[j, i] = c * dq
                qd[j, i] = omega * (damp[j, i - 1] * carg - am * sarg * dphase[j, i - 1])


@_jit_inline
def _dual_chain(k, e, L, kind, joint, axis, span, radius, qv, qd, cq, sq, p, vf, dv):
    """Strip e of panel k: its control point p and flapping velocity vf (body axes, dual
    numbers), walked from the panel up the joint chain."""
    D = p.shape[1]
    p[:, :] = 0.0
    vf[:, :] = 0.0
    p[1, 0] = radius[k, e]
    for il in range(L - 1, -1, -1):
        kd = kind[k, il]
        if kd == 0:
            p[1, 0] += span[k, il]
            continue
        j = joint[k, il]
        a = axis[k, il]
        dv[:, :] = 0.0
        if kd == 2:
            for i in range(D):
                p[a, i] += qv[j, i]
                dv[a, i] = qd[j, i]
        else:
            _drot(p, a, cq[j], sq[j], -1.0)
            _drot(vf, a, cq[j], sq[j], -1.0)
            # dv = qd * (e_a x p)
            if a == 0:
                r1, r2, o1, o2 = 1, 2, 2, 1  # (0, -z, y)
                sg1, sg2 = -1.0, 1.0
            elif a == 1:
                r1, r2, o1, o2 = 0, 2, 2, 0  # (z, 0, -x)
                sg1, sg2 = 1.0, -1.0
            else:
                r1, r2, o1, o2 = 0, 1, 1, 0  # (-y, x, 0)
                sg1, sg2 = -1.0, 1.0
            w0, a1, a2 = qd[j, 0], p[o1, 0], p[o2, 0]
            dv[r1, 0] = sg1 * w0 * a1
            dv[r2, 0] = sg2 * w0 * a2
            for i in range(1, D):
                dv[r1, i] = sg1 * (w0 * p[o1, i] + qd[j, i] * a1)
                dv[r2, i] = sg2 * (w0 * p[o2, i] + qd[j, i] * a2)
        for cc in range(3):
            for i in range(D):
                vf[cc, i] += dv[cc, i]


@_jit
def _grad_kernel(
    lo,
    hi,
    pitch,
    speed,
    climb,
    amp,
    phase,
    bias,
    const,
    damp,
    dphase,
    dbias,
    ip,
    phases,
    omega,
    rho,
    kind,
    joint,
    axis,
    group,
    span,
    length,
    radius,
    area,
    strips,
    polar,
    coeffs,
    out,
    wmass,
    dmat,
    positive,
):
    """Rows [lo, hi): out[b, r] = (value, gradient) of the mean Fx, Fy, Fz, P; with
    ``positive`` row 3 is the positive shaft power (:mod:`birdsim.physics.kernel_shaft`)."""
    J, N, K = amp.shape[1], phases.shape[0], kind.shape[0]
    D = damp.shape[1] + 1
    hp, hk = np.zeros((N if positive else 0, D)), np.zeros((N if positive else 0, D))
    res = np.zeros(D)
    ct, stt = np.cos(phases), np.sin(phases)
    for b in range(lo, hi):
        cph = np.cos(phase[b])
        sph = np.sin(phase[b])
        cq, sq, qv, qd, CP, SP, A = _dual_row(
            pitch[b], speed[b], climb[b], ip, bias[b], const, dbias, J, D, D - 1
        )
        p = np.zeros((3, D))
        vf = np.zeros((3, D))  # flapping velocity (both groups: only their sum is needed here)
        v = np.zeros((3, D))
        g = np.zeros((3, D))
        dv = np.zeros((3, D))
        gx = np.zeros(D)
        gz = np.zeros(D)
        acc = np.zeros((4, D))
        hp[:, :] = 0.0
        hk[:, :] = 0.0
        for t in range(N):
            _dual_joints(
                ct[t],
                stt[t],
                cph,
                sph,
                amp[b],
                bias[b],
                const,
                damp,
                dphase,
                dbias,
                omega,
                D - 1,
                qv,
                cq,
                sq,
                qd,
            )
            for k in range(K):
                L = length[k]
                for e in range(strips[k]):
                    # _dual_chain written out: as a call (even inlined by numba) it cost this
                    # kernel 15-45 % of its speed (measured side by side, base to m5)
                    p[:, :] = 0.0
                    vf[:, :] = 0.0
                    p[1, 0] = radius[k, e]
                    for il in range(L - 1, -1, -1):
                        kd = kind[k, il]
                        if kd == 0:
                            p[1, 0] += span[k, il]
                            continue
                        j = joint[k, il]
                        a = axis[k, il]
                        dv[:, :] = 0.0
                        if kd == 2:
                            for i in range(D):
                                p[a, i] += qv[j, i]
                                dv[a, i] = qd[j, i]
                        else:
                            _drot(p, a, cq[j], sq[j], -1.0)
                            _drot(vf, a, cq[j], sq[j], -1.0)
                            # dv = qd * (e_a x p)
                            if a == 0:
                                r1, r2, o1, o2 = 1, 2, 2, 1  # (0, -z, y)
                                sg1, sg2 = -1.0, 1.0
                            elif a == 1:
                                r1, r2, o1, o2 = 0, 2, 2, 0  # (z, 0, -x)
                                sg1, sg2 = 1.0, -1.0
                            else:
                                r1, r2, o1, o2 = 0, 1, 1, 0  # (-y, x, 0)
                                sg1, sg2 = -1.0, 1.0
                            w0, a1, a2 = qd[j, 0], p[o1, 0], p[o2, 0]
                            for i in range(D):
                                if i == 0:
                                    dv[r1, 0] = sg1 * w0 * a1
                                    dv[r2, 0] = sg2 * w0 * a2
                                else:
                                    dv[r1, i] = sg1 * (w0 * p[o1, i] + qd[j, i] * a1)
                                    dv[r2, i] = sg2 * (w0 * p[o2, i] + qd[j, i] * a2)
                        for cc in range(3):
                            for i in range(D):
                                vf[cc, i] += dv[cc, i]
                    for cc in range(3):
                        for i in range(D):
                            v[cc, i] = A[cc, i] + vf[cc, i]
                    for il in range(L):
                        if kind[k, il] == 1:
                            j = joint[k, il]
                            _drot(v, axis[k, il], cq[j], sq[j], 1.0)
                    _dpolar(polar, coeffs, v[0], v[2], area[k, e], rho, gx, gz)
                    if L < kind.shape[1] and kind[k, L] == 3:  # the area follows a joint
                        _scale_by_area(gx, gz, cq[joint[k, L]], 0.5 * span[k, L])
                    for i in range(D):
                        g[0, i], g[1, i], g[2, i] = gx[i], 0.0, gz[i]
                    for il in range(L - 1, -1, -1):
                        if kind[k, il] == 1:
                            j = joint[k, il]
                            _drot(g, axis[k, il], cq[j], sq[j], -1.0)
                    c0, s0 = CP[0], SP[0]
                    g0x, g0z = g[0, 0], g[2, 0]
                    acc[0, 0] += c0 * g0x + s0 * g0z
                    acc[1, 0] += g[1, 0]
                    acc[2, 0] += -s0 * g0x + c0 * g0z
                    pw = 0.0
                    for cc in range(3):
                        pw += g[cc, 0] * vf[cc, 0]
                    acc[3, 0] -= pw
                    if positive:
                        hp[t, 0] -= pw
                        _kinetic(hk[t], vf, wmass[k])
                    for i in range(1, D):
                        acc[0, i] += c0 * g[0, i] + CP[i] * g0x + s0 * g[2, i] + SP[i] * g0z
                        acc[1, i] += g[1, i]
                        acc[2, i] += -(s0 * g[0, i] + SP[i] * g0x) + c0 * g[2, i] + CP[i] * g0z
                        pw = 0.0
                        for cc in range(3):
                            pw += g[cc, 0] * vf[cc, i] + g[cc, i] * vf[cc, 0]
                        acc[3, i] -= pw
                        if positive:
                            hp[t, i] -= pw
        for r in range(4):
            for i in range(D):
                out[b, r, i] = acc[r, i] / N
        if positive:
            _positive_part(hp, hk, dmat, res)
            for i in range(D):
                out[b, 3, i] = res[i]
