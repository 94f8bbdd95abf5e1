"""The attitude loop's staleness check (issue 22, gusts after the fourth-stage pitch
loop): the Jacobians are re-measured when, at the wingbeat measured at now, they
under-predict the moment of the inputs in use (birdsim.flight.attitude_refresh).

The wingbeats are the seed bird's free cruise's (m3: pitch, flap_amp, twist_amp,
stroke_plane, the stroke plane compensated for the commanded body pitch): the trim's at
the start and the one the -x gust's transient left the loop with, read off the flight
(docs/free-body.md).  Tolerances: the one-sided rule exactly; the measured ratio of the
sweep authorities within 0.05 of the 0.62 measured (a held-body measurement, the same
numbers every run; the band only absorbs a change of the table's wingbeat in the last
digit); a set measured at the same wingbeat predicts the inputs' moment within 3 % (the
inputs' moment is linear to about 1 % at these sizes, measured 0.3-2.7 % in cruise); the
50 % gust within the issue's 0.05 semispan 8 wingbeats after the gust (measured 0.023)."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.flight.attitude_refresh import (
    RESIDUAL_TOL,
    StalenessCheck,
    prediction_residual,
    predicts_better,
    under_predicts,
)

TRIM = np.array([0.1302, 0.6991, 0.3211, 0.35])  # pitch 0.1302, speed 0.500
GUST = np.array([0.0318, 0.7749, 0.4757, 0.2012])  # pitch 0.1267, speed 0.496
#: cruise-sized inputs (rad): sweep, tail elevation and dihedral as the pitch loop uses them
U = np.zeros(7)
U[[2, 3, 6]] = (-0.03, 0.01, -0.013)


def test_under_predicts_is_one_sided():
    """Stale only when the delivered moment exceeds the predicted one along the
    prediction by more than the tolerance of the moment the inputs move; a set that
    over-predicts (the loop's gain below its design) is kept; no input, no verdict."""
    jac = np.zeros((3, 7))
    jac[1, [2, 3, 6]] = (-0.15, 0.02, -0.07)
    pred = jac @ U
    moved = np.linalg.norm(np.abs(jac * U).sum(axis=1))
    unit = pred / np.linalg.norm(pred)
    assert under_predicts(1.5 * RESIDUAL_TOL * moved * unit, jac, U, RESIDUAL_TOL)
    assert not under_predicts(0.5 * RESIDUAL_TOL * moved * unit, jac, U, RESIDUAL_TOL)
    assert not under_predicts(-5 * RESIDUAL_TOL * moved * unit, jac, U, RESIDUAL_TOL)
    side = np.array([1.0, 0.0, 0.0]) * 10 * moved  # across the prediction: no gain error
    assert not under_predicts(side, jac, U, RESIDUAL_TOL)
    assert not under_predicts(unit, jac, np.zeros(7), RESIDUAL_TOL)


def test_a_new_set_replaces_the_old_only_if_it_predicts_better():
    """The residual of the new set is the old one's plus (old - new) u: a set that
    predicts the delivered moment (the old one scaled to it) is better, one that misses
    it by as much on the other side is not."""
    old = np.zeros((3, 7))
    old[1, [2, 3, 6]] = (-0.09, 0.02, -0.05)
    true = 1.6 * old
    res = (true - old) @ U  # what the old set left
    assert predicts_better(res, old, true, U)
    assert not predicts_better(res, old, old + 2 * (true - old), U)
    assert not predicts_better(res, old, old, U)


@pytest.fixture
def fb():
    from birdsim.flight.presets import DEMO_MODEL, demo_bird
    from birdsim.flight.simulate import FreeBird, SimConfig

    with FreeBird(DEMO_MODEL, demo_bird(), TRIM, config=SimConfig(attitude="free")) as f:
        yield f


def test_the_gusts_set_is_stale_at_the_trims_wingbeat(fb):
    """The set the -x gust's transient left (measured at its wingbeat) has 0.62 of the
    sweep's pitch authority of the trim's wingbeat, the one flown after the gust: at the
    trim's wingbeat it under-predicts the inputs' moment (stale), the trim's own set
    predicts it within 3 % (not stale), and the trim's set at the transient's wingbeat
    over-predicts it (kept: the loop's gain is then below its design)."""
    from birdsim.flight.attitude_jacobians import measured_jacobian

    _, j_gust = measured_jacobian(fb, GUST, 0.1267, 0.496)
    _, j_trim = measured_jacobian(fb, TRIM, 0.1302, 0.5)
    assert j_gust[1, 2] / j_trim[1, 2] == pytest.approx(0.62, abs=0.05)
    res, moved = prediction_residual(fb, TRIM, 0.1302, 0.5, j_gust, U)
    assert under_predicts(res, j_gust, U, RESIDUAL_TOL)
    res, moved = prediction_residual(fb, TRIM, 0.1302, 0.5, j_trim, U)
    assert np.linalg.norm(res) < 0.03 * np.linalg.norm(moved)
    assert not under_predicts(res, j_trim, U, RESIDUAL_TOL)
    res, _ = prediction_residual(fb, GUST, 0.1267, 0.496, j_trim, U)
    assert not under_predicts(res, j_trim, U, RESIDUAL_TOL)


def test_the_check_replaces_only_j_once_per_wingbeat(fb):
    """StalenessCheck.refreshed: a stale set gets a new J (the trim's, measured at the
    wingbeat checked) and keeps its speed, M_0 and pitch; within a wingbeat of the last
    check or measurement nothing is checked, nor at a wingbeat within the measurement's
    step (JAC_STEP) of the one measured at; a fresh set is returned as it is."""
    from birdsim.flight.attitude_jacobians import measured_jacobian

    m0, j_gust = measured_jacobian(fb, GUST, 0.1267, 0.496)
    _, j_trim = measured_jacobian(fb, TRIM, 0.1302, 0.5)
    stored = (0.496, m0, j_gust, 0.1267)
    check = StalenessCheck(fb.red.period)
    check.measured(fb.time - 0.5 * fb.red.period, GUST)
    assert check.refreshed(fb, stored, TRIM, 0.1302, 0.5, U) is stored  # not due
    check.measured(fb.time - fb.red.period, GUST)
    new = check.refreshed(fb, stored, TRIM, 0.1302, 0.5, U)
    assert (check.checks, check.refreshes) == (1, 1)
    assert new[0] == stored[0] and new[1] is m0 and new[3] == stored[3]
    np.testing.assert_array_equal(new[2], j_trim)
    check.measured(fb.time - fb.red.period, GUST)
    assert check.refreshed(fb, new, TRIM, 0.1302, 0.5, U) is new
    assert (check.checks, check.refreshes) == (2, 1)
    # a wingbeat within JAC_STEP of the one measured at is not checked
    check.measured(fb.time - fb.red.period, TRIM + 0.01)
    assert check.refreshed(fb, stored, TRIM, 0.1302, 0.5, U) is stored
    assert check.checks == 2


def test_a_50_percent_headwind_gust_is_flown_back():
    """Free cruise (seed bird, m3) with a one-wingbeat -x gust of 50 % of cruise speed
    from wingbeat 3: every sample within 0.05 semispan of the path from wingbeat 12 on
    (measured: back from wingbeat 6, 0.023 at the end; without the check the set measured
    in the gust's transient stayed and the error was 0.068 at wingbeat 16), the peak
    0.17 (the gust does move the bird: above 0.1)."""
    from test_attitude_rates import free_cruise_with_gust

    a = free_cruise_with_gust(16, "3:1:-0.25:0:0")
    err = np.sqrt((a["x_ref"] - a["x"]) ** 2 + a["y"] ** 2 + (a["z_ref"] - a["z"]) ** 2)
    assert err.max() > 0.1
    assert err[12 * 64 :].max() <= 0.05, err[12 * 64 :].max()
