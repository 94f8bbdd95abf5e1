"""The continuation sweeps of a table build (dissertation sec. 4.1.1, Fig. 39): one
cell solved from a warm start and a shared screen, the V slices (sweeps in Fz and Fx,
a backward pass in Fz) and the V lines (forward and backward passes in V).

The tasks :func:`solve_slice` and :func:`solve_v_line` are top-level functions of
picklable frozen dataclasses, so that process and cluster executors can run them."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from birdsim.physics.kinematics import KinematicModel, get_model
from birdsim.tables.cost import breakdown_from_forces, forces, other_cost
from birdsim.tables.grid import BuildConfig
from birdsim.tables.optimize import ForceProblem, box_corners, random_starts, slsqp

# ---- one cell -------------------------------------------------------------------------


def _problem(
    cfg: BuildConfig,
    model: KinematicModel,
    fx: float,
    fz: float,
    v: float,
    previous: np.ndarray | None,
    climb: float = 0.0,
) -> ForceProblem:
    return ForceProblem(
        model,
        fx,
        fz,
        v,
        weights=cfg.weights,
        bird=cfg.bird,
        previous=previous,
        n=cfg.settings.n_search,
        climb=climb,
    )


def _screen(
    cfg: BuildConfig, model: KinematicModel, v: float, climb: float = 0.0
) -> tuple[np.ndarray, tuple[np.ndarray, ...], np.ndarray]:
    """Candidates (S x d), their (Fx, Fz, P) and their non-force cost, one batched call:
    scrambled Sobol points, the model's hover and cruise guesses and the box corners."""
    dummy = _problem(cfg, model, 0.0, 0.0, v, None, climb=climb)
    S = random_starts(dummy, cfg.settings.screen, cfg.settings.seed)
    guesses = [list(model.guess(r).values()) for r in ("hover", "cruise")]
    S = np.vstack([S, guesses, box_corners(dummy)])
    F = forces(model, S, v, cfg.bird, cfg.settings.n_search, climb)
    return S, F, other_cost(model, S, v, cfg.weights)


#: Measurement hook of ``scripts/polish_study.py`` (None in builds): called once per
#: polish in :func:`_solve_cell` with what was known before it and its outcome.
POLISH_PROBE: Callable[..., None] | None = None


def _solve_cell(
    cfg: BuildConfig,
    model: KinematicModel,
    fx: float,
    fz: float,
    v: float,
    warm: np.ndarray | None,
    screen: tuple[np.ndarray, tuple[np.ndarray, ...], np.ndarray],
    climb: float = 0.0,
) -> tuple[np.ndarray, float, int, bool]:
    """Warm-started SLSQP, multi-start from the screen where the warm start is poor.
    Returns (x, cost at n_search, cycle evaluations, SLSQP converged).

    With ``polish_rule`` a screen candidate is not polished after a warm start where
    the polish cannot win (docs/performance.md, "Where polishes win"): (a) the answer
    so far is within ``switch_margin`` of the cost's lower bound on the box (the force
    and power terms are >= 0, the rest is smallest at the lower bounds), so nothing
    can beat it by the margin; (b) the candidate lies within ``polish_near`` of the
    warm answer in every parameter (as a fraction of the parameter's range) and costs
    between 1 and 1 + ``polish_excess`` times as much: its polish returns to the warm
    answer's minimum (none of those won in the measured builds, which gave the same
    tables as without the rule).  Cold cells (no warm start) are always polished."""
    st = cfg.settings
    S, (Fx, Fz, P), other = screen
    c = breakdown_from_forces(Fx, Fz, P, fx, fz, cfg.weights, other).total
    order = np.argsort(c)
    prob = _problem(cfg, model, fx, fz, v, warm if cfg.weights.distance > 0 else None, climb)
    best = None
    polish = max(st.starts, 1)
    if warm is not None:
        best = slsqp(prob, warm, maxiter=st.maxiter)
        if best.cost < c[order[0]] - st.screen_gap:
            polish = st.always_polish  # a good warm start: still try the best screen candidate(s)
    warm_sol = best
    floor = float(
        other_cost(model, prob.lower[None], v, cfg.weights)[0]
    )  # the cost's lower bound on the box
    width = np.where(prob.upper > prob.lower, prob.upper - prob.lower, 1.0)
    for rank, k in enumerate(order[:polish]):
        if st.polish_rule and warm_sol is not None and best is not None:
            near = np.max(np.abs(S[k] - warm_sol.x) / width) <= st.polish_near
            returns = near and warm_sol.cost <= c[k] <= (1.0 + st.polish_excess) * warm_sol.cost
            if best.cost <= floor + st.switch_margin or returns:
                continue
        before, e0 = best, prob.evaluations
        sol = slsqp(prob, S[k], maxiter=st.maxiter)
        if best is None or sol.cost < best.cost - st.switch_margin:
            best = sol
        if POLISH_PROBE is not None:
            POLISH_PROBE(
                cfg=cfg,
                prob=prob,
                demand=(fx, fz, v, climb),
                warm=warm_sol,
                before=before,
                rank=rank,
                candidate=S[k],
                screen_cost=c[order],
                screen_force=(Fx[k], Fz[k]),
                sol=sol,
                evaluations=prob.evaluations - e0,
            )
    assert best is not None
    return best.x, best.cost, prob.evaluations, best.converged


def _resolve_from(
    cfg: BuildConfig,
    model: KinematicModel,
    fx: float,
    fz: float,
    v: float,
    start: np.ndarray,
    climb: float = 0.0,
) -> tuple[np.ndarray, float, int, bool]:
    prob = _problem(cfg, model, fx, fz, v, start if cfg.weights.distance > 0 else None, climb)
    sol = slsqp(prob, start, maxiter=cfg.settings.maxiter)
    return sol.x, sol.cost, prob.evaluations, sol.converged


#: A wrist amplitude below this (rad) counts as an idle wrist.
IDLE_WRIST = 1e-6


def canonical_params(model: KinematicModel, X: np.ndarray) -> np.ndarray:
    """Parameters with flat directions pinned: when the wrist is idle (amplitude below
    :data:`IDLE_WRIST`) its phase lag has no effect at all, so it is set to the model's
    lower bound 0 (in phase with the shoulder, what most active wrists choose) and the
    amplitude to 0.  The cost is unchanged; the table gets smoother
    and the V passes can recognise the same branch."""
    names = model.param_names
    if "wrist_amp" not in names:
        return X
    X = np.array(X, dtype=float, copy=True)
    amp, lag = names.index("wrist_amp"), names.index("wrist_lag")
    idle = X[..., amp] < IDLE_WRIST
    X[..., amp] = np.where(idle, 0.0, X[..., amp])
    X[..., lag] = np.where(idle, model.spec("wrist_lag").lower, X[..., lag])
    if "fold_phase" in names:  # m5: an idle fold (no fold, no supination) has no phase
        f, s, ph = (names.index(n) for n in ("fold_amp", "supination_amp", "fold_phase"))
        idle = (X[..., f] < IDLE_WRIST) & (X[..., s] < IDLE_WRIST)
        X[..., f] = np.where(idle, 0.0, X[..., f])
        X[..., s] = np.where(idle, 0.0, X[..., s])
        X[..., ph] = np.where(idle, 0.0, X[..., ph])
    return X


def _improve_cell(
    cfg: BuildConfig,
    model: KinematicModel,
    fx: float,
    fz: float,
    v: float,
    starts: list[np.ndarray],
    climb: float = 0.0,
) -> tuple[np.ndarray | None, float, int, bool]:
    """The best SLSQP answer from ``starts`` (None if there are none)."""
    prob = _problem(cfg, model, fx, fz, v, None, climb)
    best = None
    for x0 in starts:
        sol = slsqp(prob, x0, maxiter=cfg.settings.maxiter)
        if best is None or sol.cost < best.cost:
            best = sol
    if best is None:
        return None, np.inf, prob.evaluations, True
    return best.x, best.cost, prob.evaluations, best.converged


# ---- tasks (top-level functions: picklable for process and cluster executors) -----------


def solve_slice(cfg: BuildConfig, iv: int, ic: int | None = None) -> dict[str, np.ndarray]:
    """Phase 1 for the slice V = grid.V[iv] (and climb = grid.climb[ic] on a grid with a
    climb axis, else 0): sweep Fz (inner) and Fx (outer, downwards).

    The first column (strongest lift demand) is a chain of warm starts from +Fx_max
    down; then every Fx line sweeps Fz upwards; then a backward pass in Fz re-solves
    each cell from its Fx/Fz neighbours on other branches."""
    model = get_model(cfg.model)
    g = cfg.grid
    v = g.V[iv]
    vc = 0.0 if ic is None else g.climb[ic]
    nfx, nfz, d = len(g.Fx), len(g.Fz), len(model.param_names)
    X = np.zeros((nfx, nfz, d))
    cost = np.zeros((nfx, nfz))
    evals = np.zeros((nfx, nfz), dtype=np.int64)
    conv = np.zeros((nfx, nfz), dtype=bool)
    screen = _screen(cfg, model, v, vc)
    warm: np.ndarray | None = None
    for i in reversed(range(nfx)):  # Fx from +max down, Fz at the strongest lift demand
        X[i, 0], cost[i, 0], evals[i, 0], conv[i, 0] = _solve_cell(
            cfg, model, g.Fx[i], g.Fz[0], v, warm, screen, climb=vc
        )
        warm = X[i, 0]
    for j in range(1, nfz):  # Fz upwards to 0 along every Fx line
        for i in range(nfx):
            X[i, j], cost[i, j], evals[i, j], conv[i, j] = _solve_cell(
                cfg, model, g.Fx[i], g.Fz[j], v, X[i, j - 1], screen, vc
            )
    X = canonical_params(model, X)
    if cfg.weights.distance == 0:
        # backward pass in Fz (0 -> strongest lift): each cell re-solved from those of its
        # Fx/Fz neighbours that sit on another branch; kept if cheaper
        for j in reversed(range(nfz)):
            for i in range(nfx):
                near = [(i, j + 1), (i - 1, j), (i + 1, j)]
                starts = [
                    X[a, b].copy()
                    for a, b in near
                    if 0 <= a < nfx
                    and b < nfz
                    and np.max(np.abs(X[a, b] - X[i, j])) >= cfg.settings.branch_tol
                ]
                x, c, e, ok = _improve_cell(cfg, model, g.Fx[i], g.Fz[j], v, starts, vc)
                evals[i, j] += e
                if x is not None and c < cost[i, j] - 1e-12:
                    X[i, j], cost[i, j], conv[i, j] = canonical_params(model, x), c, ok
    evals[-1, 0] += screen[0].shape[0]  # the screen, booked on the first cell
    return {"params": X, "cost": cost, "evaluations": evals, "converged": conv}


def solve_v_line(
    cfg: BuildConfig,
    ifx: int,
    X: np.ndarray,
    cost: np.ndarray,
    conv: np.ndarray,
    ic: int | None = None,
) -> dict[str, np.ndarray]:
    """Phase 2 for the line Fx = grid.Fx[ifx] (at climb = grid.climb[ic], else 0; arrays
    nFz x nV): a forward and a backward pass in V, each cell re-solved from its
    V-neighbour and kept if cheaper.  With
    under-relaxation (relax < 1) the forward pass stores ``relax x* + (1 - relax) x_prev``
    (eq. 94) and the backward pass, which would undo that smoothing, is skipped."""
    g = cfg.grid
    vc = 0.0 if ic is None else g.climb[ic]
    return _line_passes(cfg, g.Fx[ifx], lambda j, k: (g.Fz[j], g.V[k], vc), X, cost, conv)


def solve_climb_line(
    cfg: BuildConfig, ifx: int, iv: int, X: np.ndarray, cost: np.ndarray, conv: np.ndarray
) -> dict[str, np.ndarray]:
    """Phase 3 of a grid with a climb axis, for Fx = grid.Fx[ifx] and V = grid.V[iv]
    (arrays nFz x nClimb): the passes of :func:`solve_v_line` along climb (upwards, then
    downwards), the same continuation as along V."""
    g = cfg.grid
    return _line_passes(cfg, g.Fx[ifx], lambda j, k: (g.Fz[j], g.V[iv], g.climb[k]), X, cost, conv)


def _line_passes(
    cfg: BuildConfig, fx: float, point: Any, X: np.ndarray, cost: np.ndarray, conv: np.ndarray
) -> dict[str, np.ndarray]:
    """Forward and backward passes along the second array axis; ``point(j, k)`` gives
    the (Fz, V, climb) of cell (j, k)."""
    model = get_model(cfg.model)
    st = cfg.settings
    X, cost, conv = X.copy(), cost.copy(), conv.copy()
    evals = np.zeros(cost.shape, dtype=np.int64)
    nfz, nk = cost.shape
    plain = st.relax == 1.0 and cfg.weights.distance == 0
    passes = [(range(1, nk), -1)] + ([(range(nk - 2, -1, -1), +1)] if st.relax == 1.0 else [])
    for order, step in passes:
        for k in order:
            # a neighbour this close is on the same branch: a re-solve would land here again
            todo = [
                j
                for j in range(nfz)
                if not (plain and np.max(np.abs(X[j, k + step] - X[j, k])) < st.branch_tol)
            ]
            for j in todo:
                fz, v, vc = point(j, k)
                x_new, c_new, e, ok = _resolve_from(
                    cfg, model, fx, fz, v, X[j, k + step].copy(), vc
                )
                prev = X[j, k + step]
                evals[j, k] += e
                if not plain:
                    prob = _problem(
                        cfg, model, fx, fz, v, prev if cfg.weights.distance > 0 else None, climb=vc
                    )
                    if st.relax < 1.0:
                        x_new = st.relax * x_new + (1.0 - st.relax) * prev
                        X[j, k], cost[j, k], conv[j, k] = (
                            x_new,
                            float(prob.cost(x_new[None])[0]),
                            ok,
                        )
                        continue
                    current = float(prob.cost(X[j, k][None])[0])
                else:
                    current = cost[j, k]
                if c_new < current - 1e-12:
                    X[j, k], cost[j, k], conv[j, k] = canonical_params(model, x_new), c_new, ok
    return {"params": X, "cost": cost, "evaluations": evals, "converged": conv}
