"""The rocking's rectified moment kept in the attitude loop's M_0 after the slow pitch loop
hands back (birdsim.flight.rocking_share; docs/free-body.md, "The pigeon's attitude,
eleventh stage")."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim.flight.rocking_share import ROCK_DFLAP, ROCK_LAG_BEATS, RockingShare


def test_the_share_follows_a_new_measurement_through_its_lag_and_goes_stale_with_the_flap():
    """Started at the slow loop's moment; a new measurement is followed through a first
    order lag of ROCK_LAG_BEATS wingbeats (1 - 1/e of the way after that time), on the
    pitch axis only; stale once the flap amplitude has moved by more than ROCK_DFLAP."""
    period = 2.0 * math.pi
    share = RockingShare(-0.006, 1.0)
    assert share.step(0.1, period) == pytest.approx([0.0, -0.006, 0.0])
    share.target = -0.001  # what RockingShare.measure stores
    steps = 80
    for _ in range(steps):
        m = share.step(ROCK_LAG_BEATS * period / steps, period)
    assert m[0] == 0.0 and m[2] == 0.0
    assert m[1] == pytest.approx(-0.006 + 0.005 * (1.0 - math.exp(-1.0)), rel=1e-9)
    assert not share.stale(1.0 - 0.9 * ROCK_DFLAP)
    assert share.stale(1.0 - 1.1 * ROCK_DFLAP)
    assert not share.stale(None) and not RockingShare(0.0, None).stale(0.2)


def _per_beat_pitch_error_deg(arrays: dict) -> np.ndarray:
    """The wingbeat-mean pitch minus the command per whole wingbeat (degrees), as
    attitude_summary.attitude_figures computes it."""
    from birdsim.flight.attitude_summary import unfolded_euler

    t = np.asarray(arrays["t"], dtype=float)
    n = int(round(t.size / (t[-1] / (2.0 * math.pi))))
    beats = t.size // n
    _, pitch, _ = unfolded_euler(arrays["yaw"], arrays["pitch"], arrays["roll"])
    cmd = np.asarray(arrays["pitch_command"], dtype=float)
    err = pitch[: beats * n].reshape(beats, n).mean(1) - cmd[: beats * n].reshape(beats, n).mean(1)
    return np.degrees(err)


@pytest.mark.slow  # ~10 s on this machine, with the table's load
def test_pigeon_take_off_end_with_the_rocking_moment_kept_in_m0():
    """The pigeon's free take-off (m3): its wingbeat turns from the climb's (flap about
    1.1 rad) into the cruise's (0.2-0.4) in wingbeats 23-25, after the slow loop handed
    back at wingbeat 19.  With the rocking's moment in the integral (the tenth stage) the
    body fell 10.9 degrees below the command there (wingbeat 24) and the whole flight's
    pitch was 4.43 degrees RMS off; kept in M_0, lagged: 6.4 and 3.81 (this fails on the
    tenth stage's code).  The climb (air path up to 10.8 degrees, wingbeats 11-16) left
    the body 5.0, 8.6 and 6.2 degrees low in wingbeats 12-14 with the slow loop's model
    measured in horizontal air; at the air path's angle (birdsim.flight.air_angle) 2.5,
    3.1, 0.3 and the flight 2.81 RMS, the issue's 3 (this fails on the eleventh stage's
    code).  No saturated sample, the path within 1.5 x the posed."""
    from birdsim.commands.fly import load_table_for
    from birdsim.flight.attitude_summary import attitude_figures
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import fly
    from birdsim.flight.presets import PATH_PRESETS
    from birdsim.flight.simulate import SimConfig
    from birdsim.physics.bird import Bird

    bird = Bird.from_toml("models/pigeon.toml")
    table = load_table_for(bird, "m3", None)
    r = fly(PATH_PRESETS["take-off"], table, bird, "m3", config=SimConfig(attitude="free"))
    att = attitude_figures(r.arrays)
    s = summary(log_arrays(r, "take-off"))
    per_beat = _per_beat_pitch_error_deg(r.arrays)
    end, climb = per_beat[-3:], per_beat[12:15]
    assert np.abs(end).max() < 8.0, end  # measured -0.5, -4.7, -0.2 (tenth stage -5.4, -10.9, +4.6)
    assert np.abs(climb).max() < 4.0, climb  # measured -2.5, -3.1, -0.3 (before -5.0, -8.6, -6.2)
    assert att["wingbeat_mean_pitch_rms_error_deg"] < 3.0  # 2.81 (before 3.81, 4.43)
    assert att["attitude_saturated_samples"] == 0 and s["wingbeats_saturated"] == 0
    assert s["rms_error_after_start"] < 0.0228
    assert r.meta["root_applied_max"] == 0.0
