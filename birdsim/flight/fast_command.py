"""The path controller's table lookup for a level table in one compiled call (issue 27).

:meth:`birdsim.flight.controller.Controller.lookup` for a level table (axes Fx, Fz, V)
and the default demand (:func:`birdsim.flight.demand.demand_from_acceleration`): the
air path's angle (:func:`birdsim.flight.demand.air_path_angle`), the force turned into
the air-path frame, the body drag, the demand clipped to the grid, the saturation
tests and the table's row (:mod:`birdsim.tables.fast_lookup`'s interpolation), in one
numba call instead of some forty Python and numpy-scalar calls.

Not bitwise: numba's ``hypot``, ``arctan2``, ``sin`` and ``cos`` are the C library's,
numpy's scalar ones differ in the last bit, and ``x ** 2`` is ``x * x`` here where
Python's ``**`` calls ``pow``.  A flight with this switch on stays within 1e-9
semispan of the reference's path over 10 wingbeats (``tests/test_fast_command.py``);
the Python lookup stays the reference (``ENABLED = False``).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.flight import fast_path
from birdsim.flight.demand import CLIMB_SPEED, demand_from_acceleration
from birdsim.physics.jit import numba
from birdsim.physics.units import reduced_bird
from birdsim.tables import fast_lookup

#: the compiled lookup is used where it applies (False: the Python reference)
ENABLED = True


def _level_command(ax, az, vx_air, vz_air, pitch, consts, lo, hi, tol, grids, flat, shape, out):
    """``out[:k]`` = the table's row for the acceleration (ax, az) (world, z up) at the
    air velocity (vx_air, vz_air), ``out[k:k + 3]`` = (Fx, Fz, V_table) of the demand
    and ``out[k + 3]`` the air path's angle gamma.  Returns 0 (not finite: nothing
    written), 1 (within reach) or 2 (saturated)."""
    m, grav, rm, rgrav, rho, area, climb_speed = consts
    gamma = math.atan2(vz_air, vx_air) if math.hypot(vx_air, vz_air) > 0 else 0.0
    f = vx_air if (vx_air >= 0.0 or vx_air != vx_air) else 0.0
    f = (f / climb_speed) * (f / climb_speed)
    gamma = gamma * (1.0 if 1.0 <= f else f)
    f_x, f_z = m * ax, m * (az + grav)
    c, s = math.cos(gamma), math.sin(gamma)
    w_x, w_z = c * f_x + s * f_z, -s * f_x + c * f_z
    v = math.hypot(vx_air, vz_air) if gamma != 0.0 else vx_air
    # demand_from_acceleration(w_x / m, w_z / m - grav, v, 0.0, bird, pitch - gamma)
    a_x, a_z = w_x / m, w_z / m - grav
    fx_whole, fz_whole = rm * a_x, -rm * (a_z + rgrav)
    g2 = math.atan2(0.0, v)
    mag = 0.5 * rho * abs(v) * abs(math.sin(pitch - gamma - g2)) * area
    dx = -mag * v
    fx = 0.5 * (fx_whole - dx) + dx
    fz = 0.5 * (fz_whole - mag * 0.0)
    if not (math.isfinite(fx) and math.isfinite(fz) and math.isfinite(v)):
        return 0
    cx, cz, cv = min(max(fx, lo[0]), hi[0]), min(max(fz, lo[1]), hi[1]), min(max(v, lo[2]), hi[2])
    sat = abs(cx - fx) > 1e-9 or abs(cz - fz) > 1e-9 or abs(cv - v) > tol[0]
    pts = np.empty((1, 3))
    pts[0, 0], pts[0, 1], pts[0, 2] = cx, cz, cv
    row = np.empty((1, shape[shape.shape[0] - 1]))
    _interpolate(grids, flat, shape, pts, row)
    k = out.shape[0] - 4
    for j in range(k):
        out[j] = row[0, j]
    miss = max(abs(row[0, k] - cx), abs(row[0, k + 1] - cz))
    out[k], out[k + 1], out[k + 2], out[k + 3] = fx, fz, v, gamma
    return 2 if (sat or miss > tol[1]) else 1


def _path_command(
    cx, xx, cz, xz, t, feedback, ep, ev, vx_est, gains, integral, wx, wz, pitch, consts, lo,
    hi, tol, grids, flat, shape, out,
):  # fmt: skip
    """:func:`_level_command` at the path's state at ``t`` (its x and z curves
    ``(cx, xx)``, ``(cz, xz)``: ``fast_path``'s evaluation) with the path loop's feedback
    (``feedback``: the error estimate ``ep``, ``ev`` (2,) and speed ``vx_est``, ``gains``
    = (kp, kd, ki), ``integral`` (2,)) and the wind (wx, wz): ``Controller.command``'s
    lines.  ``out`` as :func:`_level_command`'s, with the acceleration commanded (ax, az)
    in two more entries after it."""
    tt = np.empty(1)
    tt[0] = t
    xv, zv = np.empty((3, 1)), np.empty((3, 1))
    _curve(cx, xx, tt, xv)
    _curve(cz, xz, tt, zv)
    ax, az = xv[2, 0], zv[2, 0]
    if feedback:
        ax += gains[0] * ep[0] + gains[1] * ev[0] + gains[2] * integral[0]
        az += gains[0] * ep[1] + gains[1] * ev[1] + gains[2] * integral[1]
        vx, vz = vx_est, zv[1, 0] - ev[1]
    else:
        vx, vz = xv[1, 0], zv[1, 0]
    k = out.shape[0] - 2
    out[k], out[k + 1] = ax, az
    args = (vx - wx, vz - wz, pitch, consts, lo, hi, tol, grids, flat, shape)
    return _level_command_jit(ax, az, *args, out[:k])


_interpolate, _curve = fast_lookup.kernel, fast_path.values_kernel
kernel = numba.njit(cache=True)(_level_command) if numba is not None else None
_level_command_jit = kernel
path_kernel = (
    numba.njit(cache=True)(_path_command) if numba is not None and _curve is not None else None
)


def prepare(ctl: Any) -> tuple | None:
    """The controller's constants for :func:`lookup` (kept on it), or None where the
    compiled lookup does not apply (a climb table, another demand, no compiled table)."""
    prep = ctl.__dict__.get("_fast_command", False)
    if prep is not False:
        return prep
    prep, table = None, ctl.table
    interp = getattr(table, "interpolant", None)
    fast = interp() if interp is not None else None
    usable = fast is not None and fast.usable and kernel is not None
    if usable and not ctl.has_climb and ctl.to_table is demand_from_acceleration:
        if tuple(table.axis_names) == ("Fx", "Fz", "V"):
            rb, b = reduced_bird(ctl.bird), ctl.bird
            consts = (
                b.mass,
                b.gravity,
                rb.mass,
                rb.gravity,
                rb.rho,
                rb.body_drag_area,
                CLIMB_SPEED,
            )
            lo = np.array([ctl.lo[n] for n in ("Fx", "Fz", "V")])
            hi = np.array([ctl.hi[n] for n in ("Fx", "Fz", "V")])
            prep = (tuple(float(x) for x in consts), lo, hi, fast, len(ctl.names))
    ctl.__dict__["_fast_command"] = prep
    return prep


def lookup(
    ctl: Any, ax: float, az: float, vx_air: float, vz_air: float, pitch: float, tolerances: tuple
) -> tuple[float, float, float, np.ndarray, bool] | None:
    """(Fx, Fz, V_table, params, saturated) of ``ctl.lookup(ax, az, vx_air, vz_air,
    pitch)`` (the air path's angle already added to the pitch parameter), or None where
    the Python reference must answer (switch off, not applicable, a demand not finite:
    the reference names it)."""
    if not ENABLED or not fast_lookup.ENABLED:
        return None
    prep = prepare(ctl)
    if prep is None:
        return None
    consts, lo, hi, fast, d = prep
    out = np.empty(d + 4)
    tol = np.array(tolerances, dtype=float)
    args = (float(ax), float(az), float(vx_air), float(vz_air), float(pitch), consts, lo, hi, tol)
    code = kernel(*args, fast.grid, fast.flat, fast.shape, out)
    return _answer(ctl, out, d, code)


def _answer(ctl: Any, out: np.ndarray, d: int, code: int) -> tuple | None:
    """:func:`lookup`'s answer from a kernel's ``out`` and code (the air path's angle
    added to the pitch parameter)."""
    if code == 0:
        return None
    params = out[:d].copy()
    gamma = out[d + 3]
    if gamma != 0.0 and "pitch" in ctl.names:
        params[ctl.names.index("pitch")] += gamma
    return float(out[d]), float(out[d + 1]), float(out[d + 2]), params, code == 2


def path_command(
    ctl: Any,
    path: Any,
    t: float,
    est: tuple | None,
    integral: np.ndarray,
    pitch: float,
    wind: tuple[float, float],
    tolerances: tuple,
) -> tuple | None:
    """(Fx, Fz, V_table, params, saturated, (ax, az)) of ``ctl.command(path.state(t),
    est, integral, pitch, wind)`` in one compiled call, or None where the Python lines
    must answer (as :func:`lookup`; also a path whose curves are not compiled)."""
    if not (ENABLED and fast_lookup.ENABLED and fast_path.ENABLED) or path_kernel is None:
        return None
    got = ctl.__dict__.get("_fast_path_command")
    if got is None or got[0] is not path or got[1] is not ctl.gains:
        got = (path, ctl.gains, _path_arguments(ctl, path, tolerances))
        ctl.__dict__["_fast_path_command"] = got
    fixed = got[2]
    if fixed is None:
        return None
    curves, gains, zeros, tail, d = fixed
    if est is not None and not ctl.open_loop:
        f = np.asarray
        feedback, ep, ev, vx = True, f(est[0], dtype=float), f(est[1], dtype=float), float(est[2])
    else:
        feedback, ep, ev, vx = False, zeros, zeros, 0.0
    out = np.empty(d + 6)
    code = path_kernel(
        *curves, float(t), feedback, ep, ev, vx, gains, np.asarray(integral, dtype=float), float(wind[0]),
        float(wind[1]), float(pitch), *tail, out,
    )  # fmt: skip
    got = _answer(ctl, out, d, code)
    return None if got is None else (*got, (float(out[d + 4]), float(out[d + 5])))


def _path_arguments(ctl: Any, path: Any, tolerances: tuple) -> tuple | None:
    """:func:`path_command`'s fixed arguments for ``ctl`` on ``path``, or None."""
    prep, curves = prepare(ctl), fast_path.path_curves(path)
    if prep is None or curves is None:
        return None
    consts, lo, hi, fast, d = prep
    g = ctl.gains
    tol = np.array(tolerances, dtype=float)
    tail = (consts, lo, hi, tol, fast.grid, fast.flat, fast.shape)
    return curves, np.array((g.kp, g.kd, g.ki), dtype=float), np.zeros(2), tail, d


__all__ = ["ENABLED", "kernel", "lookup", "path_command", "path_kernel", "prepare"]
