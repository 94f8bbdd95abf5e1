"""The side gust's measures in `scripts/turn_gust_study.py` (docs/turning.md, "Gust stage,
fourteenth pass"): the distance from the calm flight at the same time (the study's) and
from the calm flight's track (an along-track lag alone does not count there), and the
per-wingbeat offsets along, to the left and up."""

from __future__ import annotations

import numpy as np
import pytest
from script_module import load_script

TWO_PI = 2.0 * np.pi


@pytest.fixture(scope="module")
def study():
    return load_script("turn_gust_study")


def _circle(radius: float, lag: float = 0.0, beats: float = 40.0, per_beat: int = 32) -> dict:
    """A level circle flown counter-clockwise (left) at 0.5 semispan per time unit,
    ``lag`` radians behind; reduced arrays as ``fly`` logs them."""
    t = np.arange(int(beats * per_beat)) * TWO_PI / per_beat
    w = 0.5 / 12.0  # the calm circle's radius 12
    a = w * t - lag
    return {
        "t": t,
        "x": radius * np.sin(a),
        "y": 12.0 - radius * np.cos(a),
        "z": np.full(len(t), 3.0),
        "vx": radius * w * np.cos(a),
        "vy": radius * w * np.sin(a),
        "saturated": np.zeros(len(t), dtype=bool),
    }


def test_an_along_track_lag_counts_at_the_same_time_not_from_the_track(study):
    calm = _circle(12.0)
    late = _circle(12.0, lag=0.01)  # 0.12 semispan behind on the same circle
    f = study.gust_figures(calm, late, 20.0)
    assert f["after_8"] == pytest.approx(0.12, rel=1e-3)
    assert f["after_8_along"] == pytest.approx(0.12, rel=1e-3)
    assert f["after_8_lateral"] < 1e-3
    assert f["after_8_track"] < 1e-3


def test_a_side_offset_counts_in_both_measures_and_per_wingbeat(study):
    calm = _circle(12.0)
    inside = _circle(11.94)  # 0.06 semispan to the left (inside the left turn)
    f = study.gust_figures(calm, inside, 20.0)
    assert f["after_8"] == pytest.approx(0.06, rel=1e-3)
    assert f["after_8_track"] == pytest.approx(0.06, rel=1e-3)
    rows = np.array(f["per_beat"])  # (along, lateral, height) per wingbeat after the gust
    assert rows.shape == (study.PER_BEAT, 3)
    assert np.allclose(rows[:, 1], 0.06, atol=1e-3) and np.allclose(rows[:, [0, 2]], 0.0, atol=1e-3)
