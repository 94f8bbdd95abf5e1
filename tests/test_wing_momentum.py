"""The wings' wingbeat-mean angular momentum relative to the torso
(:mod:`birdsim.flight.wing_momentum`; docs/free-body.md, 2026-12-03): zero for a wing
that flaps and twists (time symmetry), a pitch-axis mean for m5's folding wing (mirror
symmetry keeps roll and yaw zero; the fold carries it), and its change fed to the attitude loop keeps the
pigeon's free m5 landing on its path (it fell, 13.75 m, without)."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.commands.common import load_bird, load_table_for
from birdsim.flight.simulate import FreeBird, SimConfig
from birdsim.flight.wing_momentum import (
    ROUNDOFF,
    WingMomentumRate,
    has_mean_momentum,
    mean_wing_momentum,
)


def _held(model: str, fz: float):
    bird = load_bird("models/seed-bird.toml")
    table = load_table_for(bird, model, None)
    row = table.lookup(Fx=0.0, Fz=fz, V=0.5)
    return bird, np.array(list(row.values()))


def test_a_flapping_twisting_wing_has_no_mean_momentum_and_a_folding_one_pitches():
    bird, params = _held("m3", -0.2)
    with FreeBird("m3", bird, params, config=SimConfig(attitude="free")) as fb:
        assert np.all(np.abs(mean_wing_momentum(fb, params)) < ROUNDOFF)
    bird, params = _held("m5", -0.1)
    with FreeBird("m5", bird, params, config=SimConfig(attitude="free")) as fb:
        h = mean_wing_momentum(fb, params)
        assert abs(h[1]) > 1e-3  # measured 0.032 table units
        assert abs(h[0]) < ROUNDOFF and abs(h[2]) < ROUNDOFF
        # the fold carries it: unfolded (m4's wing; its lagging wrist leaves 3.6e-4)
        names = fb.schedule.names
        unfolded = params.copy()
        unfolded[names.index("fold_amp")] = 0.0
        assert abs(mean_wing_momentum(fb, unfolded)[1]) < 0.05 * abs(h[1])


@pytest.mark.parametrize("model", ["base", "m1", "m2", "m3"])
def test_shoulder_only_models_skip_a_mean_their_symmetry_makes_zero(model):
    """The models :func:`has_mean_momentum` skips (no computation in flight) have a mean of
    round-off at two demands (measured below 2e-17); m4 and m5 are computed."""
    for fz in (-0.1, -0.3):
        bird, params = _held(model, fz)
        with FreeBird(model, bird, params, config=SimConfig(attitude="free")) as fb:
            assert not has_mean_momentum(fb.schedule.names)
            assert np.all(np.abs(mean_wing_momentum(fb, params)) < ROUNDOFF)
    assert has_mean_momentum(("pitch", "wrist_amp")) and has_mean_momentum(("fold_amp",))


def test_the_rate_is_the_change_over_the_step_and_ignores_round_off(monkeypatch):
    values = iter([np.array([0.0, 0.010, 0.0]), np.array([1e-14, 0.013, 0.0])])
    monkeypatch.setattr(
        "birdsim.flight.wing_momentum.mean_wing_momentum", lambda fb, p, d=None: next(values)
    )
    rate = WingMomentumRate(active=True)
    assert not rate.step(None, np.zeros(1), 0.5).any()  # the first step: nothing to compare
    assert rate.step(None, np.zeros(1), 0.5) == pytest.approx([0.0, 0.006, 0.0])


def _pigeon_m5_landing() -> dict:
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import fly
    from birdsim.flight.presets import PATH_PRESETS

    bird = load_bird("models/pigeon.toml")
    table = load_table_for(bird, "m5", None)
    result = fly(PATH_PRESETS["landing"], table, bird, "m5", config=SimConfig(attitude="free"))
    return summary(log_arrays(result, "landing"))


def test_the_pigeon_s_free_m5_landing_stays_on_its_path():
    s = _pigeon_m5_landing()
    # measured 0.048 m (64 saturated samples of 2560)
    assert s["rms_error_after_start"] < 0.1
    assert s["saturated_samples"] < 256


def test_without_the_momentum_rate_the_pigeon_s_free_m5_landing_falls(monkeypatch):
    """Switched off (every change counted as round-off), the fold's momentum change kicks
    the torso's pitch and the landing departs: measured 13.75 m, 1984 saturated samples."""
    monkeypatch.setattr("birdsim.flight.wing_momentum.ROUNDOFF", float("inf"))
    s = _pigeon_m5_landing()
    assert s["rms_error_after_start"] > 1.0
