"""The regularising pass of a table build: among wingbeats whose cost is within
``smooth_tol`` of the best found for a cell, keep the one that continues its neighbours.

After the sweeps, the middle cells of zig-zag triples (:mod:`birdsim.tables.smoothness`)
are re-solved.  The candidates of a cell are the answers of SLSQP started at a
*target* (the midpoint of its two neighbours along an axis, or one neighbour) on the
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
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from birdsim.physics.kinematics import KinematicModel, get_model
from birdsim.tables.grid import BuildConfig
from birdsim.tables.optimize import ForceProblem, slsqp
from birdsim.tables.smoothness import ZIGZAG_RAD, effect_mask, zigzags

#: Candidate targets closer than this (rad, max norm) to one already taken are skipped.
SAME_TARGET_RAD = 0.02


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
    eff_x = effect_mask(param_names, x[None])[0]
    count = 0
    for k in range(ok.ndim):
        n = ok.shape[k]
        lo, hi = max(cell[k] - 2, 0), min(cell[k] + 3, n)
        if hi - lo < 3:
            continue
        index = cell[:k] + (slice(lo, hi),) + cell[k + 1 :]
        line = X[index].copy()
        line[cell[k] - lo] = x
        _, zig, _ = zigzags(param_names, line, ok[index], 0)
        count += int(zig.sum())
    steps = 0.0
    for _, c in _neighbours(cell, ok.shape, ok):
        both = eff_x & effect_mask(param_names, X[c][None])[0]
        steps += float(np.sum(np.where(both, x - X[c], 0.0) ** 2))
    return count, steps


def _targets(cell: tuple[int, ...], X: np.ndarray, ok: np.ndarray) -> list[np.ndarray]:
    """Midpoints of the two neighbours along each axis, then the neighbours themselves."""
    nb = _neighbours(cell, ok.shape, ok)
    out: list[np.ndarray] = []
    for k in range(ok.ndim):
        pair = [c for a, c in nb if a == k]
        if len(pair) == 2:
            out.append(0.5 * (X[pair[0]] + X[pair[1]]))
    out += [X[c].copy() for _, c in nb]
    kept: list[np.ndarray] = []
    for t in out:
        if all(np.max(np.abs(t - u)) >= SAME_TARGET_RAD for u in kept):
            kept.append(t)
    return kept


def _candidate(
    cfg: BuildConfig, model: KinematicModel, demand: tuple[float, ...], target: np.ndarray
) -> tuple[np.ndarray, int, bool]:
    fx, fz, v, vc = (tuple(demand) + (0.0,))[:4]
    weights = replace(cfg.weights, distance=cfg.weights.distance + cfg.settings.smooth_nu)
    prob = ForceProblem(
        model,
        fx,
        fz,
        v,
        weights=weights,
        bird=cfg.bird,
        previous=target,
        n=cfg.settings.n_search,
        climb=vc,
    )
    sol = slsqp(prob, target, maxiter=cfg.settings.maxiter)
    return sol.x, prob.evaluations, sol.converged


def smooth_cells(
    cfg: BuildConfig,
    cells: np.ndarray,
    X: np.ndarray,
    ok: np.ndarray,
    best_cost: np.ndarray,
    demands: np.ndarray,
) -> dict[str, np.ndarray]:
    """One task of the regularising pass: re-choose the wingbeat of each of ``cells``
    (m x ndim indices into the grid) given the table ``X`` (grid x d), the reachable
    cells ``ok`` and the best cost found so far per listed cell (``best_cost``, m).

    Returns:
        ``params`` (m x d), ``cost`` (the dissertation's cost at n_search of the kept
        wingbeat), ``best`` (the best cost found, m), ``evaluations`` and ``converged``.
    """
    from birdsim.tables.sweeps import canonical_params

    model = get_model(cfg.model)
    st = cfg.settings
    names = model.param_names
    cells = [tuple(int(i) for i in c) for c in cells]
    owner, results = [], []
    for m, cell in enumerate(cells):
        for target in _targets(cell, X, ok):
            results.append(_candidate(cfg, model, tuple(demands[cell]), target))
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
        fx, fz, v, vc = (tuple(demands[cell]) + (0.0,))[:4]
        prob = ForceProblem(
            model, fx, fz, v, weights=cfg.weights, bird=cfg.bird, n=st.n_search, climb=vc
        )
        R, h = prob.parts(cand)
        cost = np.abs(R) @ prob.weights + h
        err = np.max(np.abs(R[:, :2]), axis=1)
        evals[m] += len(cand)
        best[m] = min(best[m], float(cost.min()))
        admissible = (cost <= best[m] + st.smooth_tol) & (
            (err <= 0.5 * st.reach_tol) | (err <= err[0] + 1e-9)
        )
        if not admissible.any():  # the current one lost to a much cheaper candidate
            admissible = cost <= cost.min()
        scores = [
            local_score(names, X, ok, cell, cand[i]) + (i,) if admissible[i] else None
            for i in range(len(cand))
        ]
        pick = min(s for s in scores if s is not None)[2]
        out_x[m], out_cost[m] = cand[pick], cost[pick]
    return {
        "params": out_x,
        "cost": out_cost,
        "best": best,
        "evaluations": evals,
        "converged": conv,
    }


__all__ = ["ZIGZAG_RAD", "local_score", "smooth_cells", "zigzag_cells"]
