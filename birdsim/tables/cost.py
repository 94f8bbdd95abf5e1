"""The cost of a wingbeat (docs/design.md sec. 2, dissertation secs 3.3 and 4.1).

``cost = w_x |Fx - Fx_d| + w_z |Fz - Fz_d| + w_p |P|``  (the appendix's ``flapcost``)
``     + w_o * pitch``                  only for stroke-plane models (m3, m4, m5) at V = 0:
                                        the token orientation cost of sec. 4.1.3 that
                                        ranks stroke-plane inclination above body pitch
``     + nu * |x - x_prev|``            the optional distance cost of eq. 93 (Euclidean
                                        norm of the parameter change, radians)
``     + w_q * sum_p x_p^2``            the optional quadratic tie-break on the
                                        incidence-setting parameters (issue 24, off by
                                        default): the minimum-norm point of a flat valley

Fx, Fz and P are the dissertation's force (right wing + body drag, seed earth axes,
Fz < 0 is up) and the cycle-mean mechanical power of that wing; for a bird with
``power_cost = "positive"`` P is instead the mean positive part of that wing's
aerodynamic plus inertial power (:mod:`birdsim.physics.shaft_power`; the fused kernel
with its exact gradients, :mod:`birdsim.physics.kernel_shaft`, where it runs).  Every
function here
is vectorised: parameter sets are rows of ``X`` (shape ``B x d``, columns in
``model.param_names`` order) and demands broadcast against the batch.

The four *cost fractions* (force x, force z, power, other = orientation + distance)
are each term divided by the total (sec. 4.1.1, Fig. 36).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics import kernel
from birdsim.physics.aero import body_drag
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import DEFAULT_SAMPLES, evaluate_cycle, sample_phases
from birdsim.physics.kinematics import KinematicModel
from birdsim.physics.shaft_power import positive_power

#: The parameters that set the wing's incidence in a near-glide (flap near 0), where
#: they trade against one another at equal cost (docs/tables.md, issue 24): the default
#: set of :attr:`CostWeights.incidence_params` (a name the model lacks is skipped).
INCIDENCE_PARAMS = ("pitch", "stroke_plane", "twist_amp", "wrist_bias")

#: Names of the cost fractions, in the order of the last axis of ``fractions``.
FRACTION_NAMES = ("force_x", "force_z", "power", "other")


@dataclass(frozen=True)
class CostWeights:
    """Weights of the cost terms.  Defaults: docs/design.md's ``1, 1, 0.5``; a token
    orientation weight of 0.01 per radian of body pitch (small against the force
    weights, so it only breaks the pitch / stroke-plane degeneracy at V = 0); no
    distance cost (``distance`` is the nu of eq. 93; the dissertation tried 0.2); no
    incidence tie-break (``incidence`` is w_q per rad^2 of ``sum_p x_p^2`` over
    ``incidence_params``, centre 0: among wingbeats of nearly equal cost, the one of
    least body pitch, stroke plane, twist and wrist bias)."""

    force_x: float = 1.0
    force_z: float = 1.0
    power: float = 0.5
    orientation: float = 0.01
    distance: float = 0.0
    incidence: float = 0.0
    incidence_params: tuple[str, ...] = INCIDENCE_PARAMS

    def __post_init__(self) -> None:
        for name, value in asdict(self).items():
            if name == "incidence_params":
                continue
            if not (isinstance(value, (int, float)) and np.isfinite(value) and value >= 0):
                raise BirdsimError(
                    f"cost weight {name}={value!r} is invalid; allowed: a finite number >= 0"
                )
        names = self.incidence_params
        if isinstance(names, str) or not all(isinstance(n, str) for n in names):
            raise BirdsimError(
                f"incidence_params={names!r} is invalid; allowed: a sequence of parameter names"
            )
        object.__setattr__(self, "incidence_params", tuple(names))

    def to_dict(self) -> dict[str, Any]:
        """The weights as recorded; the incidence tie-break only when on, so that every
        table built before it existed keeps its configuration digest."""
        out: dict[str, Any] = {
            k: float(v) for k, v in asdict(self).items() if k != "incidence_params"
        }
        if self.incidence > 0:
            out["incidence_params"] = list(self.incidence_params)
        else:
            del out["incidence"]
        return out

    def incidence_index(self, model: KinematicModel) -> list[int]:
        """Columns of ``model.param_names`` the incidence tie-break acts on."""
        return [model.param_names.index(n) for n in self.incidence_params if n in model.param_names]


@dataclass(frozen=True)
class CostBreakdown:
    """Every term of the cost and the achieved forces, arrays of the batch shape."""

    force_x: np.ndarray
    force_z: np.ndarray
    power: np.ndarray
    other: np.ndarray
    Fx: np.ndarray  # achieved, dissertation force (right wing + body drag)
    Fz: np.ndarray
    P: np.ndarray  # cycle-mean power of the right wing

    @property
    def total(self) -> np.ndarray:
        return self.force_x + self.force_z + self.power + self.other

    @property
    def fractions(self) -> np.ndarray:
        """Cost fractions, batch x 4 in :data:`FRACTION_NAMES` order (zeros if the total is 0)."""
        terms = np.stack([self.force_x, self.force_z, self.power, self.other], axis=-1)
        total = terms.sum(axis=-1, keepdims=True)
        return np.divide(terms, total, out=np.zeros_like(terms), where=total > 0)


def uses_orientation_cost(model: KinematicModel) -> bool:
    """True for the stroke-plane models (m3, m4, m5)."""
    return "stroke_plane" in model.param_names


def other_cost(
    model: KinematicModel,
    X: np.ndarray,
    speed: np.ndarray | float,
    weights: CostWeights,
    previous: np.ndarray | None = None,
) -> np.ndarray:
    """Orientation cost (stroke-plane models at V == 0) plus the distance cost to
    ``previous`` (eq. 93) plus the incidence tie-break.  ``X`` is ``B x d``; returns
    shape ``B``."""
    X = np.asarray(X, dtype=float)
    out = np.zeros(X.shape[:-1])
    if weights.orientation > 0 and uses_orientation_cost(model):
        pitch = X[..., model.param_names.index("pitch")]
        out = out + weights.orientation * pitch * (np.asarray(speed) == 0.0)
    if weights.distance > 0 and previous is not None:
        out = out + weights.distance * np.linalg.norm(
            X - np.asarray(previous, dtype=float), axis=-1
        )
    if weights.incidence > 0:
        Q = X[..., weights.incidence_index(model)]
        out = out + weights.incidence * np.add.reduce(Q * Q, axis=-1)
    return out


def forces(
    model: KinematicModel,
    X: np.ndarray,
    speed: np.ndarray | float,
    bird: Bird,
    n: int = DEFAULT_SAMPLES,
    climb: np.ndarray | float = 0.0,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Achieved mean (Fx, Fz, P) of the parameter rows ``X`` (B x d), one batched cycle
    evaluation at speed V and ``climb`` (vertical speed relative to the air, up).

    Bounds are not checked: optimisers probe a hair outside them for finite differences.
    """
    X = np.asarray(X, dtype=float)
    net = bird.power_cost == "net"
    if X.ndim == 2 and not bird.induced_velocity:
        out = _kernel_forces(model, X, speed, bird, n, climb)
        if out is not None:
            return out
    params = {name: X[..., i] for i, name in enumerate(model.param_names)}
    cyc = evaluate_cycle(
        model,
        params,
        speed,
        climb=climb,
        bird=bird,
        n=n,
        check_bounds=False,
        backend="kernel" if net else "numpy",
    )
    mean = cyc.mean
    return (
        np.asarray(mean.Fx, dtype=float),
        np.asarray(mean.Fz, dtype=float),
        np.asarray(mean.P if net else positive_power(cyc, bird), dtype=float),
    )


#: Central-difference step (rad) of the fallback gradients (no compiled kernel, or
#: induced velocity on): truncation ~h^2 times the third derivative, round-off ~1e-16/h.
FD_STEP = 1e-6


def forces_and_gradients(
    model: KinematicModel,
    X: np.ndarray,
    speed: np.ndarray | float,
    bird: Bird,
    n: int = DEFAULT_SAMPLES,
    climb: np.ndarray | float = 0.0,
) -> tuple[tuple[np.ndarray, np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Mean (Fx, Fz, P) of the rows of ``X`` (B x d) and their exact gradients.

    Args:
        model: the kinematic model; ``X`` columns in ``model.param_names`` order [rad].
        speed, climb: flight speed and climb rate (broadcast against the rows).
        bird: the bird; n: samples per wingbeat.

    Returns:
        ``((Fx, Fz, P), (dFx, dFz, dP))``: values of shape B, gradients B x d (force
        and power units per radian).  Forward-mode derivatives from the fused kernel
        (:func:`birdsim.physics.kernel.means_and_gradients`) plus the analytic body-drag
        term; central differences (one batched call) where the kernel cannot run
        (no JIT, a polar it does not know, or induced velocity on).
    """
    X = np.atleast_2d(np.asarray(X, dtype=float))
    B, d = X.shape
    v = np.ascontiguousarray(np.broadcast_to(np.asarray(speed, dtype=float), (B,)))
    vc = np.ascontiguousarray(np.broadcast_to(np.asarray(climb, dtype=float), (B,)))
    flat = {name: np.ascontiguousarray(X[:, i]) for i, name in enumerate(model.param_names)}
    out = kernel.means_and_gradients(
        model, flat, v, vc, bird, sample_phases(n, False), positive=bird.power_cost == "positive"
    )
    if out is None:
        steps = FD_STEP * np.eye(d)
        Y = np.concatenate(
            [X, (X[:, None, :] + steps).reshape(-1, d), (X[:, None, :] - steps).reshape(-1, d)]
        )
        rep = np.concatenate([v, np.repeat(v, d), np.repeat(v, d)])
        rep_c = np.concatenate([vc, np.repeat(vc, d), np.repeat(vc, d)])
        F = forces(model, Y, rep, bird, n, rep_c)
        vals = tuple(f[:B] for f in F)
        grads = tuple((f[B : B + B * d] - f[B + B * d :]).reshape(B, d) / (2 * FD_STEP) for f in F)
        return vals, grads  # type: ignore[return-value]
    w, g = out
    pitch = flat["pitch"]
    dx, dz = body_drag(v, vc, pitch, bird.rho, bird.body_drag_area)
    ddx, ddz = _body_drag_pitch_derivative(v, vc, pitch, bird.rho, bird.body_drag_area)
    ip = model.param_names.index("pitch")
    gx, gz = g[:, 0].copy(), g[:, 2].copy()
    gx[:, ip] += ddx
    gz[:, ip] += ddz
    return (w[:, 0] + dx, w[:, 2] + dz, w[:, 3].copy()), (gx, gz, g[:, 3].copy())


def _body_drag_pitch_derivative(
    speed: np.ndarray, climb: np.ndarray, pitch: np.ndarray, rho: float, area: float
) -> tuple[np.ndarray, np.ndarray]:
    """d(Dx, Dz)/d(pitch) of :func:`birdsim.physics.aero.body_drag`."""
    level = -0.5 * rho * np.square(speed) * np.cos(pitch) * area
    vt = np.hypot(speed, climb)
    attack = pitch - np.arctan2(climb, speed)
    dmag = 0.5 * rho * np.square(vt) * np.sign(np.sin(attack)) * np.cos(attack) * area
    unit = np.divide(1.0, vt, out=np.zeros_like(vt), where=vt > 0.0)
    level_flight = climb == 0.0
    return np.where(level_flight, level, -dmag * unit * speed), np.where(
        level_flight, 0.0, dmag * unit * climb
    )


def other_cost_gradient(
    model: KinematicModel,
    X: np.ndarray,
    speed: np.ndarray | float,
    weights: CostWeights,
    previous: np.ndarray | None = None,
) -> np.ndarray:
    """Gradient of :func:`other_cost` with respect to the rows of ``X`` (B x d)."""
    X = np.asarray(X, dtype=float)
    out = np.zeros(X.shape)
    if weights.orientation > 0 and uses_orientation_cost(model):
        ip = model.param_names.index("pitch")
        out[..., ip] += weights.orientation * (np.asarray(speed) == 0.0)
    if weights.distance > 0 and previous is not None:
        diff = X - np.asarray(previous, dtype=float)
        norm = np.linalg.norm(diff, axis=-1, keepdims=True)
        out += weights.distance * np.divide(diff, norm, out=np.zeros_like(diff), where=norm > 0)
    if weights.incidence > 0:
        idx = weights.incidence_index(model)
        out[..., idx] += 2.0 * weights.incidence * X[..., idx]
    return out


def _kernel_forces(
    model: KinematicModel,
    X: np.ndarray,
    speed: np.ndarray | float,
    bird: Bird,
    n: int,
    climb: np.ndarray | float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """The lean path of :func:`forces`: the kernel's means without building a Cycle
    (the same numbers as ``evaluate_cycle(...).mean``); None where the kernel cannot
    run.  Non-finite parameters give NaN rows (a table cell then fails), not an error."""
    B = X.shape[0]
    try:
        v = np.ascontiguousarray(np.broadcast_to(np.asarray(speed, dtype=float), (B,)))
        vc = np.ascontiguousarray(np.broadcast_to(np.asarray(climb, dtype=float), (B,)))
    except ValueError:
        return None  # let evaluate_cycle name the shapes
    flat = {name: np.ascontiguousarray(X[:, i]) for i, name in enumerate(model.param_names)}
    pos = np.zeros(B) if bird.power_cost == "positive" else None
    phases = sample_phases(n, False)
    out = kernel.means(model, flat, v, vc, np.zeros((B, 3)), bird, phases, positive=pos)
    if out is None:
        return None
    f, p = out[0].sum(axis=-2), (out[1].sum(axis=-1) if pos is None else pos)
    if not vc.any():  # level flight: eq. 7, the same operations as aero.body_drag
        dx = -0.5 * bird.rho * np.square(v) * np.sin(flat["pitch"]) * bird.body_drag_area
        return f[:, 0] + dx, f[:, 2] + np.zeros_like(dx), p
    dx, dz = body_drag(v, vc, flat["pitch"], bird.rho, bird.body_drag_area)
    return f[:, 0] + dx, f[:, 2] + dz, p


def breakdown_from_forces(
    Fx: np.ndarray,
    Fz: np.ndarray,
    P: np.ndarray,
    Fx_demand: np.ndarray | float,
    Fz_demand: np.ndarray | float,
    weights: CostWeights,
    other: np.ndarray | float = 0.0,
) -> CostBreakdown:
    """The cost terms from already computed forces (demands broadcast against them)."""
    fx = weights.force_x * np.abs(Fx - Fx_demand)
    fz = weights.force_z * np.abs(Fz - Fz_demand)
    p = weights.power * np.abs(P)
    shape = np.broadcast_shapes(np.shape(fx), np.shape(fz), np.shape(other))
    return CostBreakdown(
        np.broadcast_to(fx, shape),
        np.broadcast_to(fz, shape),
        np.broadcast_to(p, shape),
        np.broadcast_to(np.asarray(other, dtype=float), shape),
        np.broadcast_to(Fx, shape),
        np.broadcast_to(Fz, shape),
        np.broadcast_to(P, shape),
    )


def evaluate_cost(
    model: KinematicModel,
    X: np.ndarray,
    Fx_demand: np.ndarray | float,
    Fz_demand: np.ndarray | float,
    speed: np.ndarray | float,
    *,
    weights: CostWeights | None = None,
    bird: Bird | None = None,
    previous: np.ndarray | None = None,
    n: int = DEFAULT_SAMPLES,
    climb: np.ndarray | float = 0.0,
) -> CostBreakdown:
    """Every cost term of the parameter rows ``X`` (B x d) for demands (Fx_d, Fz_d) at
    speed V and ``climb`` (positive up)."""
    weights = weights or CostWeights()
    bird = bird or Bird()
    Fx, Fz, P = forces(model, X, speed, bird, n, climb)
    other = other_cost(model, X, speed, weights, previous)
    return breakdown_from_forces(Fx, Fz, P, Fx_demand, Fz_demand, weights, other)
