"""The aero callback's forces in compiled code (numba), for the compiled free-flight loop.

:class:`birdsim.mujoco.callback.AeroCallback` on Python floats, written again for numba:
the seed polar on one element per panel (``SeedPolar.force_scalar``), the body drag and
the tail (:func:`birdsim.mujoco.tail.tail_force`), with the same floating-point
operations in the same order, the MuJoCo calls (``mj_objectVelocity``, ``mj_applyFT``)
made through :mod:`birdsim.mujoco.capi`.  Two sums differ from the Python callback's in
order only (the tail's ``xmat @ f`` that numpy hands to BLAS is summed naively here):
round-off of one ulp in the tail's force (``tests/test_fast_flight.py``).

:func:`apply_aero` adds the forces to ``qfrc_passive``: called right after ``mj_step1``
(with no passive callback installed), it leaves ``qfrc_passive`` as the Python callback
leaves it inside ``mj_step1`` (MuJoCo's later stages in ``mj_step1`` do not read it).

:func:`supported` says which callbacks this covers (one element per panel, the seed
polar; m5's folding hand included: each hand site's area scaled by
:func:`birdsim.physics.m5.area_factor` of its wrist-sweep angle, as the callback's
``fold_area_scale``); the others keep the Python path.  Axes: MuJoCo world (x
forward, y left, z up); panel axes as the callback's (seed panel x = site x, seed panel
z = -site z).
"""

from __future__ import annotations

import math

import numpy as np

from birdsim.mujoco import capi
from birdsim.mujoco.callback import AeroCallback
from birdsim.mujoco.tail import SPREAD_MIN, TailControls, frame_into, plane_force, tail_frame
from birdsim.physics.aero import SeedPolar
from birdsim.physics.jit import numba

#: indices of :func:`parameters`' float array
RHO, CD0, CD_MAX, CL_MAX, DRAG_AREA, TAIL_B, TAIL_LENGTH, FOLD_LOSS = range(8)
#: indices of :func:`parameters`' int array (TAIL_BLAS, optional: an eighth entry 1 turns
#: the tail's force into world axes by BLAS, as the Python callback's ``xmat @ f`` does)
ENABLED, BODY_DRAG, TAIL, TORSO_SITE, TORSO_BODY, TAIL_SITE, TAIL_BODY, TAIL_BLAS = range(8)


def supported(cb: AeroCallback) -> bool:
    """Whether :func:`apply_aero` computes ``cb``'s forces: one element per panel, the
    seed polar itself (not a subclass); m5's folding hand included."""
    return capi.AVAILABLE and cb.single and cb._scalar and type(cb.bird.polar) is SeedPolar


def fold_addresses(cb: AeroCallback) -> np.ndarray:
    """Per site the qpos address of the joint whose angle scales its area (m5's wrist
    sweep), -1 where none (every site of the other models)."""
    if cb.fold_qpos is None:
        return -np.ones(len(cb.site_ids), dtype=np.int64)
    return np.ascontiguousarray(cb.fold_qpos, dtype=np.int64)


def parameters(cb: AeroCallback) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The callback's constants and switches for :func:`apply_aero`: (floats, ints,
    tail frame (3, 3): columns chord, span, normal in torso axes)."""
    ctl = cb.tail_controls if cb.tail else TailControls()
    elevation, spread, roll = ctl.clipped_values()
    floats, ints = constants(cb, spread)
    if frame_kernel is None:  # pragma: no cover
        return floats, ints, np.ascontiguousarray(tail_frame(TailControls(elevation, 1.0, roll)))
    frame = np.empty((3, 3))
    frame_kernel(elevation, roll, frame)
    return floats, ints, frame


frame_kernel = numba.njit(cache=True)(frame_into) if numba is not None else None


def constants(cb: AeroCallback, spread: float) -> tuple[np.ndarray, np.ndarray]:
    """(floats, ints) of :func:`parameters` for the tail's clipped ``spread``; the same
    arrays again while the callback's switches and the spread are unchanged (the control
    loop moves the tail's elevation and roll at every update, rarely its spread).  Read
    only: the kernels do not write them."""
    key = (cb.enabled, cb.body_drag, cb.tail, cb.tail_site, cb.torso_site, cb.torso_body, spread)
    hit = cb.__dict__.get("_aero_constants")
    if hit is not None and hit[0] == key and hit[1] is cb.bird:
        return hit[2]
    b, pol = cb.bird, cb.bird.polar
    spread = min(max(float(spread), SPREAD_MIN), 1.0)
    floats = np.array(
        [b.rho, pol.cd0, pol.cd_max, pol.cl_max, b.body_drag_area, b.tail_span * spread, 0.0]
        + [b.hand_fold_area_loss]
    )
    floats[TAIL_LENGTH] = b.tail_length if cb.tail else 0.0
    tail_site = cb.tail_site if cb.tail else -1
    ints = np.array(
        [int(cb.enabled), int(cb.body_drag), int(cb.tail), cb.torso_site, cb.torso_body]
        + [tail_site, cb.torso_body],
        dtype=np.int64,
    )
    cb.__dict__["_aero_constants"] = (key, b, (floats, ints))
    return floats, ints


def _wings(
    m, d, passive, site_ids, body_ids, site_xpos, site_xmat, areas, fold, qpos, wind, fl, vel,
    buf, zero,
):  # fmt: skip
    rho, cd0, cd_max, cl_max = fl[RHO], fl[CD0], fl[CD_MAX], fl[CL_MAX]
    w0, w1, w2 = wind[0], wind[1], wind[2]
    for k in range(site_ids.shape[0]):
        sid = site_ids[k]
        capi.mj_objectVelocity(m, d, capi.OBJ_SITE, sid, vel.ctypes.data, 0)
        l0, l1, l2 = vel[3] - w0, vel[4] - w1, vel[5] - w2
        x = site_xmat[sid]
        vx = l0 * x[0] + l1 * x[3] + l2 * x[6]
        vz = -(l0 * x[2] + l1 * x[5] + l2 * x[8])
        # SeedPolar.force_scalar
        vx2, vz2 = vx * vx, vz * vz
        u2 = vx2 + vz2
        u = math.sqrt(u2)
        area = areas[k]
        if fold[k] >= 0:  # m5's hand: fold.fold_area_scale (m5.area_factor of cos q)
            area = area * (1.0 - 0.5 * fl[FOLD_LOSS] * (1.0 - math.cos(qpos[fold[k]])))
        num = 0.5 * rho * area
        inv_u = num / u if u > 0.0 else 0.0
        drag_u2 = cd0 * u2 + cd_max * vz2
        lift2 = 2.0 * cl_max
        fx = inv_u * vx * (lift2 * vz2 - drag_u2)
        fz = -inv_u * vz * (lift2 * vx2 + drag_u2)
        buf[0] = fx * x[0] - fz * x[2]
        buf[1] = fx * x[3] - fz * x[5]
        buf[2] = fx * x[6] - fz * x[8]
        point = site_xpos.ctypes.data + sid * 24
        capi.mj_applyFT(
            m, d, buf.ctypes.data, zero.ctypes.data, point, body_ids[k], passive.ctypes.data
        )


def _body_drag(m, d, passive, site_xpos, site_xmat, wind, fl, ints, vel, buf, zero):
    site = ints[TORSO_SITE]
    capi.mj_objectVelocity(m, d, capi.OBJ_SITE, site, vel.ctypes.data, 0)
    u0, u1, u2 = vel[3] - wind[0], vel[4] - wind[1], vel[5] - wind[2]
    speed = math.sqrt(u0 * u0 + u1 * u1 + u2 * u2)
    if speed == 0.0:
        return
    x = site_xmat[site]
    loc0 = x[0] * u0 + x[3] * u1 + x[6] * u2
    loc2 = x[2] * u0 + x[5] * u1 + x[8] * u2
    attack = math.atan2(-loc2, loc0)
    drag = 0.5 * fl[RHO] * (speed * speed) * abs(math.sin(attack)) * fl[DRAG_AREA]
    buf[0] = -drag * u0 / speed
    buf[1] = -drag * u1 / speed
    buf[2] = -drag * u2 / speed
    point = site_xpos.ctypes.data + site * 24
    capi.mj_applyFT(
        m, d, buf.ctypes.data, zero.ctypes.data, point, ints[TORSO_BODY], passive.ctypes.data
    )


_plane_force = plane_force  # compiled below, with the kernels


def _tail(m, d, passive, site_xpos, site_xmat, wind, fl, ints, fr, vel, buf, zero, tail_out):
    """The tail's force (birdsim.mujoco.tail.tail_force); ``tail_out`` (4,): its force in
    torso axes and its angle of attack."""
    site = ints[TAIL_SITE]
    capi.mj_objectVelocity(m, d, capi.OBJ_SITE, site, vel.ctypes.data, 1)
    x = site_xmat[site]
    w0, w1, w2 = wind[0], wind[1], wind[2]
    v0 = vel[3] - (x[0] * w0 + x[3] * w1 + x[6] * w2)
    v1 = vel[4] - (x[1] * w0 + x[4] * w1 + x[7] * w2)
    v2_ = vel[5] - (x[2] * w0 + x[5] * w1 + x[8] * w2)
    ux = fr[0, 0] * v0 + fr[1, 0] * v1 + fr[2, 0] * v2_
    uz = fr[0, 2] * v0 + fr[1, 2] * v1 + fr[2, 2] * v2_
    v2 = ux * ux + uz * uz
    rho, b, length = fl[RHO], fl[TAIL_B], fl[TAIL_LENGTH]
    if v2 == 0.0:
        f0 = f1 = f2 = 0.0
        a = 0.0
    else:
        fx, fz, a = _plane_force(ux, uz, v2, b, length, rho)
        f0 = fr[0, 0] * fx + fr[0, 2] * fz
        f1 = fr[1, 0] * fx + fr[1, 2] * fz
        f2 = fr[2, 0] * fx + fr[2, 2] * fz
    tail_out[0], tail_out[1], tail_out[2], tail_out[3] = f0, f1, f2, a
    if ints.shape[0] > TAIL_BLAS and ints[TAIL_BLAS] != 0:  # numpy's matmul: BLAS dgemv
        buf[:] = np.dot(x.reshape((3, 3)), tail_out[:3])
    else:
        buf[0] = x[0] * f0 + x[1] * f1 + x[2] * f2
        buf[1] = x[3] * f0 + x[4] * f1 + x[5] * f2
        buf[2] = x[6] * f0 + x[7] * f1 + x[8] * f2
    point = site_xpos.ctypes.data + site * 24
    capi.mj_applyFT(
        m, d, buf.ctypes.data, zero.ctypes.data, point, ints[TAIL_BODY], passive.ctypes.data
    )


def _apply_aero(
    m, d, passive, site_ids, body_ids, site_xpos, site_xmat, areas, fold, qpos, wind, fl, ints,
    frame, tail_out,
):  # fmt: skip
    """The callback's forces added to ``passive`` (= d.qfrc_passive) at the current
    kinematics (after ``mj_step1``): wings, body drag, tail, in the callback's order."""
    if ints[ENABLED] == 0:
        return
    vel = np.zeros(6)
    buf = np.zeros(3)
    zero = np.zeros(3)
    _wings(
        m, d, passive, site_ids, body_ids, site_xpos, site_xmat, areas, fold, qpos, wind, fl,
        vel, buf, zero,
    )  # fmt: skip
    if ints[BODY_DRAG] != 0:
        _body_drag(m, d, passive, site_xpos, site_xmat, wind, fl, ints, vel, buf, zero)
    if ints[TAIL] != 0:
        _tail(m, d, passive, site_xpos, site_xmat, wind, fl, ints, frame, vel, buf, zero, tail_out)


if numba is not None and capi.AVAILABLE:
    _opts = dict(cache=True, inline="always")
    _wings = numba.njit(**_opts)(_wings)
    _body_drag = numba.njit(**_opts)(_body_drag)
    _plane_force = numba.njit(**_opts)(plane_force)
    _tail = numba.njit(**_opts)(_tail)
    apply_aero = numba.njit(cache=True)(_apply_aero)
else:  # pragma: no cover
    apply_aero = None

__all__ = ["apply_aero", "fold_addresses", "parameters", "supported"]
