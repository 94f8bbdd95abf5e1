"""The lean optimiser: exact gradients of the wingbeat problem, gradients only at
SLSQP's iterates (never at line-search trials) and runs without progress ended."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim import get_model
from birdsim.tables.cost import CostWeights
from birdsim.tables.optimize import ForceProblem, FunctionProblem, slsqp


@pytest.mark.parametrize(
    "model, climb", [("m1", 0.0), ("m3", 0.0), ("m4", 0.0), ("m4", -0.3), ("m2", 0.4)]
)
def test_force_problem_jacobian_is_the_central_difference(model, climb):
    # Exact (kernel) against the finite-difference Jacobian of the same residuals: the
    # FD error is ~1e-9 (h = 1e-6), so 1e-6 relative per residual row is a real check.
    m = get_model(model)
    weights = CostWeights(distance=0.2)
    rng = np.random.default_rng(4)
    lo, hi = m.bounds
    prev = lo + (hi - lo) * rng.random(len(lo))
    for speed in (0.0, 0.6):
        prob = ForceProblem(m, 0.1, -0.2, speed, weights=weights, previous=prev, climb=climb)
        x = lo + (hi - lo) * rng.uniform(0.1, 0.9, len(lo))
        r, jr, h, gh = prob.parts_and_jacobian(x)
        r_fd, jr_fd, h_fd, gh_fd = FunctionProblem._parts_and_jacobian(
            prob, x
        )  # the FD rule of Problem
        assert np.allclose(r, r_fd, atol=1e-14) and h == pytest.approx(h_fd, abs=1e-14)
        for k in range(3):
            assert np.linalg.norm(jr[k] - jr_fd[k]) <= 1e-6 * np.linalg.norm(jr_fd[k]) + 1e-9
        assert np.linalg.norm(gh - gh_fd) <= 1e-6 * np.linalg.norm(gh_fd) + 1e-9


def test_gradients_only_at_iterates():
    prob = ForceProblem("m3", 0.1, -0.3, 0.5)
    sol = slsqp(prob, list(get_model("m3").guess("cruise").values()))
    # one gradient per accepted iterate (and the start); line-search trials cost values only
    assert prob.gradient_evaluations <= sol.iterations + 2
    assert sol.evaluations >= prob.gradient_evaluations

    class FiniteDifferences(ForceProblem):
        _parts_and_jacobian = FunctionProblem._parts_and_jacobian

    fd = slsqp(
        FiniteDifferences("m3", 0.1, -0.3, 0.5), list(get_model("m3").guess("cruise").values())
    )
    assert sol.cost <= fd.cost + 1e-6  # the same optimum as with finite differences


def test_a_run_without_progress_is_ended_at_its_best_point():
    # a function so flat that no step gains STALL_TOL (1e-10); ftol = 0 never declares
    # convergence, so only the stall rule ends the run, after `stall` iterations
    prob = FunctionProblem(
        lambda X: 1e-11 * ((X - 0.3) ** 2).sum(axis=-1), [-1.0, -1.0], [1.0, 1.0]
    )
    sol = slsqp(prob, [0.9, -0.8], ftol=0.0, maxiter=500, stall=3)
    assert not sol.converged and "no progress in 3 iterations" in sol.message
    assert sol.iterations <= 4 and sol.cost <= 1e-11 * (0.6**2 + 1.1**2)
