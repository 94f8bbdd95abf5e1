"""The regularising pass of a table build: among wingbeats whose cost is within
``smooth_tol`` of the best found for a cell, keep the one that continues its neighbours.

After the sweeps, the middle cells of zig-zag triples (:mod:`birdsim.tables.smoothness`)
are re-solved.  The candidates of a cell are the answers of SLSQP started at a
*target* (the midpoint of its two neighbours along an axis, one neighbour, or the
parameter-wise median of all its neighbours) on the
dissertation's cost plus the distance cost of eq. 93 to that target (weight
``smooth_nu``): in a flat valley the distance term holds the answer next to the target,
on a sharp optimum it moves it by little.  Each candidate is then judged on the
dissertation's cost alone: it is admissible when that cost is within ``smooth_tol`` of
the best found for the cell (the sweeps' answer, or a cheaper candidate) and it meets
the demand as well as the cell does (no reachable cell is lost).  Among the admissible
candidates (the current wingbeat included) the cell keeps the one in the fewest
zig-zags with its neighbours, then the one closest to them (sum of squared parameter
steps, parameters without effect skipped).

Cells are updated in a red-black order (cells whose index sum is even, then odd), so
that no two neighbours move at once; rounds repeat while zig-zags remain (at most
``smooth_rounds``).  A task is one Fx index's cells of one colour in one round.

**A choice that round-off cannot flip** (issue 21).  Every decision compares numbers
whose near-ties are round-off with a margin far above it, and breaks a tie by a fixed
order, never by which of two near-equal numbers happens to be smaller:

* targets are rounded to :data:`TARGET_QUANTUM_RAD` (1e-3 rad) before SLSQP starts from
  them, so the candidates of a cell are bitwise the same when its neighbours move by
  round-off (a target sits within 1e-9 of a rounding boundary with probability 2e-6);
* candidates within :data:`SAME_MINIMUM_RAD` of an earlier one (the current wingbeat
  comes first) are that one's minimum found again and are dropped;
* a cost is admissible when it is at most ``smooth_tol`` above the best found: near-tied
  costs differ by 1e-11 and sit 5e-3 from that edge; the fallback (nothing admissible:
  the current wingbeat lost to a much cheaper one) takes the costs within
  :data:`COST_TIE` (1e-7) of the cheapest, not the cheapest;
* among the admissible, the fewest zig-zags, then the smallest sum of squared steps
  *within* :data:`STEP_TIE`, then the earliest in the pool: the current wingbeat first
  (hysteresis: a cell moves only for a clearly smoother candidate), then the targets in
  their fixed order.

So a 1e-9 change of any cost changes no choice unless a cost lies within 1e-9 of the
``smooth_tol`` edge or of a tie band's edge (``tests/test_regularise.py`` perturbs the
costs the pass reads, in a random half of the cells and candidates, by +-1e-9 and gets
the identical table).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from birdsim.physics.kinematics import KinematicModel, get_model
from birdsim.tables.grid import BuildConfig
from birdsim.tables.optimize import ForceProblem, slsqp
from birdsim.tables.point import PointForces
from birdsim.tables.smoothness import ZIGZAG_RAD, effect_mask, zigzags

#: Candidate targets closer than this (rad, max norm) to one already taken are skipped.
SAME_TARGET_RAD = 0.02
#: Targets are rounded to this (rad) before SLSQP starts from them: a neighbour moved by
#: round-off gives the same start, hence the bitwise-same candidate.  Small against the
#: zig-zag size (0.15 rad) and against what the distance cost lets the answer move.
TARGET_QUANTUM_RAD = 1e-3
#: Candidates closer than this (rad, max norm over parameters with effect) to an earlier
#: one are the same minimum (SLSQP ends within ~1e-6 of a minimum; distinct minima of a
#: zig-zag differ by > 0.15 rad).
SAME_MINIMUM_RAD = 1e-4
#: Costs within this of the cheapest are tied: 1e4 x the round-off between builds
#: (1e-11) and 100 x a 1e-9 perturbation, far below ``smooth_tol`` (5e-3).
COST_TIE = 1e-7
#: Force errors within this of the current wingbeat's count as "no worse".
FORCE_TIE = 1e-7
#: Sums of squared steps (rad^2) within this of the smallest are tied.
STEP_TIE = 1e-6


def zigzag_cells(
    param_names: tuple[str, ...], X: np.ndarray, ok: np.ndarray, ends: bool = True
) -> np.ndarray:
    """Indices (m x ndim) of the cells of zig-zag triples along some axis (the middles,
    and with ``ends`` the outer cells too: sometimes they are the odd ones), C order."""
    flagged = np.zeros(ok.shape, dtype=bool)
    for k in range(ok.ndim):
        _, zig, _ = zigzags(param_names, X, ok, k)
        for shift in (0, 1, 2) if ends else (1,):
            index = [slice(None)] * ok.ndim
            index[k] = slice(shift, ok.shape[k] - 2 + shift)
            flagged[tuple(index)] |= zig
    return np.argwhere(flagged)


def _neighbours(
    cell: tuple[int, ...], shape: tuple[int, ...], ok: np.ndarray
) -> list[tuple[int, tuple[int, ...]]]:
    out = []
    for k in range(len(shape)):
        for s in (-1, 1):
            n = cell[k] + s
            if 0 <= n < shape[k]:
                c = cell[:k] + (n,) + cell[k + 1 :]
                if ok[c]:
                    out.append((k, c))
    return out


def local_score(
    param_names: tuple[str, ...],
    X: np.ndarray,
    ok: np.ndarray,
    cell: tuple[int, ...],
    x: np.ndarray,
) -> tuple[int, float]:
    """(zig-zag triples that involve ``cell`` if it held ``x``, sum of squared parameter
    steps to its reachable neighbours); smaller is smoother."""
    return local_scores(param_names, X, ok, cell, np.asarray(x, dtype=float)[None])[0]


def local_scores(
    param_names: tuple[str, ...],
    X: np.ndarray,
    ok: np.ndarray,
    cell: tuple[int, ...],
    cand: np.ndarray,
) -> list[tuple[int, float]]:
    """:func:`local_score` of every row of ``cand`` (m x d), the same numbers: the
    zig-zags of all rows counted in one call per axis (elementwise tests), the steps
    summed row by row as there (the neighbours' effect masks made once)."""
    cand = np.asarray(cand, dtype=float)
    rows = len(cand)
    eff = effect_mask(param_names, cand)
    counts = np.zeros(rows, dtype=np.int64)
    for k in range(ok.ndim):
        n = ok.shape[k]
        lo, hi = max(cell[k] - 2, 0), min(cell[k] + 3, n)
        if hi - lo < 3:
            continue
        index = cell[:k] + (slice(lo, hi),) + cell[k + 1 :]
        lines = np.repeat(X[index][None], rows, axis=0)  # rows x line x d
        lines[:, cell[k] - lo] = cand
        line_ok = np.broadcast_to(ok[index], (rows, hi - lo))
        _, zig, _ = zigzags(param_names, lines, line_ok, 1)
        counts += zig.sum(axis=1)
    near = [
        (X[c], effect_mask(param_names, X[c][None])[0]) for _, c in _neighbours(cell, ok.shape, ok)
    ]
    out = []
    for i in range(rows):
        x, steps = cand[i], 0.0
        for xc, eff_c in near:
            both = eff[i] & eff_c
            steps += float(np.sum(np.where(both, x - xc, 0.0) ** 2))
        out.append((int(counts[i]), steps))
    return out


def _targets(
    cell: tuple[int, ...], X: np.ndarray, ok: np.ndarray, median: bool = False
) -> list[np.ndarray]:
    """Midpoints of the two neighbours along each axis, then the neighbours themselves,
    then (``median``, with three or more reachable neighbours) their parameter-wise
    median (``BuildSettings.smooth_median``).

    The median (issue 24) is a median filter's answer to an isolated odd cell: where the
    neighbours sit on two branches it takes, parameter by parameter, the majority's value,
    which neither a midpoint (half-way between the branches) nor a single neighbour (one
    axis's side) offers.  With two neighbours it would be their midpoint again."""
    nb = _neighbours(cell, ok.shape, ok)
    out: list[np.ndarray] = []
    for k in range(ok.ndim):
        pair = [c for a, c in nb if a == k]
        if len(pair) == 2:
            out.append(0.5 * (X[pair[0]] + X[pair[1]]))
    out += [X[c].copy() for _, c in nb]
    if median and len(nb) >= 3:
        out.append(np.median(np.array([X[c] for _, c in nb]), axis=0))
    out = [np.round(t / TARGET_QUANTUM_RAD) * TARGET_QUANTUM_RAD for t in out]
    kept: list[np.ndarray] = []
    for t in out:
        if all(np.max(np.abs(t - u)) >= SAME_TARGET_RAD for u in kept):
            kept.append(t)
    return kept


def _candidate(
    cfg: BuildConfig,
    model: KinematicModel,
    demand: tuple[float, ...],
    target: np.ndarray,
    point: PointForces | None = None,
) -> tuple[np.ndarray, int, bool]:
    target = np.clip(target, *model.bounds)
    prob = demand_problem(cfg, model, demand, previous=target, point=point)
    sol = slsqp(prob, target, maxiter=cfg.settings.maxiter)
    return sol.x, prob.evaluations, sol.converged


def demand_problem(
    cfg: BuildConfig,
    model: KinematicModel,
    demand: tuple[float, ...],
    previous: np.ndarray | None = None,
    point: PointForces | None = None,
) -> ForceProblem:
    """The problem at a ``demand`` (Fx, Fz, V[, climb]) at n_search: the build's cost, or
    with ``previous`` the pass's (eq. 93 distance to it, weight ``distance + smooth_nu``)."""
    fx, fz, v, vc = (tuple(demand) + (0.0,))[:4]
    w = cfg.weights
    weights = w if previous is None else replace(w, distance=w.distance + cfg.settings.smooth_nu)
    return ForceProblem(
        model,
        fx,
        fz,
        v,
        weights=weights,
        bird=cfg.bird,
        previous=previous,
        n=cfg.settings.n_search,
        climb=vc,
        point=point,
    )


def candidate_costs(prob: ForceProblem, cand: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The dissertation's cost (at the problem's n) and the force error
    max(|Fx - Fx_d|, |Fz - Fz_d|) of each candidate row."""
    R, h = prob.parts(cand)
    return np.abs(R) @ prob.weights + h, np.max(np.abs(R[:, :2]), axis=1)


def _same_minimum(names: tuple[str, ...], cand: np.ndarray) -> np.ndarray:
    """True for each candidate within SAME_MINIMUM_RAD of an earlier one (parameters
    with effect in both)."""
    eff = effect_mask(names, cand)
    dup = np.zeros(len(cand), dtype=bool)
    for j in range(1, len(cand)):
        for i in range(j):
            if dup[i]:
                continue
            both = eff[i] & eff[j]
            if np.all(np.abs(np.where(both, cand[j] - cand[i], 0.0)) <= SAME_MINIMUM_RAD):
                dup[j] = True
                break
    return dup


def choose(
    cost: np.ndarray,
    err: np.ndarray,
    best: float,
    scores: list[tuple[int, float]],
    duplicate: np.ndarray,
    smooth_tol: float,
    reach_tol: float,
) -> int:
    """The candidate a cell keeps (index into its pool; 0 is the current wingbeat).

    Admissible: cost at most ``smooth_tol`` above ``best`` (the best found, these
    candidates included) and the demand met as well as the cell did (force error <=
    reach_tol / 2, or within FORCE_TIE of the current one's); if none is, the costs within
    COST_TIE of the cheapest.  Among the admissible and not ``duplicate``: the fewest
    zig-zags (``scores[i][0]``), then the steps (``scores[i][1]``) within STEP_TIE of the
    smallest, then the earliest.  No comparison decides on a difference below its tie."""
    cost, err = np.asarray(cost, dtype=float), np.asarray(err, dtype=float)
    meets = (err <= 0.5 * reach_tol) | (err <= err[0] + FORCE_TIE)
    admissible = (cost <= best + smooth_tol) & meets & ~duplicate
    if not admissible.any():  # the current one lost to a much cheaper candidate
        admissible = (cost <= cost.min() + COST_TIE) & ~duplicate
    if not admissible.any():  # every cheapest one is a duplicate of an earlier one
        admissible = cost <= cost.min() + COST_TIE
    idx = np.flatnonzero(admissible)
    fewest = min(scores[i][0] for i in idx)
    idx = [i for i in idx if scores[i][0] == fewest]
    least = min(scores[i][1] for i in idx)
    return int(next(i for i in idx if scores[i][1] <= least + STEP_TIE))


class CandidateMemo:
    """The pass's SLSQP answers by (cell, rounded target).  A candidate is a pure
    function of its cell's demand and its target (the start and the distance cost's
    anchor), so a cell flagged again in a later round reuses the answers of the targets
    it had before (bitwise the same; not counted as evaluations again)."""

    def __init__(self) -> None:
        self._by_cell: dict[tuple[int, ...], dict[bytes, np.ndarray]] = {}

    def for_cells(self, cells: np.ndarray) -> dict[tuple[tuple[int, ...], bytes], np.ndarray]:
        """The known answers of ``cells`` (m x ndim), keyed by (cell, target bytes)."""
        out = {}
        for c in cells:
            cell = tuple(int(i) for i in c)
            out.update({(cell, t): x for t, x in self._by_cell.get(cell, {}).items()})
        return out

    def groups(
        self, cells: np.ndarray, X: np.ndarray, ok: np.ndarray, median: bool, size: int
    ) -> list[np.ndarray]:
        """``cells`` (m x ndim, one colour) in ceil(m / size) tasks of similar work: by
        descending count of targets without a known answer, dealt round-robin (how the
        cells of one colour are grouped does not change the result)."""
        keys = [tuple(int(i) for i in c) for c in cells]
        fresh = [
            sum(t.tobytes() not in self._by_cell.get(c, {}) for t in _targets(c, X, ok, median))
            for c in keys
        ]
        order = np.argsort(-np.asarray(fresh), kind="stable")
        n = -(-len(cells) // size)
        return [cells[np.sort(order[g::n])] for g in range(n)]

    def add(self, result: dict[str, np.ndarray]) -> None:
        """Remember the new answers of one :func:`smooth_cells` result."""
        for c, t, x in zip(result["new_cells"], result["new_targets"], result["new_x"]):
            self._by_cell.setdefault(tuple(int(i) for i in c), {})[t.tobytes()] = x


def smooth_cells(
    cfg: BuildConfig,
    cells: np.ndarray,
    X: np.ndarray,
    ok: np.ndarray,
    best_cost: np.ndarray,
    demands: np.ndarray,
    known: dict[tuple[tuple[int, ...], bytes], np.ndarray] | None = None,
) -> dict[str, np.ndarray]:
    """One task of the regularising pass: re-choose the wingbeat of each of ``cells``
    (m x ndim indices into the grid) given the table ``X`` (grid x d), the reachable
    cells ``ok``, the best cost found so far per listed cell (``best_cost``, m) and the
    candidates found before (``known``: :meth:`CandidateMemo.for_cells`).

    Returns:
        ``params`` (m x d), ``cost`` (the dissertation's cost at n_search of the kept
        wingbeat), ``best`` (the best cost found, m), ``evaluations`` and ``converged``;
        the new candidates ``new_cells``, ``new_targets``, ``new_x`` (for the memo).
    """
    from birdsim.tables.sweeps import canonical_params

    model = get_model(cfg.model)
    st = cfg.settings
    names, d = model.param_names, X.shape[-1]
    cells = [tuple(int(i) for i in c) for c in cells]
    known = known or {}
    owner, results, fresh = [], [], []
    for m, cell in enumerate(cells):
        demand = tuple(demands[cell])
        point: PointForces | None = None  # one per cell: every candidate's demand point
        for target in _targets(cell, X, ok, st.smooth_median):
            x = known.get((cell, target.tobytes()))
            if x is None:
                if point is None:
                    fx, fz, v, vc = (demand + (0.0,))[:4]
                    point = PointForces.create(model, cfg.bird, v, vc, st.n_search)
                x, e, conv = _candidate(cfg, model, demand, target, point)
                fresh.append((cell, target, x))
            else:
                e, conv = 0, True
            results.append((x, e, conv))
            owner.append(m)
    pool: list[list[np.ndarray]] = [[X[c].copy()] for c in cells]
    evals = np.zeros(len(cells), dtype=np.int64)
    conv = np.ones(len(cells), dtype=bool)
    # the candidates' SLSQP flags are not used: `converged` stays True (kept as it was)
    for m, (x, e, _converged) in zip(owner, results):
        pool[m].append(canonical_params(model, x))
        evals[m] += e
    out_x = np.array([X[c] for c in cells], dtype=float).reshape(len(cells), -1)
    out_cost = np.zeros(len(cells))
    best = np.asarray(best_cost, dtype=float).copy()
    for m, cell in enumerate(cells):
        cand = np.array(pool[m])
        cost, err = candidate_costs(demand_problem(cfg, model, demands[cell]), cand)
        evals[m] += len(cand)
        best[m] = min(best[m], float(cost.min()))
        scores = local_scores(names, X, ok, cell, cand)
        pick = choose(
            cost, err, best[m], scores, _same_minimum(names, cand), st.smooth_tol, st.reach_tol
        )
        out_x[m], out_cost[m] = cand[pick], cost[pick]
    return {
        "params": out_x,
        "cost": out_cost,
        "best": best,
        "evaluations": evals,
        "converged": conv,
        "new_cells": np.array([f[0] for f in fresh], dtype=np.int64).reshape(-1, len(ok.shape)),
        "new_targets": np.array([f[1] for f in fresh], dtype=float).reshape(len(fresh), d),
        "new_x": np.array([f[2] for f in fresh], dtype=float).reshape(len(fresh), d),
    }


__all__ = [
    "COST_TIE",
    "CandidateMemo",
    "ZIGZAG_RAD",
    "candidate_costs",
    "choose",
    "demand_problem",
    "local_score",
    "local_scores",
    "smooth_cells",
    "zigzag_cells",
]
