"""The pitch authority bound (birdsim.flight.pitch_feasibility) on cases with a closed
form: the linear authority against every corner of the inputs' box, the least tracking
error of a body short of authority against the double integral of its shortfall, the
error response of a restoring stiffness against the undamped oscillator, the command's
wingbeat differences on a parabola."""

from __future__ import annotations

import itertools
import math

import numpy as np

from birdsim.flight.pitch_feasibility import (
    beat_differences,
    corner_inputs,
    error_response,
    least_tracking_error,
    pitch_authority,
    required_moment,
)


def test_authority_is_the_extreme_over_the_corners_of_the_box():
    rng = np.random.default_rng(3)
    for _ in range(20):
        row = rng.normal(size=3) * 0.1
        lo = -rng.uniform(0.05, 0.5, size=3)
        hi = rng.uniform(0.05, 0.5, size=3)
        corners = [row @ np.array(c) for c in itertools.product(*zip(lo, hi))]
        down, up = pitch_authority(row, lo, hi)
        assert math.isclose(down, min(corners), abs_tol=1e-15)
        assert math.isclose(up, max(corners), abs_tol=1e-15)
        assert math.isclose(row @ corner_inputs(row, lo, hi, True), up, abs_tol=1e-15)
        assert math.isclose(row @ corner_inputs(row, lo, hi, False), down, abs_tol=1e-15)
    # an input of zero bounds adds nothing
    got = pitch_authority(np.array([0.2, -0.1]), np.array([-0.3, 0.0]), np.array([0.3, 0.0]))
    assert np.allclose(got, (-0.06, 0.06), atol=1e-15)


def test_within_authority_the_bound_is_zero():
    req = np.array([0.001, -0.002, 0.003])
    rms, err, m = least_tracking_error(req, -0.01, 0.01, 0.8, 0.5)
    assert rms == 0.0 and not err.any() and np.array_equal(m, req)


def test_a_body_short_of_authority_falls_behind_by_the_shortfall_integrated_twice():
    # a command needing c = 0.01 against an authority of a = 0.004 (no damping or
    # stiffness): the best is the whole authority all along, error (a - c) t^2 / 2 I
    inertia, dt, n, c, a = 0.78, 0.3, 40, 0.01, 0.004
    req = np.full(n, c)
    rms, err, m = least_tracking_error(req, np.full(n, -a), np.full(n, a), inertia, dt)
    t = dt * np.arange(1, n + 1)
    exact = (a - c) * t**2 / (2 * inertia)
    assert np.allclose(m, a, atol=1e-9)
    assert np.allclose(err, exact, rtol=1e-6, atol=1e-12)
    assert math.isclose(rms, math.sqrt(np.mean(exact**2)), rel_tol=1e-6)
    # the error scales with the shortfall: half of it, half the error
    rms2, *_ = least_tracking_error(
        np.full(n, a + 0.5 * (c - a)), np.full(n, -a), np.full(n, a), inertia, dt
    )
    assert math.isclose(rms2, 0.5 * rms, rel_tol=1e-6)


def test_error_response_of_a_restoring_stiffness_is_the_oscillator():
    # a unit moment held from t = 0 on I e'' = K e + 1, K < 0: e = (1 - cos wt) / |K|
    inertia, k, dt, n = 0.78, -0.02, 0.25, 60
    g = error_response(inertia, dt, np.zeros(n), np.full(n, k))
    t = dt * np.arange(1, n + 1)
    w = math.sqrt(-k / inertia)
    assert np.allclose(g.sum(axis=1), (1 - np.cos(w * t)) / -k, rtol=1e-9, atol=1e-12)
    # causal: a moment at step j moves no error before the end of step j
    assert np.all(np.triu(g, 1) == 0.0)


def test_required_moment_and_the_wingbeat_differences_of_a_parabola():
    period = 2 * math.pi
    means = 0.01 * np.arange(10) ** 2  # rad per wingbeat mean: acceleration 0.02 / period^2
    rate, acc = beat_differences(means, period)
    assert np.allclose(acc[1:-1], 0.02 / period**2)
    assert np.allclose(rate[1:-1], 0.02 * np.arange(1, 9) / period)
    need = required_moment(0.78, acc, rate, -0.003, 0.05)
    assert np.allclose(need, 0.78 * acc + 0.003 - 0.05 * rate)
