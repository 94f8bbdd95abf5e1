"""The free body's static pitch stiffness in the pitch loop (issue 22, the pigeon's
attitude): measured on the held body with the stroke plane held in the world
(birdsim.flight.attitude_stiffness), counted as part of the plant by the gains
(birdsim.flight.attitude.damped_gains).

Tolerances: the closed-loop poles 1e-6 relative where they are simple and 2e-3 where a
double root's round-off goes as the square root of the polynomial's; the stiffness's
speed scaling 1e-6 relative (the tail's quasi-steady lift is exactly quadratic in the
airspeed below its angle cap); the measured values within 0.002 table units of what was
measured (docs/free-body.md)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim.flight.attitude import damped_gains

WA = 1.0 / (2 * math.pi * 2.0)  # omega_a of 2 wingbeats (AXIS_BEATS), reduced units


@pytest.mark.parametrize("damping", [0.0, 0.4])
@pytest.mark.parametrize("stiffness", [0.0, 0.5 * WA**2, 4.1 * WA**2])
def test_stiffness_gains_place_the_closed_loop_poles(damping, stiffness):
    """With the body's damping c and restoring stiffness k (per unit inertia) the loop
    ``s^3 + (c + Kd) s^2 + (k + Kp) s + Ki`` has a pole at -max(c, omega_a) and the roots
    of ``s^2 + 2 omega_a s + max(omega_a^2, k)``: the designed double pole while the
    stiffness is below the design's, else the body's natural frequency kept (the
    pigeon's cruise: k = 4.1 omega_a^2)."""
    g = damped_gains(np.full(3, WA), np.full(3, damping), np.full(3, stiffness))
    roots = np.sort_complex(
        np.roots([1.0, damping + g.kd[0], stiffness + g.kp[0], g.ki[0]]).astype(complex)
    )
    q = max(WA**2, stiffness)
    want = np.sort_complex(
        np.concatenate([[-max(damping, WA)], np.roots([1.0, 2 * WA, q]).astype(complex)])
    )
    double = q == WA**2
    np.testing.assert_allclose(roots, want, rtol=2e-3 if double else 1e-6, atol=1e-9)
    assert g.kp[0] >= 0 and g.kd[0] >= 0 and g.ki[0] > 0


def test_no_stiffness_is_the_damped_design_bit_for_bit():
    for c in (0.0, 0.03, 0.4):
        plain = damped_gains(np.full(3, WA), np.full(3, c))
        zero = damped_gains(np.full(3, WA), np.full(3, c), np.zeros(3))
        for k in ("kp", "kd", "ki"):
            np.testing.assert_array_equal(getattr(plain, k), getattr(zero, k))


def test_measured_pitch_stiffness_is_the_tails_and_restoring():
    """Cruise-like m3 wingbeat, seed bird and pigeon: the held body pitched with its
    stroke plane held in the world meets a restoring moment of about -0.020 weight x
    semispan per rad (the tail's angle of attack follows the body; the wings' wingbeat
    is the same in the world), a quarter of it at half the speed (the tail's lift goes as
    V^2) and none without air (hover: the tail has no flow)."""
    from birdsim.flight.attitude_stiffness import measured_pitch_stiffness
    from birdsim.flight.presets import demo_bird
    from birdsim.flight.simulate import FreeBird, SimConfig
    from birdsim.physics.bird import Bird

    p = np.array([0.12, 0.9, 0.35, 0.12])  # m3: pitch, flap_amp, twist_amp, stroke_plane
    for bird in (demo_bird(), Bird.from_toml("models/pigeon.toml")):
        with FreeBird("m3", bird, p, config=SimConfig(attitude="free")) as fb:
            cruise = measured_pitch_stiffness(fb, p, 0.12, 0.5)
            half = measured_pitch_stiffness(fb, p, 0.12, 0.25)
            still = measured_pitch_stiffness(fb, p, 1.2, 0.0)
        assert cruise == pytest.approx(-0.020, abs=0.002)  # seed -0.0200, pigeon -0.0206
        assert half == pytest.approx(cruise / 4, rel=1e-6)
        assert abs(still) < 1e-12


@pytest.mark.slow
def test_pigeon_free_cruise_meets_the_targets_and_stays():
    """The pigeon's cruise (m3, its table) with the attitude free, the issue's targets:
    altitude RMS within 1.5 x the posed 0.0041 m (measured 0.0052; main: 0.0187),
    wingbeat-mean pitch within 3 degrees RMS of the command after two wingbeats (1.58;
    main: 14.9), no attitude-saturated sample (main: 16), roll and yaw zero by symmetry,
    nothing on the root.  And it stays: flown for 20 wingbeats the rocking of wingbeats
    15-20 is about 6 degrees (before the slow-to-fast allocation: past 45 by wingbeat 11) and the
    wingbeat-mean pitch within 1 degree of the command (measured: 0.3)."""
    from birdsim.commands.fly import load_table_for
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import fly
    from birdsim.flight.presets import PATH_PRESETS
    from birdsim.flight.simulate import SimConfig
    from birdsim.physics.bird import Bird

    bird = Bird.from_toml("models/pigeon.toml")
    table = load_table_for(bird, "m3", None)

    def means(a, key):
        n = 64
        return np.array([a[key][b * n : (b + 1) * n].mean() for b in range(len(a["t"]) // n)])

    r = fly(PATH_PRESETS["cruise"], table, bird, "m3", config=SimConfig(attitude="free"))
    a = r.arrays
    pitch_err = (means(a, "pitch") - means(a, "pitch_command"))[2:]
    assert math.degrees(np.sqrt(np.mean(pitch_err**2))) < 3.0
    assert summary(log_arrays(r, "cruise"))["rms_altitude_error_after_start"] <= 1.5 * 0.0041
    assert not np.any(a["attitude_saturated"])
    assert np.abs(a["roll"]).max() < 1e-6 and np.abs(a["yaw"]).max() < 1e-6
    assert r.meta["root_applied_max"] == 0.0
    long = fly(
        PATH_PRESETS["cruise"], table, bird, "m3", beats=20, config=SimConfig(attitude="free")
    ).arrays
    late = slice(15 * 64, 20 * 64)
    rocking = [np.ptp(long["pitch"][late][i : i + 64]) for i in range(0, 5 * 64, 64)]
    assert math.degrees(max(rocking)) < 10.0
    late_err = (means(long, "pitch") - means(long, "pitch_command"))[15:]
    assert math.degrees(np.abs(late_err).max()) < 1.0
