"""The obstacles a flight path must miss, in three dimensions (issue 9 item 3, issue 23).

The floor: the body must stay :data:`FLOOR_CLEARANCE` semispans above it (a wing's
length), except on the segment next to an end at rest on the ground. The perches of the
path's scene (:mod:`birdsim.mujoco.perches`; the presets' one perch at (:data:`PERCH_X`,
:data:`PERCH_Y`) holds the body at :data:`PERCH_Z`): the body may not be within
:data:`PERCH_KEEPOUT` of a post *horizontally* (the distance in x and y) below its
perched height. An end at rest must be at rest on a perch or on the ground. A refusal is one line naming the first keyframe that is itself in the way, else the
segment where the path first is (issue 28 item 3).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.mujoco.perches import DEFAULT_SCENE, GROUND_REST_Z, Scene

#: Where the torso origin sits when the bird is perched (semispans, x forward, y left,
#: z up): the scene's perch post at x = 6 s, y = 0, its top site at 1.54 s, plus the
#: torso's half height 0.13 s (birdsim/mujoco/model.py; ``test_path.py`` checks both
#: against ``render.renderer.perch_seed_position``).
PERCH_X = 6.0
PERCH_Y = 0.0
PERCH_Z = 1.67
#: Horizontal distance from the perch post within which the body may not be below
#: ``PERCH_Z`` (the torso's half length 0.55 s), except at a perched end (semispans).
PERCH_KEEPOUT = 0.55
#: Lowest allowed height of the body above the floor (semispans): a wing's length, so a
#: wing flapped straight down does not reach the floor.
FLOOR_CLEARANCE = 1.0
#: Slack for touching the perch height (semispans).
PERCH_TOL = 0.02
#: Samples per wingbeat of the obstacle check.
CHECK_SAMPLES_PER_BEAT = 64
TWO_PI = 2.0 * math.pi


class PathError(BirdsimError):
    """A flight path that cannot be flown (below the floor, through the perch, bad keyframes)."""


def _where_bad(path: Any, tb: np.ndarray, bad: np.ndarray) -> tuple[str, int]:
    """The place to fix and the sample to show: the first keyframe that is itself in the
    way (its own sample), else the segment (between two keyframes, before the first or
    after the last) where the path first is (the first offending sample)."""
    ks = path.keyframes
    for j, k in enumerate(ks, 1):
        i = int(np.searchsorted(tb, k.t - 1e-12))
        if i < len(tb) and abs(tb[i] - k.t) < 1e-9 and bad[i]:
            return f"keyframe {j} (t={k.t:g}) is", i
    i = int(np.argmax(bad))
    if tb[i] < ks[0].t:
        return f"the path before keyframe 1 (t={ks[0].t:g}) goes", i
    k = path.keyframe_before(tb[i])
    if k >= len(ks):
        return f"the path after keyframe {k} (t={ks[k - 1].t:g}) goes", i
    return (
        f"the segment from keyframe {k} (t={ks[k - 1].t:g}) to keyframe {k + 1} "
        f"(t={ks[k].t:g}) goes",
        i,
    )


def check_obstacles(path: Any) -> None:
    """Refuse a path below the floor or through a perch of its scene (in 3-D), in one
    line naming the first keyframe that is itself in the way, else the segment where the
    path first is; and a rest end that is not at rest on a perch or the ground
    (:func:`rest_supports`).  Next to an end at rest on the ground the floor clearance is
    the ground's rest height (the segment to the neighbouring keyframe).

    Args:
        path: a :class:`birdsim.flight.path.FlightPath` (its ``sample``, ``state``,
            ``keyframes``, ``keyframe_before``, ``duration_beats``, perch flags).

    Raises:
        PathError: the first sample closer to the floor than ``FLOOR_CLEARANCE`` or within
            ``PERCH_KEEPOUT`` of the perch post (horizontally) below the perched height; a
            perched end that is not at rest on the perch.
    """
    scene = getattr(path, "scene", None) or DEFAULT_SCENE
    n = max(2, int(math.ceil(path.duration_beats * CHECK_SAMPLES_PER_BEAT)) + 1)
    tb = np.linspace(0.0, path.duration_beats, n)
    tb = np.union1d(tb, [k.t for k in path.keyframes if k.t <= path.duration_beats])
    s = path.sample(tb * TWO_PI)
    supports = rest_supports(path, scene)
    ks = path.keyframes
    floor = np.full(tb.shape, FLOOR_CLEARANCE)
    # next to an end at rest on the ground the body comes down to it
    if supports[0] == "ground":
        floor[tb <= (ks[1].t if len(ks) > 1 else np.inf)] = GROUND_REST_Z
    if supports[1] == "ground" or getattr(path, "low_end", False):
        floor[tb >= (ks[-2].t if len(ks) > 1 else -np.inf)] = GROUND_REST_Z
    if getattr(path, "low_end", False) and len(ks) > 2:  # a landing's flare and descent
        floor[tb >= ks[-3].t] = GROUND_REST_Z
    low = s["z"] < floor - 1e-9
    checks = [(low, f"below the floor clearance z >= {FLOOR_CLEARANCE:g} semispans")]
    for j, p in enumerate(scene.perches, 1):
        # hypot(dx, 0) == |dx| exactly: a path in the x-z plane is checked as before
        near = np.hypot(s["x"] - p.x, s["y"] - p.y) < PERCH_KEEPOUT
        label = "the perch" if len(scene.perches) == 1 else f"perch {j}"
        checks.append(
            (
                near & (s["z"] < p.rest_z - PERCH_TOL),
                f"through {label} (within {PERCH_KEEPOUT:g} of x = {p.x:g}, y = {p.y:g} "
                f"below z = {p.rest_z:g})",
            )
        )
    for bad, what in checks:
        if np.any(bad):
            place, i = _where_bad(path, tb, bad)
            raise PathError(
                f"path {path.name!r}: {place} {what}: at t={tb[i]:.3g} wingbeats "
                f"x={s['x'][i]:.3g}, y={s['y'][i]:.3g}, z={s['z'][i]:.3g} semispans; allowed: "
                "a path above the floor and around the perch"
            )


def rest_supports(path: Any, scene: Scene | None = None) -> tuple[str | None, str | None]:
    """Where the path starts and ends at rest: ``"perch N"``, ``"ground"``, or None for
    an end that is not at rest (``perch_start`` / ``perch_end`` off).

    Raises:
        PathError: a rest end that is moving or in mid-air (one line naming the keyframe
            and the scene's rest places).
    """
    scene = scene or getattr(path, "scene", None) or DEFAULT_SCENE
    out: list[str | None] = []
    for flag, idx, label in (
        (path.perch_start, 0, "perch_start"),
        (path.perch_end, -1, "perch_end"),
    ):
        if not flag:
            out.append(None)
            continue
        k = path.keyframes[idx]
        st = path.state(k.t * TWO_PI)
        support = scene.support_at(st.x, st.y, st.z)
        if support is None or max(abs(st.vx), abs(st.vy), abs(st.vz)) > 1e-9:
            num = 1 if idx == 0 else len(path.keyframes)
            what = "moving" if support is not None else "in mid-air"
            raise PathError(
                f"path {path.name!r}: {label} but keyframe {num} is at x={st.x:g}, "
                f"y={st.y:g}, z={st.z:g}, speed ({st.vx:g}, {st.vy:g}, {st.vz:g}): {what}; "
                f"allowed: at rest on a perch or the ground ({scene.rest_places()})"
            )
        out.append(support)
    return out[0], out[1]


__all__ = [
    "CHECK_SAMPLES_PER_BEAT",
    "FLOOR_CLEARANCE",
    "PERCH_KEEPOUT",
    "PERCH_TOL",
    "PERCH_X",
    "PERCH_Y",
    "PERCH_Z",
    "PathError",
    "check_obstacles",
    "rest_supports",
]
