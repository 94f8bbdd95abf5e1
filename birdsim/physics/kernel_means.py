"""The compiled code of the fused wingbeat kernel (:mod:`birdsim.physics.kernel`): the
element force of a polar, the chain's rotations and the cycle-means kernels, with and
without a body rate.  Called through :func:`birdsim.physics.kernel.means`; the chain
encoding is :class:`birdsim.physics.kernel.Setup`'s.  An element's area is scaled by
``1 - lambda (1 - cos q) / 2`` where its panel carries an area-fold column (code 3 at
index ``length[k]``: the joint in ``joint``, ``lambda`` in ``span``; m5's folding hand,
:func:`birdsim.physics.m5.area_factor`); models without one never reach that line.
With ``positive`` the kernel also keeps the per-sample power and kinetic energy of the
wing for the positive shaft power (:mod:`birdsim.physics.kernel_shaft`); without it
those lines are skipped and the means are unchanged bit for bit.
"""

from __future__ import annotations

import math

import numpy as np

from birdsim.physics.jit import jit as _jit
from birdsim.physics.kernel_shaft import _positive_part

# ---- compiled code --------------------------------------------------------------------
# Conventions as in frames.rotate: the passive Table 2 rotation about `axis` with (c, s);
# the way back passes -s.  Values only here; the dual-number version follows.


@_jit
def _polar_force(polar, coeffs, vx, vz, area, rho):
    """Panel-axes (fx, fz) of an element: the seed polar's algebraic form, or robofly."""
    if polar == 0:
        vx2, vz2 = vx * vx, vz * vz
        u2 = vx2 + vz2
        u = math.sqrt(u2)
        inv_u = 0.5 * rho * area / u if u > 0.0 else 0.0
        drag_u2 = coeffs[1] * u2 + coeffs[2] * vz2
        lift2 = 2.0 * coeffs[0]
        return inv_u * vx * (lift2 * vz2 - drag_u2), -inv_u * vz * (lift2 * vx2 + drag_u2)
    alpha = math.atan2(vz, vx)
    x = alpha + 0.5 * math.pi
    a = x % math.pi - 0.5 * math.pi  # Python's float mod is numpy's: the sign of pi
    deg = abs(a) * (180.0 / math.pi)
    cl = 0.225 + 1.58 * math.sin((2.13 * deg - 7.20) * (math.pi / 180.0))
    cd = 1.92 - 1.55 * math.cos((2.04 * deg - 9.82) * (math.pi / 180.0))
    sg = 1.0 if a > 0.0 else (-1.0 if a < 0.0 else (0.0 if a == 0.0 else a))
    cl = sg * cl
    q_area = 0.5 * rho * (vx * vx + vz * vz) * area
    ca, sa = math.cos(alpha), math.sin(alpha)
    return q_area * (-cd * ca + cl * sa), q_area * (-cd * sa - cl * ca)


@_jit
def _rot(axis, c, s, x, y, z):
    if axis == 1:
        return c * x - s * z, y, s * x + c * z
    if axis == 0:
        return x, c * y + s * z, -s * y + c * z
    return c * x + s * y, -s * x + c * y, z


@_jit
def _means_rate_kernel(
    lo,
    hi,
    pitch,
    speed,
    climb,
    air_earth,
    amp,
    phase,
    bias,
    const,
    phases,
    half,
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
    F,
    P,
    JP,
    PP,
    wmass,
    dmat,
    positive,
    rate,
    rotating,
):
    """The means of :func:`_means_kernel` with a body rate (B x 3) when ``rotating``."""
    J, N, K = amp.shape[1], phases.shape[0], kind.shape[0]
    ct, stt = np.cos(phases), np.sin(phases)
    cq = np.empty(J)
    sq = np.empty(J)
    cph, sph = np.empty(J), np.empty(J)
    qv = np.empty(J)
    qd = np.empty(J)
    fxs, fys, fzs = np.empty(K), np.empty(K), np.empty(K)
    ps = np.empty(K)
    TQ, TD, TC, TS = np.empty((N, J)), np.empty((N, J)), np.empty((N, J)), np.empty((N, J))
    # per-sample power and kinetic energy of the right wing (the positive power only)
    hp, hk = np.zeros((N if positive else 0, 1)), np.zeros((N if positive else 0, 1))
    res = np.zeros(1)
    for b in range(lo, hi):
        hp[:, :] = 0.0
        hk[:, :] = 0.0
        for j in range(J):
            cph[j], sph[j] = math.cos(phase[b, j]), math.sin(phase[b, j])
        cp, sp = math.cos(pitch[b]), math.sin(pitch[b])
        # the body relative to the air, body axes: ((V, 0, -climb) - w_air) by the pitch
        rx, ry, rz = speed[b] - air_earth[b, 0], -air_earth[b, 1], -climb[b] - air_earth[b, 2]
        ax, ay, az = cp * rx - sp * rz, ry, sp * rx + cp * rz
        for j in range(J):
            if const[j]:
                qv[j], qd[j] = bias[b, j], 0.0
                cq[j], sq[j] = math.cos(bias[b, j]), math.sin(bias[b, j])
        for k in range(K):
            fxs[k], fys[k], fzs[k], ps[k] = 0.0, 0.0, 0.0, 0.0
        j0, j1 = 0.0, 0.0
        # joint states at every sample; a joint without bias is odd over half a period
        # (q(t + pi) = -q(t)), so on an even periodic grid its second half is free
        for j in range(J):
            if const[j]:
                continue
            # a joint that moves as an earlier one, mirrored (m5's wrist sweep is the
            # elbow's -1 times at coupling 1): the same states negated, bit for bit (the
            # rounding of a * s + b is symmetric; libm's cos is even, sin odd)
            mirror = -1
            for i in range(j):
                if (
                    not const[i]
                    and phase[b, i] == phase[b, j]
                    and amp[b, i] == -amp[b, j]
                    and bias[b, i] == -bias[b, j]
                ):
                    mirror = i
                    break
            if mirror >= 0:
                for t in range(N):
                    TQ[t, j], TD[t, j] = -TQ[t, mirror], -TD[t, mirror]
                    TC[t, j], TS[t, j] = TC[t, mirror], -TS[t, mirror]
                continue
            odd = half > 0 and bias[b, j] == 0.0
            for t in range(half if odd else N):
                # sin and cos of (omega t + phase) by the addition theorem
                sarg = stt[t] * cph[j] + ct[t] * sph[j]
                carg = ct[t] * cph[j] - stt[t] * sph[j]
                q = amp[b, j] * sarg + bias[b, j]
                TQ[t, j], TD[t, j] = q, (amp[b, j] * omega) * carg
                TC[t, j], TS[t, j] = math.cos(q), math.sin(q)
            if odd:
                for t in range(half):
                    TQ[t + half, j], TD[t + half, j] = -TQ[t, j], -TD[t, j]
                    TC[t + half, j], TS[t + half, j] = TC[t, j], -TS[t, j]
        for t in range(N):
            for j in range(J):
                if not const[j]:
                    qv[j], qd[j], cq[j], sq[j] = TQ[t, j], TD[t, j], TC[t, j], TS[t, j]
            for k in range(K):
                L = length[k]
                for e in range(strips[k]):
                    # position and flapping velocity (per group) in body axes: inward pass
                    px, py, pz = 0.0, radius[k, e], 0.0
                    sx, sy, sz = 0.0, 0.0, 0.0  # shoulder group
                    wx, wy, wz = 0.0, 0.0, 0.0  # wrist group
                    s_on, w_on = False, False  # a zero vector is not rotated
                    for i in range(L - 1, -1, -1):
                        kd = kind[k, i]
                        if kd == 0:
                            py += span[k, i]
                            continue
                        j = joint[k, i]
                        a = axis[k, i]
                        dx, dy, dz = 0.0, 0.0, 0.0
                        if kd == 2:
                            if a == 0:
                                px += qv[j]
                                dx = qd[j]
                            elif a == 1:
                                py += qv[j]
                                dy = qd[j]
                            else:
                                pz += qv[j]
                                dz = qd[j]
                        else:
                            c, s = cq[j], -sq[j]
                            px, py, pz = _rot(a, c, s, px, py, pz)
                            if s_on:
                                sx, sy, sz = _rot(a, c, s, sx, sy, sz)
                            if w_on:
                                wx, wy, wz = _rot(a, c, s, wx, wy, wz)
                            w = qd[j]
                            if a == 0:
                                dx, dy, dz = 0.0, -w * pz, w * py
                            elif a == 1:
                                dx, dy, dz = w * pz, 0.0, -w * px
                            else:
                                dx, dy, dz = -w * py, w * px, 0.0
                        if group[k, i] == 0:
                            sx, sy, sz = sx + dx, sy + dy, sz + dz
                            s_on = True
                        else:
                            wx, wy, wz = wx + dx, wy + dy, wz + dz
                            w_on = True
                    fx_, fy_, fz_ = sx + wx, sy + wy, sz + wz  # flapping velocity
                    vx, vy, vz = ax + fx_, ay + fy_, az + fz_
                    if rotating:  # omega x r, r from the torso origin
                        vx += rate[b, 1] * pz - rate[b, 2] * py
                        vy += rate[b, 2] * px - rate[b, 0] * pz
                        vz += rate[b, 0] * py - rate[b, 1] * px
                    for i in range(L):
                        if kind[k, i] == 1:
                            j = joint[k, i]
                            vx, vy, vz = _rot(axis[k, i], cq[j], sq[j], vx, vy, vz)
                    ar = area[k, e]
                    if L < kind.shape[1] and kind[k, L] == 3:  # the area follows a joint
                        ar *= 1.0 - 0.5 * span[k, L] * (1.0 - cq[joint[k, L]])
                    gx, gz = _polar_force(polar, coeffs, vx, vz, ar, rho)
                    gy = 0.0
                    for i in range(L - 1, -1, -1):
                        if kind[k, i] == 1:
                            j = joint[k, i]
                            gx, gy, gz = _rot(axis[k, i], cq[j], -sq[j], gx, gy, gz)
                    # earth axes (body -> earth: the pitch rotation transposed)
                    fxs[k] += cp * gx + sp * gz
                    fys[k] += gy
                    fzs[k] += -sp * gx + cp * gz
                    ps[k] -= gx * fx_ + gy * fy_ + gz * fz_
                    if positive:
                        hp[t, 0] -= gx * fx_ + gy * fy_ + gz * fz_
                        hk[t, 0] += 0.5 * wmass[k] * (fx_ * fx_ + fy_ * fy_ + fz_ * fz_)
                    j0 -= gx * sx + gy * sy + gz * sz
                    j1 -= gx * wx + gy * wy + gz * wz
        for k in range(K):
            F[b, k, 0] = fxs[k] / N
            F[b, k, 1] = fys[k] / N
            F[b, k, 2] = fzs[k] / N
            P[b, k] = ps[k] / N
        JP[b, 0] = j0 / N
        JP[b, 1] = j1 / N
        if positive:
            _positive_part(hp, hk, dmat, res)
            PP[b] = res[0]


@_jit
def _means_kernel(
    lo,
    hi,
    pitch,
    speed,
    climb,
    air_earth,
    amp,
    phase,
    bias,
    const,
    phases,
    half,
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
    F,
    P,
    JP,
    PP,
    wmass,
    dmat,
    positive,
):
    """Cycle means of rows [lo, hi) into F, P, JP (a body that does not rotate), and
    when ``positive`` each row's positive shaft power into PP (panel masses ``wmass``,
    spectral d/dt ``dmat``: :mod:`birdsim.physics.kernel_shaft`)."""
    _means_rate_kernel(
        lo,
        hi,
        pitch,
        speed,
        climb,
        air_earth,
        amp,
        phase,
        bias,
        const,
        phases,
        half,
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
        F,
        P,
        JP,
        PP,
        wmass,
        dmat,
        positive,
        np.zeros((1, 3)),
        False,
    )
