"""Exact gradients for models whose panel areas follow a joint (m5's folding hand): a
copy of :func:`birdsim.physics.kernel_dual._grad_kernel` that scales each element's
dual force by its panel's area factor (:mod:`birdsim.physics.kernel_fold`)."""

from __future__ import annotations

import math

import numpy as np

from birdsim.physics.jit import jit as _jit
from birdsim.physics.kernel_dual import _dpolar, _drot


@_jit
def _scale_by_area(gx, gz, cq, half_loss):
    """Multiply the dual force (gx, gz) by the dual area factor ``1 - h (1 - cos q)``
    (``cq`` the dual cos q, ``h`` = lambda / 2): product rule."""
    f0 = 1.0 - half_loss * (1.0 - cq[0])
    for i in range(1, gx.shape[0]):
        fi = half_loss * cq[i]
        gx[i] = f0 * gx[i] + fi * gx[0]
        gz[i] = f0 * gz[i] + fi * gz[0]
    gx[0] *= f0
    gz[0] *= f0


@_jit
def _fold_grad_kernel(
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
):
    J, N, K = amp.shape[1], phases.shape[0], kind.shape[0]
    D = damp.shape[1] + 1
    ct, stt = np.cos(phases), np.sin(phases)
    for b in range(lo, hi):
        cph = np.cos(phase[b])
        sph = np.sin(phase[b])
        cq = np.zeros((J, D))
        sq = np.zeros((J, D))
        qv = np.zeros((J, D))
        qd = np.zeros((J, D))
        CP = np.zeros(D)
        SP = np.zeros(D)
        CP[0], SP[0] = math.cos(pitch[b]), math.sin(pitch[b])
        CP[1 + ip], SP[1 + ip] = -SP[0], CP[0]
        rx, rz = speed[b], -climb[b]
        A = np.zeros((3, D))
        for i in range(D):
            A[0, i] = CP[i] * rx - SP[i] * rz
            A[2, i] = SP[i] * rx + CP[i] * rz
        for j in range(J):
            if const[j]:
                q = bias[b, j]
                c, s = math.cos(q), math.sin(q)
                qv[j, 0], cq[j, 0], sq[j, 0] = q, c, s
                for i in range(1, D):
                    qv[j, i] = dbias[j, i - 1]
                    cq[j, i] = -s * dbias[j, i - 1]
                    sq[j, i] = c * dbias[j, i - 1]
        p = np.zeros((3, D))
        vf = np.zeros((3, D))  # flapping velocity (both groups: only their sum is needed here)
        v = np.zeros((3, D))
        g = np.zeros((3, D))
        dv = np.zeros((3, D))
        gx = np.zeros(D)
        gz = np.zeros(D)
        acc = np.zeros((4, D))
        for t in range(N):
            for j in range(J):
                if not const[j]:
                    sarg = stt[t] * cph[j] + ct[t] * sph[j]
                    carg = ct[t] * cph[j] - stt[t] * sph[j]
                    am = amp[b, j]
                    q = am * sarg + bias[b, j]
                    c, s = math.cos(q), math.sin(q)
                    qv[j, 0], cq[j, 0], sq[j, 0] = q, c, s
                    qd[j, 0] = (am * omega) * carg
                    for i in range(1, D):
                        dq = damp[j, i - 1] * sarg + am * carg * dphase[j, i - 1] + dbias[j, i - 1]
                        qv[j, i] = dq
                        cq[j, i] = -s * dq
                        sq[j, i] = c * dq
                        qd[j, i] = omega * (damp[j, i - 1] * carg - am * sarg * dphase[j, i - 1])
            for k in range(K):
                L = length[k]
                for e in range(strips[k]):
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
                    for i in range(1, D):
                        acc[0, i] += c0 * g[0, i] + CP[i] * g0x + s0 * g[2, i] + SP[i] * g0z
                        acc[1, i] += g[1, i]
                        acc[2, i] += -(s0 * g[0, i] + SP[i] * g0x) + c0 * g[2, i] + CP[i] * g0z
                        pw = 0.0
                        for cc in range(3):
                            pw += g[cc, 0] * vf[cc, i] + g[cc, i] * vf[cc, 0]
                        acc[3, i] -= pw
        for r in range(4):
            for i in range(D):
                out[b, r, i] = acc[r, i] / N
