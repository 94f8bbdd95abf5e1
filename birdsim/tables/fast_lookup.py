"""A table's multilinear interpolation in compiled code, as scipy's
``RegularGridInterpolator(method="linear")`` computes it for grids of three or more axes.

scipy (1.17, ``_rgi.py``) finds each axis' interval ``i`` (``grid[i] <= x < grid[i+1]``,
the last interval at the upper end) and ``y = (x - grid[i]) / (grid[i+1] - grid[i])``,
then sums, over the cell's corners in ``itertools.product`` order (axis 0 slowest; 0 =
the lower node with weight ``1 - y``, 1 = the upper with ``y``), the corner's values
times the weight ``((1 w_0) w_1) ... w_n``, starting from 0.  :func:`interpolate` does
the same operations in the same order in numba (the same numbers:
``tests/test_fast_flight.py``), without the some thirty numpy calls per point that make
scipy's lookup cost ~0.3 ms: the flight controller looks the table up 8 times per
wingbeat.  Points outside the grid or not finite, fewer than three axes, or no numba:
:func:`interpolate` returns None and the caller asks scipy (which refuses or fills).
"""

from __future__ import annotations

import math

import numpy as np

from birdsim.physics.jit import numba

#: the compiled interpolation is used where it applies (False: always scipy)
ENABLED = True


def _interval(grid: np.ndarray, x: float) -> int:
    n = grid.shape[0]
    lo = 0
    hi = n - 1
    if x >= grid[n - 1]:
        return n - 2
    while hi - lo > 1:  # grid[lo] <= x < grid[hi]
        mid = (lo + hi) // 2
        if grid[mid] <= x:
            lo = mid
        else:
            hi = mid
    return lo


def _interpolate(grids, flat_values, shape, pts, out):
    """``out[j] = `` the interpolation at ``pts[j]``; ``flat_values``: the values
    (n_0, ..., n_d-1, k) in C order, ``shape`` their shape.  False (``out`` unset) when
    a point is outside the grid or not finite."""
    d = pts.shape[1]
    for j in range(pts.shape[0]):
        for a in range(d):
            g = grids[a]
            x = pts[j, a]
            if not (g[0] <= x <= g[g.shape[0] - 1]):  # also NaN
                return False
    idx = np.zeros(d, dtype=np.int64)
    y = np.zeros(d)
    k = out.shape[1]
    for j in range(pts.shape[0]):
        for a in range(d):
            g = grids[a]
            i = _interval(g, pts[j, a])
            idx[a] = i
            y[a] = (pts[j, a] - g[i]) / (g[i + 1] - g[i])
        for c in range(k):
            out[j, c] = 0.0
        for h in range(1 << d):
            weight = 1.0
            flat = 0
            for a in range(d):
                bit = (h >> (d - 1 - a)) & 1
                weight = weight * (y[a] if bit else 1 - y[a])
                flat = flat * shape[a] + idx[a] + bit
            base = flat * k
            for c in range(k):
                out[j, c] = out[j, c] + flat_values[base + c] * weight
    return True


if numba is not None:
    _interval = numba.njit(cache=True, inline="always")(_interval)
    kernel = numba.njit(cache=True)(_interpolate)
else:  # pragma: no cover
    kernel = None


class Interpolant:
    """A table's grid and values made ready for :func:`interpolate` once."""

    def __init__(self, grid: tuple[np.ndarray, ...], values: np.ndarray):
        self.grid = tuple(np.ascontiguousarray(g, dtype=float) for g in grid)
        values = np.ascontiguousarray(values, dtype=float)
        self.k = values.shape[-1]
        self.flat = values.reshape(-1)
        self.shape = np.array(values.shape, dtype=np.int64)
        self.usable = kernel is not None and len(grid) >= 3 and values.ndim == len(grid) + 1


def interpolate(table: Interpolant, pts: np.ndarray) -> np.ndarray | None:
    """The multilinear interpolation at ``pts`` (m, d), as scipy's
    RegularGridInterpolator computes it; None where this does not apply (the caller then
    asks scipy)."""
    if not ENABLED or not table.usable or pts.ndim != 2 or pts.shape[1] != len(table.grid):
        return None
    out = np.empty((pts.shape[0], table.k))
    pts = np.ascontiguousarray(pts, dtype=float)
    if not kernel(table.grid, table.flat, table.shape, pts, out):
        return None
    return out


def scalar_point(
    axes: dict, axis_names: tuple, values: tuple, climb: object, clip: bool
) -> tuple[np.ndarray, tuple] | None:
    """:func:`birdsim.tables.demand_points.demand_points`' point for one level demand of
    Python floats (Fx, Fz, V) on a table of those three axes, without its array calls:
    each value clipped to its axis (``np.clip`` of a finite float is ``min(max(v, lo),
    hi)``); None for anything else (arrays, a climb axis or a climb, a value that is not
    finite or, unclipped, outside the grid: the caller's path checks and refuses)."""
    if not ENABLED or len(axis_names) != 3 or type(climb) is not float or climb != 0.0:
        return None
    row = []
    for name, v in zip(axis_names, values):
        if type(v) is not float or not math.isfinite(v):
            return None
        lo, hi = float(axes[name][0]), float(axes[name][-1])
        if not clip and (v < lo - 1e-12 or v > hi + 1e-12):
            return None
        row.append(min(max(v, lo), hi))
    return np.array([row]), ()


__all__ = ["Interpolant", "interpolate", "kernel", "scalar_point"]
