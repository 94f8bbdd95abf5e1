"""Demands against a table's grid: checked (finite, inside the grid unless clipped) and
turned into interpolation points, and the grid cells around a point.

The axes are a lookup table's (``LookupTable.axes``, in ``LookupTable.axis_names``
order: Fx, Fz, V and optionally climb); a table without a climb axis answers climb = 0
only (level flight).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from birdsim.tables.table_error import TableError


def demand_points(
    axes: Mapping[str, np.ndarray],
    axis_names: Sequence[str],
    values: Mapping[str, Any],
    clip: bool,
) -> tuple[np.ndarray, tuple[int, ...]]:
    """Demands as interpolation points.

    Args:
        axes: axis name -> increasing grid values.
        axis_names: the axes in grid order.
        values: axis name -> demand (number or array; broadcast together).
        clip: clip demands outside the grid to its edge instead of refusing them.

    Returns:
        (points, M x len(axis_names); the broadcast shape of the demands).

    Raises:
        TableError: a demand that is not a finite number, or outside the grid without
            ``clip`` (one line naming the axis).
    """
    arrays = {}
    for a in axis_names:
        try:
            arr = np.asarray(values[a], dtype=float)
        except (TypeError, ValueError):
            raise TableError(f"{a}={values[a]!r} is not a number") from None
        if not np.all(np.isfinite(arr)):
            bad = arr[~np.isfinite(arr)].flat[0] if arr.ndim else float(arr)
            raise TableError(
                f"{a}={bad} is not finite; allowed: a number in [{axes[a][0]:g}, {axes[a][-1]:g}]"
            )
        lo, hi = float(axes[a][0]), float(axes[a][-1])
        if clip:
            arr = np.clip(arr, lo, hi)
        else:
            # 1e-12: a demand printed from the axis itself must count as inside
            out = (arr < lo - 1e-12) | (arr > hi + 1e-12)
            if np.any(out):
                bad = float(arr[out].flat[0]) if arr.ndim else float(arr)
                raise TableError(
                    f"{a}={bad:g} is outside the table grid; allowed: [{lo:g}, {hi:g}] (or clip=True)"
                )
            arr = np.clip(arr, lo, hi)
        arrays[a] = arr
    b = np.broadcast_arrays(*(arrays[a] for a in axis_names))
    return np.stack([x.ravel() for x in b], axis=-1), b[0].shape


def check_level_climb(climb: Any, clip: bool) -> None:
    """A table without a climb axis answers climb = 0 (or anything, clipped to 0).

    Raises:
        TableError: ``climb`` is not a finite number, or not 0 without ``clip``.
    """
    try:
        arr = np.asarray(climb, dtype=float)
    except (TypeError, ValueError):
        raise TableError(f"climb={climb!r} is not a number") from None
    if not np.all(np.isfinite(arr)):
        raise TableError(
            f"climb={arr[~np.isfinite(arr)].flat[0] if arr.ndim else float(arr)} is not finite; allowed: 0 (this table has no climb axis)"
        )
    if not clip and np.any(np.abs(arr) > 1e-12):
        bad = float(arr[np.abs(arr) > 1e-12].flat[0]) if arr.ndim else float(arr)
        raise TableError(
            f"climb={bad:g} is outside the table grid; allowed: 0 (a table without a climb axis is for level flight; "
            "build one with `birdsim tables build --climb`, or clip=True / --clip)"
        )


def cells_around(
    axes: Mapping[str, np.ndarray], axis_names: Sequence[str], point: np.ndarray
) -> list[list[int]]:
    """Per axis, the indices of the grid nodes around ``point`` (one point, in the
    grid): the two nodes either side, or the node itself when the point is on one
    (within 1e-12)."""
    idx = []
    for k, a in enumerate(axis_names):
        ax = axes[a]
        i = int(np.clip(np.searchsorted(ax, point[k]) - 1, 0, len(ax) - 2))
        near = [i, i + 1]
        for j in (i, i + 1):  # on a node: that node only
            if abs(ax[j] - point[k]) < 1e-12:
                near = [j]
        idx.append(near)
    return idx
