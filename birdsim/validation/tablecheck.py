"""The shipped table's answer for level flight: a start for the optimiser and a cross-check.

For a bird whose reduced bird has a shipped table (``tables/pigeon-m3.npz``), the table is
looked up at the level-flight demand (table ``Fz = -w/2``, ``Fx = D(theta)/2`` with the
body drag at the looked-up pitch: two lookups, the second at the first one's drag) at
each speed inside its grid.  The interpolated parameters are one more start for the trim
solve ("look up and polish"); the interpolated power is reported beside the solve's, so a
reader sees how far multilinear interpolation of the table is from the direct optimum.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from birdsim.physics.aero import body_drag_x
from birdsim.physics.bird import Bird
from birdsim.physics.units import scales, weight_in_table_units
from birdsim.tables.lookup import LookupTable, TableError, load_table


@dataclass(frozen=True)
class TableLevelFlight:
    """Per speed [bird units]: the table's parameter row (or None outside its grid), the
    whole bird's interpolated power [W for an SI bird] (or None) and the demand looked up
    (table units: Fx, Fz, V; or None)."""

    path: str
    starts: tuple[np.ndarray | None, ...]
    power: tuple[float | None, ...]
    demands: tuple[tuple[float, float, float] | None, ...] = ()


def find_table(bird: Bird, model: str) -> LookupTable | None:
    """The shipped table built for ``bird``'s reduced bird and ``model``, or None."""
    from birdsim.tables.shipped import shipped_table

    try:
        table = load_table(shipped_table(bird, model))
        table.require_model(model)
        table.require_bird(bird)
    except TableError:
        return None
    return table


def level_flight_from_table(
    table: LookupTable, bird: Bird, speeds: Sequence[float], path: str | Path = ""
) -> TableLevelFlight:
    """Look the level-flight demand up at each speed (see the module docstring).

    Returns:
        TableLevelFlight with one entry per speed (None where the speed or the demand is
        outside the table's grid).
    """
    sc = scales(bird)
    w = weight_in_table_units(bird)
    i_pitch = table.param_names.index("pitch")
    starts: list[np.ndarray | None] = []
    powers: list[float | None] = []
    demands: list[tuple[float, float, float] | None] = []
    for v in speeds:
        v_red = v / sc.speed
        try:
            fx = fx_looked_up = 0.0
            for _ in range(2):
                fx_looked_up = fx
                out = table.lookup_many(fx, -w / 2.0, v_red)
                pitch = float(out[table.param_names[i_pitch]])
                fx = (
                    float(body_drag_x(np.array(v), np.array(pitch), bird.rho, bird.body_drag_area))
                    / 2.0
                    / sc.force
                )
        except TableError:
            starts.append(None)
            powers.append(None)
            demands.append(None)
            continue
        starts.append(np.array([float(out[n]) for n in table.param_names]))
        powers.append(2.0 * float(out["achieved_P"]) * sc.power)
        demands.append((fx_looked_up, -w / 2.0, float(v_red)))
    return TableLevelFlight(str(path), tuple(starts), tuple(powers), tuple(demands))


__all__ = ["TableLevelFlight", "find_table", "level_flight_from_table"]
