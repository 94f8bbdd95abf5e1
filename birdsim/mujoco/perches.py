"""Perches and the ground of a scene (issue 25 item 2), in semispans (x forward, y left,
z up, the ground at z = 0).

A :class:`Perch` is a post at (x, y) carrying a round bar across the flight direction
(along y, :data:`BAR_HALF_LENGTH` either side) whose axis is ``height`` above the
ground and whose radius is ``radius``.  A bird *at rest* on a perch has its torso origin
at ``(x, y, height + radius + TORSO_HALF_HEIGHT)``; at rest on the ground at
``z = GROUND_REST_Z``.  The presets' scene (:data:`DEFAULT_SCENE`) is the one perch at
x = 6, height 1.5, radius 0.04: the torso at rest on it at z = 1.67, as before.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from birdsim.errors import BirdsimError

#: Half height of the torso (semispans): a resting torso sits this far above the surface
#: (the path convention; birdsim/mujoco/model.py's torso, checked in tests/test_path.py).
TORSO_HALF_HEIGHT = 0.13
#: Where a bird at rest on the ground has its torso origin (semispans).
GROUND_REST_Z = TORSO_HALF_HEIGHT
#: Half length of a perch's bar along y, and its post's radius (semispans).
BAR_HALF_LENGTH = 0.6
POST_RADIUS = 0.05
#: Least horizontal gap between two perches' bars (semispans): room for a bird's body
#: (half length 0.55) on either side.
PERCH_GAP = 1.1


class SceneError(BirdsimError):
    """A scene that cannot be built (a perch below the ground, perches inside each other)."""


@dataclass(frozen=True)
class Perch:
    """A perch: post at ``x``, ``y`` [s], bar axis ``height`` [s] above the ground, bar
    ``radius`` [s]."""

    x: float
    y: float = 0.0
    height: float = 1.5
    radius: float = 0.04

    @property
    def top(self) -> float:
        """Height of the bar's top (semispans)."""
        return self.height + self.radius

    @property
    def rest_z(self) -> float:
        """Torso origin height of a bird at rest on the perch (semispans)."""
        return self.top + TORSO_HALF_HEIGHT


@dataclass(frozen=True)
class Scene:
    """The perches of a scene (the ground is always there, at z = 0)."""

    perches: tuple[Perch, ...] = (Perch(6.0),)

    def support_at(self, x: float, y: float, z: float, tol: float = 1e-6) -> str | None:
        """Where a body at rest at (x, y, z) stands: ``"perch N"`` (1-based), ``"ground"``
        or None (mid-air)."""
        for i, p in enumerate(self.perches, 1):
            if abs(x - p.x) <= tol and abs(y - p.y) <= tol and abs(z - p.rest_z) <= tol:
                return f"perch {i}"
        return "ground" if abs(z - GROUND_REST_Z) <= tol else None

    def surface(self, support: str, x: float, y: float) -> tuple[float, float, float]:
        """The world point under the feet of a bird at rest on ``support`` at (x, y):
        the perch's bar top (at the perch's x, y) or the ground (z = 0)."""
        if support == "ground":
            return (x, y, 0.0)
        p = self.perches[int(support.split()[1]) - 1]
        return (p.x, p.y, p.top)

    def rest_places(self) -> str:
        """The allowed rest positions, for an error line."""
        perches = "; ".join(
            f"perch {i}: x={p.x:g}, y={p.y:g}, z={p.rest_z:g}"
            for i, p in enumerate(self.perches, 1)
        )
        return (
            f"{perches}; the ground: z={GROUND_REST_Z:g}"
            if perches
            else (f"the ground: z={GROUND_REST_Z:g}")
        )


DEFAULT_SCENE = Scene()


def check_scene(scene: Scene, where: str = "scene") -> None:
    """Refuse a perch that is not a finite number, not above the ground, or inside
    another (bars closer than :data:`PERCH_GAP` horizontally), in one line.

    Raises:
        SceneError: naming the perch (1-based) and what is allowed.
    """
    for i, p in enumerate(scene.perches, 1):
        for name in ("x", "y", "height", "radius"):
            v = getattr(p, name)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                raise SceneError(
                    f"{where}: perch {i} {name}={v!r} is not a finite number; allowed: a "
                    "finite number of semispans"
                )
        if not 0.0 < p.radius <= 0.5:
            raise SceneError(
                f"{where}: perch {i} radius={p.radius:g}; allowed: 0 < radius <= 0.5 semispans"
            )
        if p.height - p.radius <= 0.0:
            raise SceneError(
                f"{where}: perch {i} height={p.height:g} puts its bar (radius {p.radius:g}) at "
                f"or below the ground; allowed: height > radius, above the ground z = 0"
            )
    for i, a in enumerate(scene.perches, 1):
        for j, b in enumerate(scene.perches[i:], i + 1):
            gap = math.hypot(a.x - b.x, max(0.0, abs(a.y - b.y) - 2.0 * BAR_HALF_LENGTH))
            if gap < PERCH_GAP - 1e-9:
                raise SceneError(
                    f"{where}: perch {j} at x={b.x:g}, y={b.y:g} is inside perch {i} at "
                    f"x={a.x:g}, y={a.y:g} (bars {gap:.3g} semispans apart); allowed: bars at "
                    f"least {PERCH_GAP:g} semispans apart horizontally"
                )


__all__ = [
    "BAR_HALF_LENGTH",
    "DEFAULT_SCENE",
    "GROUND_REST_Z",
    "PERCH_GAP",
    "POST_RADIUS",
    "Perch",
    "Scene",
    "SceneError",
    "TORSO_HALF_HEIGHT",
    "check_scene",
]
