"""The body's rocking's rectified pitching moment (birdsim.flight.pitch_rocking) and the
slow straight flight's pitch loop that counts it (birdsim.flight.pitch_section;
docs/free-body.md, "The pigeon's attitude, tenth stage")."""

from __future__ import annotations

import math

import numpy as np
import pytest

# the pigeon's take-off, wingbeat 14.5 (m3: pitch, flap_amp, twist_amp, stroke_plane as
# the attitude loop measured its Jacobians there), the commanded pitch, the airspeed
TAKE_OFF = (np.array([0.6432, 1.2699, 0.7854, 0.4407]), 0.5526, 0.3946)


def test_the_rocking_moment_is_nose_down_in_the_climb_out_and_scales_with_the_rocking():
    """At the pigeon's take-off speeds the held body's rocking (its periodic solution,
    peak to peak 22 degrees; the flight shows 12-20) times the per-phase angle and rate
    derivatives has a mean of about -0.007 table units, nose down: the moment the section
    loop's model missed in flight (-0.001 to -0.012).  Linear in the rocking: with twice
    the inertia the rocking and the moment halve.  No air, a symmetric wingbeat: none."""
    from birdsim.flight.pitch_rocking import rocking_pitch_moment
    from birdsim.flight.simulate import FreeBird, SimConfig
    from birdsim.physics.bird import Bird

    bird = Bird.from_toml("models/pigeon.toml")
    params, pitch, speed = TAKE_OFF
    with FreeBird("m3", bird, params, config=SimConfig(attitude="free")) as fb:
        inertia = 0.782  # the pigeon's reduced pitch inertia (the attitude loop's)
        moment, ptp = rocking_pitch_moment(fb, params, pitch, speed, inertia)
        moment2, ptp2 = rocking_pitch_moment(fb, params, pitch, speed, 2.0 * inertia)
        still, _ = rocking_pitch_moment(fb, params, pitch, 0.0, inertia)
    assert -0.010 < moment < -0.004, moment  # measured -0.00700
    assert 15.0 < math.degrees(ptp) < 30.0, math.degrees(ptp)  # 21.8
    assert ptp2 / ptp == pytest.approx(0.5, abs=0.05)
    assert moment2 / moment == pytest.approx(0.5, abs=0.1)
    assert abs(still) < 0.002  # hover-like: the rocking's moment is small without air


@pytest.mark.slow  # ~10 s on this machine, with the table's load
def test_pigeon_take_off_pitch_with_the_rocking_moment():
    """The pigeon's free take-off (m3): wingbeat-mean pitch 4.43 degrees RMS from the
    command after two wingbeats (7.79 without the rocking's moment, 6.09 with it measured
    only at the Jacobians' 0.1 rad steps: this fails on both; the issue's target is 3),
    no saturated sample, the path within 1.5 x the posed."""
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
    assert att["wingbeat_mean_pitch_rms_error_deg"] < 5.5
    assert att["attitude_saturated_samples"] == 0 and s["wingbeats_saturated"] == 0
    assert s["rms_error_after_start"] < 0.0228
    assert r.meta["root_applied_max"] == 0.0


def test_the_periodic_rocking_rate_is_its_pitch_changing_and_makes_the_rectified_moment():
    """:func:`periodic_rocking` (the per-phase solution ``scripts/rocking_drift.py`` reads;
    docs/free-body.md, "the rocking's drift measured"): the rate is the pitch's time
    derivative (centred differences over the phases within 15 % of the rate's peak to
    peak: 16 phases per wingbeat), both have a mean of 0, and
    :func:`rocking_pitch_moment` is the mean of its derivatives times them, bit for bit."""
    from birdsim.flight.pitch_rocking import periodic_rocking, rocking_pitch_moment
    from birdsim.flight.simulate import FreeBird, SimConfig
    from birdsim.physics.bird import Bird

    bird = Bird.from_toml("models/pigeon.toml")
    params, pitch, speed = TAKE_OFF
    with FreeBird("m3", bird, params, config=SimConfig(attitude="free")) as fb:
        d_q, d_th, theta, rate = periodic_rocking(fb, params, pitch, speed, 0.782)
        moment, ptp = rocking_pitch_moment(fb, params, pitch, speed, 0.782)
        dt = fb.red.period / len(theta)
    slope = (np.roll(theta, -1) - np.roll(theta, 1)) / (2.0 * dt)
    assert np.max(np.abs(slope - rate)) < 0.15 * np.ptp(rate)
    assert abs(theta.mean()) < 1e-12 and abs(rate.mean()) < 1e-12
    assert moment == float(np.mean(d_q * rate + d_th * theta)) and ptp == float(np.ptp(theta))
