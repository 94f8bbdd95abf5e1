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
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from scipy import optimize as so

from birdsim.errors import BirdsimError, check_number
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import KinematicModel, get_model
from birdsim.tables import slsqp_driver
from birdsim.tables.cost import (
    CostWeights,
    forces,
    forces_and_gradients,
    other_cost,
    other_cost_gradient,
    uses_orientation_cost,
)
from birdsim.tables.point import PointForces

#: Central-difference step (rad) of the batched gradients: truncation error ~h^2 f''',
#: round-off ~1e-16/h; 1e-6 keeps both below 1e-9 for these O(1) smooth functions.
FD_STEP = 1e-6

#: A run is ended when its best cost has not dropped by more than STALL_TOL for this
#: many iterations (SLSQP otherwise spends maxiter oscillating on a kink or a bound).
STALL_ITERATIONS = 25
STALL_TOL = 1e-10


@dataclass(frozen=True)
class Solution:
    """One optimiser's answer: parameters, cost, achieved force and power, status."""

    x: np.ndarray
    cost: float
    method: str
    converged: bool
    message: str
    evaluations: int  # parameter sets evaluated (each a full wingbeat for the bird)
    iterations: int
    Fx: float = float("nan")
    Fz: float = float("nan")
    P: float = float("nan")

    @property
    def status(self) -> str:
        """``converged`` or ``stopped: <solver message>``."""
        return "converged" if self.converged else f"stopped: {self.message}"

    def params(self, names: Sequence[str]) -> dict[str, float]:
        return {n: float(v) for n, v in zip(names, self.x)}


class Problem:
    """A vectorised objective ``sum_k w_k |r_k(x)| + h(x)`` on a box; counts evaluations."""

    weights: np.ndarray = np.zeros(0)

    def __init__(self, lower: Sequence[float], upper: Sequence[float]) -> None:
        self.lower = np.asarray(lower, dtype=float)
        self.upper = np.asarray(upper, dtype=float)
        if self.lower.shape != self.upper.shape or np.any(self.lower > self.upper):
            raise BirdsimError(
                f"bounds lower={self.lower} upper={self.upper} are invalid; allowed: lower <= upper"
            )
        self.evaluations = 0
        self.gradient_evaluations = 0  # points whose gradient was asked for

    @property
    def dim(self) -> int:
        return self.lower.size

    def _parts(self, X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        raise NotImplementedError

    def parts(self, X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Residuals R (M x K) and smooth rest h (M,) of the rows of X (M x d)."""
        X = np.atleast_2d(np.asarray(X, dtype=float))
        self.evaluations += X.shape[0]
        return self._parts(X)

    def cost(self, X: np.ndarray) -> np.ndarray:
        R, h = self.parts(X)
        return np.abs(R) @ self.weights + h

    def _parts_and_jacobian(
        self, x: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, float, np.ndarray]:
        """Central differences of :meth:`parts` in one batched call (point + 2d points)."""
        d = self.dim
        steps = FD_STEP * np.eye(d)
        R, h = self.parts(np.vstack([x[None], x + steps, x - steps]))
        jr = (R[1 : d + 1] - R[d + 1 :]).T / (2 * FD_STEP)  # K x d
        gh = (h[1 : d + 1] - h[d + 1 :]) / (2 * FD_STEP)
        return R[0], jr, float(h[0]), gh

    def parts_and_jacobian(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, float, np.ndarray]:
        """``(r (K,), dr/dx (K x d), h, dh/dx (d,))`` at one point ``x`` (d,)."""
        self.gradient_evaluations += 1
        return self._parts_and_jacobian(np.asarray(x, dtype=float))

    def point_parts(self, x: np.ndarray) -> tuple[np.ndarray, float]:
        """``(r (K,), h)`` at one point ``x`` (d,): :meth:`parts` of one row."""
        R, h = self.parts(x[None])
        return R[0], float(h[0])

    def achieved(self, x: np.ndarray) -> tuple[float, float, float]:
        """Achieved (Fx, Fz, P) for a wingbeat problem; NaN for a plain function."""
        return (float("nan"),) * 3


class FunctionProblem(Problem):
    """A plain vectorised function ``fun(X: M x d) -> M`` (no absolute-value structure)."""

    def __init__(
        self,
        fun: Callable[[np.ndarray], np.ndarray],
        lower: Sequence[float],
        upper: Sequence[float],
    ) -> None:
        super().__init__(lower, upper)
        self.fun = fun

    def _parts(self, X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return np.zeros((X.shape[0], 0)), np.asarray(self.fun(X), dtype=float)


class ForceProblem(Problem):
    """Find the wingbeat of ``model`` that delivers (Fx_d, Fz_d) at speed V and ``climb``
    (vertical speed relative to the air, positive up) for the least cost
    (:mod:`birdsim.tables.cost`).  ``n`` samples per wingbeat in the search.  An
    ``evaluator(X, speed)`` replaces the cycle evaluation; at a climb other than 0 it is
    called as ``evaluator(X, speed, climb=climb)``."""

    def __init__(
        self,
        model: KinematicModel | str,
        Fx_demand: float,
        Fz_demand: float,
        speed: float,
        *,
        weights: CostWeights | None = None,
        bird: Bird | None = None,
        previous: np.ndarray | None = None,
        n: int = 32,
        evaluator: Callable[..., tuple[np.ndarray, np.ndarray, np.ndarray]] | None = None,
        climb: float = 0.0,
    ) -> None:
        self.model = model if isinstance(model, KinematicModel) else get_model(model)
        super().__init__(*self.model.bounds)
        self.Fx_demand = check_number("Fx_demand", Fx_demand)
        self.Fz_demand = check_number("Fz_demand", Fz_demand)
        self.speed = check_number("speed", speed, "a finite number >= 0", minimum=0.0)
        self.cost_weights = weights or CostWeights()
        self.weights = np.array(
            [self.cost_weights.force_x, self.cost_weights.force_z, self.cost_weights.power]
        )
        self.climb = check_number("climb", climb, "a finite number (positive up)")
        self.bird = bird or Bird()
        self.previous = None if previous is None else np.asarray(previous, dtype=float)
        self.n = n
        self.evaluator = evaluator  # (X, speed) -> (Fx, Fz, P), replaces the cycle evaluation
        self._point: PointForces | None | bool = False  # made on first use (None: no lean path)
        # other_cost of one row: the orientation term is linear in the pitch
        self._ip = self.model.param_names.index("pitch")
        orient = (
            self.cost_weights.orientation > 0
            and uses_orientation_cost(self.model)
            and self.speed == 0.0
        )
        self._orientation = self.cost_weights.orientation if orient else 0.0

    def _point_forces(self) -> PointForces | None:
        if self._point is False:
            lean = self.evaluator is None
            self._point = (
                PointForces.create(self.model, self.bird, self.speed, self.climb, self.n)
                if lean
                else None
            )
        return self._point  # type: ignore[return-value]

    def _other_point(self, x: np.ndarray) -> float:
        """:func:`other_cost` of one row (the orientation term is linear in the pitch)."""
        if self.cost_weights.distance > 0 and self.previous is not None:
            return float(
                other_cost(self.model, x[None], self.speed, self.cost_weights, self.previous)[0]
            )
        return float(self._orientation * x[self._ip])

    def point_parts(self, x: np.ndarray) -> tuple[np.ndarray, float]:
        pf = self._point_forces()
        if pf is None:
            return super().point_parts(x)
        self.evaluations += 1
        fx, fz, p = pf.values(x)
        return np.array([fx - self.Fx_demand, fz - self.Fz_demand, p]), self._other_point(x)

    def _forces(self, X: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        if self.evaluator is not None:
            if self.climb != 0.0:
                return self.evaluator(X, self.speed, climb=self.climb)
            return self.evaluator(X, self.speed)
        return forces(self.model, X, self.speed, self.bird, self.n, self.climb)

    def _parts(self, X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        Fx, Fz, P = self._forces(X)
        R = np.stack([Fx - self.Fx_demand, Fz - self.Fz_demand, P], axis=-1)
        return R, other_cost(self.model, X, self.speed, self.cost_weights, self.previous)

    def achieved(self, x: np.ndarray) -> tuple[float, float, float]:
        Fx, Fz, P = self._forces(np.atleast_2d(x))
        return float(Fx[0]), float(Fz[0]), float(P[0])

    def _parts_and_jacobian(
        self, x: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, float, np.ndarray]:
        """Exact: the kernel's forward-mode gradients (or an evaluator's ``gradients``)."""
        pf = self._point_forces()
        if pf is not None:
            self.evaluations += 1
            vals, jr = pf.gradients(x)
            r = np.array([vals[0] - self.Fx_demand, vals[1] - self.Fz_demand, vals[2]])
            if self.cost_weights.distance > 0 and self.previous is not None:
                gh = other_cost_gradient(
                    self.model, x[None], self.speed, self.cost_weights, self.previous
                )[0]
            else:
                gh = np.zeros(self.dim)
                gh[self._ip] = self._orientation
            return r, jr, self._other_point(x), gh
        X = x[None]
        grad_fn = getattr(self.evaluator, "gradients", None) if self.evaluator is not None else None
        if self.evaluator is not None and grad_fn is None:
            return super()._parts_and_jacobian(x)  # an evaluator of values only
        self.evaluations += 1
        if grad_fn is not None:
            (Fx, Fz, P), (gx, gz, gp) = grad_fn(X, self.speed, climb=self.climb)
        else:
            (Fx, Fz, P), (gx, gz, gp) = forces_and_gradients(
                self.model, X, self.speed, self.bird, self.n, self.climb
            )
        r = np.array([Fx[0] - self.Fx_demand, Fz[0] - self.Fz_demand, P[0]])
        jr = np.stack([gx[0], gz[0], gp[0]])
        h = other_cost(self.model, X, self.speed, self.cost_weights, self.previous)
        gh = other_cost_gradient(self.model, X, self.speed, self.cost_weights, self.previous)
        return r, jr, float(h[0]), gh[0]

    def achieved_from(self, r: np.ndarray) -> tuple[float, float, float]:
        """(Fx, Fz, P) from the residuals of one point."""
        return float(r[0] + self.Fx_demand), float(r[1] + self.Fz_demand), float(r[2])


def _finish(
    problem: Problem,
    x: np.ndarray,
    method: str,
    converged: bool,
    message: str,
    evals0: int,
    nit: int,
    parts: tuple[np.ndarray, float] | None = None,
) -> Solution:
    """The solution at ``x`` (clipped to the box); ``parts`` = (R, h) at x if known."""
    x = np.clip(np.asarray(x, dtype=float), problem.lower, problem.upper)
    if parts is None:
        R, h = problem.parts(x[None])
        parts = (R[0], float(h[0]))
    r, h0 = parts
    cost = float(np.abs(r) @ problem.weights + h0)
    Fx, Fz, P = (
        problem.achieved_from(r) if isinstance(problem, ForceProblem) else (float("nan"),) * 3
    )
    return Solution(
        x,
        cost,
        method,
        bool(converged),
        str(message),
        problem.evaluations - evals0,
        int(nit),
        Fx,
        Fz,
        P,
    )


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
    grads: dict[bytes, tuple[np.ndarray, np.ndarray]] = {}

    def point(z: np.ndarray) -> tuple[np.ndarray, bytes]:
        x = np.minimum(np.maximum(z[:d], lo), hi)
        return x, x.tobytes()

    def val(z: np.ndarray) -> tuple[np.ndarray, float]:
        x, key = point(z)
        if key not in values:
            if len(values) > 256:
                values.clear()
            values[key] = problem.point_parts(x)
        return values[key]

    def grad(z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        x, key = point(z)
        if key not in grads:
            r, jr, h, gh = problem.parts_and_jacobian(x)
            grads.clear()
            grads[key] = (jr, gh)
            values.setdefault(key, (r, h))
        return grads[key]

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

    best: dict[str, object] = {"cost": np.inf, "x": x0, "since": 0}

    def track(z: np.ndarray) -> None:
        x, _ = point(z)
        r, h = val(z)
        c = float(np.abs(r) @ w + h)
        if c < float(best["cost"]) - STALL_TOL:  # type: ignore[arg-type]
            best.update(cost=c, x=x, since=0)
        else:
            if c < float(best["cost"]):  # type: ignore[arg-type]
                best.update(cost=c, x=x)
            best["since"] = int(best["since"]) + 1  # type: ignore[call-overload]
            if int(best["since"]) >= stall:  # type: ignore[call-overload]
                raise StopIteration

    r0 = val(np.concatenate([x0, np.zeros(K)]))[0]
    z0 = np.concatenate([x0, np.abs(r0)])
    track(z0)
    if K:
        res = slsqp_driver.minimize(
            fun,
            jac,
            cons,
            cons_jac,
            z0,
            np.concatenate([lo, np.zeros(K)]),
            np.concatenate([hi, np.full(K, np.inf)]),
            maxiter=maxiter,
            ftol=ftol,
            callback=track,
        )
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
    if float(np.abs(r) @ w + h) > float(best["cost"]):  # type: ignore[arg-type]
        x = np.asarray(best["x"])
        r, h = val(np.concatenate([x, np.zeros(K)]))
    message = f"no progress in {stall} iterations" if stalled else res_message
    return _finish(problem, x, "slsqp", success and not stalled, message, evals0, nit, (r, h))


def multistart(problem: Problem, starts: np.ndarray, **kwargs: object) -> Solution:
    """SLSQP from each row of ``starts``; the best answer, with every start's evaluations counted."""
    evals0 = problem.evaluations
    best: Solution | None = None
    for x0 in np.atleast_2d(starts):
        sol = slsqp(problem, x0, **kwargs)  # type: ignore[arg-type]
        if best is None or sol.cost < best.cost:
            best = sol
    assert best is not None
    return _replace_evals(best, problem.evaluations - evals0, "slsqp-multistart")


def _replace_evals(sol: Solution, evaluations: int, method: str) -> Solution:
    return Solution(
        sol.x,
        sol.cost,
        method,
        sol.converged,
        sol.message,
        evaluations,
        sol.iterations,
        sol.Fx,
        sol.Fz,
        sol.P,
    )


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
    return _finish(problem, best_x, "complete", True, f"{total} nodes", evals0, total)


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
    sol = _finish(problem, res.x, "evolutionary", res.success, res.message, evals0, res.nit)
    if polish:
        pol = slsqp(problem, sol.x)
        if pol.cost < sol.cost:
            sol = pol
    return _replace_evals(sol, problem.evaluations - evals0, "evolutionary")


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
