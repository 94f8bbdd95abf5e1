"""Compiled whole-bird wingbeat moments and their exact derivatives.

The kernel walks the same chain encoding as :mod:`birdsim.physics.kernel` and carries
forward-mode dual numbers (:mod:`birdsim.physics.kernel_dual`) with one slot per
wingbeat parameter of the input model and three for the body rate (p, q, r): each
element's air velocity is the body's, plus its flapping velocity, plus ``omega x r``;
the mean force and the mean moment ``r x F`` (body axes, about the shoulder = torso
origin) of a right wing come out with their derivatives.  :func:`whole_bird` evaluates
both wings (the left as a mirrored right wing, :mod:`birdsim.physics.moments`) and
assembles the whole bird's values and Jacobians.  None where the kernel cannot run
(the caller then uses the numpy reference of :mod:`birdsim.physics.moments_eval`).
"""

from __future__ import annotations

import math

import numpy as np

from birdsim.physics import kernel
from birdsim.physics.jit import jit as _jit
from birdsim.physics.kernel_dual import _dpolar, _drot, _scale_by_area
from birdsim.physics.wing_sides import MIRROR_F, MIRROR_M, drag_body, sides


def right_wings(mx, p, speed, climb, rate, bird, phases) -> np.ndarray | None:
    """B x 6 x (1 + d + 3): mean force (rows 0-2) and moment (3-5) of right wings, body
    axes, value in [..., 0], d/d(param i) in [..., 1 + i], d/d(p, q, r) in the last 3."""
    if not kernel.available() or not kernel.supported(bird) or bird.induced_velocity:
        return None
    st = kernel.setup(mx, bird)
    amp, phase, bias, const = kernel.joint_coefficients(mx, p, bird)
    damp, dphase, dbias = kernel.joint_derivatives(mx, bird)
    c = np.ascontiguousarray
    B, d = len(speed), len(mx.param_names)
    out = np.zeros((B, 6, d + 4))
    args = (
        c(p["pitch"], dtype=float),
        c(speed, dtype=float),
        c(climb, dtype=float),
        c(rate, dtype=float),
        amp,
        phase,
        bias,
        const,
        damp,
        dphase,
        dbias,
        mx.param_names.index("pitch"),
        c(phases, dtype=float),
        float(bird.omega),
        float(bird.rho),
        st.kind,
        st.joint,
        st.axis,
        st.span,
        st.length,
        st.radius,
        st.area,
        st.strips,
        st.polar,
        st.coeffs,
        out,
    )
    if not kernel._run(_moments_kernel, B, args):
        return None
    return out


def whole_bird(mx, sym, speed, climb, rate, u, bird, phases, signs) -> dict | None:
    """Whole-bird values and Jacobians (see :func:`birdsim.physics.moments_eval.whole_bird`)."""
    right, left = sides(mx, sym, u, signs)
    B, d = len(speed), len(mx.param_names)
    both = {k: np.concatenate([right[k], left[k]]) for k in mx.param_names}
    rates = np.concatenate([rate, MIRROR_M * rate])
    out = right_wings(
        mx,
        both,
        np.concatenate([speed, speed]),
        np.concatenate([climb, climb]),
        rates,
        bird,
        phases,
    )
    if out is None:
        return None
    mirror = np.concatenate([MIRROR_F, MIRROR_M])[None, :, None]
    r_, l_ = out[:B], mirror * out[B:]  # the left wing's rows mirrored back
    val = r_[..., 0] + l_[..., 0]
    sr, sl, idx = signs
    cols = 1 + np.asarray(idx)
    du = r_[..., cols] * sr + l_[..., cols] * sl
    drate = r_[..., 1 + d :] + l_[..., 1 + d :] * MIRROR_M  # the left sees (-p, q, -r)
    return {
        "force_body": val[:, :3] + drag_body(sym, speed, climb, bird),
        "moment_body": val[:, 3:],
        "force_du": du[:, :3],
        "moment_du": du[:, 3:],
        "force_drate": drate[:, :3],
        "moment_drate": drate[:, 3:],
    }


@_jit
def _moments_kernel(
    lo,
    hi,
    pitch,
    speed,
    climb,
    rate,
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
    d = damp.shape[1]
    D = d + 4
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
        W = np.zeros((3, D))  # the body rate: value and d/d(p, q, r)
        for cc in range(3):
            W[cc, 0] = rate[b, cc]
            W[cc, 1 + d + cc] = 1.0
        for j in range(J):
            if const[j]:
                q = bias[b, j]
                c, s = math.cos(q), math.sin(q)
                qv[j, 0], cq[j, 0], sq[j, 0] = q, c, s
                for i in range(1, d + 1):
                    qv[j, i] = dbias[j, i - 1]
                    cq[j, i] = -s * dbias[j, i - 1]
                    sq[j, i] = c * dbias[j, i - 1]
        p = np.zeros((3, D))
        vf = np.zeros((3, D))
        v = np.zeros((3, D))
        g = np.zeros((3, D))
        dv = np.zeros((3, D))
        gx = np.zeros(D)
        gz = np.zeros(D)
        acc = np.zeros((6, D))
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
                    for i in range(1, d + 1):
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
                            if a == 0:
                                r1, r2, o1, o2 = 1, 2, 2, 1
                                sg1, sg2 = -1.0, 1.0
                            elif a == 1:
                                r1, r2, o1, o2 = 0, 2, 2, 0
                                sg1, sg2 = 1.0, -1.0
                            else:
                                r1, r2, o1, o2 = 0, 1, 1, 0
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
                    # air velocity: body + flapping + omega x r (dual products)
                    for cc in range(3):
                        c1, c2 = (cc + 1) % 3, (cc + 2) % 3
                        v[cc, 0] = A[cc, 0] + vf[cc, 0] + W[c1, 0] * p[c2, 0] - W[c2, 0] * p[c1, 0]
                        for i in range(1, D):
                            v[cc, i] = (
                                A[cc, i]
                                + vf[cc, i]
                                + W[c1, i] * p[c2, 0]
                                + W[c1, 0] * p[c2, i]
                                - W[c2, i] * p[c1, 0]
                                - W[c2, 0] * p[c1, i]
                            )
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
                    for cc in range(3):
                        c1, c2 = (cc + 1) % 3, (cc + 2) % 3
                        acc[cc, 0] += g[cc, 0]
                        acc[3 + cc, 0] += p[c1, 0] * g[c2, 0] - p[c2, 0] * g[c1, 0]
                        for i in range(1, D):
                            acc[cc, i] += g[cc, i]
                            acc[3 + cc, i] += (
                                p[c1, i] * g[c2, 0]
                                + p[c1, 0] * g[c2, i]
                                - p[c2, i] * g[c1, 0]
                                - p[c2, 0] * g[c1, i]
                            )
        for r in range(6):
            for i in range(D):
                out[b, r, i] = acc[r, i] / N
