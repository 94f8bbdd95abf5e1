"""The wings' prescription in compiled code: :meth:`WingbeatSchedule.prescribe` for the
models whose joint coefficients are single parameters times constants, plus a constant
(base, m1-m5).

The reference chain (:func:`birdsim.flight.playback.joint_derivatives`, then
:func:`birdsim.mujoco.driver.wing_arrays` with :func:`birdsim.mujoco.ball.ball_state`)
runs some hundred numpy calls on 16-sample arrays per control step; :func:`prescribe`
does the same per-sample formulas in one numba call: joint angles ``a sin(phase + c) + b``
with the coefficient rates by the reference's central difference along p' and p''
(``h = 1e-6``: the same round-off), the attitude loop's shoulder offsets, the shoulder's
ball joint composed as :func:`ball_state` composes it, the hinges and the heave.  The
floating-point operations are the reference's in its order but for the summation order
of two 3-term sums (numpy's ``einsum`` and stacked ``matmul`` in the ball joint):
``tests/test_fast_flight.py`` holds the rows to 1e-13 of the reference.

:func:`spec` reads the coefficients' form from ``kin.joint_motion`` itself (each
amplitude, phase and bias a constant, ``scale * p[i]`` or ``scale * p[i] + const``: m5's
fold phase ``-p - pi/2``); a model of another form gets None and keeps the reference
path, as does a non-finite input (the reference names the joint).  m5's elbow and wrist
sweep are two more hinges, its supination is added to the wrist twist's hinge as
:func:`birdsim.mujoco.driver.wing_arrays` adds it (``driver.SAME_AXIS``).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from birdsim.mujoco.ball import _skew
from birdsim.mujoco.driver import FOLD_HINGES, HINGES, SHOULDER, _plan
from birdsim.physics.bird import Bird
from birdsim.physics.jit import numba
from birdsim.physics.kinematics import KinematicModel

#: the compiled prescription is used where a spec exists (False: the reference path)
ENABLED = True
#: joint order of the kernel: heave, the shoulder's four (driver.SHOULDER), the hinges
#: (m4's two, m5's two), m5's supination (onto the wrist twist's hinge)
JOINT_ORDER = ("heave",) + SHOULDER + HINGES + FOLD_HINGES + ("supination",)
_SUPINATION = JOINT_ORDER.index("supination")
_SWEEP, _FLAP = JOINT_ORDER.index("sweep"), JOINT_ORDER.index("flap")
#: the reference's difference step (playback.joint_derivatives)
DIFF_STEP = 1e-6

_SPECS: dict[tuple, object] = {}


def spec(kin: KinematicModel, bird: Bird) -> tuple | None:
    """(present (J,), index (J, 3), scale (J, 3), const (J, 3), affine (J, 3)) of each
    joint's amplitude, phase and bias: ``scale * p[index]`` (``+ const`` where affine is
    1), or ``const`` where index is -1; None when a coefficient has another form or a
    joint is outside :data:`JOINT_ORDER`."""
    key = (kin.name, id(bird))
    hit = _SPECS.get(key)
    if hit is not None and hit[0] is bird:
        return hit[1]
    names = kin.param_names
    n = len(names)
    probe = np.array([1.0, 2.0, -0.7])

    def motion(i: int | None) -> dict:
        return kin.joint_motion(
            {k: probe.copy() if j == i else np.zeros(3) for j, k in enumerate(names)}, bird
        )

    base = motion(None)
    per = [motion(i) for i in range(n)]
    out = None
    if set(base) <= set(JOINT_ORDER):
        J = len(JOINT_ORDER)
        present = np.zeros(J, dtype=np.int64)
        index = -np.ones((J, 3), dtype=np.int64)
        scale = np.zeros((J, 3))
        const = np.zeros((J, 3))
        affine = np.zeros((J, 3), dtype=np.int64)
        ok = True
        for j, joint in enumerate(JOINT_ORDER):
            if joint not in base:
                continue
            present[j] = 1
            for f, field in enumerate(("amp", "phase", "bias")):
                v0 = getattr(base[joint], field)
                if type(v0) is float and all(type(getattr(m[joint], field)) is float for m in per):
                    const[j, f] = v0
                    continue
                a0 = np.broadcast_to(np.asarray(v0, dtype=float), probe.shape)
                c0 = float(a0[0])
                if np.any(a0 != c0):
                    ok = False
                    continue
                hits = [
                    i for i in range(n) if not np.array_equal(getattr(per[i][joint], field), a0)
                ]
                if len(hits) != 1:
                    ok = False
                    continue
                got = np.asarray(getattr(per[hits[0]][joint], field), dtype=float)
                if c0 == 0.0:  # scale * p
                    s = float(got[0])
                    ok = ok and np.array_equal(got, s * probe)
                else:  # scale * p + const, the reference's numbers for these probes
                    raw = float((got[0] - c0) / probe[0])
                    s = next(
                        (c for c in (raw, round(raw, 9)) if np.array_equal(got, c * probe + c0)),
                        math.nan,
                    )
                    ok = ok and math.isfinite(s)
                    const[j, f], affine[j, f] = c0, 1
                index[j, f], scale[j, f] = hits[0], s
        out = (present, index, scale, const, affine) if ok else None
    if len(_SPECS) > 64:
        _SPECS.clear()
    _SPECS[key] = (bird, out)
    return out


def _coef(p, t, idx, scale, const, aff):
    if idx < 0:
        return const
    if aff:
        return scale * p[t, idx] + const
    return scale * p[t, idx]


def _shifted(p, dp, t, idx, scale, const, aff, h, step):
    """The reference's central difference of a coefficient along dp."""
    if idx < 0:
        return (const - const) / step
    if aff:
        hi = scale * (p[t, idx] + h * dp[t, idx]) + const
        return (hi - (scale * (p[t, idx] - h * dp[t, idx]) + const)) / step
    return (scale * (p[t, idx] + h * dp[t, idx]) - scale * (p[t, idx] - h * dp[t, idx])) / step


def _side(
    times, p, dp, ddp, sh, shd, shdd, s0, use_sh, present, index, scale, const, affine,
    omega, plan, axes, kmat, kkmat, qpos, qvel, qacc,
):  # fmt: skip
    """One wing's joints into qpos/qvel/qacc rows; ``sh*``: shoulder offsets (T, 4),
    this side's (sweep, dihedral) at columns s0, s0 + 1."""
    J = present.shape[0]
    h = 1e-6
    step = 2 * h
    ang = np.zeros(J)
    rate = np.zeros(J)
    acc = np.zeros(J)
    eye = np.eye(3)
    for t in range(times.shape[0]):
        phase = omega * times[t]
        for j in range(J):
            if present[j] == 0:
                ang[j] = rate[j] = acc[j] = 0.0
                continue
            a = _coef(p, t, index[j, 0], scale[j, 0], const[j, 0], affine[j, 0])
            c = _coef(p, t, index[j, 1], scale[j, 1], const[j, 1], affine[j, 1])
            b = _coef(p, t, index[j, 2], scale[j, 2], const[j, 2], affine[j, 2])
            da = _shifted(p, dp, t, index[j, 0], scale[j, 0], const[j, 0], affine[j, 0], h, step)
            dc = _shifted(p, dp, t, index[j, 1], scale[j, 1], const[j, 1], affine[j, 1], h, step)
            db = _shifted(p, dp, t, index[j, 2], scale[j, 2], const[j, 2], affine[j, 2], h, step)
            dda = _shifted(p, ddp, t, index[j, 0], scale[j, 0], const[j, 0], affine[j, 0], h, step)
            ddc = _shifted(p, ddp, t, index[j, 1], scale[j, 1], const[j, 1], affine[j, 1], h, step)
            ddb = _shifted(p, ddp, t, index[j, 2], scale[j, 2], const[j, 2], affine[j, 2], h, step)
            arg = phase + c
            sn, cs = math.sin(arg), math.cos(arg)
            ang[j] = a * sn + b
            rate[j] = da * sn + a * (omega + dc) * cs + db
            w = omega + dc
            acc[j] = dda * sn + 2.0 * da * w * cs + a * ddc * cs - a * w * w * sn + ddb
        if use_sh:
            ang[1 + 0] = ang[1 + 0] + 1.0 * sh[t, s0]
            rate[1 + 0] = rate[1 + 0] + 1.0 * shd[t, s0]
            acc[1 + 0] = acc[1 + 0] + 1.0 * shdd[t, s0]
            ang[1 + 2] = ang[1 + 2] + -1.0 * sh[t, s0 + 1]
            rate[1 + 2] = rate[1 + 2] + -1.0 * shd[t, s0 + 1]
            acc[1 + 2] = acc[1 + 2] + -1.0 * shdd[t, s0 + 1]
        # heave
        qpos[t, plan[0]] = ang[0]
        qvel[t, plan[1]] = rate[0]
        qacc[t, plan[1]] = acc[0]
        # the shoulder's ball joint (ball.ball_state): quaternion
        half = 0.5 * ang[1]
        w = math.cos(half)
        sn = math.sin(half)
        x, y, z = sn * axes[0, 0], sn * axes[0, 1], sn * axes[0, 2]
        for k in range(1, 4):
            half = 0.5 * ang[1 + k]
            w2 = math.cos(half)
            sn = math.sin(half)
            x2, y2, z2 = sn * axes[k, 0], sn * axes[k, 1], sn * axes[k, 2]
            w, x, y, z = (
                w * w2 - x * x2 - y * y2 - z * z2,
                w * x2 + x * w2 + y * z2 - z * y2,
                w * y2 - x * z2 + y * w2 + z * x2,
                w * z2 + x * y2 - y * x2 + z * w2,
            )
        qpos[t, plan[2]], qpos[t, plan[2] + 1] = w, x
        qpos[t, plan[2] + 2], qpos[t, plan[2] + 3] = y, z
        # child-frame axes v_k = B^T a_k, B = A_{k+1} .. A_n (from the inside out)
        v = np.zeros((4, 3))
        bm = np.zeros((3, 3))
        rot = np.zeros((3, 3))
        for k in range(3, -1, -1):
            if k == 3:
                for i in range(3):
                    v[k, i] = axes[k, i]
            else:
                for i in range(3):
                    v[k, i] = bm[0, i] * axes[k, 0] + bm[1, i] * axes[k, 1] + bm[2, i] * axes[k, 2]
            s, c = math.sin(ang[1 + k]), math.cos(ang[1 + k])
            for i in range(3):
                for jj in range(3):
                    rot[i, jj] = eye[i, jj] + s * kmat[k, i, jj] + (1.0 - c) * kkmat[k, i, jj]
            if k == 3:
                for i in range(3):
                    for jj in range(3):
                        bm[i, jj] = rot[i, jj]
            else:
                nb = np.zeros((3, 3))
                for i in range(3):
                    for jj in range(3):
                        nb[i, jj] = (
                            rot[i, 0] * bm[0, jj] + rot[i, 1] * bm[1, jj] + rot[i, 2] * bm[2, jj]
                        )
                bm[:, :] = nb
        al0 = al1 = al2 = 0.0
        o0 = o1 = o2 = 0.0
        for k in range(3, -1, -1):
            r = rate[1 + k]
            q2 = acc[1 + k]
            v0, v1, v2 = v[k, 0], v[k, 1], v[k, 2]
            c0 = o1 * v2 - o2 * v1
            c1 = o2 * v0 - o0 * v2
            c2 = o0 * v1 - o1 * v0
            al0 = al0 + (v0 * q2 - r * c0)
            al1 = al1 + (v1 * q2 - r * c1)
            al2 = al2 + (v2 * q2 - r * c2)
            o0, o1, o2 = o0 + v0 * r, o1 + v1 * r, o2 + v2 * r
        qvel[t, plan[3]], qvel[t, plan[3] + 1], qvel[t, plan[3] + 2] = o0, o1, o2
        qacc[t, plan[3]], qacc[t, plan[3] + 1], qacc[t, plan[3] + 2] = al0, al1, al2
        # hinges (wrist flap, wrist twist, elbow, wrist sweep); m5's supination onto the
        # wrist twist's (driver.SAME_AXIS: the twist's series plus the supination's)
        if present[_SUPINATION] != 0:
            ang[6] = ang[6] + ang[_SUPINATION]
            rate[6] = rate[6] + rate[_SUPINATION]
            acc[6] = acc[6] + acc[_SUPINATION]
        for k in range(4):
            qa, da_ = plan[4 + 2 * k], plan[5 + 2 * k]
            if qa >= 0:
                qpos[t, qa] = ang[5 + k]
                qvel[t, da_] = rate[5 + k]
                qacc[t, da_] = acc[5 + k]


def _prescribe(
    times, p, dp, ddp, pl, dpl, ddpl, sh, shd, shdd, use_sh, present, index, scale, const,
    affine, omega, plans, axes, kmat, kkmat, qpos, qvel, qacc,
):  # fmt: skip
    for side in range(2):
        if side == 0:
            a, b, c = p, dp, ddp
        else:
            a, b, c = pl, dpl, ddpl
        _side(
            times, a, b, c, sh, shd, shdd, 2 * side, use_sh, present, index, scale, const,
            affine, omega, plans[side], axes[side], kmat[side], kkmat[side], qpos, qvel, qacc,
        )  # fmt: skip


def _all_finite(*arrays):
    """Whether every entry of the 2-D arrays is finite."""
    for a in arrays:
        for i in range(a.shape[0]):
            for j in range(a.shape[1]):
                if not np.isfinite(a[i, j]):
                    return False
    return True


if numba is not None:
    all_finite = numba.njit(cache=True)(_all_finite)
    _coef = numba.njit(cache=True)(_coef)
    _shifted = numba.njit(cache=True)(_shifted)
    _side = numba.njit(cache=True)(_side)
    prescribe_kernel = numba.njit(cache=True)(_prescribe)
else:  # pragma: no cover
    prescribe_kernel = None
    all_finite = _all_finite

_GEOMETRY: dict[int, tuple] = {}


def geometry(m: mujoco.MjModel) -> tuple | None:
    """(plans (2, 12): heave q/dof, ball q/dof, the hinges' q/dof or -1 (wrist flap,
    wrist twist, elbow, wrist sweep); axes (2, 4, 3), their cross-product matrices k and
    k @ k (2, 4, 3, 3)) per side, right first."""
    hit = _GEOMETRY.get(id(m))
    if hit is not None and hit[0] is m:
        return hit[1]
    plan = _plan(m)
    plans, axes, ks, kks = [], [], [], []
    for side in ("r", "l"):
        hq, hd, ax, (sq, sd), hinges = plan[side]
        row = [hq, hd, sq, sd]
        for _, adr in hinges:  # driver's order: HINGES + FOLD_HINGES, as JOINT_ORDER
            row += [-1, -1] if adr is None else [adr[0], adr[1]]
        plans.append(row)
        axes.append(np.array(ax, dtype=float))
        ks.append(np.array([_skew(a)[0] for a in ax]))
        kks.append(np.array([_skew(a)[1] for a in ax]))
    out = (np.array(plans, dtype=np.int64), np.array(axes), np.array(ks), np.array(kks))
    if len(_GEOMETRY) > 64:
        _GEOMETRY.clear()
    _GEOMETRY[id(m)] = (m, out)
    return out


def wing_rows(
    m: mujoco.MjModel,
    kin: KinematicModel,
    bird: Bird,
    times: np.ndarray,
    p: np.ndarray,
    dp: np.ndarray,
    ddp: np.ndarray,
    left: tuple | None,
    shoulder: tuple | None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """qpos (T, nq), qvel, qacc (T, nv) of both wings (root entries at rest / zero) as
    the reference computes them, or None where the compiled path does not apply."""
    if not ENABLED or prescribe_kernel is None:
        return None
    sp = spec(kin, bird)
    geo = geometry(m)
    if sp is None or geo is None:
        return None
    t = len(times)
    pl = (p, dp, ddp) if left is None else left
    f = np.ascontiguousarray
    use_sh = shoulder is not None
    sh = shoulder if use_sh else (np.zeros((t, 4)),) * 3
    qpos = np.empty((t, m.nq))
    qpos[:] = m.qpos0  # np.tile(m.qpos0, (t, 1))
    qvel = np.zeros((t, m.nv))
    qacc = np.zeros((t, m.nv))
    prescribe_kernel(
        f(times, dtype=float), f(p), f(dp), f(ddp), *(f(a) for a in pl), *(f(a) for a in sh),
        use_sh, *sp, float(bird.omega), *geo, qpos, qvel, qacc,
    )  # fmt: skip
    if not all_finite(qpos, qvel, qacc):
        return None  # the reference names the joint
    return qpos, qvel, qacc


__all__ = ["ENABLED", "JOINT_ORDER", "geometry", "prescribe_kernel", "spec", "wing_rows"]
