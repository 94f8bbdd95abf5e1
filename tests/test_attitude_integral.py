"""The attitude integral's bound (birdsim.flight.attitude.integral_bound): radians times
omega_a^2 per unit inertia, or the moment the axis's inputs deliver at their bounds."""

from __future__ import annotations

import math

import numpy as np

from birdsim.flight.attitude import (
    INTEGRAL_LIMIT_RAD,
    LAT_INPUTS,
    SYM_INPUTS,
    attitude_gains,
    integral_bound,
)

# the pigeon's cruise Jacobian as the loop measured it (reduced units; rows roll, pitch,
# yaw; columns flap_amp, twist_amp, sweep, tail_elevation, tail_roll, stroke_plane,
# dihedral) and its whole-bird principal moments with the wings
JAC = np.array(
    [
        [0.0049, 0.0258, 0.0, 0.0, 0.0, -0.1552, 0.0],
        [0.0, 0.0, -0.1498, 0.0206, 0.0001, 0.0, -0.06],
        [-0.0544, 0.0355, 0.0, 0.0, -0.0026, 0.0469, 0.0],
    ]
)
INERTIA = np.array([0.7532, 0.782, 1.3066])
HI = np.array([0.15, 0.15, 0.3, math.radians(30), math.radians(30), 0.15, 0.3])


def test_without_authority_the_bound_is_radians_times_omega_a_squared():
    wa = attitude_gains(1.0).omega_a
    got = integral_bound(wa, JAC, -HI, HI, INERTIA, authority=False)
    np.testing.assert_array_equal(got, INTEGRAL_LIMIT_RAD * wa**2)


def test_authority_bound_is_each_axis_own_inputs_at_their_bounds():
    wa = attitude_gains(1.0).omega_a
    got = integral_bound(wa, JAC, -HI, HI, INERTIA, authority=True)
    # by hand: pitch from the symmetric inputs only, roll and yaw from the differential
    pitch = (0.1498 * 0.3 + 0.0206 * math.radians(30) + 0.06 * 0.3) / 0.782
    roll = sum(abs(JAC[0, c]) * HI[c] for c in LAT_INPUTS) / 0.7532
    yaw = sum(abs(JAC[2, c]) * HI[c] for c in LAT_INPUTS) / 1.3066
    np.testing.assert_allclose(got, [roll, pitch, yaw], rtol=1e-12)
    # the pigeon's pitch: the radians' bound is a moment of 0.0025 table units, the
    # inputs deliver 30 times more (the flown bias was 0.002-0.008, docs/free-body.md)
    assert INTEGRAL_LIMIT_RAD * wa[1] ** 2 * 0.782 < 0.0026
    assert got[1] > 25 * INTEGRAL_LIMIT_RAD * wa[1] ** 2
    # a symmetric input never enters the lateral bound and vice versa
    assert set(SYM_INPUTS).isdisjoint(LAT_INPUTS)


def test_authority_bound_never_below_the_radians_bound():
    wa = attitude_gains(1.0).omega_a
    got = integral_bound(wa, np.zeros((3, 7)), -HI, HI, INERTIA, authority=True)
    np.testing.assert_array_equal(got, INTEGRAL_LIMIT_RAD * wa**2)


def test_authority_bound_per_axis_pitch_only():
    """The loop's setting (INTEGRAL_AUTHORITY): the pitch integral bounded by the
    symmetric inputs' authority, roll and yaw by the radians' bound as before."""
    from birdsim.flight.attitude import INTEGRAL_AUTHORITY

    wa = attitude_gains(1.0).omega_a
    got = integral_bound(wa, JAC, -HI, HI, INERTIA, authority=(False, True, False))
    every = integral_bound(wa, JAC, -HI, HI, INERTIA, authority=True)
    radians = INTEGRAL_LIMIT_RAD * wa**2
    np.testing.assert_array_equal(got, [radians[0], every[1], radians[2]])
    assert tuple(INTEGRAL_AUTHORITY) == (False, True, False)
