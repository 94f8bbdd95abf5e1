"""Plane moves (birdsim/tables/plane_moves.py): a plane of zig-zag middles that the
one-cell regularising pass cannot straighten, moved together, loses its zig-zags within the
pass's cost tolerance, every reachable cell kept."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.tables import build
from birdsim.tables.checkpoints import Checkpoints
from birdsim.tables.cost import CostWeights, forces
from birdsim.tables.finish import demand_grid
from birdsim.tables.grid import BuildConfig, BuildSettings, Grid, sub_grid
from birdsim.tables.optimize import ForceProblem
from birdsim.tables.plane_moves import components, plane_moves, zigzag_triples
from birdsim.tables.regularise import candidate_costs
from birdsim.tables.smoothness import zigzags

#: A 5 x 6 x 6 block of the seed bird's m5 table (Fx -0.3..0.1, Fz -0.45..-0.2, V 0.5-1.0)
#: as the regularising pass left it at its fixed point (w_q 1e-4, smooth_tol 0.03, X86_V3;
#: the state the shipped table's plane moves start from), and the best cost found per
#: cell.  It holds the glides with the fold near 0 at Fx -0.1 (Fz -0.4..-0.25, V 0.6-0.9)
#: between braking with the fold at 0.4-0.8 (Fx -0.2) and flapping (Fx 0): 8 zig-zags along
#: Fx whose middles form one plane (docs/tables.md, "family 2"), and one more.
BLOCK = Path(__file__).resolve().parent / "data" / "m5_glide_plane.npz"
NAMES = get_model("m5").param_names


def _block():
    z = np.load(BLOCK)
    grid = sub_grid(Grid.parse("", 11), z["Fx_index"], z["Fz_index"], z["V_index"])
    settings = BuildSettings(
        smooth_tol=0.03, smooth_median=True, smooth_fixed_point=True, smooth_rounds=32
    )
    cfg = BuildConfig("m5", grid, Bird(), CostWeights(incidence=1e-4), settings)
    return cfg, z["params"], z["best"]


def _force_error(cfg, X):
    D = demand_grid(cfg.grid)
    Fx, Fz, _ = forces(get_model("m5"), X, D[..., 2], cfg.bird, cfg.settings.n_search, 0.0)
    return np.maximum(np.abs(Fx - D[..., 0]), np.abs(Fz - D[..., 1]))


def _middles(X, ok, axis):
    return [tuple(int(i) for i in c) for c in np.argwhere(zigzags(NAMES, X, ok, axis)[1])]


def test_the_one_cell_pass_leaves_the_plane_and_the_plane_move_straightens_it():
    cfg, X, best = _block()
    st = cfg.settings
    err0 = _force_error(cfg, X)
    ok = err0 <= st.reach_tol
    assert ok.sum() == 178  # of 180
    # 9 zig-zags, all along Fx; 8 of them with middles at Fx -0.1 (block index 2), one plane
    mids = _middles(X, ok, 0)
    assert zigzag_triples(NAMES, X, ok) == 9 and len(mids) == 9
    plane = [(c[0] + 1,) + c[1:] for c in mids if c[0] + 1 == 2]
    assert len(plane) == 8 and len(components(set(plane), 0)) == 1
    zero = np.zeros(ok.shape, dtype=np.int64)
    # the regularising pass (one cell at a time, to its fixed point) cannot move it
    ckpt = Checkpoints(None, cfg.digest(), cfg.stamp())
    Xp, *_ = build._regularise(cfg, build._InlineExecutor(), ckpt, X, best, zero)
    assert zigzag_triples(NAMES, Xp, ok) == 9
    # the plane moves: the 8 go together; 2 appear along V where the plane ends (V 0.6)
    X1, evals, summary = plane_moves(cfg, X, best, zero)
    assert summary["zigzag_triples"] == [9, 3] and zigzag_triples(NAMES, X1, ok) == 3
    assert all(c[0] + 1 != 2 for c in _middles(X1, ok, 0))
    moved = np.any(X1 != X, axis=-1)
    assert set(map(tuple, np.argwhere(moved))) >= set(plane) and moved[2].sum() == moved.sum()
    # the moves' wingbeat evaluations are counted (cells tried and not kept too), never
    # at an unreachable cell
    assert np.all(evals[moved] > 0) and np.all(evals[~ok] == 0)
    fold = NAMES.index("fold_amp")
    glides = tuple(np.array(plane).T)
    assert np.all(X[glides][:, fold] <= 0.11)  # glides with the fold near 0 ...
    assert np.all(X1[glides][:, fold] >= 0.4)  # ... fold like their neighbours now
    # the wrist is pinned (it does not zig-zag here): an idle wrist stays idle
    wrist = [NAMES.index("wrist_amp"), NAMES.index("wrist_lag")]
    np.testing.assert_array_equal(X1[..., wrist], X[..., wrist])
    # demand met as before (none lost) and each moved cell within smooth_tol of its best
    err1 = _force_error(cfg, X1)
    assert np.all((err1 <= 0.5 * st.reach_tol) | (err1 <= err0 + 1e-7))
    assert np.all(err1[ok] <= st.reach_tol)
    D = demand_grid(cfg.grid)
    for cell in map(tuple, np.argwhere(moved)):
        fx, fz, v = D[cell][:3]
        prob = ForceProblem(get_model("m5"), fx, fz, v, weights=cfg.weights, n=st.n_search)
        cost, _ = candidate_costs(prob, X1[cell][None])
        assert cost[0] <= best[cell] + st.smooth_tol


def test_without_a_move_that_lowers_the_count_nothing_moves():
    # after the moves no component lowers the count any more: a second call is a no-op
    cfg, X, best = _block()
    zero = np.zeros(X.shape[:3], dtype=np.int64)
    X1, _, _ = plane_moves(cfg, X, best, zero)
    X2, _, summary = plane_moves(cfg, X1, best, zero)
    assert X2.tobytes() == X1.tobytes() and summary["moves_kept"] == 0
    assert summary["sweeps"] == 1 and summary["zigzag_triples"] == [3, 3]
    # and the setting changes nothing else: a zero tolerance admits no move
    tight = replace(cfg, settings=replace(cfg.settings, smooth_tol=1e-12))
    X3, _, s3 = plane_moves(tight, X, best, zero)
    assert X3.tobytes() == X.tobytes() and s3["moves_kept"] == 0


def test_components_join_cells_adjacent_along_the_other_axes_only():
    middles = {(1, 0, 0), (1, 1, 0), (1, 1, 1), (2, 3, 3), (1, 3, 3)}
    # along axis 0: (2,3,3) is next to (1,3,3) along the axis itself, not joined
    assert components(middles, 0) == [
        [(1, 0, 0), (1, 1, 0), (1, 1, 1)],
        [(1, 3, 3)],
        [(2, 3, 3)],
    ]
    # along axis 2: (1,1,0) and (1,1,1) differ along the axis itself
    assert components(middles, 2) == [
        [(1, 0, 0), (1, 1, 0)],
        [(1, 1, 1)],
        [(1, 3, 3), (2, 3, 3)],
    ]
