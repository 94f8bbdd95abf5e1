"""The polish rule of a table build (``_solve_cell`` in birdsim/tables/sweeps.py,
``BuildSettings.polish_rule / polish_near / polish_excess``): screen candidates whose
polish cannot win are skipped, the others are still polished, and the answer does not
change (docs/performance.md, "Where polishes win")."""

from dataclasses import replace

import numpy as np
import pytest

from birdsim.errors import BirdsimError
from birdsim.physics.kinematics import get_model
from birdsim.tables.build import BuildConfig, BuildSettings, Grid
from birdsim.tables.cost import forces, other_cost
from birdsim.tables.optimize import ForceProblem, slsqp
from birdsim.tables.sweeps import _solve_cell

MODEL = get_model("base")
CFG = BuildConfig("base", Grid.default(3))
OFF = replace(CFG, settings=replace(CFG.settings, polish_rule=False))


def _screen(S: np.ndarray, v: float):
    S = np.atleast_2d(S)
    return (
        S,
        forces(MODEL, S, v, CFG.bird, CFG.settings.n_search),
        other_cost(MODEL, S, v, CFG.weights),
    )


def _both(fx, fz, v, warm, S):
    """(rule on, rule off) answers of _solve_cell: (x, cost, evaluations, converged)."""
    screen = _screen(S, v)
    return _solve_cell(CFG, MODEL, fx, fz, v, warm, screen), _solve_cell(
        OFF, MODEL, fx, fz, v, warm, screen
    )


@pytest.fixture(scope="module")
def optimum():
    """An unreachable cell (cost ~0.19) and its optimum at n_search."""
    fx, fz, v = 0.2, -0.4, 0.5
    prob = ForceProblem(MODEL, fx, fz, v, n=CFG.settings.n_search)
    return (fx, fz, v), slsqp(prob, list(MODEL.guess("cruise").values())).x, prob


def test_near_candidate_is_not_polished(optimum):
    (fx, fz, v), x, prob = optimum
    step = 0.03 * (prob.upper - prob.lower) * np.array([-1.0, 1.0, -1.0])  # 3 % of each range
    cand = np.clip(x + step, prob.lower, prob.upper)
    cw, cc = prob.cost(np.vstack([x, cand]))
    assert cw < cc <= (1 + CFG.settings.polish_excess) * cw  # the rule's premise holds here
    on, off = _both(fx, fz, v, x, cand)
    assert on[2] < off[2]  # the polish was skipped: fewer wingbeats (warm run only)
    assert (
        np.array_equal(on[0], off[0]) and on[1] == off[1]
    )  # the skipped polish would not have won


def test_far_candidate_is_still_polished(optimum):
    (fx, fz, v), x, prob = optimum
    cand = np.clip(
        x + 0.5 * (prob.upper - prob.lower) * np.array([1.0, -1.0, 1.0]), prob.lower, prob.upper
    )
    on, off = _both(fx, fz, v, x, cand)
    assert on[2] == off[2] > 2  # polished as without the rule
    assert np.array_equal(on[0], off[0])


def test_a_cost_at_its_floor_is_not_polished():
    # hover with no demand: a still wing costs exactly 0 (no force, no power; the base
    # model has no orientation cost), so no polish can beat it, however far the candidate
    x = np.array([0.3, 0.0, 0.2])
    assert ForceProblem(MODEL, 0.0, 0.0, 0.0, n=32).cost(x[None])[0] == 0.0
    far = np.array([MODEL.bounds[1], 0.5 * (MODEL.bounds[0] + MODEL.bounds[1])])
    on, off = _both(0.0, 0.0, 0.0, x, far)
    assert on[2] < off[2] and on[1] == off[1] == 0.0


def test_cold_cells_are_always_polished():
    S = np.array([list(MODEL.guess("cruise").values())])
    on, off = _both(0.0, -0.2, 0.5, None, S)
    assert on[2] == off[2] > 0 and np.array_equal(on[0], off[0])


@pytest.mark.parametrize(
    "name, value",
    [
        ("polish_near", float("nan")),
        ("polish_near", -0.1),
        ("polish_excess", float("nan")),
        ("polish_excess", -1.0),
        ("polish_rule", "yes"),
        ("polish_rule", 1),
        ("v_passes", "no"),
    ],
)
def test_bad_polish_settings(name, value):
    with pytest.raises(BirdsimError, match=f"{name}=.* is invalid"):
        BuildSettings(**{name: value})
