"""The fused wingbeat kernel: cycle means (and their exact gradients) in one pass per
sample, compiled by numba, parallel over parameter sets.

The numpy path of :mod:`birdsim.physics.cycle` stays the readable reference and the test
oracle; this module evaluates the same physics sample by sample with scalars, no array
temporaries, on every core (``prange`` over parameter sets).  The model is data: each
panel's chain (hinges, slides, the wrist offset) is encoded as small integer arrays and
walked at run time, so one compiled kernel serves every model, strip count and bird.

:func:`means` returns the cycle means per panel; :func:`means_and_gradients` adds the
exact derivatives of the means with respect to every wingbeat parameter, by forward-mode
dual numbers carried through the same chain (no finite differences).

Where numba is missing or its compilation fails, :func:`available` is False (one warning
line) and callers use the numpy path.  Compiled code is cached on disk (``cache=True``:
``__pycache__`` beside this file, or numba's user-wide cache where that is read-only).
"""

from __future__ import annotations

import math
import multiprocessing
import os
import warnings
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numpy as np

from birdsim.physics.aero import RoboflyPolar, SeedPolar
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import Joint, KinematicModel, Offset, strip_positions

try:  # numba is a dependency, but a machine without a working JIT still runs (numpy)
    import numba
    from numba import njit
except Exception:  # pragma: no cover - exercised through _disable in the tests
    numba = None

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


def _run(kernel, B: int, args: tuple) -> bool:
    """Run ``kernel(lo, hi, *args)`` over rows [0, B) on :func:`threads` threads; False
    (after one warning line) if the JIT fails."""
    try:
        n = threads()
        if n == 1 or B <= CHUNK:
            kernel(0, B, *args)
            return True
        pool = _POOL.get(n) or _POOL.setdefault(n, ThreadPoolExecutor(n, thread_name_prefix="birdsim-kernel"))
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
    return Setup(kind, joint, axis, group, span, length, radius, area, strips, polar, coeffs, groups, names)


def joint_coefficients(m: KinematicModel, flat: dict[str, np.ndarray], bird: Bird) -> tuple[np.ndarray, ...]:
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
        warnings.warn(f"birdsim: the fused kernel is unavailable ({reason}); using the numpy path", RuntimeWarning, stacklevel=3)


def means(
    m: KinematicModel,
    flat: dict[str, np.ndarray],
    speed: np.ndarray,
    climb: np.ndarray,
    air_earth: np.ndarray,
    bird: Bird,
    phases: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """Cycle means per panel for flat (B,) parameter arrays, or None where the kernel
    cannot run (the caller then uses numpy).

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
        c(flat["pitch"], dtype=float), c(speed, dtype=float), c(climb, dtype=float), c(air_earth, dtype=float),
        amp, phase, bias, const, c(phases, dtype=float), float(bird.omega), float(bird.rho),
        st.kind, st.joint, st.axis, st.group, st.span, st.length, st.radius, st.area, st.strips, st.polar, st.coeffs,
        F, P, JP,
    )
    if not _run(_means_kernel, B, args):
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
    damp, dphase, dbias = joint_derivatives(m, bird)
    ip = m.param_names.index("pitch")
    c = np.ascontiguousarray
    B, d = len(speed), len(m.param_names)
    out = np.zeros((B, 4, d + 1))
    args = (
        c(flat["pitch"], dtype=float), c(speed, dtype=float), c(climb, dtype=float),
        amp, phase, bias, const, damp, dphase, dbias, ip, c(phases, dtype=float), float(bird.omega), float(bird.rho),
        st.kind, st.joint, st.axis, st.group, st.span, st.length, st.radius, st.area, st.strips, st.polar, st.coeffs,
        out,
    )
    if not _run(_grad_kernel, B, args):
        return None
    return out[:, :, 0], out[:, :, 1:]


# ---- compiled code --------------------------------------------------------------------
# Conventions as in frames.rotate: the passive Table 2 rotation about `axis` with (c, s);
# the way back passes -s.  Values only here; the dual-number version follows.

if numba is not None:
    # fused multiply-add and no signed zeros only: NaN and infinity checks stay (no
    # 'nnan'/'ninf'), exact libm functions (no 'afn')
    _FAST = {"contract", "nsz"}
    _jit = njit(cache=True, nogil=True, error_model="numpy", fastmath=_FAST)
else:  # pragma: no cover

    def _jit(f):
        return f


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
def _means_kernel(
    lo, hi, pitch, speed, climb, air_earth, amp, phase, bias, const, phases, omega, rho,
    kind, joint, axis, group, span, length, radius, area, strips, polar, coeffs, F, P, JP,
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
        for t in range(N):
            for j in range(J):
                if not const[j]:
                    # sin and cos of (omega t + phase) by the addition theorem
                    sarg = stt[t] * cph[j] + ct[t] * sph[j]
                    carg = ct[t] * cph[j] - stt[t] * sph[j]
                    q = amp[b, j] * sarg + bias[b, j]
                    qv[j] = q
                    qd[j] = (amp[b, j] * omega) * carg
                    cq[j], sq[j] = math.cos(q), math.sin(q)
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
def _grad_kernel(
    lo, hi, pitch, speed, climb, amp, phase, bias, const, damp, dphase, dbias, ip, phases, omega, rho,
    kind, joint, axis, group, span, length, radius, area, strips, polar, coeffs, out,
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
        vs = np.zeros((3, D))
        vw = np.zeros((3, D))
        vf = np.zeros((3, D))
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
                    vs[:, :] = 0.0
                    vw[:, :] = 0.0
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
                            _drot(vs, a, cq[j], sq[j], -1.0)
                            _drot(vw, a, cq[j], sq[j], -1.0)
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
                        grp = vs if group[k, il] == 0 else vw
                        if True:
                            for cc in range(3):
                                for i in range(D):
                                    grp[cc, i] += dv[cc, i]
                    for cc in range(3):
                        for i in range(D):
                            vf[cc, i] = vs[cc, i] + vw[cc, i]
                            v[cc, i] = A[cc, i] + vf[cc, i]
                    for il in range(L):
                        if kind[k, il] == 1:
                            j = joint[k, il]
                            _drot(v, axis[k, il], cq[j], sq[j], 1.0)
                    _dpolar(polar, coeffs, v[0], v[2], area[k, e], rho, gx, gz)
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
