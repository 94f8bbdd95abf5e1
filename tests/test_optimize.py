"""Optimisers: Table 3 of sec. 3.6.4 on the test functions f and g, and the wingbeat
problem solved by independent paths (slack SLSQP vs evolutionary search on the plain cost)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim.errors import BirdsimError
from birdsim.physics.kinematics import get_model
from birdsim.tables.cost import evaluate_cost
from birdsim.tables.optimize import (
    ForceProblem,
    FunctionProblem,
    box_corners,
    complete_search,
    evolutionary,
    random_starts,
    slsqp,
    solve,
)


def f(X: np.ndarray) -> np.ndarray:  # eq. 89
    return ((X[:, 0] - 0.5) ** 2 + 0.5) * ((X[:, 1] - 0.5) ** 2 + 0.5)


def g(X: np.ndarray) -> np.ndarray:  # eq. 90
    return 0.25 * np.sin(2 * X[:, 0]) + np.sin(2 * X[:, 1])


def unit(fun):
    return FunctionProblem(fun, [0.0, 0.0], [1.0, 1.0])


# ---- Table 3 ---------------------------------------------------------------------------


def test_complete_search_f_error_0_0021_at_12_nodes():
    sol = complete_search(unit(f), nodes=12)
    # Table 3: error in f_min 0.0021 (4 dp), 144 iterations; minimum at (5/11, 5/11)
    assert round(sol.cost - 0.25, 4) == 0.0021
    assert sol.iterations == 144
    np.testing.assert_allclose(sol.x, [5 / 11, 5 / 11], atol=1e-12)  # grid nodes are exact


def test_complete_search_g_hits_the_corner_minimum_exactly():
    sol = complete_search(unit(g), nodes=12)
    assert sol.cost == 0.0 and np.all(sol.x == 0.0)  # a node sits on the minimum: zero error


def test_gradient_method_f_from_0_1_reaches_the_centre():
    sol = slsqp(unit(f), [0.0, 1.0])
    assert sol.cost == pytest.approx(0.25, abs=1e-8)  # Table 3: error 0.0000
    assert sol.status == "converged"
    stopped = slsqp(unit(f), [0.0, 1.0], maxiter=1)
    assert not stopped.converged and stopped.status.startswith("stopped: ")
    np.testing.assert_allclose(sol.x, [0.5, 0.5], atol=1e-4)


@pytest.mark.parametrize(
    "start, x_end, value",
    [
        ((0.0, 1.0), (0.0, 1.0), math.sin(2.0)),  # stays at the local minimum g(0,1) = 0.9093
        ((0.8, 0.5), (1.0, 0.0), 0.25 * math.sin(2.0)),  # runs to g(1,0) = 0.2273
        ((0.7, 0.7), (0.0, 0.0), 0.0),  # finds the global minimum
    ],
)
def test_gradient_method_g_local_minima_from_the_stated_starts(start, x_end, value):
    sol = slsqp(unit(g), start)
    # 1e-6: the minima sit on the box corners, which SLSQP's bounds hit exactly
    np.testing.assert_allclose(sol.x, x_end, atol=1e-6)
    assert sol.cost == pytest.approx(value, abs=1e-6)
    assert round(value, 4) in (0.9093, 0.2273, 0.0)  # the values printed in sec. 3.6.2


def test_evolutionary_search_finds_both_global_minima():
    # differential evolution plays the role of the dissertation's genetic algorithm
    for fun, fmin in ((f, 0.25), (g, 0.0)):
        sol = evolutionary(unit(fun), seed=3)
        assert sol.cost == pytest.approx(fmin, abs=1e-7)  # polished by SLSQP: no GA residue
        assert sol.evaluations > 100  # a global search spends far more than SLSQP's handful


def test_solve_interface_and_bad_method():
    for method in ("slsqp", "multistart", "complete", "evolutionary"):
        sol = solve(unit(f), method)
        assert sol.cost == pytest.approx(0.25, abs=0.0021 + 1e-9)  # complete search is the coarsest
        assert sol.evaluations > 0
    with pytest.raises(BirdsimError, match="method='newton' is unknown"):
        solve(unit(f), "newton")


@pytest.mark.parametrize(
    "args, message",
    [
        ((math.nan, -0.2, 0.5), "Fx_demand=nan is not finite"),
        ((0.1, -math.inf, 0.5), "Fz_demand=-inf is not finite"),
        ((0.1, -0.2, -1.0), "speed=-1.0 is invalid"),
    ],
)
def test_force_problem_refuses_non_finite_demands(args, message):
    # a NaN demand used to give a NaN cost and a "solution" without a word
    with pytest.raises(BirdsimError, match=message):
        ForceProblem("m1", *args)


def test_start_sets_fill_the_box():
    p = unit(f)
    S = random_starts(p, 64, seed=1)
    assert S.shape == (64, 2) and np.all((S >= 0) & (S <= 1))
    assert {tuple(c) for c in box_corners(p)} == {(0, 0), (0, 1), (1, 0), (1, 1)}


# ---- the wingbeat problem ----------------------------------------------------------------


def test_reachable_demand_is_met_exactly_and_agrees_with_a_global_search():
    # base model cruise (V = 0.9, Fx = 0, Fz = -0.2): reachable, so the L1 cost is an exact
    # penalty and the optimum meets the demand to solver precision.
    prob = ForceProblem("base", 0.0, -0.2, 0.9, n=64)
    sol = solve(prob, "multistart", starts=4)
    assert abs(sol.Fx) < 1e-7 and abs(sol.Fz + 0.2) < 1e-7
    # the slack reformulation against the plain (non-smooth) cost searched by DE:
    de = evolutionary(ForceProblem("base", 0.0, -0.2, 0.9, n=64), seed=0, polish=False)
    assert sol.cost <= de.cost + 1e-6  # DE unpolished converges to ~1e-8 of the same minimum
    assert de.cost - sol.cost < 1e-4
    # cost agrees with the cost module evaluated independently on the returned point
    b = evaluate_cost(get_model("base"), sol.x[None], 0.0, -0.2, 0.9, n=64)
    assert float(b.total[0]) == pytest.approx(sol.cost, rel=1e-12)
    assert sol.Fx == pytest.approx(float(b.Fx[0]), abs=1e-12)


def test_hover_demand_beyond_reach_goes_to_the_bounds():
    # eq. 57: all parameters at their maxima give Fz ~ -0.29 for the base model at V = 0;
    # Fz = -0.5 cannot be reached, the optimum saturates pitch, flap and twist.
    sol = solve(ForceProblem("base", 0.0, -0.5, 0.0, n=64), "multistart", starts=4)
    lo, hi = get_model("base").bounds
    np.testing.assert_allclose(sol.x, hi, atol=1e-6)
    assert sol.Fz == pytest.approx(-0.2895, abs=1e-3)


def test_search_resolution_barely_moves_the_optimum():
    # the builder searches with 32 samples per wingbeat and checks with 64
    for model, demand in (("base", (0.0, -0.2, 0.9)), ("m4", (0.1, -0.15, 0.6))):
        coarse = solve(ForceProblem(model, *demand, n=32), "multistart", starts=4)
        fine = ForceProblem(model, *demand, n=64)
        c32_at_64 = float(fine.cost(coarse.x[None])[0])
        polished = slsqp(fine, coarse.x)
        # the n=32 optimum costs at most 1e-6 more than the n=64 optimum polished from it
        assert c32_at_64 - polished.cost < 1e-6


def test_orientation_cost_prefers_the_stroke_plane_in_m3_hover():
    sol = solve(ForceProblem("m3", 0.0, -0.5, 0.0, n=32), "multistart", starts=4)
    x = dict(zip(get_model("m3").param_names, sol.x))
    assert x["stroke_plane"] == pytest.approx(0.35, abs=1e-6)  # at its bound
    # the stroke plane sits at pitch + theta_sp: vertical as the base model's pitch (sec. 4.1.3)
    assert x["pitch"] + x["stroke_plane"] == pytest.approx(math.pi / 2, abs=1e-4)
