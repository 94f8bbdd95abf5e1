"""The quadratic incidence tie-break of the cost (issue 24, an m5 build option, off by
default): its value, its exact gradient on the optimiser's one-row path, and that a
table without it records (and hashes) exactly what it did before."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim import get_model
from birdsim.errors import BirdsimError
from birdsim.tables.cost import INCIDENCE_PARAMS, CostWeights, other_cost, other_cost_gradient
from birdsim.tables.grid import BuildConfig, Grid
from birdsim.tables.problem import ForceProblem


def _rows(n: int, seed: int = 0) -> np.ndarray:
    lo, hi = get_model("m5").bounds
    return lo + (hi - lo) * np.random.default_rng(seed).random((n, lo.size))


def test_tie_break_is_w_times_the_squared_norm_of_the_named_parameters():
    m, X = get_model("m5"), _rows(4)
    w = CostWeights(incidence=2e-3)
    idx = [m.param_names.index(n) for n in INCIDENCE_PARAMS]
    # at V > 0 the orientation cost is off, so the other cost is the tie-break alone
    np.testing.assert_allclose(
        other_cost(m, X, 0.5, w), 2e-3 * np.sum(X[:, idx] ** 2, axis=1), rtol=1e-14, atol=0
    )
    np.testing.assert_array_equal(other_cost(m, X, 0.5, CostWeights()), 0.0)
    # a name the model lacks is skipped (base has no stroke plane and no wrist)
    base = get_model("base")
    Xb = np.array([[0.3, 0.5, 0.2]])
    assert base.param_names == ("pitch", "flap_amp", "twist_amp")
    np.testing.assert_allclose(other_cost(base, Xb, 0.5, w), 2e-3 * (0.09 + 0.04), rtol=1e-14)


@pytest.mark.parametrize("speed", [0.0, 0.7])
def test_one_row_path_has_the_batched_value_and_the_exact_gradient(speed):
    """The optimiser's lean path (``ForceProblem._parts_and_jacobian``) against the batched
    ``other_cost`` (bitwise) and central differences of it (1e-9: h = 1e-6 on a quadratic,
    exact up to round-off)."""
    m = get_model("m5")
    w = CostWeights(incidence=1e-3, distance=0.1)
    x = _rows(1, seed=3)[0]
    prev = _rows(1, seed=4)[0]
    prob = ForceProblem(m, -0.3, -0.05, speed, weights=w, previous=prev, n=32)
    _, _, h, gh = prob.parts_and_jacobian(x)
    assert h == float(other_cost(m, x[None], speed, w, prev)[0])
    assert prob.point_parts(x)[1] == h
    np.testing.assert_allclose(
        gh, other_cost_gradient(m, x[None], speed, w, prev)[0], rtol=1e-12, atol=1e-15
    )
    eye = 1e-6 * np.eye(x.size)
    fd = (other_cost(m, x + eye, speed, w, prev) - other_cost(m, x - eye, speed, w, prev)) / 2e-6
    np.testing.assert_allclose(gh, fd, atol=1e-9)
    # the tie-break's own part: 2 w x on the named parameters, zero elsewhere
    off = CostWeights(distance=0.1)
    tb = gh - other_cost_gradient(m, x[None], speed, off, prev)[0]
    idx = [m.param_names.index(n) for n in INCIDENCE_PARAMS]
    expect = np.zeros(x.size)
    expect[idx] = 2e-3 * x[idx]
    np.testing.assert_allclose(tb, expect, atol=1e-15)


def test_recorded_only_when_on():
    """Off, the weights record the keys they always did (so every shipped table's
    configuration digest and checkpoints are unchanged); on, the weight and the
    parameters, and they read back."""
    assert set(CostWeights().to_dict()) == {
        "force_x",
        "force_z",
        "power",
        "orientation",
        "distance",
    }
    on = CostWeights(incidence=1e-4, incidence_params=("pitch", "stroke_plane"))
    d = on.to_dict()
    assert d["incidence"] == 1e-4 and d["incidence_params"] == ["pitch", "stroke_plane"]
    assert CostWeights(**d) == on
    grid = Grid.parse("", 3)
    assert BuildConfig("m5", grid).digest() != BuildConfig("m5", grid, weights=on).digest()


@pytest.mark.parametrize(
    "bad", [dict(incidence=-1e-3), dict(incidence=float("nan")), dict(incidence_params="pitch")]
)
def test_bad_tie_break_names_itself(bad):
    with pytest.raises(BirdsimError, match="incidence"):
        CostWeights(**bad)
