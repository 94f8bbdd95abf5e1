"""Plane moves (birdsim/tables/plane_moves.py): a plane of zig-zag middles moved together
straightens it, within the pass's cost tolerance, every reachable cell kept."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.tables.cost import CostWeights, forces
from birdsim.tables.finish import demand_grid
from birdsim.tables.grid import BuildConfig, BuildSettings, Grid, sub_grid
from birdsim.tables.optimize import ForceProblem
from birdsim.tables.plane_moves import components, plane_moves, zigzag_triples
from birdsim.tables.regularise import candidate_costs

#: A 3 x 4 x 4 block of the seed bird's m5 table (Fx -0.2..0, Fz -0.4..-0.25, V 0.6-0.9)
#: as the regularising pass left it at its fixed point (w_q 1e-4, smooth_tol 0.03, X86_V3):
#: glides with the fold near 0 at Fx -0.1 between braking with the fold at 0.5-0.8 (Fx
#: -0.2) and flapping (Fx 0): 8 zig-zags along Fx whose middles form one plane
#: (docs/tables.md, "family 2"), and the best cost found per cell.
BLOCK = Path(__file__).resolve().parent / "data" / "m5_glide_plane.npz"


def _block():
    z = np.load(BLOCK)
    grid = sub_grid(Grid.parse("", 11), z["Fx_index"], z["Fz_index"], z["V_index"])
    settings = BuildSettings(smooth_tol=0.03, smooth_median=True, smooth_planes=True)
    cfg = BuildConfig("m5", grid, Bird(), CostWeights(incidence=1e-4), settings)
    return cfg, z["params"], z["best"]


def _force_error(cfg, X):
    D = demand_grid(cfg.grid)
    Fx, Fz, _ = forces(get_model("m5"), X, D[..., 2], cfg.bird, cfg.settings.n_search, 0.0)
    return np.maximum(np.abs(Fx - D[..., 0]), np.abs(Fz - D[..., 1]))


def test_a_plane_of_glides_is_moved_together_and_its_zigzags_go():
    cfg, X, best = _block()
    names, st = get_model("m5").param_names, cfg.settings
    err0 = _force_error(cfg, X)
    ok = err0 <= st.reach_tol
    assert ok.sum() >= 40  # of 48
    assert zigzag_triples(names, X, ok) == 8  # all along Fx, middles at Fx -0.1
    X1, evals, summary = plane_moves(cfg, X, best, np.zeros(ok.shape, dtype=np.int64))
    moved = np.any(X1 != X, axis=-1)
    assert zigzag_triples(names, X1, ok) == 0 and summary["zigzag_triples"] == [8, 0]
    # one move of the whole plane: the 8 middles (Fx index 1), nothing else
    assert summary["moves_kept"] == 1 and moved.sum() == 8 and moved[1].sum() == 8
    assert np.all(evals[moved] > 0) and np.all(evals[~moved] == 0)
    fold = names.index("fold_amp")
    assert np.all(X[1, ..., fold][moved[1]] <= 0.11)  # glides with the fold near 0 ...
    assert np.all(X1[1, ..., fold][moved[1]] >= 0.3)  # ... fold like their neighbours
    # the pinned parameters are untouched: only the moved ones and the trim changed
    free = [names.index(n) for n in ("fold_amp", "fold_phase", "supination_amp")]
    free += [names.index(n) for n in ("pitch", "stroke_plane", "wrist_bias", "twist_amp")]
    pinned = np.setdiff1d(np.arange(len(names)), free)
    np.testing.assert_array_equal(X1[..., pinned], X[..., pinned])
    # demand met as before (none lost) and each cell within smooth_tol of its best
    err1 = _force_error(cfg, X1)
    assert np.all((err1 <= 0.5 * st.reach_tol) | (err1 <= err0 + 1e-7))
    assert np.all(err1[ok] <= st.reach_tol)
    D = demand_grid(cfg.grid)
    for cell in map(tuple, np.argwhere(moved)):
        fx, fz, v = D[cell][:3]
        prob = ForceProblem(get_model("m5"), fx, fz, v, weights=cfg.weights, n=st.n_search)
        cost, _ = candidate_costs(prob, X1[cell][None])
        assert cost[0] <= best[cell] + st.smooth_tol


def test_without_a_plane_nothing_moves():
    # the same block with the glides' fold already on the neighbours' side: no zig-zag,
    # no component, the table returned unchanged
    cfg, X, best = _block()
    X1, _, _ = plane_moves(cfg, X, best, np.zeros(X.shape[:3], dtype=np.int64))
    X2, evals, summary = plane_moves(cfg, X1, best, np.zeros(X.shape[:3], dtype=np.int64))
    assert X2.tobytes() == X1.tobytes() and evals.sum() == 0
    assert summary["moves_kept"] == 0 and summary["sweeps"] == 1


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
