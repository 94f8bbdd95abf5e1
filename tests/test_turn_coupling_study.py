"""`scripts/turn_coupling_study.py` (docs/turning.md, "The calm circle's swing: the height
loop's sideways share", 2026-12-03): its per-wingbeat means and the sideways part of the
path loop's vertical correction, ``dv sin|bank|``."""

from __future__ import annotations

import math

import numpy as np
import pytest
from script_module import load_script


@pytest.fixture(scope="module")
def study():
    return load_script("turn_coupling_study")


def test_the_vertical_correction_turns_sideways_by_the_sine_of_the_bank(study):
    per = 16  # control steps per wingbeat
    t = np.arange(3 * per) / per  # wingbeats 0-2
    bank = np.radians(np.where(t < 1.0, 0.0, -40.0))  # level, then a left bank of 40 degrees
    dv = np.where(t < 2.0, 1e-3, 2e-3)  # the path loop's push up
    steps = np.stack([t, 0.1 * t, 0 * t, 0 * t, 0 * t, dv, 0 * t, bank], 1)
    rows = study.per_beat(steps)
    assert rows.shape == (3, 9)
    assert rows[:, 0].tolist() == [0.0, 1.0, 2.0]
    assert rows[1, 1] == pytest.approx(0.1 * (1.0 + 0.5 * (per - 1) / per))  # the mean of y
    # level: nothing sideways; banked 40 degrees: sin(40) = 0.643 of the push, either sign
    assert rows[0, 8] == 0.0
    assert rows[1, 8] == pytest.approx(1e-3 * math.sin(math.radians(40.0)), rel=1e-12)
    assert rows[2, 8] == pytest.approx(2e-3 * math.sin(math.radians(40.0)), rel=1e-12)


def test_the_study_flies_the_bird_and_preset_it_is_given(study, monkeypatch):
    flown = []

    def fake_fly(bird_file, preset):
        flown.append((bird_file, preset))
        return "flight"

    monkeypatch.setattr(study, "fly_preset", fake_fly)
    result, steps = study.fly_recorded("models/pigeon.toml", "s-turn")
    assert flown == [("models/pigeon.toml", "s-turn")]
    assert result == "flight" and len(steps) == 0
    study.fly_recorded()  # the seed bird's circle by default
    assert flown[-1] == (None, "circle")


def test_the_scripts_offer_every_turning_preset_and_no_other(study):
    from birdsim.flight.turn_presets import TURN_PRESETS

    assert sorted(study.TURN_NAMES) == sorted(TURN_PRESETS)
