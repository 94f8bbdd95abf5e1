"""Local search: bounded SLSQP (scipy) and SLSQP from many starts.

SLSQP gets the standard slack-variable reformulation of the absolute values,
``min w.s + h(x)  s.t.  -s <= r(x) <= s``, which is smooth, so the kinks of ``|r|``
(exactly where a reachable demand is met) do not stall the line search.  SLSQP asks for
values at line-search trials and for gradients only at accepted iterates, so the two
are cached separately and a trial costs one wingbeat.  A run whose best cost stops
improving is ended (:data:`STALL_ITERATIONS`) and the best point it visited is returned.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from scipy import optimize as so

from birdsim.tables import slsqp_driver
from birdsim.tables.problem import Problem, Solution, finish, with_evaluations

#: A run is ended when its best cost has not dropped by more than STALL_TOL for this
#: many iterations (SLSQP otherwise spends maxiter oscillating on a kink or a bound).
STALL_ITERATIONS = 25
STALL_TOL = 1e-10


def slsqp(
    problem: Problem,
    x0: Sequence[float],
    *,
    maxiter: int = 100,
    ftol: float = 1e-10,
    stall: int = STALL_ITERATIONS,
) -> Solution:
    """Bounded SLSQP from ``x0`` with slack variables for the absolute values.

    Values and gradients are cached by point: line-search trials cost values only,
    accepted iterates one gradient evaluation.  The run ends after ``stall`` iterations
    without a drop of the best cost by more than :data:`STALL_TOL`; the best point
    visited is returned (``converged`` False, ``message`` says why).
    """
    d, w = problem.dim, problem.weights
    K = w.size
    lo, hi = problem.lower, problem.upper
    x0 = np.clip(np.asarray(x0, dtype=float), lo, hi)
    evals0 = problem.evaluations
    values: dict[bytes, tuple[np.ndarray, float]] = {}
    last_grad: list = [None, None]  # the one cached gradient: key, (dr/dx, dh/dx)

    def point(z: np.ndarray) -> tuple[np.ndarray, bytes]:
        x = np.minimum(np.maximum(z[:d], lo), hi)
        return x, x.tobytes()

    def cached(x: np.ndarray, key: bytes) -> tuple[np.ndarray, float]:
        found = values.get(key)
        if found is None:
            if len(values) > 256:
                values.clear()
            found = values[key] = problem.point_parts(x)
        return found

    def val(z: np.ndarray) -> tuple[np.ndarray, float]:
        return cached(*point(z))

    def grad(z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        x, key = point(z)
        if key != last_grad[0]:
            r, jr, h, gh = problem.parts_and_jacobian(x)
            last_grad[:] = key, (jr, gh)
            values.setdefault(key, (r, h))
        return last_grad[1]

    def fun(z: np.ndarray) -> float:
        return float(w @ z[d:] + val(z)[1])

    grad_z = np.concatenate([np.zeros(d), w])

    def jac(z: np.ndarray) -> np.ndarray:
        grad_z[:d] = grad(z)[1]
        return grad_z.copy()

    cons_z = np.zeros(2 * K)

    def cons(z: np.ndarray) -> np.ndarray:
        r, s = val(z)[0], z[d:]
        cons_z[:K], cons_z[K:] = s - r, s + r
        return cons_z.copy()

    # d(cons)/dz = [[-dr/dx, I], [dr/dx, I]]
    cons_dz = np.block([[np.zeros((K, d)), np.eye(K)], [np.zeros((K, d)), np.eye(K)]])

    def cons_jac(z: np.ndarray) -> np.ndarray:
        jr = grad(z)[0]
        cons_dz[:K, :d], cons_dz[K:, :d] = -jr, jr
        return cons_dz.copy()

    zlo, zhi = np.concatenate([lo, np.zeros(K)]), np.concatenate([hi, np.full(K, np.inf)])

    # fun and cons (jac and cons_jac) in one call, for the driver's fused loop: the same
    # numbers, with the point clipped and looked up once
    last: list = [b"", None]  # the last evaluated z (bytes) and its (x, key, (r, h))

    def evaluate(z: np.ndarray, out: np.ndarray) -> float:
        inside = np.minimum(np.maximum(z, zlo), zhi)  # = the driver's inside(z)
        x = inside[:d]  # = point(z) and point(inside) (bounds: lo < hi, ties -> the bound)
        key = x.tobytes()
        r, h = found = cached(x, key)
        last[0], last[1] = z.tobytes(), (x, key, found)
        s = z[d:]
        out[:K] = s - r
        out[K:] = s + r
        return float(w @ inside[d:] + h)

    def differentiate(z: np.ndarray, g: np.ndarray, C: np.ndarray) -> None:
        jr, gh = grad(z)
        grad_z[:d] = gh
        g[:] = grad_z
        cons_dz[:K, :d], cons_dz[K:, :d] = -jr, jr
        C[:] = cons_dz

    best_cost, best_x, since = np.inf, x0, 0

    def track(z: np.ndarray) -> None:
        nonlocal best_cost, best_x, since
        if z.tobytes() == last[0]:  # evaluated just now (the usual case)
            x, key, (r, h) = last[1]
        else:
            x, key = point(z)
            r, h = cached(x, key)
        c = float(np.abs(r) @ w + h)
        if c < best_cost - STALL_TOL:
            best_cost, best_x, since = c, x, 0
        else:
            if c < best_cost:
                best_cost, best_x = c, x
            since += 1
            if since >= stall:
                raise StopIteration

    r0 = val(np.concatenate([x0, np.zeros(K)]))[0]
    z0 = np.concatenate([x0, np.abs(r0)])
    track(z0)
    if K:
        kw = dict(maxiter=maxiter, ftol=ftol, callback=track)
        res = slsqp_driver.minimize_fused(evaluate, differentiate, 2 * K, z0, zlo, zhi, **kw)
        if res is None:  # the compiled routine is missing or refused the call
            res = slsqp_driver.minimize(fun, jac, cons, cons_jac, z0, zlo, zhi, **kw)
        stalled, success, nit, res_message, res_x = (
            res.stopped,
            res.success,
            res.nit,
            res.message,
            res.x,
        )
    else:
        sres = so.minimize(
            fun,
            z0,
            jac=jac,
            method="SLSQP",
            bounds=list(zip(lo, hi)),
            options={"maxiter": maxiter, "ftol": ftol},
            callback=track,
        )
        stalled = sres.status == 99  # the callback raised StopIteration
        success, nit, res_message, res_x = sres.success, sres.nit, sres.message, sres.x
    x, _ = point(res_x)
    r, h = val(np.concatenate([x, np.zeros(K)]))
    if float(np.abs(r) @ w + h) > best_cost:
        x = np.asarray(best_x)
        r, h = val(np.concatenate([x, np.zeros(K)]))
    message = f"no progress in {stall} iterations" if stalled else res_message
    return finish(problem, x, "slsqp", success and not stalled, message, evals0, nit, (r, h))


def multistart(problem: Problem, starts: np.ndarray, **kwargs: object) -> Solution:
    """SLSQP from each row of ``starts``; the best answer, with every start's evaluations counted."""
    evals0 = problem.evaluations
    best: Solution | None = None
    for x0 in np.atleast_2d(starts):
        sol = slsqp(problem, x0, **kwargs)  # type: ignore[arg-type]
        if best is None or sol.cost < best.cost:
            best = sol
    assert best is not None
    return with_evaluations(best, problem.evaluations - evals0, "slsqp-multistart")


__all__ = ["STALL_ITERATIONS", "STALL_TOL", "multistart", "slsqp"]
