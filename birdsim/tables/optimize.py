"""Optimisers behind one interface (dissertation sec. 3.6): bounded SLSQP with
multi-start, the complete search of sec. 3.6.1 and an evolutionary global search.

A *problem* is a vectorised objective over parameter rows ``X`` (M x d) inside box
bounds, written as ``cost(x) = sum_k w_k |r_k(x)| + h(x)``: ``parts(X)`` returns the
residuals ``R`` (M x K) and the smooth rest ``h`` (M,).  The wingbeat cost has
``r = (Fx - Fx_d, Fz - Fz_d, P)`` and ``w = (1, 1, 0.5)``; a plain test function has
K = 0.  Every solver returns a :class:`Solution`.

SLSQP (scipy) gets the standard slack-variable reformulation of the absolute values,
``min w.s + h(x)  s.t.  -s <= r(x) <= s``, which is smooth, so the kinks of ``|r|``
(exactly where a reachable demand is met) do not stall the line search.  Gradients
are exact for the wingbeat problem (forward-mode derivatives from the fused kernel,
:func:`birdsim.tables.cost.forces_and_gradients`) and central finite differences in
ONE batched call for a plain function.  SLSQP asks for values at line-search trials
and for gradients only at accepted iterates, so the two are cached separately and a
trial costs one wingbeat.  A run whose best cost stops improving is ended
(:data:`STALL_ITERATIONS`) and the best point it visited is returned.

Where things are: the problems and :class:`Solution` in :mod:`birdsim.tables.problem`,
SLSQP and multi-start in :mod:`birdsim.tables.local`, the global searches in
:mod:`birdsim.tables.search`; this module is the one interface (:func:`solve`) and
re-exports them all, so ``from birdsim.tables.optimize import ForceProblem, slsqp``
keeps working.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.tables.local import STALL_ITERATIONS, STALL_TOL, multistart, slsqp
from birdsim.tables.problem import (
    FD_STEP,
    ForceProblem,
    FunctionProblem,
    Problem,
    Solution,
)
from birdsim.tables.search import box_corners, complete_search, evolutionary, random_starts

SOLVERS = ("slsqp", "multistart", "complete", "evolutionary")


def solve(
    problem: Problem,
    method: str = "multistart",
    *,
    x0: Sequence[float] | None = None,
    starts: int = 8,
    seed: int | None = 0,
    **kwargs: object,
) -> Solution:
    """One entry point: ``slsqp`` (from ``x0``), ``multistart`` (``x0`` plus ``starts``
    Sobol points), ``complete`` (``nodes=``) or ``evolutionary``."""
    if method == "slsqp":
        start = x0 if x0 is not None else 0.5 * (problem.lower + problem.upper)
        return slsqp(problem, start, **kwargs)  # type: ignore[arg-type]
    if method == "multistart":
        S = random_starts(problem, starts, seed)
        if x0 is not None:
            S = np.vstack([np.asarray(x0, dtype=float)[None], S])
        return multistart(problem, S, **kwargs)
    if method == "complete":
        return complete_search(problem, **kwargs)  # type: ignore[arg-type]
    if method == "evolutionary":
        return evolutionary(problem, seed=seed, **kwargs)  # type: ignore[arg-type]
    raise BirdsimError(f"method={method!r} is unknown; allowed: {', '.join(SOLVERS)}")


__all__ = [
    "FD_STEP",
    "SOLVERS",
    "STALL_ITERATIONS",
    "STALL_TOL",
    "ForceProblem",
    "FunctionProblem",
    "Problem",
    "Solution",
    "box_corners",
    "complete_search",
    "evolutionary",
    "multistart",
    "random_starts",
    "slsqp",
    "solve",
]
