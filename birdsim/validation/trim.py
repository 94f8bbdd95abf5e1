"""Trimmed level flight of a real bird: the optimal wingbeat at each speed, its power.

Level, unaccelerated flight of the whole bird needs (docs/conventions.md, "Which force")

* vertical: two wings carry the weight, ``2 Fz_wing = -m g``, i.e. the table force
  ``Fz = -w / 2`` with ``w`` the weight in force units ``rho omega^2 s^3 c``;
* horizontal: zero net force, ``2 Fx_wing + D = 0`` with ``D`` the body drag (earth X,
  negative) at the trimmed pitch, i.e. the table force ``Fx = Fx_wing + D = D / 2``.

Because ``D`` depends on the pitch, which the optimiser chooses, the x residual is written
as ``Fx_table - D/2`` (half the whole bird's net Fx) with demand 0.  The optimiser is
:mod:`birdsim.tables.optimize` (bounded SLSQP, the tables' cost ``|Fx - Fx_d| + |Fz - Fz_d|
+ 0.5 |P|`` in reduced units); the wingbeat is evaluated on the bird itself (SI) and
divided by the reference scales, so the problem is exactly the table's, and stays exact
with induced velocity on (where the reduced bird alone would not be).

Power: the table's P is one wing's cycle-mean mechanical (aerodynamic) power, positive
when the wing works on the air; the whole bird's is ``2 P`` (W for an SI bird).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.aero import body_drag_x
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.frames import earth_to_body
from birdsim.physics.kinematics import (
    KinematicModel,
    body_to_panel,
    get_model,
    joint_states,
    points_in_body,
)
from birdsim.physics.tip_path import tip_stroke_plane_deg
from birdsim.physics.units import Scales, scales, weight_in_table_units
from birdsim.tables.cost import forces
from birdsim.tables.optimize import ForceProblem, Solution, box_corners, random_starts, slsqp

#: A speed is trimmed when both force residuals are within this fraction of the weight.
TRIM_TOL = 1e-3
#: Samples per wingbeat: the search (as the tables) and the reported values (as their check).
N_SEARCH, N_CHECK = 32, 64


@dataclass(frozen=True)
class TrimPoint:
    """The optimal level-flight wingbeat at one speed.

    ``speed`` [m/s for an SI bird]; ``power`` the whole bird's mechanical power [W];
    ``params`` by table name [rad]; ``residual_x``, ``residual_z`` the whole bird's net
    force / weight (0 when trimmed); ``wing_lift_fraction`` = -2 Fz_wing / weight;
    ``tip_stroke_plane`` the wingtip's stroke-plane angle [deg]
    (:func:`birdsim.physics.tip_path.tip_stroke_plane_deg`), set by :func:`trim_sweep`.
    """

    speed: float
    power: float
    params: dict[str, float]
    trimmed: bool
    residual_x: float
    residual_z: float
    cost: float
    wing_lift_fraction: float
    tip_stroke_plane: float | None = None

    @property
    def amplitude_deg(self) -> float:
        """Peak-to-peak flap amplitude, 2 Phi_f [deg] (the biologists' stroke amplitude)."""
        return math.degrees(2.0 * self.params["flap_amp"])

    @property
    def body_angle_deg(self) -> float:
        """Body pitch to the horizontal [deg] (level flight: to the flight path)."""
        return math.degrees(self.params["pitch"])

    @property
    def flap_plane_deg(self) -> float:
        """Angle of the shoulder's flap plane (side view) to the horizontal [deg]: the flap
        swings the arm along body z tilted by pitch + stroke plane, so 90 - (theta +
        theta_sp).  The wingtip's path for a rigid wing (base-m3), not once a wrist or a
        fold moves the tip off that plane (m4, m5)."""
        return 90.0 - math.degrees(self.params["pitch"] + self.params.get("stroke_plane", 0.0))

    @property
    def stroke_plane_deg(self) -> float:
        """The wingtip's stroke-plane angle to the horizontal [deg] (Tobalske & Dial 1996
        measure it at the wingtip): ``tip_stroke_plane``; for a point built without one,
        the flap plane (exact for a rigid wing)."""
        return self.flap_plane_deg if self.tip_stroke_plane is None else self.tip_stroke_plane

    def to_dict(self) -> dict[str, object]:
        return {
            "speed": self.speed,
            "power": self.power,
            "params": dict(self.params),
            "trimmed": self.trimmed,
        }


@dataclass(frozen=True)
class TrimSweep:
    """Trimmed wingbeats of one bird and model over increasing speeds."""

    model: str
    points: tuple[TrimPoint, ...]
    seconds: float = 0.0
    label: str = "seed polar"
    extra: dict[str, object] = field(default_factory=dict)

    @property
    def speeds(self) -> np.ndarray:
        return np.array([p.speed for p in self.points])

    @property
    def powers(self) -> np.ndarray:
        return np.array([p.power for p in self.points])

    def at(self, speed: float) -> TrimPoint:
        """The point at ``speed`` (must be one of the sweep's speeds, to 1e-9)."""
        for p in self.points:
            if abs(p.speed - speed) < 1e-9:
                return p
        raise BirdsimError(
            f"speed={speed!r} m/s is not in the sweep; allowed: {', '.join(f'{p.speed:g}' for p in self.points)}"
        )

    def min_power(self) -> tuple[float, float] | None:
        """(speed, power) of least power among trimmed points, refined by a parabola through
        the grid minimum and its two trimmed neighbours; None if nothing trims."""
        ok = [i for i, p in enumerate(self.points) if p.trimmed]
        if not ok:
            return None
        i = min(ok, key=lambda j: self.points[j].power)
        if (
            0 < i < len(self.points) - 1
            and self.points[i - 1].trimmed
            and self.points[i + 1].trimmed
        ):
            x = np.array([self.points[j].speed for j in (i - 1, i, i + 1)])
            y = np.array([self.points[j].power for j in (i - 1, i, i + 1)])
            a, b, c = np.polyfit(x, y, 2)
            if a > 0:
                v = float(np.clip(-b / (2 * a), x[0], x[2]))
                return v, float(np.polyval([a, b, c], v))
        return self.points[i].speed, self.points[i].power

    def trim_range(self) -> tuple[float, float] | None:
        """The contiguous trimmed speed range around the minimum-power speed, (low, high)."""
        mp = self.min_power()
        if mp is None:
            return None
        idx = [i for i, p in enumerate(self.points) if p.trimmed]
        i0 = min(idx, key=lambda j: abs(self.points[j].speed - mp[0]))
        lo = hi = i0
        while lo > 0 and self.points[lo - 1].trimmed:
            lo -= 1
        while hi < len(self.points) - 1 and self.points[hi + 1].trimmed:
            hi += 1
        return self.points[lo].speed, self.points[hi].speed


class TrimProblem(ForceProblem):
    """Level flight of ``bird`` at ``speed_si``: residuals (whole-bird Fx / 2, Fz_table + w/2),
    in the reduced units of the bird (force rho omega^2 s^3 c, power rho omega^3 s^4 c)."""

    def __init__(
        self, model: KinematicModel, bird: Bird, speed_si: float, *, n: int = N_SEARCH
    ) -> None:
        self.sc: Scales = scales(bird)
        self.speed_si = float(speed_si)
        self.bird_si = bird
        w = weight_in_table_units(bird)
        super().__init__(
            model,
            0.0,
            -w / 2.0,
            self.speed_si / self.sc.speed,
            bird=bird,
            n=n,
            evaluator=self._evaluate,
        )
        self.weight = w

    def _evaluate(self, X: np.ndarray, speed: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        Fx, Fz, P = forces(self.model, X, self.speed_si, self.bird_si, self.n)
        pitch = X[:, self.model.param_names.index("pitch")]
        drag = body_drag_x(
            np.full(X.shape[0], self.speed_si), pitch, self.bird_si.rho, self.bird_si.body_drag_area
        )
        return (Fx - drag / 2.0) / self.sc.force, Fz / self.sc.force, P / self.sc.power


def check_flying_bird(bird: Bird) -> None:
    """A bird validation can fly: it needs gravity (weight). Raises BirdsimError naming the field."""
    if not bird.gravity > 0:
        raise BirdsimError(
            f"bird.gravity={bird.gravity!r} is invalid; allowed: a number > 0 (level flight carries the weight m g)"
        )


def _point(problem: TrimProblem, sol: Solution) -> TrimPoint:
    """Re-evaluate the solution at N_CHECK samples; SI power and residuals / weight.  The
    power is the net aerodynamic power whatever the bird's ``power_cost`` (the one the
    measurements compare with); the cost is the optimiser's."""
    bird = problem.bird_si
    if bird.power_cost != "net":
        bird = replace(bird, power_cost="net")
    check = TrimProblem(problem.model, bird, problem.speed_si, n=N_CHECK)
    fx, fz, p = check.achieved(sol.x)
    params = sol.params(problem.model.param_names)
    w = problem.weight
    rx, rz = 2.0 * fx / w, (2.0 * fz + w) / w
    return TrimPoint(
        speed=problem.speed_si,
        power=2.0 * p * problem.sc.power,
        params=params,
        trimmed=bool(max(abs(rx), abs(rz)) <= TRIM_TOL),
        residual_x=rx,
        residual_z=rz,
        cost=sol.cost,
        wing_lift_fraction=-2.0 * fz / w,
        tip_stroke_plane=tip_stroke_plane_deg(problem.model, params, bird=bird, check_bounds=False),
    )


def trim_sweep(
    model: str | KinematicModel,
    bird: Bird,
    speeds: Sequence[float],
    *,
    starts: int = 4,
    first_starts: int = 16,
    start_from: Sequence[np.ndarray] | None = None,
    extra_starts: Sequence[np.ndarray | None] | None = None,
    label: str = "seed polar",
    backward: bool = True,
    corners: bool = True,
    progress: object | None = None,
) -> TrimSweep:
    """Trimmed level flight at each speed [bird units, m/s for SI], warm-started along speed.

    Forward pass: the first speed from ``first_starts`` Sobol points plus the box corners
    (``corners=False``: without them);
    each next speed from the previous optimum plus ``starts`` Sobol points.  Backward pass:
    each speed re-solved from its faster neighbour's optimum, kept if cheaper (a branch
    found late reaches back; ``backward=False`` skips it).  ``start_from`` (one parameter
    row per speed, e.g. another sweep's optimum) is then the only start at each speed
    (the variants' cheap mode: one SLSQP per speed).  ``extra_starts`` (one row or None
    per speed, e.g. the shipped table's lookup) are added to the starts.  Deterministic
    (Sobol seed 0).

    Returns:
        TrimSweep with one TrimPoint per speed, in the given order.
    Raises:
        BirdsimError: bird without gravity, unknown model, negative or non-finite speed.
    """
    import time

    check_flying_bird(bird)
    m = model if isinstance(model, KinematicModel) else get_model(model)
    t0 = time.perf_counter()
    problems = [TrimProblem(m, bird, v) for v in speeds]
    sols: list[Solution] = []
    for k, prob in enumerate(problems):
        cands: list[np.ndarray] = []
        if start_from is not None:
            cands.append(np.asarray(start_from[k], dtype=float))
        elif sols:
            cands.append(sols[-1].x)
        if not sols and start_from is None:
            cands.extend(random_starts(prob, first_starts, seed=0))
            cands.extend(box_corners(prob) if corners else ())
        elif start_from is None:
            cands.extend(random_starts(prob, starts, seed=k))
        if extra_starts is not None and extra_starts[k] is not None:
            cands.append(np.asarray(extra_starts[k], dtype=float))
        best = min((slsqp(prob, x0) for x0 in cands), key=lambda s: s.cost)
        sols.append(best)
        if progress is not None:
            progress.update(1)  # type: ignore[attr-defined]
    for k in range(len(problems) - 2, -1, -1) if backward else ():
        alt = slsqp(problems[k], sols[k + 1].x)
        if alt.cost < sols[k].cost - 1e-12:
            sols[k] = alt
    points = tuple(_point(p, s) for p, s in zip(problems, sols))
    return TrimSweep(m.name, points, time.perf_counter() - t0, label)


def mid_span_station(model: KinematicModel, bird: Bird) -> tuple[int, float]:
    """(panel index, distance from the panel's root [bird length units]) of the point at
    ``cp_span_fraction`` of the extended semispan, counted along the panels from the
    shoulder: the scorecard's angle-of-attack station, the same for every model."""
    geometry = model.chain_with_geometry(bird)
    station = bird.cp_span_fraction * sum(span for _, span, _ in geometry)
    root = 0.0
    for k, (_, span, _) in enumerate(geometry):
        if station <= root + span or k == len(geometry) - 1:
            return k, station - root
        root += span
    raise AssertionError("unreachable")  # pragma: no cover


def angle_of_attack_deg(
    model: str | KinematicModel, bird: Bird, point: TrimPoint, phase: float
) -> float:
    """Geometric angle of attack [deg] at wingbeat phase ``phase`` (rad; 0 =
    mid-downstroke, pi = mid-upstroke), relative to the freestream plus flapping velocity
    (and the disc's inflow when induced velocity is on, taken from the cycle's mean force);
    positive = air from below the wing.

    The station is the same for every model: ``cp_span_fraction`` of the extended semispan
    (:func:`mid_span_station`; the one panel's control point for base-m3, on the arm for
    m4/m5, where the first panel's own control point sits at a third of the semispan)."""
    m = model if isinstance(model, KinematicModel) else get_model(model)
    params = {k: np.array([v]) for k, v in point.params.items()}
    air = np.zeros((1, 3))
    if bird.induced_velocity:
        from birdsim.physics.aero import induced_velocity

        cyc = evaluate_cycle(m, point.params, point.speed, bird=bird, n=N_CHECK, check_bounds=False)
        f = 2.0 * np.asarray(cyc.force_earth).mean(axis=-2).reshape(1, 3)
        f[:, 1] = 0.0
        vi = induced_velocity(f, np.array([point.speed]), bird.rho, bird.disc_area)
        air = -vi[:, None] * f / max(np.linalg.norm(f), 1e-300)
    phases = np.array([phase])
    states = joint_states(m, params, bird, phases, trailing=1)
    pitch = params["pitch"][:, None, None]
    rel = tuple(c[:, None, None] for c in (point.speed - air[:, 0], -air[:, 1], -air[:, 2]))
    air_body = earth_to_body(pitch, rel)
    panel, r_panel = mid_span_station(m, bird)
    chain = m.chain_with_geometry(bird)[panel][0]
    r = np.array([r_panel])
    _, vel_groups = points_in_body(chain, states, r)
    v_flap = [sum(np.asarray(g[i]) for g in vel_groups.values()) for i in range(3)]
    v_rel = tuple(np.asarray(a) + b for a, b in zip(air_body, v_flap))
    vx, _, vz = body_to_panel(chain, states, v_rel)
    return float(np.degrees(np.arctan2(np.asarray(vz), np.asarray(vx))).ravel()[0])


__all__ = [
    "TRIM_TOL",
    "TrimPoint",
    "TrimProblem",
    "TrimSweep",
    "angle_of_attack_deg",
    "mid_span_station",
    "check_flying_bird",
    "trim_sweep",
]
