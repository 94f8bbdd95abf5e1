"""Global search: space-filling starts, the box's corners, the complete search of
sec. 3.6.1 and scipy's differential evolution (the dissertation's genetic algorithm)."""

from __future__ import annotations

import numpy as np
from scipy import optimize as so

from birdsim.errors import BirdsimError
from birdsim.tables.local import slsqp
from birdsim.tables.problem import Problem, Solution, finish, with_evaluations


def random_starts(problem: Problem, count: int, seed: int | None = 0) -> np.ndarray:
    """``count`` scrambled-Sobol points in the box (a space-filling multi-start set)."""
    m = max(0, int(np.ceil(np.log2(max(count, 1)))))
    from scipy.stats import qmc  # 0.2 s to import: only where a screen is drawn

    u = qmc.Sobol(problem.dim, scramble=True, seed=seed).random_base2(m)[:count]
    return problem.lower + u * (problem.upper - problem.lower)


def box_corners(problem: Problem) -> np.ndarray:
    """The 2^d corners of the box: optimal wingbeats often sit on bounds (flap and twist
    at their maxima in hover, wrist idle), which random points never hit exactly."""
    d = problem.dim
    bits = (np.arange(2**d)[:, None] >> np.arange(d)) & 1
    return np.where(bits == 1, problem.upper, problem.lower)


def complete_search(problem: Problem, nodes: int = 12, *, chunk: int = 50_000) -> Solution:
    """The complete search of sec. 3.6.1: the cost at ``nodes`` equally spaced nodes per
    dimension (bounds included), the best node wins.  Evaluated in batches of ``chunk``."""
    if not isinstance(nodes, (int, np.integer)) or nodes < 2:
        raise BirdsimError(f"nodes={nodes!r} is invalid; allowed: an integer >= 2")
    evals0 = problem.evaluations
    axes = [np.linspace(a, b, int(nodes)) for a, b in zip(problem.lower, problem.upper)]
    total = int(nodes) ** problem.dim
    best_cost, best_x = np.inf, None
    for start in range(0, total, chunk):
        idx = np.unravel_index(
            np.arange(start, min(start + chunk, total)), (int(nodes),) * problem.dim
        )
        X = np.stack([ax[i] for ax, i in zip(axes, idx)], axis=-1)
        c = problem.cost(X)
        k = int(np.argmin(c))
        if c[k] < best_cost:
            best_cost, best_x = float(c[k]), X[k]
    return finish(problem, best_x, "complete", True, f"{total} nodes", evals0, total)


def evolutionary(
    problem: Problem,
    *,
    seed: int | None = 0,
    popsize: int = 15,
    maxiter: int = 200,
    polish: bool = True,
    tol: float = 1e-8,
) -> Solution:
    """scipy's differential evolution (the role of the dissertation's hand-made genetic
    algorithm), the population evaluated in one batched call per generation; optionally
    polished with :func:`slsqp`."""
    evals0 = problem.evaluations

    def f(xT: np.ndarray) -> np.ndarray:
        return problem.cost(np.asarray(xT).T)

    res = so.differential_evolution(
        f,
        list(zip(problem.lower, problem.upper)),
        seed=seed,
        popsize=popsize,
        maxiter=maxiter,
        tol=tol,
        polish=False,
        vectorized=True,
        updating="deferred",
    )
    sol = finish(problem, res.x, "evolutionary", res.success, res.message, evals0, res.nit)
    if polish:
        pol = slsqp(problem, sol.x)
        if pol.cost < sol.cost:
            sol = pol
    return with_evaluations(sol, problem.evaluations - evals0, "evolutionary")


__all__ = ["box_corners", "complete_search", "evolutionary", "random_starts"]
