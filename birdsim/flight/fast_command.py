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


_interpolate = fast_lookup.kernel
kernel = numba.njit(cache=True)(_level_command) if numba is not None else None


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
    if code == 0:
        return None
    params = out[:d].copy()
    gamma = out[d + 3]
    if gamma != 0.0 and "pitch" in ctl.names:
        params[ctl.names.index("pitch")] += gamma
    return float(out[d]), float(out[d + 1]), float(out[d + 2]), params, code == 2


__all__ = ["ENABLED", "kernel", "lookup", "prepare"]
