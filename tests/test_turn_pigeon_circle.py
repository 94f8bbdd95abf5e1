"""The pigeon's ``circle`` (issue 23): a bird on the fourth-stage pitch loop (the
pigeon) turns with the pitch time constant of
:data:`birdsim.flight.turning.FOURTH_STAGE_TURN_AXIS_BEATS` (2.5 wingbeats; 2.25 before).

Tolerances: the preset's path RMS after two wingbeats is bounded at 0.13 semispan, a
quarter above the measured 0.0351 m = 0.106 semispan (the issue's target is 0.1; with
the pitch at 2.25 wingbeats 0.0636 m = 0.193 semispan with 8 saturated samples, and 2.4 /
2.6 gave 0.101 / 0.113 semispan: docs/turning.md, "The pigeon's cruise turns: the pitch
loop's time constant"), no saturated sample.
"""

from __future__ import annotations

import pytest


@pytest.mark.slow
def test_the_pigeon_flies_its_circle_unsaturated():
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import fly
    from birdsim.flight.simulate import SimConfig
    from birdsim.flight.turn_presets import TURN_PRESETS

    bird = load_bird("models/pigeon.toml")
    table = load_table_for(bird, "m3", None)
    result = fly(TURN_PRESETS["circle"], table, bird, "m3", config=SimConfig(attitude="free"))
    info = summary(log_arrays(result, "circle"))
    assert info["saturated_samples"] == 0
    assert info["rms_error_after_start"] / bird.semispan <= 0.13
