"""The fused wingbeat kernel: cycle means (and their exact gradients) in one pass per
sample, compiled by numba, spread over the cores in tasks of parameter sets.

The numpy path of :mod:`birdsim.physics.cycle` stays the readable reference and the test
oracle; this module evaluates the same physics sample by sample with scalars, no array
temporaries, on every core (tasks of :data:`CHUNK` parameter sets on a thread pool;
the compiled code releases the GIL).  The model is data: each
panel's chain (hinges, slides, the wrist offset) is encoded as small integer arrays and
walked at run time, so one compiled kernel serves every model, strip count and bird.

:func:`means` returns the cycle means per panel; :func:`means_and_gradients` adds the
exact derivatives of the means with respect to every wingbeat parameter, by forward-mode
dual numbers carried through the same chain (:mod:`birdsim.physics.kernel_dual`).

Where numba is missing or its compilation fails, :func:`available` is False (one warning
line) and callers use the numpy path.  Compiled code is cached on disk (``cache=True``:
``__pycache__`` beside this file, or numba's user-wide cache where that is read-only).
"""

from __future__ import annotations

import functools
import math
import multiprocessing
import os
import warnings
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numpy as np

from birdsim.physics.aero import RoboflyPolar, SeedPolar
from birdsim.physics.bird import Bird
from birdsim.physics.jit import jit as _jit
from birdsim.physics.jit import numba
from birdsim.physics.kinematics import Joint, KinematicModel, Offset, strip_positions

_STATE = {"ok": numba is not None, "warned": False}

#: Parameter sets per task when a batch is spread over threads (each task is one call
#: of a compiled kernel, which releases the GIL).  Smaller batches run in the caller.
CHUNK = 128


def threads() -> int:
    """Threads a batch is spread over: ``BIRDSIM_THREADS`` if set, else every core;
    1 inside a worker process (a table build already runs one process per core)."""
    env = os.environ.get("BIRDSIM_THREADS", "")
    if env.isdigit() and int(env) > 0:
        return int(env)
    if multiprocessing.parent_process() is not None:
        return 1
    return max(1, os.cpu_count() or 1)


_POOL: dict[int, ThreadPoolExecutor] = {}


def _half(phases: np.ndarray) -> int:
    """N/2 when the samples are an even periodic grid (phase t + N/2 is phase t + pi),
    else 0 (the appendix grid with both end points)."""
    n = len(phases)
    if n % 2 or n < 2 or not np.isclose(phases[n // 2] - phases[0], np.pi, rtol=0, atol=1e-12):
        return 0
    return n // 2


def _run(kernel, B: int, args: tuple) -> bool:
    """Run ``kernel(lo, hi, *args)`` over rows [0, B) on :func:`threads` threads; False
    (after one warning line) if the JIT fails."""
    try:
        n = threads()
        if n == 1 or B <= CHUNK:
            kernel(0, B, *args)
            return True
        pool = _POOL.get(n) or _POOL.setdefault(
            n, ThreadPoolExecutor(n, thread_name_prefix="birdsim-kernel")
        )
        bounds = range(0, B, CHUNK)
        for f in [pool.submit(kernel, lo, min(lo + CHUNK, B), *args) for lo in bounds]:
            f.result()
        return True
    except Exception as exc:  # noqa: BLE001 - a JIT failure must not stop the simulator
        first = str(exc).splitlines()[0] if str(exc) else ""
        _disable(f"{type(exc).__name__}: {first}")
        return False


# chain element codes
_OFFSET, _HINGE, _SLIDE = 0, 1, 2
_AXES = {"x": 0, "y": 1, "z": 2}
_GROUPS = ("shoulder", "wrist")
# polar codes
_SEED, _ROBOFLY = 0, 1


@dataclass(frozen=True)
class Setup:
    """A model and a bird as the kernel's arrays (see :func:`setup`)."""

    kind: np.ndarray  # K x L chain element codes, body -> panel order
    joint: np.ndarray  # K x L joint index
    axis: np.ndarray  # K x L axis 0, 1, 2
    group: np.ndarray  # K x L group 0 (shoulder), 1 (wrist)
    span: np.ndarray  # K x L offset along y (offsets only)
    length: np.ndarray  # K chain lengths
    radius: np.ndarray  # K x S span positions of the elements
    area: np.ndarray  # K x S element areas
    strips: np.ndarray  # K number of elements
    polar: int
    coeffs: np.ndarray  # polar coefficients
    groups: tuple[str, ...]  # group names present in the model
    joint_names: tuple[str, ...]


def supported(bird: Bird) -> bool:
    """True when the kernel knows the bird's polar (seed or robofly, exact types)."""
    return type(bird.polar) in (SeedPolar, RoboflyPolar)


@functools.lru_cache(maxsize=64)
def setup(m: KinematicModel, bird: Bird) -> Setup:
    """Encode the chains of ``m`` for ``bird`` (geometry, strips, polar) as arrays."""
    panels = m.chain_with_geometry(bird)
    names = tuple(j.name for j in m.joints)
    K, L = len(panels), max(len(c) for c, _, _ in panels)
    kind, joint, axis, group = (np.zeros((K, L), dtype=np.int64) for _ in range(4))
    span = np.zeros((K, L))
    length = np.zeros(K, dtype=np.int64)
    elems = [strip_positions(s, bird.cp_span_fraction, bird.strips) for _, s, _ in panels]
    S = max(len(r) for r, _ in elems)
    radius, area = np.zeros((K, S)), np.zeros((K, S))
    strips = np.zeros(K, dtype=np.int64)
    present = set()
    for k, (chain, _, chord) in enumerate(panels):
        length[k] = len(chain)
        for i, el in enumerate(chain):
            if isinstance(el, Offset):
                kind[k, i], span[k, i] = _OFFSET, el.span
                continue
            assert isinstance(el, Joint)
            kind[k, i] = _HINGE if el.kind == "hinge" else _SLIDE
            joint[k, i], axis[k, i] = names.index(el.name), _AXES[el.axis]
            group[k, i] = _GROUPS.index(el.group)
            present.add(el.group)
        r, w = elems[k]
        strips[k] = len(r)
        radius[k, : len(r)] = r
        area[k, : len(r)] = w * chord
    if isinstance(bird.polar, SeedPolar):
        polar, coeffs = _SEED, np.array([bird.polar.cl_max, bird.polar.cd0, bird.polar.cd_max])
    else:
        polar, coeffs = _ROBOFLY, np.zeros(3)
    groups = tuple(g for g in _GROUPS if g in present)
    return Setup(
        kind, joint, axis, group, span, length, radius, area, strips, polar, coeffs, groups, names
    )


def joint_coefficients(
    m: KinematicModel, flat: dict[str, np.ndarray], bird: Bird
) -> tuple[np.ndarray, ...]:
    """Per parameter set (B) and joint (J): amplitude, phase, bias of the joint's sinusoid
    (exactly the values the numpy path uses) and whether the joint is constant."""
    names = tuple(j.name for j in m.joints)
    b = len(flat["pitch"])
    motion = m.joint_motion(flat, bird)
    amp, phase, bias = (np.zeros((b, len(names))) for _ in range(3))
    const = np.zeros(len(names), dtype=np.bool_)
    for j, name in enumerate(names):
        s = motion[name]
        amp[:, j], phase[:, j], bias[:, j] = s.amp, s.phase, s.bias
        const[j] = isinstance(s.amp, float) and s.amp == 0.0
    return amp, phase, bias, const


@functools.lru_cache(maxsize=64)
def joint_derivatives(m: KinematicModel, bird: Bird) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """d(amp, phase, bias)/d(param), J x d: every joint's sinusoid is affine in the parameters."""
    names = m.param_names
    d = len(names)

    def at(x: np.ndarray) -> tuple[np.ndarray, ...]:
        a, p, b, _ = joint_coefficients(m, {n: x[i : i + 1] for i, n in enumerate(names)}, bird)
        return a[0], p[0], b[0]

    zero = at(np.zeros(d))
    out = [np.zeros((len(zero[0]), d)) for _ in range(3)]
    for i in range(d):
        e = np.zeros(d)
        e[i] = 1.0
        for q, (v1, v0) in enumerate(zip(at(e), zero)):
            out[q][:, i] = v1 - v0
    return out[0], out[1], out[2]


def available() -> bool:
    """True while the compiled kernel can be used."""
    return _STATE["ok"]


def _disable(reason: str) -> None:
    _STATE["ok"] = False
    if not _STATE["warned"]:
        _STATE["warned"] = True
        warnings.warn(
            f"birdsim: the fused kernel is unavailable ({reason}); using the numpy path",
            RuntimeWarning,
            stacklevel=3,
        )


def means(
    m: KinematicModel,
    flat: dict[str, np.ndarray],
    speed: np.ndarray,
    climb: np.ndarray,
    air_earth: np.ndarray,
    bird: Bird,
    phases: np.ndarray,
    *,
    body_rate: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """Cycle means per panel for flat (B,) parameter arrays, or None where the kernel
    cannot run (the caller then uses numpy).  ``body_rate`` (B x 3, body axes, or None
    for none) adds ``omega x r`` to every element's air velocity.

    Returns:
        ``(force_earth B x K x 3, power B x K, joint_power B x G)`` (groups in
        :attr:`Setup.groups` order; seed earth axes, no body drag).
    """
    if not _STATE["ok"] or not supported(bird):
        return None
    st = setup(m, bird)
    amp, phase, bias, const = joint_coefficients(m, flat, bird)
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
        _half(phases),
        float(bird.omega),
        float(bird.rho),
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
        F,
        P,
        JP,
    )
    if body_rate is not None:  # the rotating body: same kernel, omega x r added
        args, fn = args + (c(body_rate, dtype=float), True), _means_rate_kernel
    else:
        fn = _means_kernel
    if not _run(fn, B, args):
        return None
    return F, P, JP[:, [_GROUPS.index(g) for g in st.groups]]


def means_and_gradients(
    m: KinematicModel,
    flat: dict[str, np.ndarray],
    speed: np.ndarray,
    climb: np.ndarray,
    bird: Bird,
    phases: np.ndarray,
) -> tuple[np.ndarray, np.ndarray] | None:
    """Right-wing mean force and power with their exact parameter gradients (no induced
    velocity, no body drag), or None where the kernel cannot run.

    Returns:
        ``(values B x 4, gradients B x 4 x d)``: rows Fx, Fy, Fz, P of the right wing
        (seed earth axes), columns of the gradient in ``m.param_names`` order.
    """
    if not _STATE["ok"] or not supported(bird) or bird.induced_velocity:
        return None
    st = setup(m, bird)
    amp, phase, bias, const = joint_coefficients(m, flat, bird)
    from birdsim.physics.kernel_dual import _grad_kernel

    damp, dphase, dbias = joint_derivatives(m, bird)
    ip = m.param_names.index("pitch")
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
        ip,
        c(phases, dtype=float),
        float(bird.omega),
        float(bird.rho),
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
        out,
    )
    if not _run(_grad_kernel, B, args):
        return None
    return out[:, :, 0], out[:, :, 1:]


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
    rate,
    rotating,
):
    """The means of :func:`_means_kernel` with a body rate (B x 3) when ``rotating``."""
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
                    if rotating:  # omega x r, r from the torso origin
                        vx += rate[b, 1] * pz - rate[b, 2] * py
                        vy += rate[b, 2] * px - rate[b, 0] * pz
                        vz += rate[b, 0] * py - rate[b, 1] * px
                    for i in range(L):
                        if kind[k, i] == 1:
                            j = joint[k, i]
                            vx, vy, vz = _rot(axis[k, i], cq[j], sq[j], vx, vy, vz)
                    gx, gz = _polar_force(polar, coeffs, vx, vz, area[k, e], rho)
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
):
    """Cycle means of rows [lo, hi) into F, P, JP (a body that does not rotate)."""
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
        np.zeros((1, 3)),
        False,
    )
