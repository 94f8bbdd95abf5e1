"""The numbers of the search figures: cost landscapes (Figs 33, 34, 50, 51), solutions
over speed (Figs 35-38, 44, 45, 52) and the optimisers on the test functions (Figs 28-31,
Table 3)."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.report.figgrid import GridMeans, grid_means, mesh

# ---- cost landscapes (Figs 33, 34, 50, 51) -------------------------------------------

CostFunction = Callable[[GridMeans, Mapping[str, np.ndarray], np.ndarray], np.ndarray]


@dataclass(frozen=True)
class Landscape:
    """Cost over two plotted axes, minimised over the remaining free axes (a profile).

    ``cost`` is (len(x), len(y)); ``argmin`` holds, per plotted cell, the values of the
    profiled parameters at the minimum; ``best`` the parameters of the overall minimum."""

    x_name: str
    x: np.ndarray
    y_name: str
    y: np.ndarray
    cost: np.ndarray
    argmin: dict[str, np.ndarray]
    best: dict[str, float]


def landscape(
    model: str,
    speed: float,
    cost: CostFunction,
    x: tuple[str, np.ndarray],
    y: tuple[str, np.ndarray],
    *,
    fixed: Mapping[str, float] | None = None,
    profile: Mapping[str, np.ndarray] | None = None,
    derived: Callable[[dict[str, np.ndarray]], dict[str, np.ndarray]] | None = None,
    bird: Bird | None = None,
    n: int = 32,
) -> Landscape:
    """Cost of ``model`` at ``speed`` on the grid x * y * profile axes, minimised over the
    profile axes.  ``derived`` maps the grid arrays to further parameters (e.g. the
    wrist activity coefficient K to the wrist amplitude, lag and bias)."""
    fixed = dict(fixed or {})
    profile = dict(profile or {})
    names = [x[0], y[0], *profile]
    grids = mesh([x[1], y[1], *profile.values()])
    params: dict[str, np.ndarray] = {
        **{k: np.asarray(v) for k, v in fixed.items()},
        **dict(zip(names, grids)),
    }
    if derived is not None:
        params.update(derived(params))
    model_params = {k: v for k, v in params.items() if k in get_model(model).param_names}
    means = grid_means(model, model_params, speed, bird=bird, n=n)
    c = cost(means, model_params, np.asarray(speed, dtype=float))
    full = np.broadcast_to(c, np.broadcast_shapes(*(g.shape for g in grids), c.shape))
    flat = full.reshape(len(x[1]), len(y[1]), -1)
    k = np.argmin(flat, axis=-1)
    prof_shape = tuple(len(v) for v in profile.values())
    idx = np.unravel_index(k, prof_shape) if profile else ()
    argmin = {name: np.asarray(vals)[i] for (name, vals), i in zip(profile.items(), idx)}
    surface = np.take_along_axis(flat, k[..., None], axis=-1)[..., 0]
    bi, bj = np.unravel_index(np.argmin(surface), surface.shape)
    best = {x[0]: float(x[1][bi]), y[0]: float(y[1][bj])}
    best.update({name: float(a[bi, bj]) for name, a in argmin.items()})
    return Landscape(x[0], np.asarray(x[1]), y[0], np.asarray(y[1]), surface, argmin, best)


# ---- Figs 35-38, 44, 45, 52: solutions over speed ------------------------------------


@dataclass(frozen=True)
class SpeedSweep:
    """Optimal wingbeats over speed for one demand, solved in order with warm starts.

    ``params`` is len(speeds) x d (columns ``param_names``); ``fractions`` the cost
    fractions (``birdsim.tables.cost.FRACTION_NAMES``) of each solution, len(speeds) x 4."""

    model: str
    direction: str  # "forward" (V increasing) or "backward"
    speeds: np.ndarray
    param_names: tuple[str, ...]
    params: np.ndarray
    cost: np.ndarray
    fractions: np.ndarray
    achieved: np.ndarray  # len(speeds) x 3: Fx, Fz, P


def speed_sweep(
    model: str,
    demand: tuple[float, float],
    speeds: np.ndarray,
    start: Mapping[str, float],
    *,
    backward: bool = False,
    fixed: Mapping[str, float] | None = None,
    bird: Bird | None = None,
    n: int = 32,
) -> SpeedSweep:
    """Sec. 4.1.1 'updating solutions': SLSQP at each speed in turn, started from the
    previous speed's optimum (the first from ``start``); ``backward`` runs from the
    highest speed down.  ``fixed`` pins parameters (both bounds set to the value, e.g.
    m4's stroke plane in Fig 52).  Uses :class:`birdsim.tables.optimize.ForceProblem`."""
    from birdsim.tables.cost import CostWeights, evaluate_cost
    from birdsim.tables.optimize import ForceProblem, slsqp

    m = get_model(model)
    bird = bird or Bird()
    order = np.argsort(speeds)[::-1] if backward else np.argsort(speeds)
    d = len(m.param_names)
    X = np.zeros((len(speeds), d))
    cost = np.zeros(len(speeds))
    x = np.array([start[k] for k in m.param_names], dtype=float)
    for i in order:
        prob = ForceProblem(m, demand[0], demand[1], float(speeds[i]), bird=bird, n=n)
        for name, value in (fixed or {}).items():
            k = m.param_names.index(name)
            prob.lower[k] = prob.upper[k] = value
        sol = slsqp(prob, x)
        X[i], cost[i] = sol.x, sol.cost
        x = sol.x
    b = evaluate_cost(
        m,
        X,
        demand[0],
        demand[1],
        np.asarray(speeds, dtype=float),
        weights=CostWeights(),
        bird=bird,
        n=n,
    )
    return SpeedSweep(
        m.name,
        "backward" if backward else "forward",
        np.asarray(speeds, dtype=float),
        m.param_names,
        X,
        np.asarray(b.total, dtype=float),
        b.fractions,
        np.stack([b.Fx, b.Fz, b.P], axis=-1),
    )


# ---- Figs 28-31, Table 3: optimisers on the test functions ---------------------------


def test_function_f(X: np.ndarray) -> np.ndarray:
    """Eq. 89: ``((x - 0.5)^2 + 0.5)((y - 0.5)^2 + 0.5)`` on [0, 1]^2, minimum 0.25 at (0.5, 0.5)."""
    X = np.atleast_2d(X)
    return ((X[:, 0] - 0.5) ** 2 + 0.5) * ((X[:, 1] - 0.5) ** 2 + 0.5)


def test_function_g(X: np.ndarray) -> np.ndarray:
    """Eq. 90: ``0.25 sin(2x) + sin(2y)`` on [0, 1]^2, minimum 0 at (0, 0), local minima at corners."""
    X = np.atleast_2d(X)
    return 0.25 * np.sin(2 * X[:, 0]) + np.sin(2 * X[:, 1])


@dataclass(frozen=True)
class OptimiserRun:
    """One solver on one test function: every point it evaluated, in order."""

    function: str
    method: str
    label: str
    points: np.ndarray  # M x 2
    values: np.ndarray  # M
    x: np.ndarray  # the answer
    value: float
    evaluations: int
    iterations: int

    @property
    def best_so_far(self) -> np.ndarray:
        return np.minimum.accumulate(self.values)


def optimiser_run(
    function: str, method: str, *, x0: Sequence[float] | None = None, nodes: int = 12, seed: int = 0
) -> OptimiserRun:
    """Run one of ``birdsim.tables.optimize``'s solvers on f or g, recording each evaluation."""
    from birdsim.tables.optimize import FunctionProblem, complete_search, evolutionary, slsqp

    fun = {"f": test_function_f, "g": test_function_g}[function]
    seen: list[np.ndarray] = []

    def recorded(X: np.ndarray) -> np.ndarray:
        X = np.atleast_2d(np.asarray(X, dtype=float))
        seen.append(X.copy())
        return fun(X)

    prob = FunctionProblem(recorded, [0.0, 0.0], [1.0, 1.0])
    if method == "complete":
        sol = complete_search(prob, nodes=nodes)
        label = f"complete search, {nodes} x {nodes} nodes"
    elif method == "slsqp":
        sol = slsqp(prob, x0 if x0 is not None else [0.5, 0.5])
        label = f"SLSQP from ({x0[0]:g}, {x0[1]:g})" if x0 is not None else "SLSQP"
    else:
        sol = evolutionary(prob, seed=seed, popsize=5, polish=False)
        label = f"differential evolution (seed {seed})"
    pts = np.concatenate(seen) if seen else np.zeros((0, 2))
    return OptimiserRun(
        function,
        method,
        label,
        pts,
        fun(pts),
        np.asarray(sol.x),
        float(fun(sol.x)[0]),
        sol.evaluations,
        sol.iterations,
    )
