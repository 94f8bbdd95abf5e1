"""scipy's SLSQP, its iterations driven directly.

``scipy.optimize.minimize(method="SLSQP")`` (scipy >= 1.16) is a Python loop around one
compiled routine, ``scipy.optimize._slsqplib.slsqp``, that asks for values or gradients
through a mode flag.  Around it, the public wrapper builds per run and per call what a
table cell's solve does not need (a ``ScalarFunction`` with its own cache, bound
checks, array-namespace dispatch, a result object per iteration for the callback).  For
the optimiser's many short runs that is a fifth of the CPU time (docs/performance.md),
so :func:`minimize` runs the same loop with the same compiled routine and the same
calls, and gives the same iterates (``tests/test_slsqp_driver.py`` compares them
with scipy's own wrapper).

The routine is private to scipy.  Where it is missing (scipy < 1.16) or refuses the call
(its interface changed), :func:`minimize` uses ``scipy.optimize.minimize`` instead, with
unchanged results.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy import optimize as so

try:
    from scipy.optimize._slsqplib import slsqp as _core
except ImportError:  # pragma: no cover - older scipy
    _core = None

_STATE = {"direct": _core is not None}

#: scipy's exit modes of SLSQP (the messages of scipy.optimize.minimize).
EXIT_MODES = {
    0: "Optimization terminated successfully",
    2: "More equality constraints than independent variables",
    3: "More than 3*n iterations in LSQ subproblem",
    4: "Inequality constraints incompatible",
    5: "Singular matrix E in LSQ subproblem",
    6: "Singular matrix C in LSQ subproblem",
    7: "Rank-deficient equality constraint subproblem HFTI",
    8: "Positive directional derivative for linesearch",
    9: "Iteration limit reached",
}


@dataclass(frozen=True)
class Result:
    """The end of a run: the last iterate, scipy's exit mode and message, iterations,
    and whether the callback stopped the run (raised StopIteration)."""

    x: np.ndarray
    success: bool
    stopped: bool
    nit: int
    message: str


Vector = Callable[[np.ndarray], np.ndarray]


def minimize(
    fun: Callable[[np.ndarray], float],
    jac: Vector,
    cons: Vector,
    cons_jac: Vector,
    z0: np.ndarray,
    lower: np.ndarray,
    upper: np.ndarray,
    *,
    maxiter: int,
    ftol: float,
    callback: Callable[[np.ndarray], None],
) -> Result:
    """Minimise ``fun`` subject to ``cons(z) >= 0`` and ``lower <= z <= upper`` (infinite
    bounds allowed) from ``z0``; ``callback(z)`` after every iteration may raise
    StopIteration to end the run.  As ``scipy.optimize.minimize(method="SLSQP")``."""
    if _STATE["direct"]:
        try:
            return _direct(fun, jac, cons, cons_jac, z0, lower, upper, maxiter, ftol, callback)
        except _Refused:
            _STATE["direct"] = False
    bounds = [
        (a if np.isfinite(a) else None, b if np.isfinite(b) else None) for a, b in zip(lower, upper)
    ]
    res = so.minimize(
        fun,
        z0,
        jac=jac,
        method="SLSQP",
        bounds=bounds,
        constraints=[{"type": "ineq", "fun": cons, "jac": cons_jac}],
        options={"maxiter": maxiter, "ftol": ftol},
        callback=callback,
    )
    stopped = res.status == 99  # the callback raised StopIteration
    return Result(
        np.asarray(res.x),
        bool(res.success) and not stopped,
        stopped,
        int(res.nit),
        str(res.message),
    )


class _Refused(Exception):
    """The compiled routine did not accept the call (scipy changed its interface)."""


def _workspace(
    n: int, m: int, maxiter: int, ftol: float
) -> tuple[dict, np.ndarray, np.ndarray, np.ndarray]:
    """The routine's state and work arrays for n variables and m inequality constraints
    (as scipy's ``_minimize_slsqp`` sizes them)."""
    state = {
        "acc": ftol,
        "alpha": 0.0,
        "f0": 0.0,
        "gs": 0.0,
        "h1": 0.0,
        "h2": 0.0,
        "h3": 0.0,
        "h4": 0.0,
        "t": 0.0,
        "t0": 0.0,
        "tol": 10.0 * ftol,
        "exact": 0,
        "inconsistent": 0,
        "reset": 0,
        "iter": 0,
        "itermax": int(maxiter),
        "line": 0,
        "m": m,
        "meq": 0,
        "mode": 0,
        "n": n,
    }
    indices = np.zeros(max(m + 2 * n + 2, 1), dtype=np.int32)
    buffer = np.zeros(max(n * (n + 1) // 2 + 3 * m * n + 9 * m + 8 * n * n + 35 * n + 28, 1))
    mult = np.zeros(max(1, m + 2 * n + 2))
    return state, indices, buffer, mult


def _direct(fun, jac, cons, cons_jac, z0, lower, upper, maxiter, ftol, callback) -> Result:
    """scipy 1.16-1.17's ``_minimize_slsqp`` loop without its wrappers (:func:`_loop`
    fed ``fun`` and ``cons`` in scipy's order: the constraints first at the start, for m)."""
    x = np.clip(np.asarray(z0, dtype=float), lower, upper)
    d = np.atleast_1d(np.asarray(cons(x), dtype=float)).copy()
    started = [False]

    def inside(z: np.ndarray) -> np.ndarray:  # SLSQP may step 1-2 ulps outside a bound
        return np.minimum(np.maximum(z, lower), upper)

    def evaluate(z: np.ndarray, d_out: np.ndarray) -> float:
        f = float(fun(inside(z)))
        if started[0]:
            d_out[:] = cons(z)
        started[0] = True  # at the start d holds cons(x) already
        return f

    def differentiate(z: np.ndarray, g: np.ndarray, C: np.ndarray) -> None:
        g[:] = np.asarray(jac(inside(z)), dtype=float)
        C[:] = cons_jac(z)

    return _loop(evaluate, differentiate, x, d, lower, upper, maxiter, ftol,
                 lambda z: callback(np.copy(z)))  # fmt: skip


def _loop(evaluate, differentiate, x, d, lower, upper, maxiter, ftol, callback) -> Result:
    """The routine's reverse-communication loop from ``x`` (inside the bounds; ``d`` the
    constraints' array, m = its size): values (``evaluate``) and gradients
    (``differentiate``) at the start and whenever the routine asks, ``callback`` after
    every iteration.  Raises :class:`_Refused` where the routine does not accept the call."""
    n, m = x.size, d.size
    state, indices, buffer, mult = _workspace(n, m, maxiter, ftol)
    xl = np.where(np.isfinite(lower), lower, np.nan)
    xu = np.where(np.isfinite(upper), upper, np.nan)
    C = np.zeros((max(1, m), n), order="F")
    g = np.zeros(n)
    fx = evaluate(x, d)
    differentiate(x, g, C)
    previous = 0
    while True:
        try:
            _core(state, fx, g, C, d, x, mult, xl, xu, buffer, indices)
        except (TypeError, KeyError, ValueError) as exc:
            raise _Refused(str(exc)) from None
        mode = state["mode"]
        if mode == 1:  # values wanted
            fx = evaluate(x, d)
        elif mode == -1:  # gradients wanted
            differentiate(x, g, C)
        if state["iter"] > previous:
            try:
                callback(x)
            except StopIteration:
                return Result(x, False, True, int(state["iter"]), "stopped by the callback")
        if abs(mode) != 1:
            return Result(
                x, mode == 0, False, int(state["iter"]), EXIT_MODES.get(mode, f"exit mode {mode}")
            )
        previous = state["iter"]


#: ``evaluate(z, d) -> f``: the objective at z clipped to the bounds, the constraints at
#: z written into d; ``differentiate(z, g, C)``: their gradients written into g and C.
Evaluate = Callable[[np.ndarray, np.ndarray], float]
Differentiate = Callable[[np.ndarray, np.ndarray, np.ndarray], None]


def minimize_fused(
    evaluate: Evaluate,
    differentiate: Differentiate,
    m: int,
    z0: np.ndarray,
    lower: np.ndarray,
    upper: np.ndarray,
    *,
    maxiter: int,
    ftol: float,
    callback: Callable[[np.ndarray], None],
) -> Result | None:
    """:func:`minimize` with the objective and the ``m`` constraints asked for together
    (``evaluate``, ``differentiate``: one call each where :func:`minimize` makes two, the
    arrays written in place), for callers whose objective and constraints share their
    work.  The same routine fed the same numbers: the same iterates as :func:`minimize`
    (``tests/test_slsqp_driver.py``).  ``callback(z)`` gets the routine's own array (it
    must not keep it).  None where the routine is missing or refuses the call: the caller
    then uses :func:`minimize`."""
    if not _STATE["direct"]:
        return None
    x = np.clip(np.asarray(z0, dtype=float), lower, upper)
    try:
        return _loop(evaluate, differentiate, x, np.zeros(m), lower, upper, maxiter, ftol, callback)
    except _Refused:
        _STATE["direct"] = False
        return None
