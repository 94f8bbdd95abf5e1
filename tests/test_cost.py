"""Cost terms against the cycle evaluation computed independently, and their invariants."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim import evaluate_cycle, get_model
from birdsim.errors import BirdsimError
from birdsim.physics.cycle import DEFAULT_SAMPLES
from birdsim.tables.cost import (
    FRACTION_NAMES,
    CostWeights,
    breakdown_from_forces,
    evaluate_cost,
    other_cost,
)


def rows(model, n, seed=0):
    m = get_model(model)
    lo, hi = m.bounds
    return m, lo + (hi - lo) * np.random.default_rng(seed).random((n, lo.size))


@pytest.mark.parametrize("model", ["base", "m2", "m4"])
def test_cost_is_the_flapcost_of_the_cycle_means(model):
    m, X = rows(model, 5)
    b = evaluate_cost(m, X, 0.1, -0.2, 0.4)
    for k in range(5):
        mean = evaluate_cycle(
            model, dict(zip(m.param_names, X[k])), 0.4
        ).mean  # one by one, the same default n
        expect = abs(float(mean.Fx) - 0.1) + abs(float(mean.Fz) + 0.2) + 0.5 * abs(float(mean.P))
        # 1e-12: the same arithmetic, batched vs single
        assert float(b.total[k]) == pytest.approx(expect, abs=1e-12)
        assert float(b.Fx[k]) == pytest.approx(float(mean.Fx), abs=1e-12)


def test_orientation_cost_only_for_stroke_plane_models_at_rest():
    w = CostWeights(orientation=0.01)
    for model, expected in (
        ("base", False),
        ("m1", False),
        ("m2", False),
        ("m3", True),
        ("m4", True),
    ):
        m, X = rows(model, 4)
        at_rest = other_cost(m, X, 0.0, w)
        moving = other_cost(m, X, 0.3, w)
        pitch = X[:, m.param_names.index("pitch")]
        np.testing.assert_allclose(at_rest, 0.01 * pitch if expected else 0.0, atol=0)
        np.testing.assert_array_equal(moving, 0.0)


def test_distance_cost_is_eq_93():
    m, X = rows("m3", 3)
    prev = X[0]
    d = other_cost(m, X, 0.5, CostWeights(distance=0.2), previous=prev)
    np.testing.assert_allclose(d, 0.2 * np.linalg.norm(X - prev, axis=1), rtol=1e-14)
    assert d[0] == 0.0


def test_fractions_sum_to_one_and_name_each_term():
    m, X = rows("m3", 50, seed=2)
    b = evaluate_cost(m, X, 0.0, -0.3, 0.0, weights=CostWeights(distance=0.1), previous=X[0])
    f = b.fractions
    assert f.shape == (50, len(FRACTION_NAMES)) and FRACTION_NAMES == (
        "force_x",
        "force_z",
        "power",
        "other",
    )
    assert np.all(f >= 0)
    np.testing.assert_allclose(f.sum(axis=1), 1.0, rtol=1e-12)
    np.testing.assert_allclose(f[:, 2] * b.total, b.power, rtol=1e-12)


def test_zero_cost_has_zero_fractions():
    b = breakdown_from_forces(
        np.array([0.1]), np.array([-0.2]), np.array([0.0]), 0.1, -0.2, CostWeights()
    )
    assert float(b.total[0]) == 0.0
    np.testing.assert_array_equal(b.fractions, 0.0)


@pytest.mark.parametrize("bad", [-1.0, float("nan"), float("inf")])
def test_bad_weight_names_itself(bad):
    with pytest.raises(BirdsimError, match="cost weight power="):
        CostWeights(power=bad)


def test_climb_threads_through_cost_and_force_problem():
    from birdsim.tables.optimize import ForceProblem

    m = get_model("m3")
    X = np.array([[0.3, 0.8, 0.3, 0.2]])
    b = evaluate_cost(m, X, 0.1, -0.2, 0.5, climb=0.3)
    c = evaluate_cycle("m3", {k: X[0, i] for i, k in enumerate(m.param_names)}, 0.5, climb=0.3).mean
    assert float(b.Fz[0]) == float(c.Fz) and float(b.Fx[0]) == float(c.Fx)
    prob = ForceProblem(m, 0.1, -0.2, 0.5, climb=0.3, n=DEFAULT_SAMPLES)
    assert prob.achieved(X[0]) == (float(c.Fx), float(c.Fz), float(c.P))
    level = evaluate_cost(m, X, 0.1, -0.2, 0.5)
    assert float(level.Fz[0]) != float(b.Fz[0])
