"""Plane moves: after the regularising pass, move a whole plane of zig-zag middles at once.

The pass (:mod:`birdsim.tables.regularise`) moves one cell at a time, so it cannot
straighten a zig-zag whose middle cells form a coherent *plane* across the other axes:
moving one of them trades the zig-zag along the axis for two along the plane (issue 24,
the seed bird's m5 table: glides with the fold near 0 at Fx -0.1 between a folded
braking plane at Fx -0.2 and flapping at Fx 0).  A plane move takes, for one axis, the
middles of its zig-zag triples, grouped into *components* of cells adjacent along the
other axes, and moves a component together:

* each cell's *target* is its own wingbeat with the zig-zagging parameters (those more
  than :data:`~birdsim.tables.smoothness.ZIGZAG_RAD` from both neighbours along the
  axis; with the fold or supination amplitude also the fold phase, with the wrist
  amplitude also the wrist lag) set to the midpoint of its two neighbours along the
  axis, those rounded to :data:`~birdsim.tables.regularise.TARGET_QUANTUM_RAD` (the
  others keep their exact values, so that an idle wrist stays idle);
* SLSQP re-solves the cell from its target on the pass's cost (the build's cost plus
  the distance cost ``smooth_nu`` to the target) with the moved parameters and the
  *trim* (:data:`TRIM_PARAMS`: they re-trim the force) free and every other parameter
  pinned at the cell's value by bounds :data:`PIN_HALF_WIDTH_RAD` either side;
* a cell's answer is admissible by the pass's rules (cost within ``smooth_tol`` of the
  best found, demand met as well as before: no reachable cell is lost); the admissible
  cells of the component move together, and the move is kept when the table's
  zig-zag triples (every axis) fall.

The axes are swept in order until a sweep keeps no move (at most :data:`MAX_SWEEPS`).
Everything runs in the building process (about 1 s for an 11^3 table) and is
deterministic: components in C order, SLSQP answers memoised by (cell, target, free set).
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from birdsim.physics.kinematics import KinematicModel, get_model
from birdsim.tables.cost import forces
from birdsim.tables.finish import demand_grid
from birdsim.tables.grid import BuildConfig
from birdsim.tables.optimize import slsqp
from birdsim.tables.regularise import (
    FORCE_TIE,
    TARGET_QUANTUM_RAD,
    candidate_costs,
    demand_problem,
)
from birdsim.tables.smoothness import ZIGZAG_RAD, zigzags

#: Parameters free in every plane move besides the moved ones (those the model has): the
#: body pitch, stroke plane, wrist bias and twist, which set the wing's incidence and so
#: re-trim the force when the moved parameters change it.
TRIM_PARAMS = ("pitch", "stroke_plane", "wrist_bias", "twist_amp")
#: Half width (rad) of the bounds that pin a parameter at its value during a re-solve.
PIN_HALF_WIDTH_RAD = 1e-7
#: At most this many sweeps over the axes.
MAX_SWEEPS = 6

Cell = tuple[int, ...]


def zigzag_triples(names: tuple[str, ...], X: np.ndarray, ok: np.ndarray) -> int:
    """Zig-zag triples of ``X`` (grid x d, rad) over every axis, among ``ok`` cells."""
    return sum(int(zigzags(names, X, ok, k)[1].sum()) for k in range(ok.ndim))


def along(cell: Cell, axis: int) -> tuple[Cell, Cell]:
    """The cell's two neighbours along ``axis`` (one step down, one up; maybe off the grid)."""
    head, i, tail = cell[:axis], cell[axis], cell[axis + 1 :]
    return head + (i - 1,) + tail, head + (i + 1,) + tail


def components(middles: set[Cell], axis: int) -> list[list[Cell]]:
    """``middles`` grouped into sets connected by unit steps along the axes other than
    ``axis``; each component sorted, components in the order of their first cell."""
    seen: set[Cell] = set()
    out: list[list[Cell]] = []
    for start in sorted(middles):
        if start in seen:
            continue
        stack, comp = [start], []
        seen.add(start)
        while stack:
            u = stack.pop()
            comp.append(u)
            for j in range(len(u)):
                if j == axis:
                    continue
                for s in (-1, 1):
                    v = u[:j] + (u[j] + s,) + u[j + 1 :]
                    if v in middles and v not in seen:
                        seen.add(v)
                        stack.append(v)
        out.append(sorted(comp))
    return out


class _Mover:
    """The state of the moves on one table: parameters ``X`` (grid x d, rad), the
    reachable cells ``ok`` (fixed: judged at the start, at n_search), the best cost
    found per cell and the evaluations (kinematics per cell)."""

    def __init__(
        self, cfg: BuildConfig, X: np.ndarray, best: np.ndarray, evals: np.ndarray
    ) -> None:
        self.cfg, self.st = cfg, cfg.settings
        self.model: KinematicModel = get_model(cfg.model)
        self.names = self.model.param_names
        self.X, self.best, self.evals = X.copy(), best.copy(), evals.copy()
        self.D = demand_grid(cfg.grid)
        climb = self.D[..., 3] if self.D.shape[-1] > 3 else 0.0
        Fx, Fz, _ = forces(self.model, self.X, self.D[..., 2], cfg.bird, self.st.n_search, climb)
        err = np.maximum(np.abs(Fx - self.D[..., 0]), np.abs(Fz - self.D[..., 1]))
        self.ok = err <= self.st.reach_tol
        self.trim = np.isin(np.array(self.names), TRIM_PARAMS)
        self._memo: dict[tuple[Cell, bytes, bytes], np.ndarray] = {}

    def _index(self, name: str) -> int | None:
        return self.names.index(name) if name in self.names else None

    def moved_params(self, cell: Cell, axis: int) -> np.ndarray | None:
        """The parameters of ``cell`` that zig-zag along ``axis`` (bool, d), or None when
        the cell or one of its two neighbours along the axis is off the grid or not ok."""
        a, b = along(cell, axis)
        if a[axis] < 0 or b[axis] >= self.ok.shape[axis]:
            return None
        if not (self.ok[a] and self.ok[b] and self.ok[cell]):
            return None
        line = np.stack([self.X[a], self.X[cell], self.X[b]])[None]
        size = zigzags(self.names, line, np.ones((1, 3), dtype=bool), 1)[2][0, 0]
        sel = size > ZIGZAG_RAD
        fold, sup, phase = (self._index(n) for n in ("fold_amp", "supination_amp", "fold_phase"))
        wrist, lag = self._index("wrist_amp"), self._index("wrist_lag")
        if phase is not None and any(i is not None and sel[i] for i in (fold, sup)):
            sel[phase] = True  # a moved fold or supination carries its phase
        if wrist is not None and lag is not None and sel[wrist]:
            sel[lag] = True  # a moved wrist carries its lag
        return sel

    def _solve(self, cell: Cell, target: np.ndarray, free: np.ndarray) -> np.ndarray:
        """SLSQP from ``target`` on the pass's cost, the parameters not ``free`` pinned."""
        key = (cell, target.tobytes(), free.tobytes())
        if key in self._memo:
            return self._memo[key]
        prob = demand_problem(self.cfg, self.model, self.D[cell], previous=target)
        lo0, hi0 = self.model.bounds
        lo, hi = prob.lower.copy(), prob.upper.copy()
        pin = ~free
        lo[pin] = np.maximum(lo0[pin], target[pin] - PIN_HALF_WIDTH_RAD)
        hi[pin] = np.minimum(hi0[pin], target[pin] + PIN_HALF_WIDTH_RAD)
        prob.lower, prob.upper = lo, hi
        x = slsqp(prob, np.clip(target, lo, hi), maxiter=self.st.maxiter).x.copy()
        x[pin] = target[pin]
        self.evals[cell] += prob.evaluations
        self._memo[key] = x
        return x

    def try_cell(self, cell: Cell, axis: int, sel: np.ndarray) -> tuple[np.ndarray, float] | None:
        """The cell's answer to its midpoint target along ``axis`` and its cost (n_search),
        or None when the answer is not admissible."""
        a, b = along(cell, axis)
        target = self.X[cell].copy()  # the pinned parameters keep their exact values
        mid = 0.5 * (self.X[a] + self.X[b])
        target[sel] = np.round(mid[sel] / TARGET_QUANTUM_RAD) * TARGET_QUANTUM_RAD
        x = self._solve(cell, target, sel | self.trim)
        prob = demand_problem(self.cfg, self.model, self.D[cell])
        cost, err = candidate_costs(prob, np.vstack([self.X[cell], x]))
        st = self.st
        self.evals[cell] += 2
        best = min(float(self.best[cell]), float(cost.min()))
        meets = err[1] <= 0.5 * st.reach_tol or err[1] <= err[0] + FORCE_TIE
        if cost[1] <= best + st.smooth_tol and meets:
            return x, float(cost[1])
        return None

    def move(self, comp: list[Cell], axis: int) -> tuple[int, int, int]:
        """Try one component along ``axis``: (triples before, after, cells moved); the
        move is applied when the triples fall."""
        sels = [self.moved_params(c, axis) for c in comp]
        before = zigzag_triples(self.names, self.X, self.ok)
        if any(s is None for s in sels):
            return before, before, 0
        Xn, moved = self.X.copy(), {}
        for cell, sel in zip(comp, sels):
            assert sel is not None
            r = self.try_cell(cell, axis, sel)
            if r is not None:
                Xn[cell], moved[cell] = r
        after = zigzag_triples(self.names, Xn, self.ok) if moved else before
        if moved and after < before:
            self.X = Xn
            for cell, c in moved.items():
                self.best[cell] = min(self.best[cell], c)
            return before, after, len(moved)
        return before, before, 0


def plane_moves(
    cfg: BuildConfig, X: np.ndarray, best: np.ndarray, evals: np.ndarray
) -> tuple[np.ndarray, np.ndarray, dict[str, Any]]:
    """The plane moves (module docstring) on the regularising pass's answer.

    Args:
        cfg: the build's configuration (``smooth_tol``, ``smooth_nu``, ``reach_tol``,
            ``n_search``, ``maxiter`` of its settings; its cost weights).
        X: the table's parameters (grid x d, rad) after the pass.
        best: the best cost found per cell (grid, the dissertation's cost at n_search).
        evals: the evaluations per cell so far (grid); the moves' are added.
    Returns:
        (parameters, evaluations, summary for the provenance: sweeps, moves kept, cells
        moved (each once, however often), zig-zag triples before and after, seconds).
    """
    t0 = time.perf_counter()
    m = _Mover(cfg, X, best, evals)
    start = zigzag_triples(m.names, m.X, m.ok)
    summary: dict[str, Any] = {"sweeps": 0, "moves_kept": 0}
    for sweep in range(MAX_SWEEPS):
        kept = 0
        for axis in range(m.ok.ndim):
            zig = zigzags(m.names, m.X, m.ok, axis)[1]
            middles = {
                tuple(int(i) + (j == axis) for j, i in enumerate(idx)) for idx in np.argwhere(zig)
            }
            for comp in components(middles, axis):
                before, after, _ = m.move(comp, axis)
                kept += after < before
        summary["sweeps"] = sweep + 1
        summary["moves_kept"] += kept
        if not kept:
            break
    summary["cells_moved"] = int(np.any(m.X != X, axis=-1).sum())  # each counted once
    summary["zigzag_triples"] = [start, zigzag_triples(m.names, m.X, m.ok)]
    summary["seconds"] = round(time.perf_counter() - t0, 3)
    return m.X, m.evals, summary


__all__ = ["MAX_SWEEPS", "PIN_HALF_WIDTH_RAD", "TRIM_PARAMS", "components", "plane_moves"]
