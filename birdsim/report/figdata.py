"""The numbers behind the report's figures (pure numpy, no matplotlib).

Every function here evaluates the physics core (``evaluate_cycle``) on a whole grid of
parameter sets in one batched call (chunked to bound memory), or reads the polar
directly.  ``birdsim/report/plots.py`` draws these arrays; ``birdsim/report/claims.py`` compares
them with what the dissertation printed.  Forces are the dissertation's force (right
wing + body drag, seed earth axes, Fz < 0 is up) unless a name says otherwise.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from birdsim.physics.aero import Polar
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.frames import body_to_earth
from birdsim.physics.kinematics import get_model, joint_states, panel_to_body, points_in_body

#: Flatten batches larger than this into chunks (parameter sets per evaluate_cycle call).
CHUNK = 8192


@dataclass(frozen=True)
class GridMeans:
    """Mean forces and power over a grid of parameter sets (arrays of the grid shape).

    ``Fx`` includes the body drag (dissertation force); ``P`` is the mean mechanical
    power of the right wing."""

    Fx: np.ndarray
    Fz: np.ndarray
    P: np.ndarray


def grid_means(
    model: str,
    params: Mapping[str, np.ndarray | float],
    speed: np.ndarray | float,
    *,
    bird: Bird | None = None,
    n: int = 32,
    check_bounds: bool = False,
) -> GridMeans:
    """Batched cycle means of every parameter set of a broadcastable grid.

    The grid is flattened and evaluated in chunks of :data:`CHUNK` sets, each one
    vectorised ``evaluate_cycle`` call.
    """
    arrays = {k: np.asarray(v, dtype=float) for k, v in params.items()}
    v = np.asarray(speed, dtype=float)
    shape = np.broadcast_shapes(v.shape, *(a.shape for a in arrays.values()))
    flat = {k: np.broadcast_to(a, shape).reshape(-1) for k, a in arrays.items()}
    vf = np.broadcast_to(v, shape).reshape(-1)
    size = vf.size
    fx, fz, p = np.empty(size), np.empty(size), np.empty(size)
    for lo in range(0, size, CHUNK):
        hi = min(lo + CHUNK, size)
        cyc = evaluate_cycle(
            model,
            {k: a[lo:hi] for k, a in flat.items()},
            vf[lo:hi],
            bird=bird,
            n=n,
            check_bounds=check_bounds,
        )
        m = cyc.mean
        fx[lo:hi], fz[lo:hi], p[lo:hi] = m.Fx, m.Fz, m.P
    return GridMeans(fx.reshape(shape), fz.reshape(shape), p.reshape(shape))


def mesh(axes: Sequence[np.ndarray]) -> list[np.ndarray]:
    """Open-mesh views (``np.ix_``) of 1-D axes: arrays that broadcast to the full grid."""
    return list(np.ix_(*[np.asarray(a, dtype=float) for a in axes]))


# ---- Fig 9: thrust coefficient over advance angle and twist --------------------------


def thrust_coefficient(polar: Polar, advance_angle: np.ndarray, twist: np.ndarray) -> np.ndarray:
    """Eq. 20/23: ``C_Fx = C_L(a) sin(zeta) - C_D(a) cos(zeta)`` with ``a = zeta - theta_f``.

    A translating section meets the air at the advance angle ``zeta = atan(w_f / V)``;
    twist ``theta_f`` (leading edge down) reduces its incidence to ``zeta - theta_f``.
    Lift is normal and drag parallel to the relative wind, so their components along
    the flight direction give the thrust coefficient.  (The printed eq. 23 drops the
    ``sin(zeta)`` of the lift term -- an OCR/typesetting slip: with it, eq. 23 reduces to
    eq. 15 at zero twist as the text says.)  Arrays broadcast.
    """
    zeta = np.asarray(advance_angle, dtype=float)
    cl, cd = polar.coefficients(zeta - np.asarray(twist, dtype=float))
    return cl * np.sin(zeta) - cd * np.cos(zeta)


# ---- Figs 26-27: wrist lag and bias --------------------------------------------------

#: sec. 3.5.7: cruise-like case, pitch, stroke plane and twist omitted.
WRIST_STUDY = dict(speed=0.5, pitch=0.0, twist_amp=0.0, stroke_plane=0.0)


def wrist_upward_force(
    flap_amp: np.ndarray | float,
    wrist_amp: np.ndarray | float,
    wrist_lag: np.ndarray | float,
    wrist_bias: np.ndarray | float,
    *,
    bird: Bird | None = None,
    n: int = 32,
) -> np.ndarray:
    """Upward mean force ``-Fz`` of m4 (dissertation force) in the sec. 3.5.7 study
    (V = 0.5, pitch = twist = stroke plane = 0), over any broadcastable grid.

    The dissertation's "F_z(max)" is the largest upward force; its amplitudes and bias
    exceed the default bounds (up to pi/2), so bounds are not checked here.
    """
    s = WRIST_STUDY
    params = dict(
        pitch=s["pitch"],
        flap_amp=flap_amp,
        twist_amp=s["twist_amp"],
        stroke_plane=s["stroke_plane"],
        wrist_amp=wrist_amp,
        wrist_bias=wrist_bias,
        wrist_lag=wrist_lag,
    )
    return -grid_means("m4", params, s["speed"], bird=bird, n=n).Fz


@dataclass(frozen=True)
class WristOptimum:
    """Per (flap_amp, wrist_amp): the lag and bias giving the largest upward force."""

    flap_amp: np.ndarray  # I
    wrist_amp: np.ndarray  # J
    lag_star: np.ndarray  # I x J
    bias_star: np.ndarray  # I x J
    upward_max: np.ndarray  # I x J


def wrist_optimum(
    flap_amp: np.ndarray,
    wrist_amp: np.ndarray,
    lag: np.ndarray,
    bias: np.ndarray,
    *,
    bird: Bird | None = None,
    n: int = 32,
) -> WristOptimum:
    """Fig 27: argmax over the (lag, bias) grid of the upward force, for every amplitude pair."""
    up = wrist_upward_force(*mesh([flap_amp, wrist_amp, lag, bias]), bird=bird, n=n)
    i, j = up.shape[:2]
    flat = up.reshape(i, j, -1)
    best = np.argmax(flat, axis=-1)
    li, bi = np.unravel_index(best, (len(lag), len(bias)))
    return WristOptimum(
        np.asarray(flap_amp),
        np.asarray(wrist_amp),
        np.asarray(lag)[li],
        np.asarray(bias)[bi],
        np.take_along_axis(flat, best[..., None], axis=-1)[..., 0],
    )


# ---- Fig 49: wrist activity coefficient K --------------------------------------------


def wrist_activity(k: np.ndarray | float) -> dict[str, np.ndarray]:
    """Eq. 95: wrist amplitude, lag and bias as ``K`` times their upper bounds (m4)."""
    m = get_model("m4")
    k = np.asarray(k, dtype=float)
    return {name: k * m.spec(name).upper for name in ("wrist_amp", "wrist_lag", "wrist_bias")}


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


# ---- Figs 41-43, 46-48, 53-55: control-point paths and chord lines -------------------


@dataclass(frozen=True)
class ControlPointPaths:
    """Per panel: CP path and chord segments in earth-oriented axes relative to the
    shoulder (seed axes: X forward, Y right, Z down), over one wingbeat.

    ``path`` is K x N x 3; ``leading``/``trailing`` are K x N x 3, the ends of the chord
    line through each CP (leading edge = +x of the panel)."""

    model: str
    panel_names: tuple[str, ...]
    phase: np.ndarray  # N, t/T in [0, 1)
    path: np.ndarray
    leading: np.ndarray
    trailing: np.ndarray


def control_point_paths(
    model: str, params: Mapping[str, float], *, bird: Bird | None = None, n: int = 64
) -> ControlPointPaths:
    """Where each panel's control point goes over one wingbeat, with its chord line.

    Uses the kinematic chain directly (``joint_states``, ``points_in_body``,
    ``panel_to_body``) and the body pitch to turn body axes into earth axes; the body
    stays at the origin (paths relative to the shoulder, as the dissertation draws them).
    """
    bird = bird or Bird()
    m = get_model(model)
    p = {k: np.asarray(float(v)) for k, v in params.items()}
    phases = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    states = joint_states(m, p, bird, phases, trailing=1)
    pitch = float(p["pitch"])
    paths, leads, trails, names = [], [], [], []
    for (chain, span, chord), geom in zip(m.chain_with_geometry(bird), bird.panels(m.name)):
        r = np.array([bird.cp_span_fraction * span])
        pos, _ = points_in_body(chain, states, r)
        x_axis = panel_to_body(chain, states, (np.ones((n, 1)), np.zeros((n, 1)), np.zeros((n, 1))))
        pos = np.stack(
            [np.broadcast_to(c, (n, 1))[:, 0] for c in body_to_earth(pitch, pos)], axis=-1
        )
        ax = np.stack(
            [np.broadcast_to(c, (n, 1))[:, 0] for c in body_to_earth(pitch, x_axis)], axis=-1
        )
        paths.append(pos)
        leads.append(pos + 0.5 * chord * ax)
        trails.append(pos - 0.5 * chord * ax)
        names.append(geom.name)
    return ControlPointPaths(
        m.name,
        tuple(names),
        phases / (2 * math.pi),
        np.stack(paths),
        np.stack(leads),
        np.stack(trails),
    )


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
