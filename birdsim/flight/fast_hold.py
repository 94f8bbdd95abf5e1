"""The attitude loop's held-body pose (``attitude_jacobians._hold``) in one compiled call
(issue 27: a free flight's set-up).

Every Jacobian measurement poses the model at one prescription row with the body held
and runs MuJoCo's position and velocity stages, the Python aero callback adding the
passive forces: some 270 poses at a flight's start, each about 80 us, most of it the
callback's Python.  :func:`hold` does the same in one numba call: the rows written,
``mj_fwdPosition`` and ``mj_fwdVelocity`` with the callback uninstalled, then the
callback's forces by :func:`birdsim.mujoco.aero_kernel.apply_aero` added to
``qfrc_passive`` (the callback runs last in MuJoCo's passive stage and nothing after it
in ``mj_fwdVelocity`` reads ``qfrc_passive``), the tail's force turned into world axes
by BLAS as the callback's ``xmat @ f`` (``aero_kernel.TAIL_BLAS``): the callback's
numbers bit for bit (``tests/test_fast_hold.py``).  The callback's state is left as it
leaves it (the tail's last force and angle of attack).  :data:`ENABLED` False gives the
reference.  Reduced units.
"""

from __future__ import annotations

import mujoco
import numpy as np

from birdsim.mujoco import aero_kernel, capi
from birdsim.mujoco.callback import AeroCallback
from birdsim.physics.jit import numba

#: the held pose compiled (False: MuJoCo's stages from Python with the Python callback)
ENABLED = True


def _hold(m, d, qpos_d, qvel_d, row_q, row_v, quat, speed, omega, passive, site_ids,
          body_ids, site_xpos, site_xmat, areas, fold, wind, fl, ints, frame, tail_out):  # fmt: skip
    qpos_d[:] = row_q
    qvel_d[:] = row_v
    qpos_d[0], qpos_d[1], qpos_d[2] = 0.0, 0.0, 6.0
    qpos_d[3:7] = quat
    qvel_d[0], qvel_d[1], qvel_d[2] = speed, 0.0, 0.0
    qvel_d[3:6] = omega
    capi.mj_fwdPosition(m, d)
    capi.mj_fwdVelocity(m, d)
    aero_kernel.apply_aero(
        m, d, passive, site_ids, body_ids, site_xpos, site_xmat, areas, fold, qpos_d, wind,
        fl, ints, frame, tail_out,
    )  # fmt: skip


def _hold_rows(m, d, qpos_d, qvel_d, rows_q, rows_v, quat, speed, omega, passive, site_ids,
               body_ids, site_xpos, site_xmat, areas, fold, wind, fl, ints, frame, tail_out,
               c, vec, res, mom, h, acc):  # fmt: skip
    """:func:`_hold` at every row of ``rows_q`` / ``rows_v``, each pose's moment
    ``qfrc_passive[3:6] * c`` into ``mom`` (n, 3) and added to ``acc`` (3,) (unscaled, in
    order), and the wings' angular momentum relative to the torso (``M`` times qvel with
    the root's six entries zeroed, ``[3:6] * c``) into ``h`` (n, 3; none where ``h`` has
    no rows); ``vec``, ``res`` (nv,) scratch."""
    for k in range(rows_q.shape[0]):
        kernel(
            m, d, qpos_d, qvel_d, rows_q[k], rows_v[k], quat, speed, omega, passive, site_ids,
            body_ids, site_xpos, site_xmat, areas, fold, wind, fl, ints, frame, tail_out,
        )  # fmt: skip
        for j in range(3):
            mom[k, j] = passive[3 + j] * c[j]
            acc[j] += passive[3 + j]
        if h.shape[0] == 0:
            continue
        for i in range(vec.shape[0]):
            vec[i] = qvel_d[i]
        for i in range(6):
            vec[i] = 0.0
        capi.mj_mulM(m, d, res.ctypes.data, vec.ctypes.data)
        for j in range(3):
            h[k, j] = res[3 + j] * c[j]


if numba is not None and aero_kernel.apply_aero is not None:
    kernel = numba.njit(cache=True)(_hold)
    rows_kernel = numba.njit(cache=True)(_hold_rows)
else:  # pragma: no cover
    kernel = rows_kernel = None


def _arguments(cb: AeroCallback, m: mujoco.MjModel, d: mujoco.MjData) -> tuple:
    """The kernel's arguments for ``d`` (its qpos, qvel and qfrc_passive, then the sites';
    kept per MjData) and the callback's current constants (made again when the tail's
    controls or the switches change)."""
    key = d._address
    got = cb.__dict__.get("_fast_hold")
    if got is None or got[0] != key:
        sites = (
            np.ascontiguousarray(cb.site_ids), np.ascontiguousarray(cb.body_ids), d.site_xpos,
            d.site_xmat, np.ascontiguousarray(cb.areas[:, 0]), aero_kernel.fold_addresses(cb),
            m.opt.wind,
        )  # fmt: skip
        # the views the kernel writes and reads first (MjData's memory stays where it is)
        got = (key, (d.qpos, d.qvel, d.qfrc_passive, *sites), None, None)
    params_key = (cb.tail_controls, cb.enabled, cb.body_drag)
    if got[2] is None or any(a is not b for a, b in zip(params_key, got[2])):
        fl, ints, frame = aero_kernel.parameters(cb)
        ints = np.append(ints, 1)  # TAIL_BLAS: the callback's xmat @ f
        got = (key, got[1], params_key, (fl, ints, frame))
    cb.__dict__["_fast_hold"] = got
    return got[1], got[3]


def _run(fn, m: mujoco.MjModel, d: mujoco.MjData, qpos: np.ndarray, qvel: np.ndarray,
         quat: np.ndarray, speed: float, omega_mj: np.ndarray, poses: int, extra: tuple) -> bool:  # fmt: skip
    """``fn`` (:data:`kernel` or :data:`rows_kernel`; None: not compiled) on the installed
    AeroCallback of ``m`` with the callback uninstalled for the call, ``extra`` its
    arguments after the tail's; the callback's state then as ``poses`` calls of it leave
    it (the last one's tail).  False (nothing done) where the compiled forces do not
    cover the callback or it is not ``m``'s."""
    if not ENABLED or fn is None:
        return False
    cb = mujoco.get_mjcb_passive()
    if not (isinstance(cb, AeroCallback) and cb.model._address == m._address):
        return False
    if not aero_kernel.supported(cb):
        return False
    (qpos_d, qvel_d, passive, *sites), (fl, ints, frame) = _arguments(cb, m, d)
    tail_out = np.zeros(4)
    f = np.ascontiguousarray
    mujoco.set_mjcb_passive(None)
    try:
        fn(
            m._address, d._address, qpos_d, qvel_d, f(qpos, dtype=float), f(qvel, dtype=float),
            f(quat, dtype=float), float(speed), f(omega_mj, dtype=float), passive,
            *sites, fl, ints, frame, tail_out, *extra,
        )  # fmt: skip
    finally:
        mujoco.set_mjcb_passive(cb)
    if cb.enabled:
        cb.calls += poses
        if cb.tail:
            cb.tail_force_body = tail_out[:3].copy()
            cb.tail_alpha = float(tail_out[3])
    return True


def hold_rows(m: mujoco.MjModel, d: mujoco.MjData, qpos: np.ndarray, qvel: np.ndarray,
              quat: np.ndarray, speed: float, omega_mj: np.ndarray, c: np.ndarray,
              mom: np.ndarray, h: np.ndarray | None = None,
              acc: np.ndarray | None = None) -> bool:  # fmt: skip
    """:func:`hold` at every row of ``qpos`` / ``qvel`` (n, nq) / (n, nv) in one call,
    per row ``d.qfrc_passive[3:6] * c`` into ``mom`` (n, 3), ``d.qfrc_passive[3:6]``
    added to ``acc`` (3,) one row after the other, and ``mj_mulM`` of ``d.qvel`` with
    its first six entries zeroed, ``[3:6] * c``, into ``h`` (n, 3) where given: the
    loops of ``attitude_jacobians.measured_with_rocking`` and ``measured_jacobian``, the
    same numbers.  False (nothing done) where :func:`hold` does not apply."""
    extra = (
        np.ascontiguousarray(c, dtype=float), np.zeros(m.nv), np.zeros(m.nv), mom,
        np.zeros((0, 3)) if h is None else h, np.zeros(3) if acc is None else acc,
    )  # fmt: skip
    return _run(rows_kernel, m, d, qpos, qvel, quat, speed, omega_mj, len(qpos), extra)


def hold(m: mujoco.MjModel, d: mujoco.MjData, qpos: np.ndarray, qvel: np.ndarray,
         quat: np.ndarray, speed: float, omega_mj: np.ndarray) -> bool:  # fmt: skip
    """``attitude_jacobians._hold`` compiled: True when done (``d`` posed and forward, its
    ``qfrc_passive`` the Python callback's), False (nothing done) where it does not apply
    (switched off, no installed AeroCallback of ``m`` that the compiled forces cover)."""
    return _run(kernel, m, d, qpos, qvel, quat, speed, omega_mj, 1, ())


__all__ = ["ENABLED", "hold", "hold_rows", "kernel", "rows_kernel"]
