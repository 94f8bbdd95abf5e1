"""`scripts/estimate_response.py` (docs/turning.md, 2026-12-03, p23p): the attitude
estimate's response to a slow swing, against the closed forms it stands for."""

from __future__ import annotations

import math

import numpy as np
import pytest
from script_module import load_script


@pytest.fixture(scope="module")
def er():
    return load_script("estimate_response")


def test_the_fit_rejects_the_wingbeat_s_first_three_harmonics_and_passes_a_constant(er):
    tau = er.sample_times(64)
    from birdsim.flight.body_attitude import wingbeat_fit_matrix

    fit = wingbeat_fit_matrix(len(tau), 1.0)[0]
    assert fit @ np.ones(len(tau)) == pytest.approx(1.0, abs=1e-12)
    for k in (1, 2, 3):
        assert abs(fit @ np.exp(2j * math.pi * k * tau)) < 1e-10
    assert fit @ tau == pytest.approx(0.0, abs=1e-12)  # a ramp is read at now, no lag


def test_the_mean_carried_by_the_rate_is_its_closed_form_and_zero_at_harmonics(er):
    for period in (2.0, 5.3):
        tau = np.arange(-1.0, 0.0, 1e-5) + 0.5e-5  # midpoints over the last wingbeat
        w = 2.0 * math.pi / period
        x = np.exp(1j * w * tau)
        numeric = x.mean() + 0.5 * (1j * w * x).mean()
        assert er.mean_response(period) == pytest.approx(numeric, abs=1e-8)
    assert abs(er.mean_response(1.0)) < 1e-12
    assert abs(er.mean_response(0.5)) < 1e-12


def test_at_the_circle_s_swing_the_fit_lags_three_degrees_as_the_mean_does(er):
    # docs/turning.md p23p: 5.3 wingbeats, fit -3.1 deg (gain 1.09), mean+rate -3.3
    fit, mean = er.fit_response(5.3, 64), er.mean_response(5.3)
    assert math.degrees(np.angle(fit)) == pytest.approx(-3.1, abs=0.1)
    assert math.degrees(np.angle(mean)) == pytest.approx(-3.3, abs=0.1)
    assert abs(fit) == pytest.approx(1.091, abs=0.002)


def test_the_smoothing_and_the_hold_lag_as_first_order_stages_and_half_a_step(er):
    assert math.degrees(er.smoothing_phase(5.3, 0.125)) == pytest.approx(
        -2 * math.degrees(math.atan(2 * math.pi * 0.125 / 5.3))
    )
    assert er.hold_phase(4.0, 8) == pytest.approx(-2 * math.pi / 4.0 * (0.5 / 8))
