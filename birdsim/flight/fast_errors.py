"""A straight free flight's per-sample path errors after each control interval in one
compiled call (issue 27: the control update's Python).

After its steps, :func:`birdsim.flight.freeflight.fly` turns the interval's samples into
the path loop's position and velocity errors (x, z), the lateral window's (y, vy) and the
logged airspeed ``|v - wind|``: three ``np.stack`` calls and a dot product per sample,
about 60 us per update.  :func:`straight_errors` does the same in one numba call: the
differences are the reference's elementwise ones, the airspeed ``sqrt(u . u)`` by numba's
``np.dot`` (the BLAS ``ddot`` numpy's ``u.dot(u)`` calls: bitwise, ``tests/test_fast_errors.py``).
:data:`ENABLED` False gives the numpy reference.  Reduced units, world axes (z up).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.flight import fast_path
from birdsim.flight.flight_arrays import keep_last
from birdsim.flight.simulate import C_SEED
from birdsim.flight.trim import sample_reference
from birdsim.physics.jit import numba

#: the errors compiled (False: the numpy reference)
ENABLED = True


def air_speeds(v_new: np.ndarray, wind: np.ndarray) -> list[float]:
    """``|v - wind|`` per sample (``v_new`` (n, nv), its first three the torso's linear
    velocity), as ``np.linalg.norm`` computes it (sqrt of the dot product): the
    reference."""
    return [math.sqrt(u.dot(u)) for u in v_new[:, :3] - wind]


def _errors(x, z, vx, vz, q_new, v_new, wind, e_pos, e_vel, lat_new, v_air):
    u = np.empty(3)
    for i in range(q_new.shape[0]):
        e_pos[i, 0] = x[i] - q_new[i, 0]
        e_pos[i, 1] = z[i] - q_new[i, 2]
        e_vel[i, 0] = vx[i] - v_new[i, 0]
        e_vel[i, 1] = vz[i] - v_new[i, 2]
        lat_new[i, 0] = q_new[i, 1]
        lat_new[i, 1] = v_new[i, 1]
        for j in range(3):
            u[j] = v_new[i, j] - wind[j]
        v_air[i] = math.sqrt(np.dot(u, u))


kernel = numba.njit(cache=True)(_errors) if numba is not None else None


def _path_errors(cx, xx, cz, xz, t, q_new, v_new, wind, refs, e_pos, e_vel, lat_new, v_air):
    """:func:`_errors` against a straight path's x and z curves (``fast_path``'s
    evaluation at the samples' times ``t``; their values, slopes and second derivatives
    into ``refs`` (6, n): x, vx, ax, z, vz, az)."""
    _curve(cx, xx, t, refs[0:3])
    _curve(cz, xz, t, refs[3:6])
    _errors_jit(
        refs[0], refs[3], refs[1], refs[4], q_new, v_new, wind, e_pos, e_vel, lat_new, v_air
    )


def _keep_last(old, new, out):
    """``out`` (m, k) = the last m rows of ``old`` (n_old, k) followed by ``new`` (n, k)
    (``flight_arrays.keep_last``'s ``np.concatenate([old, new])[-m:]``)."""
    n_old = old.shape[0]
    skip = n_old + new.shape[0] - out.shape[0]
    for r in range(out.shape[0]):
        s = skip + r
        if s < n_old:
            out[r, :] = old[s, :]
        else:
            out[r, :] = new[s - n_old, :]


def _samples(
    cx, xx, cz, xz, t, q_new, v_new, wind, refs, e_pos, e_vel, lat_new, v_air, c_seed,
    quat, omega, lat, new_quat, new_omega, new_lat,
):  # fmt: skip
    """:func:`_path_errors`, then the attitude window (``quat`` (., 4), ``omega`` (., 3):
    MuJoCo's quaternions and ``c_seed`` times the body rates) and the lateral one (``lat``
    (., 2): y, vy) with the samples appended, their last rows into ``new_*``."""
    _path_errors(cx, xx, cz, xz, t, q_new, v_new, wind, refs, e_pos, e_vel, lat_new, v_air)
    n = q_new.shape[0]
    rates = np.empty((n, 3))
    for i in range(n):
        for j in range(3):
            rates[i, j] = c_seed[j] * v_new[i, 3 + j]
    _keep_last(quat, q_new[:, 3:7], new_quat)
    _keep_last(omega, rates, new_omega)
    _keep_last(lat, lat_new, new_lat)


_errors_jit, _curve = kernel, fast_path.values_kernel
path_kernel = samples_kernel = None
if kernel is not None and _curve is not None:
    _path_errors = numba.njit(cache=True)(_path_errors)
    _keep_last = numba.njit(cache=True)(_keep_last)
    path_kernel, samples_kernel = _path_errors, numba.njit(cache=True)(_samples)


def path_errors(
    reference: Any, t: np.ndarray, q_new: np.ndarray, v_new: np.ndarray, wind: np.ndarray
) -> tuple[dict, np.ndarray, np.ndarray, np.ndarray, list[float]]:
    """(the reference's x and z at the samples' times ``t``, then :func:`straight_errors`'
    four) in one compiled call for a straight path's own curves
    (:func:`birdsim.flight.fast_path.path_curves`), else ``sample_reference`` and
    :func:`straight_errors`: the same numbers."""
    curves = fast_path.path_curves(reference) if ENABLED and path_kernel is not None else None
    if curves is None:
        refs = sample_reference(reference, t)
        return (refs, *straight_errors(refs, q_new, v_new, wind))
    n = q_new.shape[0]
    refs = np.empty((6, n))
    e_pos, e_vel, lat_new, v_air = np.empty((n, 2)), np.empty((n, 2)), np.empty((n, 2)), np.empty(n)
    path_kernel(*curves, t, q_new, v_new, wind, refs, e_pos, e_vel, lat_new, v_air)
    return {"x": refs[0], "z": refs[3]}, e_pos, e_vel, lat_new, v_air.tolist()


def straight_samples(
    reference: Any,
    t: np.ndarray,
    q_new: np.ndarray,
    v_new: np.ndarray,
    wind: np.ndarray,
    att_window: tuple[np.ndarray, np.ndarray],
    lat_window: np.ndarray,
    n_fit: int,
) -> tuple:
    """(refs, e_pos, e_vel, airspeeds) of :func:`path_errors`, then the attitude window
    (quat, ``C_SEED`` omega) and the lateral window (y, vy) with the samples appended,
    their last ``n_fit`` rows (``flight_arrays.keep_last``): in one compiled call where
    :func:`path_errors` makes one, the same numbers."""
    curves = fast_path.path_curves(reference) if ENABLED and samples_kernel is not None else None
    quat, omega = att_window
    n = q_new.shape[0]
    if curves is None or n_fit < 1 or lat_window.shape[1:] != (2,) or not len(t):
        refs, e_pos, e_vel, lat_new, v_air = path_errors(reference, t, q_new, v_new, wind)
        att_window = keep_last(att_window, (q_new[:, 3:7], C_SEED * v_new[:, 3:6]), n_fit)
        return refs, e_pos, e_vel, v_air, att_window, keep_last((lat_window,), (lat_new,), n_fit)[0]
    refs = np.empty((6, n))
    e_pos, e_vel, lat_new, v_air = np.empty((n, 2)), np.empty((n, 2)), np.empty((n, 2)), np.empty(n)
    m_att, m_lat = min(len(quat) + n, n_fit), min(len(lat_window) + n, n_fit)
    new_quat, new_omega, new_lat = np.empty((m_att, 4)), np.empty((m_att, 3)), np.empty((m_lat, 2))
    samples_kernel(
        *curves, t, q_new, v_new, wind, refs, e_pos, e_vel, lat_new, v_air, C_SEED, quat, omega,
        lat_window, new_quat, new_omega, new_lat,
    )  # fmt: skip
    refs_xz = {"x": refs[0], "z": refs[3]}
    return refs_xz, e_pos, e_vel, v_air.tolist(), (new_quat, new_omega), new_lat


def straight_errors(
    refs: dict, q_new: np.ndarray, v_new: np.ndarray, wind: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[float]]:
    """(position errors (n, 2) (x, z), velocity errors (n, 2), lateral samples (n, 2)
    (y, vy), airspeeds) of the samples ``q_new`` / ``v_new`` (n, nq) / (n, nv) against
    the reference's ``refs`` (x, z, vx, vz per sample) under ``wind`` (3,)."""
    if not ENABLED or kernel is None:
        e_pos = np.stack([refs["x"] - q_new[:, 0], refs["z"] - q_new[:, 2]], axis=1)
        e_vel = np.stack([refs["vx"] - v_new[:, 0], refs["vz"] - v_new[:, 2]], axis=1)
        lat_new = np.stack([q_new[:, 1], v_new[:, 1]], axis=1)
        return e_pos, e_vel, lat_new, air_speeds(v_new, wind)
    n = q_new.shape[0]
    e_pos, e_vel, lat_new, v_air = np.empty((n, 2)), np.empty((n, 2)), np.empty((n, 2)), np.empty(n)
    f = np.ascontiguousarray
    kernel(
        f(refs["x"], dtype=float), f(refs["z"], dtype=float), f(refs["vx"], dtype=float),
        f(refs["vz"], dtype=float), q_new, v_new, f(wind, dtype=float), e_pos, e_vel,
        lat_new, v_air,
    )  # fmt: skip
    return e_pos, e_vel, lat_new, v_air.tolist()


__all__ = [
    "ENABLED",
    "air_speeds",
    "kernel",
    "path_errors",
    "path_kernel",
    "samples_kernel",
    "straight_errors",
    "straight_samples",
]
