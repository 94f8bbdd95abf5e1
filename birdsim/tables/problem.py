"""The optimisation problems (dissertation sec. 3.6) and their answer.

A *problem* is a vectorised objective over parameter rows ``X`` (M x d) inside box
bounds, written as ``cost(x) = sum_k w_k |r_k(x)| + h(x)``: ``parts(X)`` returns the
residuals ``R`` (M x K) and the smooth rest ``h`` (M,).  The wingbeat cost
(:class:`ForceProblem`) has ``r = (Fx - Fx_d, Fz - Fz_d, P)`` and ``w = (1, 1, 0.5)``;
a plain test function (:class:`FunctionProblem`) has K = 0.  Every solver
(:mod:`birdsim.tables.optimize`) returns a :class:`Solution`.

Gradients are exact for the wingbeat problem (forward-mode derivatives from the fused
kernel, :func:`birdsim.tables.cost.forces_and_gradients`) and central finite
differences in ONE batched call for a plain function.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from birdsim.errors import BirdsimError, check_number
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import KinematicModel, get_model
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
        point: PointForces | None = None,
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
        # made on first use (None: no lean path); or ``point``, one made for the same model,
        # bird, speed, climb and n (every call rewrites its buffers, so problems can share it)
        self._point: PointForces | None | bool = point if point is not None else False
        # other_cost of one row: the orientation term is linear in the pitch
        self._ip = self.model.param_names.index("pitch")
        orient = (
            self.cost_weights.orientation > 0
            and uses_orientation_cost(self.model)
            and self.speed == 0.0
        )
        self._orientation = self.cost_weights.orientation if orient else 0.0
        self._incidence = self.cost_weights.incidence
        self._iq = self.cost_weights.incidence_index(self.model)

    def _point_forces(self) -> PointForces | None:
        if self._point is False:
            lean = self.evaluator is None
            self._point = (
                PointForces.create(self.model, self.bird, self.speed, self.climb, self.n)
                if lean
                else None
            )
        return self._point  # type: ignore[return-value]

    def _other_point(self, x: np.ndarray, norm: float | None = None) -> float:
        """:func:`other_cost` of one row, bitwise (the orientation term is linear in the
        pitch; the distance term's norm is summed as ``np.linalg.norm`` sums it; ``norm``:
        that norm where the caller has it already)."""
        if self.cost_weights.distance > 0 and self.previous is not None:
            if norm is None:
                norm = math.sqrt(_sum_of_squares(x - self.previous))
            h = float(self._orientation * x[self._ip] + self.cost_weights.distance * norm)
        else:
            h = float(self._orientation * x[self._ip])
        if self._incidence > 0:
            h = float(h + self._incidence * _sum_of_squares(x[self._iq]))
        return h

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
            gh = np.zeros(self.dim)
            gh[self._ip] = self._orientation
            norm = None
            if self.cost_weights.distance > 0 and self.previous is not None:
                # other_cost_gradient of one row, bitwise; the norm is _other_point's
                diff = x - self.previous
                norm = math.sqrt(_sum_of_squares(diff))
                if norm > 0:
                    gh += self.cost_weights.distance * (diff / norm)
            if self._incidence > 0:
                gh[self._iq] += 2.0 * self._incidence * x[self._iq]
            return r, jr, self._other_point(x, norm), gh
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


def _sum_of_squares(diff: np.ndarray) -> float:
    """``sum(diff**2)`` of a 1-D row as ``np.linalg.norm(X, axis=-1)`` sums it (the same
    ufunc reduction over a contiguous axis, hence the same rounding)."""
    return float(np.add.reduce(diff * diff))


def finish(
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


def with_evaluations(sol: Solution, evaluations: int, method: str) -> Solution:
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


__all__ = [
    "FD_STEP",
    "ForceProblem",
    "FunctionProblem",
    "Problem",
    "Solution",
    "finish",
    "with_evaluations",
]
