"""Decorations added to MuJoCo's scene each frame as user geoms (``MjvScene.geoms``
after ``update_scene``): control-point pathlines (sec. 4.2.2) and a reference path.

Each decoration has ``segid = -1``: it is not an object of the model, so segmentation
images skip it.  When the scene's geom buffer is full, further segments are dropped.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

#: Pathline colours: hand CP blue, arm / single-panel CP red.
HAND_RGB = (0.1, 0.35, 0.95)
ARM_RGB = (0.95, 0.15, 0.1)
#: Reference path: thin, dark yellow, half transparent.
PATH_RGBA = (0.95, 0.8, 0.1, 0.8)
#: Most segments drawn for a reference path (longer polylines are thinned evenly).
PATH_MAX_SEGMENTS = 400


def add_segment(
    mj: Any, scn: Any, a: np.ndarray, b: np.ndarray, rgba: Sequence[float], width: float
) -> bool:
    """Append a line from ``a`` to ``b`` (world) of ``width`` pixels; False when full."""
    if scn.ngeom >= scn.maxgeom:
        return False
    g = scn.geoms[scn.ngeom]
    mj.mjv_initGeom(
        g,
        mj.mjtGeom.mjGEOM_LINE,
        np.zeros(3),
        np.zeros(3),
        np.eye(3).ravel(),
        np.asarray(rgba, dtype=np.float32),
    )
    mj.mjv_connector(
        g,
        mj.mjtGeom.mjGEOM_LINE,
        float(width),
        np.asarray(a, dtype=float),
        np.asarray(b, dtype=float),
    )
    g.segid = -1  # decoration: not an object of the model (segmentation skips it)
    scn.ngeom += 1
    return True


def add_arrow(
    mj: Any, scn: Any, a: np.ndarray, b: np.ndarray, rgba: Sequence[float], width: float
) -> bool:
    """Append an arrow from ``a`` to ``b`` (world) of shaft radius ``width``; nothing for
    a zero-length arrow; False when the scene is full."""
    if scn.ngeom >= scn.maxgeom:
        return False
    if float(np.linalg.norm(np.asarray(b) - np.asarray(a))) < 1e-9 * max(width, 1e-300):
        return True
    g = scn.geoms[scn.ngeom]
    mj.mjv_initGeom(
        g,
        mj.mjtGeom.mjGEOM_ARROW,
        np.zeros(3),
        np.zeros(3),
        np.eye(3).ravel(),
        np.asarray(rgba, dtype=np.float32),
    )
    mj.mjv_connector(
        g,
        mj.mjtGeom.mjGEOM_ARROW,
        float(width),
        np.asarray(a, dtype=float),
        np.asarray(b, dtype=float),
    )
    g.segid = -1
    scn.ngeom += 1
    return True


def add_trails(
    mj: Any, scn: Any, points: np.ndarray, site_names: Sequence[str], width: float = 3.0
) -> None:
    """Pathlines of each site through ``points`` (instants, sites, 3), oldest first,
    fading in from transparent."""
    n = len(points)
    if n < 2:
        return
    for s in range(points.shape[1]):
        base = HAND_RGB if "hand" in site_names[s] else ARM_RGB
        for k in range(n - 1):
            age = (k + 1) / (n - 1)
            if not add_segment(
                mj, scn, points[k, s], points[k + 1, s], (*base, 0.25 + 0.75 * age), width
            ):
                return


def add_polyline(
    mj: Any, scn: Any, points: np.ndarray, rgba: Sequence[float] = PATH_RGBA, width: float = 2.0
) -> None:
    """A polyline through ``points`` (K, 3) in world coordinates, at most
    :data:`PATH_MAX_SEGMENTS` segments (evenly thinned, end points kept)."""
    pts = np.asarray(points, dtype=float)
    if len(pts) > PATH_MAX_SEGMENTS + 1:
        pts = pts[
            np.unique(np.linspace(0, len(pts) - 1, PATH_MAX_SEGMENTS + 1).round().astype(int))
        ]
    for a, b in zip(pts[:-1], pts[1:]):
        if not add_segment(mj, scn, a, b, rgba, width):
            return


def trail_window(frame: int, instants_per_frame: int, keep: int) -> slice:
    """Instants shown as a pathline at video frame ``frame``: the last ``keep`` up to
    and including the frame's own instant."""
    end = frame * instants_per_frame + 1
    return slice(max(0, end - keep), end)


__all__ = ["add_arrow", "add_polyline", "add_segment", "add_trails", "trail_window"]
