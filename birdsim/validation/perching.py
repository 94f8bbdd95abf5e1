"""The perching rows' birdsim values (issue 25): the bird's take-off and landing with
legs (``birdsim fly take-off --legs``, ``fly landing --legs``), flown with the demo
model m3 and the bird's shipped m3 table (the model the presets are laid out for)."""

from __future__ import annotations

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.units import scales

#: The model the perching flights use (every preset is laid out for it).
PERCH_MODEL = "m3"


def perch_values(bird: Bird) -> dict[str, float]:
    """birdsim's values of the perching rows by compare key, in the rows' units; empty
    when the bird cannot fly the presets (no m3 table, a flight that fails)."""
    from birdsim.commands.common import load_table_for
    from birdsim.flight.perch_landing import land
    from birdsim.flight.perched import take_off
    from birdsim.flight.presets import PATH_PRESETS

    try:
        table = load_table_for(bird, PERCH_MODEL, None)
        up = take_off(PATH_PRESETS["take-off"], table, bird, PERCH_MODEL).meta["legs"]
        down = land(PATH_PRESETS["landing"], table, bird, PERCH_MODEL).meta["legs"]
    except BirdsimError:
        return {}
    return {
        "perch_leg_share": 100.0 * up["leg_share"],
        "perch_takeoff_peak_force": up["peak_foot_force_over_weight"],
        "perch_touchdown_speed": down["touchdown_speed"] * scales(bird).speed,
        "perch_landing_over_takeoff_force": down["peak_foot_force_over_weight"]
        / up["peak_foot_force_over_weight"],
    }


__all__ = ["PERCH_MODEL", "perch_values"]
