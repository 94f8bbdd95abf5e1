"""Stand-ins for the flight tests: a straight path and the table-force conversion
(the interface birdsim.flight.path / birdsim.flight.demand implement)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from birdsim.physics.aero import body_drag_x
from birdsim.physics.bird import Bird


@dataclass(frozen=True)
class State:
    x: float
    z: float
    vx: float
    vz: float
    ax: float
    az: float


@dataclass(frozen=True)
class StraightPath:
    """Level flight at speed ``v`` and height ``z0`` (reduced units)."""

    v: float = 0.9
    z0: float = 6.0
    duration_beats: float = 8.0
    name: str = "straight"
    perch_start: bool = False
    perch_end: bool = False

    def state(self, t: float) -> State:
        return State(self.v * t, self.z0, self.v, 0.0, 0.0, 0.0)


def to_table(ax_up: float, az_up: float, vx: float, vz: float, bird: Bird, pitch: float) -> tuple[float, float]:
    """m a = whole-bird aero + weight -> table force (one wing + body drag, seed axes)."""
    m = bird.mass
    fx_whole = m * ax_up
    fz_up_whole = m * (az_up + bird.gravity)
    drag = float(body_drag_x(math.hypot(vx, vz), abs(pitch), bird.rho, bird.body_drag_area))
    return 0.5 * (fx_whole + drag), -0.5 * fz_up_whole
