"""The fused kernel for models whose panel areas follow a joint (m5's folding hand):
the same chain walk as :mod:`birdsim.physics.kernel`, with each element's area scaled by
``1 - lambda (1 - cos q) / 2`` of its panel's fold joint (:func:`birdsim.physics.m5.area_factor`).

Kept apart from the general kernel so that its code paths stay untouched: the fold is
encoded as one extra chain column per panel (code 3 at index ``length[k]``: the joint
in ``joint``, ``lambda`` in ``span``), which only these kernels read.
:func:`means` and :func:`means_and_gradients` serve every model: without area folds they
are :func:`birdsim.physics.kernel.means` and ``means_and_gradients``.
"""

from __future__ import annotations

import functools
import math
from dataclasses import replace

import numpy as np

from birdsim.physics import kernel
from birdsim.physics.bird import Bird
from birdsim.physics.jit import jit as _jit
from birdsim.physics.kernel import _polar_force, _rot
from birdsim.physics.kinematics import KinematicModel

_FOLD = 3  # chain element code of an area fold (after the chain's last element)


def folds(m: KinematicModel) -> bool:
    """True when a panel's area follows a joint (these kernels are needed)."""
    return any(name is not None for name in m.area_folds)


@functools.lru_cache(maxsize=64)
def setup(m: KinematicModel, bird: Bird) -> kernel.Setup:
    """:func:`birdsim.physics.kernel.setup` plus the area-fold column of each panel."""
    st = kernel.setup(m, bird)
    if not folds(m):
        return st
    K, L = st.kind.shape
    kind, joint, axis, group = (np.zeros((K, L + 1), dtype=np.int64) for _ in range(4))
    span = np.zeros((K, L + 1))
    for new, old in ((kind, st.kind), (joint, st.joint), (axis, st.axis), (group, st.group)):
        new[:, :L] = old
    span[:, :L] = st.span
    for k, name in enumerate(m.area_folds):
        if name is not None:
            n = st.length[k]
            kind[k, n], joint[k, n] = _FOLD, st.joint_names.index(name)
            span[k, n] = bird.hand_fold_area_loss
    return replace(st, kind=kind, joint=joint, axis=axis, group=group, span=span)


def compiled(m: KinematicModel) -> tuple:
    """``(means_kernel, grad_kernel)`` for ``m``: the fold kernels or the general ones."""
    if folds(m):
        from birdsim.physics.kernel_fold_dual import _fold_grad_kernel

        return _fold_means_kernel, _fold_grad_kernel
    from birdsim.physics.kernel_dual import _grad_kernel

    return kernel._means_kernel, _grad_kernel


def means(
    m: KinematicModel,
    flat: dict[str, np.ndarray],
    speed: np.ndarray,
    climb: np.ndarray,
    air_earth: np.ndarray,
    bird: Bird,
    phases: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """:func:`birdsim.physics.kernel.means` for every model (area folds included)."""
    if not folds(m):
        return kernel.means(m, flat, speed, climb, air_earth, bird, phases)
    if not kernel.available() or not kernel.supported(bird):
        return None
    st = setup(m, bird)
    amp, phase, bias, const = kernel.joint_coefficients(m, flat, bird)
    c = np.ascontiguousarray
    B, K = len(speed), len(st.length)
    F, P, JP = np.zeros((B, K, 3)), np.zeros((B, K)), np.zeros((B, 2))
    args = (
        c(flat["pitch"], dtype=float),
        c(speed, dtype=float),
        c(climb, dtype=float),
        c(air_earth, dtype=float),
        amp,
        phase,
        bias,
        const,
        c(phases, dtype=float),
        kernel._half(phases),
        float(bird.omega),
        float(bird.rho),
        *geometry(st),
        F,
        P,
        JP,
    )
    if not kernel._run(_fold_means_kernel, B, args):
        return None
    return F, P, JP[:, [kernel._GROUPS.index(g) for g in st.groups]]


def means_and_gradients(
    m: KinematicModel,
    flat: dict[str, np.ndarray],
    speed: np.ndarray,
    climb: np.ndarray,
    bird: Bird,
    phases: np.ndarray,
) -> tuple[np.ndarray, np.ndarray] | None:
    """:func:`birdsim.physics.kernel.means_and_gradients` for every model."""
    if not folds(m):
        return kernel.means_and_gradients(m, flat, speed, climb, bird, phases)
    if not kernel.available() or not kernel.supported(bird) or bird.induced_velocity:
        return None
    from birdsim.physics.kernel_fold_dual import _fold_grad_kernel

    st = setup(m, bird)
    amp, phase, bias, const = kernel.joint_coefficients(m, flat, bird)
    damp, dphase, dbias = kernel.joint_derivatives(m, bird)
    c = np.ascontiguousarray
    B, d = len(speed), len(m.param_names)
    out = np.zeros((B, 4, d + 1))
    args = (
        c(flat["pitch"], dtype=float),
        c(speed, dtype=float),
        c(climb, dtype=float),
        amp,
        phase,
        bias,
        const,
        damp,
        dphase,
        dbias,
        m.param_names.index("pitch"),
        c(phases, dtype=float),
        float(bird.omega),
        float(bird.rho),
        *geometry(st),
        out,
    )
    if not kernel._run(_fold_grad_kernel, B, args):
        return None
    return out[:, :, 0], out[:, :, 1:]


def geometry(st: kernel.Setup) -> tuple:
    """The chain and element arrays in the kernels' argument order."""
    return (
        st.kind,
        st.joint,
        st.axis,
        st.group,
        st.span,
        st.length,
        st.radius,
        st.area,
        st.strips,
        st.polar,
        st.coeffs,
    )


# ---- compiled code (a copy of kernel._means_kernel with the area fold) ------------------


@_jit
def _fold_means_kernel(
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
):
    J, N, K = amp.shape[1], phases.shape[0], kind.shape[0]
    ct, stt = np.cos(phases), np.sin(phases)
    for b in range(lo, hi):
        cph = np.cos(phase[b])
        sph = np.sin(phase[b])
        cq = np.empty(J)
        sq = np.empty(J)
        qv = np.empty(J)
        qd = np.empty(J)
        cp, sp = math.cos(pitch[b]), math.sin(pitch[b])
        # the body relative to the air, body axes: ((V, 0, -climb) - w_air) by the pitch
        rx, ry, rz = speed[b] - air_earth[b, 0], -air_earth[b, 1], -climb[b] - air_earth[b, 2]
        ax, ay, az = cp * rx - sp * rz, ry, sp * rx + cp * rz
        for j in range(J):
            if const[j]:
                qv[j], qd[j] = bias[b, j], 0.0
                cq[j], sq[j] = math.cos(bias[b, j]), math.sin(bias[b, j])
        fxs, fys, fzs = np.zeros(K), np.zeros(K), np.zeros(K)
        ps = np.zeros(K)
        j0, j1 = 0.0, 0.0
        # joint states at every sample; a joint without bias is odd over half a period
        # (q(t + pi) = -q(t)), so on an even periodic grid its second half is free
        TQ, TD, TC, TS = np.empty((N, J)), np.empty((N, J)), np.empty((N, J)), np.empty((N, J))
        for j in range(J):
            if const[j]:
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
                            sx, sy, sz = _rot(a, c, s, sx, sy, sz)
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
                        else:
                            wx, wy, wz = wx + dx, wy + dy, wz + dz
                    fx_, fy_, fz_ = sx + wx, sy + wy, sz + wz  # flapping velocity
                    vx, vy, vz = ax + fx_, ay + fy_, az + fz_
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
                    j0 -= gx * sx + gy * sy + gz * sz
                    j1 -= gx * wx + gy * wy + gz * wz
        for k in range(K):
            F[b, k, 0] = fxs[k] / N
            F[b, k, 1] = fys[k] / N
            F[b, k, 2] = fzs[k] / N
            P[b, k] = ps[k] / N
        JP[b, 0] = j0 / N
        JP[b, 1] = j1 / N
