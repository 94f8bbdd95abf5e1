"""The regularising pass of a table build: fewer zig-zags, every cell within the stated
cost tolerance of the best found, no reachable cell lost, the same table on 1 or 2
processes."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from birdsim.tables.build import BuildConfig, BuildSettings, Grid, build_table
from birdsim.tables.regularise import _targets, local_score, local_scores, zigzag_cells
from birdsim.tables.smoothness import table_smoothness

# a corner of the base table where the sweeps leave zig-zags along Fx (cruise-like
# demands around Fx = -0.1, where the optimum is flat)
GRID = Grid.parse("Fx=-0.3|-0.2|-0.1|0|0.1,Fz=-0.2|-0.15|-0.1,V=0.4|0.5")


@pytest.fixture(scope="module")
def pair():
    plain = build_table(BuildConfig("base", GRID, settings=BuildSettings(smooth_tol=0)), jobs=1)
    smooth = build_table(BuildConfig("base", GRID), jobs=1)
    return plain, smooth


def test_the_pass_removes_zigzags_within_the_cost_tolerance(pair):
    plain, smooth = pair
    before, after = table_smoothness(plain), table_smoothness(smooth)
    assert before.zigzag_triples >= 4 and after.zigzag_triples <= before.zigzag_triples // 2
    tol = smooth.meta["solver"]["smooth_tol"]
    assert tol == 5e-3 and "regularising_pass" in smooth.meta
    ok = plain.status == "ok"
    np.testing.assert_array_equal(smooth.status[ok], "ok")  # no reachable cell lost
    # each cell within tol of the best found (the sweeps' answer; 1e-6: n = 32 vs 64)
    assert np.max(smooth.cost - plain.cost) <= tol + 1e-6
    assert np.max(smooth.cost - plain.cost) > 1e-4  # the pass did trade cost for smoothness
    changed = np.any(smooth.params != plain.params, axis=-1)
    assert changed.sum() >= 4 and not np.any(changed & ~ok)  # unreachable cells are left alone


def test_two_processes_give_the_same_regularised_table(pair):
    _, smooth = pair
    pooled = build_table(BuildConfig("base", GRID), jobs=2)
    assert pooled.params.tobytes() == smooth.params.tobytes()
    assert pooled.cost.tobytes() == smooth.cost.tobytes()


def test_the_candidates_of_a_cell_are_scored_at_once_as_one_by_one():
    # local_scores (all candidates of a cell in one zigzags call per axis) against
    # local_score row by row, on the shipped m5 table (idle wrists and folds, unreachable
    # cells, grid edges): the same counts and bitwise the same step sums
    from birdsim.physics.kinematics import get_model
    from birdsim.tables.lookup import load_table
    from birdsim.tables.shipped import PACKAGE_TABLES

    t = load_table(PACKAGE_TABLES / "m5.npz")
    names, X, ok = get_model("m5").param_names, np.asarray(t.params), t.status == "ok"
    rng = np.random.default_rng(3)
    for _ in range(60):
        cell = tuple(int(i) for i in rng.integers(0, 11, 3))
        cand = X[tuple(rng.integers(0, 11, (3, 6)))] + rng.normal(0, 0.2, (6, X.shape[-1]))
        cand[rng.random(cand.shape) < 0.15] = 0.0  # idle wrists and folds too
        batch = local_scores(names, X, ok, cell, cand)
        single = [local_score(names, X, ok, cell, x) for x in cand]
        assert [(c, np.float64(s).tobytes()) for c, s in batch] == [
            (c, np.float64(s).tobytes()) for c, s in single
        ]


def test_local_score_counts_the_zigzags_a_cell_takes_part_in():
    names = ("pitch", "flap_amp")
    X = np.zeros((5, 1, 1, 2))
    ok = np.ones((5, 1, 1), bool)
    assert local_score(names, X, ok, (2, 0, 0), np.array([0.0, 0.0])) == (0, 0.0)
    count, steps = local_score(names, X, ok, (2, 0, 0), np.array([0.0, 0.5]))
    assert count == 1 and steps == pytest.approx(
        2 * 0.25
    )  # the middle of one triple; two neighbours
    X[2, 0, 0, 1] = 0.5
    assert len(zigzag_cells(names, X, ok)) == 3 and len(zigzag_cells(names, X, ok, ends=False)) == 1


def test_the_neighbours_median_is_a_target_where_three_or_more_are_reachable():
    """Issue 24: a cell whose neighbours sit on two branches (five at flap 0.2, one at
    flap 1.4) gets the majority's flap in a target, with the pitch their median; no
    midpoint along an axis nor one neighbour is it.  With two neighbours: no median.
    Without ``smooth_median`` (the default, every table but m5): no median either."""
    X = np.zeros((3, 3, 3, 2))
    nb = {(0, 1, 1): (0.0, 0.2), (2, 1, 1): (0.1, 0.2), (1, 0, 1): (0.2, 0.2)}
    nb |= {(1, 2, 1): (0.5, 1.4), (1, 1, 0): (0.0, 0.2), (1, 1, 2): (0.4, 0.2)}
    for c, x in nb.items():
        X[c] = x
    ok = np.ones((3, 3, 3), bool)
    assert len(_targets((1, 1, 1), X, ok)) == 3 + 6 - 2
    targets = _targets((1, 1, 1), X, ok, median=True)
    assert len(targets) == 3 + 6 + 1 - 2  # two repeats (SAME_TARGET_RAD) dropped
    np.testing.assert_allclose(targets[-1], (0.15, 0.2))  # the median of 6 neighbours
    assert not any(np.allclose(t, (0.15, 0.2)) for t in targets[:-1])
    line = np.array([(0.0, 0.2), (0.5, 1.4), (1.0, 0.2)])[:, None, None]
    assert len(_targets((1, 0, 0), line, np.ones((3, 1, 1), bool), True)) == 1 + 2  # no median
    # the setting is recorded only when on: tables built before it keep their digest
    off = BuildConfig("base", Grid.default(), settings=BuildSettings())
    on = BuildConfig("base", Grid.default(), settings=BuildSettings(smooth_median=True))
    assert "smooth_median" not in off.to_dict()["solver"]
    assert on.to_dict()["solver"]["smooth_median"] is True


def test_the_pass_to_its_fixed_point_stops_by_itself_and_is_recorded_only_when_on(pair):
    """Issue 24: ``smooth_fixed_point`` runs rounds until one changes no cell (not the
    default's stop after a round that removes no zig-zag cell), well within its cap, and
    leaves at most the default's zig-zags; the setting is recorded only when on (with
    ``smooth_planes``), so that the other tables keep their configuration digest."""
    _, smooth = pair
    st = BuildSettings(smooth_fixed_point=True, smooth_rounds=32)
    fixed = build_table(BuildConfig("base", GRID, settings=st), jobs=1)
    rounds = fixed.meta["regularising_pass"]["rounds"]
    assert smooth.meta["regularising_pass"]["rounds"] < rounds < 32  # here 2 and 3
    assert table_smoothness(fixed).zigzag_triples <= table_smoothness(smooth).zigzag_triples
    again = build_table(
        BuildConfig("base", GRID, settings=replace(st, smooth_rounds=rounds - 1)), jobs=1
    )
    assert again.params.tobytes() == fixed.params.tobytes()  # the last round changed nothing
    off = BuildConfig("base", GRID).to_dict()["solver"]
    assert "smooth_fixed_point" not in off and "smooth_planes" not in off
    on = BuildConfig("base", GRID, settings=replace(st, smooth_planes=True)).to_dict()["solver"]
    assert on["smooth_fixed_point"] is True and on["smooth_planes"] is True


# ---- a choice that round-off cannot flip (issue 21) ------------------------------------


def _perturbed_build(monkeypatch, *, cost_eps=0.0, param_eps=0.0, seed=0):
    """The GRID table with the pass's inputs perturbed: every cost the pass reads (the
    sweeps' costs and each candidate's) and/or the sweeps' parameters, by +-eps in a
    random half of the cells (random sign per cell and candidate)."""
    import birdsim.tables.build as build
    import birdsim.tables.regularise as reg

    rng = np.random.default_rng(seed)
    sweep, costs = build._sweep, reg.candidate_costs

    def noisy_sweep(*a, **k):
        X, cost, evals, conv, X_slices = sweep(*a, **k)
        hit = rng.random(cost.shape) < 0.5
        cost = cost + np.where(hit, rng.choice([-1.0, 1.0], cost.shape) * cost_eps, 0.0)
        X = X + np.where(hit[..., None], rng.choice([-1.0, 1.0], X.shape) * param_eps, 0.0)
        return X, cost, evals, conv, X_slices

    def noisy_costs(prob, cand):
        cost, err = costs(prob, cand)
        if rng.random() < 0.5:
            cost = cost + rng.choice([-1.0, 1.0], cost.shape) * cost_eps
        return cost, err

    monkeypatch.setattr(build, "_sweep", noisy_sweep)
    monkeypatch.setattr(reg, "candidate_costs", noisy_costs)
    return build_table(BuildConfig("base", GRID), jobs=1)


@pytest.mark.parametrize("seed", [1, 2])
def test_costs_perturbed_by_1e_9_give_the_identical_table(pair, monkeypatch, seed):
    """Every decision of the pass has a margin far above 1e-9 (COST_TIE 1e-7 for ties,
    smooth_tol 5e-3 for admissibility), so the parameters are bitwise those of the
    unperturbed build (the stored costs too: they come from the final check)."""
    _, smooth = pair
    assert smooth.meta["regularising_pass"]["cells_changed"] >= 4  # the pass did choose
    t = _perturbed_build(monkeypatch, cost_eps=1e-9, seed=seed)
    assert t.params.tobytes() == smooth.params.tobytes()
    assert t.cost.tobytes() == smooth.cost.tobytes()


def test_parameters_perturbed_by_1e_9_rad_move_the_table_by_no_more(pair, monkeypatch):
    """Round-off in the sweeps' parameters: the rounded targets give bitwise the same
    candidates, the ties keep the same choices, so each cell is either the same candidate
    (bitwise) or its own perturbed input (1e-9 rad)."""
    _, smooth = pair
    t = _perturbed_build(monkeypatch, param_eps=1e-9, seed=3)
    assert np.max(np.abs(t.params - smooth.params)) <= 1e-9 * (1 + 1e-6)
    assert np.array_equal(t.status, smooth.status)


def test_choose_breaks_ties_by_order_not_by_round_off():
    from birdsim.tables.regularise import COST_TIE, choose

    no = np.zeros(3, dtype=bool)
    err = np.zeros(3)
    # same zig-zags, steps 1e-12 apart: the earliest (the current wingbeat) stays
    assert (
        choose([0.1, 0.1, 0.1], err, 0.1, [(0, 1.0), (0, 1.0 - 1e-12), (0, 2.0)], no, 5e-3, 0.01)
        == 0
    )
    # clearly smoother (by more than STEP_TIE): it moves
    assert choose([0.1, 0.1, 0.1], err, 0.1, [(0, 1.0), (0, 0.5), (0, 2.0)], no, 5e-3, 0.01) == 1
    # fewer zig-zags beats steps; beyond smooth_tol is not admissible
    assert choose([0.1, 0.1, 0.2], err, 0.1, [(1, 0.0), (0, 3.0), (0, 0.0)], no, 5e-3, 0.01) == 1
    # nothing admissible (the current one much costlier and the cheap ones miss the
    # demand): the cheapest within COST_TIE, first in order, not the smallest number
    far = np.array([0.0, 0.009, 0.009])
    pick = choose(
        [0.5, 0.1 + 0.5 * COST_TIE, 0.1], far, 0.1, [(0, 0.0), (0, 1.0), (0, 0.0)], no, 5e-3, 0.01
    )
    assert pick == 2  # both tied in cost; the second is smoother
    pick = choose(
        [0.5, 0.1 + 0.5 * COST_TIE, 0.1], far, 0.1, [(0, 0.0), (0, 0.0), (0, 0.0)], no, 5e-3, 0.01
    )
    assert pick == 1  # tied in cost and steps: the earlier
    # a duplicate of an earlier candidate is never picked
    dup = np.array([False, False, True])
    assert choose([0.1, 0.1, 0.1], err, 0.1, [(1, 0.5), (1, 0.0), (0, 0.0)], dup, 5e-3, 0.01) == 1


def test_the_candidate_memo_changes_no_wingbeat_and_saves_slsqp_runs(pair, monkeypatch):
    """A cell flagged again in a later round reuses the SLSQP answers of the targets it had
    before (a candidate is a pure function of its demand and rounded target): the table is
    bitwise the one rebuilt without the memo, with fewer wingbeat evaluations."""
    import birdsim.tables.regularise as reg

    _, smooth = pair
    assert smooth.meta["regularising_pass"]["rounds"] >= 2
    monkeypatch.setattr(reg.CandidateMemo, "for_cells", lambda self, cells: {})
    without = build_table(BuildConfig("base", GRID), jobs=1)
    assert without.params.tobytes() == smooth.params.tobytes()
    assert without.cost.tobytes() == smooth.cost.tobytes()
    assert smooth.evaluations.sum() < without.evaluations.sum()
