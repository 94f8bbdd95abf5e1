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

import numpy as np

from birdsim.physics import kernel
from birdsim.physics.jit import jit as _jit
from birdsim.physics.kernel_dual import (
    _dpolar,
    _drot,
    _dual_chain,
    _dual_joints,
    _dual_row,
    _scale_by_area,
)
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
        cq, sq, qv, qd, CP, SP, A = _dual_row(
            pitch[b], speed[b], climb[b], ip, bias[b], const, dbias, J, D, d
        )
        W = np.zeros((3, D))  # the body rate: value and d/d(p, q, r)
        for cc in range(3):
            W[cc, 0] = rate[b, cc]
            W[cc, 1 + d + cc] = 1.0
        p = np.zeros((3, D))
        vf = np.zeros((3, D))
        v = np.zeros((3, D))
        g = np.zeros((3, D))
        dv = np.zeros((3, D))
        gx = np.zeros(D)
        gz = np.zeros(D)
        acc = np.zeros((6, D))
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
                d,
                qv,
                cq,
                sq,
                qd,
            )
            for k in range(K):
                L = length[k]
                for e in range(strips[k]):
                    _dual_chain(k, e, L, kind, joint, axis, span, radius, qv, qd, cq, sq, p, vf, dv)
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
