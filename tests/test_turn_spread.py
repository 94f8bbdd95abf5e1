"""`scripts/turn_spread.py` (docs/turning.md, 2026-12-03, p23c2): the perturbed flights
nudge one constant each by its factor and put it back."""

from __future__ import annotations

import pytest
from script_module import load_script

from birdsim.flight import bank, turning


@pytest.fixture(scope="module")
def spread():
    return load_script("turn_spread")


def test_a_nudge_scales_a_number_or_a_triple_s_middle_entry(spread):
    assert spread.nudged(6.0, 6.01 / 6.0) == pytest.approx(6.01, rel=1e-15)
    assert spread.nudged((1.0, 2.5, 2.0), 2.49 / 2.5) == pytest.approx((1.0, 2.49, 2.0))


def test_each_flight_sees_one_nudged_constant_and_all_are_restored(spread, monkeypatch):
    lateral, axes = bank.LATERAL_BEATS, turning.FOURTH_STAGE_TURN_AXIS_BEATS
    seen = []

    def fake(preset, bird_file, model="m3"):
        seen.extend([bank.LATERAL_BEATS, turning.FOURTH_STAGE_TURN_AXIS_BEATS[1]])
        return 0.005 * len(seen), 0

    monkeypatch.setattr(spread, "fly_figures", fake)
    rows = spread.spread("circle", None)
    assert [r[1] for r in rows] == pytest.approx([0.01, 0.02, 0.03, 0.04, 0.05])
    assert seen == pytest.approx(
        [lateral, axes[1], 5.99, axes[1], 6.01, axes[1], lateral, 2.49, lateral, 2.51]
    )
    assert bank.LATERAL_BEATS == lateral and turning.FOURTH_STAGE_TURN_AXIS_BEATS == axes


def test_every_flight_is_flown_with_the_model_asked_for(spread, monkeypatch):
    models = []

    def fake(preset, bird_file, model="m3"):
        models.append(model)
        return 0.01, 0

    monkeypatch.setattr(spread, "fly_figures", fake)
    spread.spread("circle", None, "m5")
    assert models == ["m5"] * 5
