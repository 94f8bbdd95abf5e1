"""The tail's operating point for the attitude loop's Jacobians (issue 22, the pigeon's
attitude, fifth stage; birdsim.flight.tail_trim): at a steep held body the tail's angle of
attack is beyond the slender-wing cap, so its measured derivative is zero; measured at
the operating point it is the linear range's.

Tolerances: the operating point's arithmetic exact (1e-15); the measured derivatives
against zero to 1e-12 (a capped lift does not change at all) and above 0.004 table
units per rad (measured 0.0113 for the held seed bird at 40 degrees and 0.4 semispan
omega, the tail's V^2 scaling of the cruise's 0.021 at 0.5 and its 20-degree arm of
the lift curve); at a shallow body the operating point is zero and the measurement the
same bit for bit."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim.flight.attitude_jacobians import INPUTS, JAC_STEP, measured_jacobian
from birdsim.flight.tail_trim import (
    TRIM_ALPHA,
    operating_point,
    tail_elevation_range,
    tail_operating_elevation,
)
from birdsim.mujoco.tail import ALPHA_MAX, ELEVATION_MAX

TAIL = [name for name, _, _ in INPUTS].index("tail_elevation")


@pytest.mark.parametrize("deg", [-30.0, 0.0, 7.5, 10.0, 25.0, 35.0, 45.0, 89.0])
def test_operating_point_brings_the_tail_within_its_range(deg):
    pitch = math.radians(deg)
    e = tail_operating_elevation(pitch)
    top = ELEVATION_MAX - JAC_STEP
    if abs(pitch) <= TRIM_ALPHA:
        assert e == 0.0  # a shallow body: the loop's tail as before
    elif pitch > TRIM_ALPHA:
        assert e == pytest.approx(min(pitch - TRIM_ALPHA, top), abs=1e-15)
    else:  # nose down: the tail's angle of attack is negative, within -TRIM_ALPHA
        assert e == pytest.approx(max(pitch + TRIM_ALPHA, -top), abs=1e-15)
    lo, hi = tail_elevation_range(pitch)
    assert -ELEVATION_MAX <= lo <= hi <= ELEVATION_MAX
    if pitch - ALPHA_MAX <= ELEVATION_MAX:  # some elevation brings the tail within the cap
        assert lo - 1e-15 <= e <= hi + 1e-15
    u0 = operating_point(pitch)
    assert u0[TAIL] == e and np.count_nonzero(np.delete(u0, TAIL)) == 0


def test_steep_held_body_tail_derivative_is_zero_untrimmed_and_not_at_the_operating_point():
    from birdsim.flight.presets import demo_bird
    from birdsim.flight.simulate import FreeBird, SimConfig

    p = np.array([0.7, 0.9, 0.35, 0.12])  # m3: pitch, flap_amp, twist_amp, stroke_plane
    with FreeBird("m3", demo_bird(), p, config=SimConfig(attitude="free")) as fb:
        _, plain = measured_jacobian(fb, p, 0.7, 0.4)
        _, trimmed = measured_jacobian(fb, p, 0.7, 0.4, u0=operating_point(0.7))
        m_a, j_a = measured_jacobian(fb, p, 0.12, 0.4)
        m_b, j_b = measured_jacobian(fb, p, 0.12, 0.4, u0=operating_point(0.12))
    assert abs(plain[1, TAIL]) < 1e-12  # 40 degrees: the tail's lift at its cap
    assert trimmed[1, TAIL] > 0.004  # nose up per rad of elevation, as in cruise
    np.testing.assert_array_equal(m_a, m_b)
    np.testing.assert_array_equal(j_a, j_b)
