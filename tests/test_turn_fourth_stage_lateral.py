"""The pigeon's cruise turns on the flown prediction (issue 23): a bird on the
fourth-stage pitch loop (the pigeon) hands its lateral inputs to
:mod:`birdsim.flight.flown_lateral` in its cruise turns too
(:func:`birdsim.flight.turning.flown_lateral_loop`), its roll and yaw integral held while
it does; the seed bird's turns (second-stage loop) and straight flight keep theirs.

Tolerances: which loops may engage is exact; the pigeon's 360-degree turn at cruise
speed on R = 35 semispans is bounded by the issue's tracking target (path RMS after two
wingbeats 0.1 semispan; measured 0.0242 m = 0.073 semispan, none saturated; without the
change it diverged inside the turn, 7.0 m RMS; docs/turning.md, "The pigeon's cruise
turns on the flown prediction"), no saturated sample.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from birdsim.flight import turning
from birdsim.flight.presets import CRUISE_SPEED
from birdsim.flight.turn_presets import level_turns
from birdsim.flight.turning import flown_lateral_loop

TWO_PI = 2.0 * math.pi


def test_which_loops_hand_their_lateral_inputs_over(monkeypatch):
    fourth, second = SimpleNamespace(straight=True), SimpleNamespace(straight=False)
    assert flown_lateral_loop(fourth, turn=False)  # straight flight's loop
    assert not flown_lateral_loop(second, turn=False)
    assert flown_lateral_loop(second, turn=True)  # the seed bird's turns, the slow turns
    assert flown_lateral_loop(fourth, turn=True)  # the pigeon's cruise turns
    monkeypatch.setattr(turning, "FOURTH_STAGE_FLOWN_LATERAL", False)
    assert not flown_lateral_loop(fourth, turn=True)
    assert flown_lateral_loop(second, turn=True)


@pytest.mark.slow
def test_the_pigeon_flies_a_360_at_cruise_speed_on_r35():
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import fly
    from birdsim.flight.simulate import SimConfig

    bird = load_bird("models/pigeon.toml")
    table = load_table_for(bird, "m3", None)
    path = level_turns("r35", [TWO_PI], CRUISE_SPEED, 35.0, 6.0, "test")
    log = log_arrays(fly(path, table, bird, "m3", config=SimConfig(attitude="free")), "t")
    info = summary(log)
    assert info["saturated_samples"] == 0
    assert info["rms_error_after_start"] / bird.semispan <= 0.1
