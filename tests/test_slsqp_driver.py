"""scipy's SLSQP driven directly (birdsim.tables.slsqp_driver) against scipy's wrapper."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim import get_model
from birdsim.tables import slsqp_driver
from birdsim.tables.cost import CostWeights
from birdsim.tables.optimize import ForceProblem, slsqp


def _both(monkeypatch, make, x0, **kw):
    direct = slsqp(make(), x0, **kw)
    monkeypatch.setitem(slsqp_driver._STATE, "direct", False)
    wrapped = slsqp(make(), x0, **kw)
    return direct, wrapped


@pytest.mark.parametrize(
    "model, demand", [("m1", (0.1, -0.3, 0.0)), ("m4", (0.05, -0.2, 0.6)), ("m3", (0.4, -0.5, 0.2))]
)
def test_the_same_iterates_as_scipys_wrapper(monkeypatch, model, demand):
    # the same compiled routine fed the same numbers: bitwise the same answer, the same
    # number of iterations and of wingbeats evaluated (m3's demand is unreachable: a
    # run that ends on the stall rule or the iteration limit)
    if slsqp_driver._core is None:
        pytest.skip("scipy < 1.16: only scipy's wrapper exists")
    x0 = list(get_model(model).guess("cruise").values())
    direct, wrapped = _both(monkeypatch, lambda: ForceProblem(model, *demand[:2], demand[2]), x0)
    np.testing.assert_array_equal(direct.x, wrapped.x)
    assert (direct.iterations, direct.evaluations, direct.cost) == (
        wrapped.iterations,
        wrapped.evaluations,
        wrapped.cost,
    )
    assert direct.converged == wrapped.converged


def test_a_routine_that_refuses_the_call_falls_back_to_scipys_wrapper(monkeypatch):
    def changed(*args):
        raise TypeError("slsqp() takes 12 arguments")

    monkeypatch.setattr(slsqp_driver, "_core", changed)
    monkeypatch.setitem(slsqp_driver._STATE, "direct", True)
    x0 = list(get_model("m2").guess("hover").values())
    sol = slsqp(ForceProblem("m2", 0.0, -0.2, 0.0), x0)
    assert not slsqp_driver._STATE["direct"]  # switched to the wrapper for good
    assert sol.converged and abs(sol.Fz + 0.2) < 1e-6


@pytest.mark.parametrize(
    "model, demand, previous",
    [
        ("m5", (0.1, -0.3, 0.5), None),
        ("m5", (0.3, -0.5, 0.0), "hover"),
        ("m4", (0.4, -0.5, 0.2), None),
    ],
)
def test_the_fused_loop_gives_the_unfused_loops_answer(monkeypatch, model, demand, previous):
    # objective and constraints asked for together (one clip and one lookup per request,
    # the arrays written in place) against the loop that asks for each separately: the
    # same iterates to the bit, the same wingbeats evaluated (the first run ends at the
    # iteration limit, the second carries a distance cost, the others converge)
    if slsqp_driver._core is None:
        pytest.skip("scipy < 1.16: only scipy's wrapper exists")
    m = get_model(model)
    x0 = list(m.guess("cruise").values())
    prev = None if previous is None else np.array(list(m.guess(previous).values()))
    weights = CostWeights(distance=0.05) if prev is not None else None

    def make():
        return ForceProblem(model, *demand[:2], demand[2], previous=prev, weights=weights)

    fused = slsqp(make(), x0, maxiter=60)
    monkeypatch.setattr(slsqp_driver, "minimize_fused", lambda *a, **k: None)
    separate = slsqp(make(), x0, maxiter=60)
    assert slsqp_driver._STATE["direct"]  # both ran the compiled routine directly
    np.testing.assert_array_equal(fused.x, separate.x)
    assert (fused.iterations, fused.evaluations, fused.cost, fused.converged) == (
        separate.iterations,
        separate.evaluations,
        separate.cost,
        separate.converged,
    )
