"""What a bird can do with a table: the flight envelope (issue 9, item 2).

Everything is read from a lookup table (reduced units: forces in ``rho omega^2 s^3 c``,
speeds in ``omega s``, power in ``rho omega^3 s^4 c``) and converted to the bird's own
units with :func:`birdsim.physics.units.scales`. Forces are the *whole bird's* (two wings
and the body) unless a name says ``table`` (one wing + body drag, the dissertation's).

Definitions (docs/flight.md, "Envelope of each model"):

* **reachable** demand (Fx, Fz, V): every corner of the table cell around it is ``ok``
  (the force error of its optimal wingbeat <= the table's reach tolerance) -- what
  ``LookupTable.status_at`` reports and what the flight log calls "not saturated".
* **trimmed**: the whole bird's Fx is zero, i.e. the table's ``Fx = D / 2`` with ``D`` the
  body drag at the table's pitch (:func:`birdsim.flight.demand.body_drag_earth`).
* **largest lift** at V: ``-2 Fz`` for the most upward reachable trimmed table demand
  (Fz sampled every :data:`FZ_STEP`).
  The optimiser's own limit, ``best_lift``: ``-2`` x the achieved Fz stored in the cell
  that demands the most upward force of the grid with Fx = 0 at each V node.
* **heaviest bird that can hover**: the largest lift at V = 0 (weight in table units, N, kg).
* **level flight**: the speeds at which the trimmed demand ``Fz = -w / 2`` is reachable.
* **minimum-power speed**: the level-flight speed of least whole-bird power (2 x the
  table's interpolated achieved power of one wing).
* **steepest climb**: the table read in wind axes (turned by the flight-path angle gamma,
  speed V along the path): a steady climb needs a thrust ``w sin(gamma)`` plus the body
  drag along the path and a lift ``w cos(gamma)`` across it, i.e. the table demand
  ``(w sin(gamma) / 2 + D / 2, -w cos(gamma) / 2, V)``; per speed the steepest gamma
  reachable from level flight (every angle below it reachable too); the steepest climb is
  the largest climb rate ``V sin(gamma)`` over V > 0. The table does not bound power, so
  the climb is what the wingbeats can do aerodynamically, not what muscles sustain.
* **acceleration** in level flight at V: the largest forward and backward ``ax`` with the
  weight carried (``Fz = -w / 2`` reachable with ``Fx = (m ax + D) / 2``).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np

from birdsim.flight.demand import body_drag_earth
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird, scales, weight_in_table_units
from birdsim.tables.lookup import AXES, LookupTable

#: Speed sampling of the envelope (omega s) and of Fz / Fx searches (table units).
V_STEP = 0.01
FZ_STEP = 0.0025
FX_STEP = 0.0025
GAMMA_STEP_DEG = 0.25


def reachable(table: LookupTable, Fx: Any, Fz: Any, V: Any) -> np.ndarray:
    """Vectorised ``status_at == "ok"``: every corner of each demand's cell is ok
    (a demand on a node needs only that node); demands outside the grid are not."""
    pts = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (Fx, Fz, V)))
    inside = np.ones(pts[0].shape, dtype=bool)
    lo_idx, hi_idx = [], []
    for k, a in enumerate(AXES):
        ax = np.asarray(table.axes[a], dtype=float)
        x = pts[k]
        inside &= (x >= ax[0] - 1e-12) & (x <= ax[-1] + 1e-12)
        i = np.clip(np.searchsorted(ax, x) - 1, 0, len(ax) - 2)
        lo, hi = i.copy(), i + 1
        on_lo = np.abs(ax[i] - x) < 1e-12
        on_hi = np.abs(ax[i + 1] - x) < 1e-12
        hi = np.where(on_lo, lo, hi)
        lo = np.where(on_hi, hi, lo)
        lo_idx.append(lo)
        hi_idx.append(hi)
    ok = table.status_code == 0
    out = inside.copy()
    for cx in (lo_idx[0], hi_idx[0]):
        for cz in (lo_idx[1], hi_idx[1]):
            for cv in (lo_idx[2], hi_idx[2]):
                out &= ok[cx, cz, cv]
    return out


def trim_drag(table: LookupTable, bird: Bird, Fz: Any, V: Any) -> np.ndarray:
    """Body drag D (seed X, <= 0) at the table's pitch for the trimmed demand (Fx = D/2, Fz, V):
    two fixed-point steps from D = 0."""
    rb = reduced_bird(bird)
    Fz, V = np.broadcast_arrays(np.asarray(Fz, dtype=float), np.asarray(V, dtype=float))
    d = np.zeros(Fz.shape)
    for _ in range(2):
        pitch = table.lookup_many(Fx=d / 2, Fz=Fz, V=V, clip=True)["pitch"]
        d = body_drag_earth(rb, V, 0.0, pitch)[0]
    return d


@dataclass(frozen=True)
class Envelope:
    """The envelope of one bird with one table (see the module docstring for definitions).

    Reduced units unless the name ends in ``_si`` (the bird file's units: N, m/s, W, kg).
    Per-speed arrays are sampled at ``speeds``.
    """

    model: str
    bird: str
    mass_ratio: float
    weight: float  # whole bird, table force units
    weight_si: float
    speeds: list[float]
    lift: list[float]  # largest trimmed lift, whole bird, table units
    lift_si: list[float]
    best_lift_speeds: list[float]  # the table's V nodes
    best_lift: list[float]
    hover_weight: float
    hover_weight_si: float
    hover_mass_si: float | None
    can_hover: bool
    level_speeds: list[list[float]]  # intervals [V_lo, V_hi] of level flight
    level_speeds_si: list[list[float]]
    min_power_speed: float | None
    min_power_speed_si: float | None
    min_power: float | None  # whole bird
    min_power_si: float | None
    climb_angle_deg: float | None
    climb_rate: float | None
    climb_rate_si: float | None
    climb_speed: float | None
    climb_angles_deg: list[float]  # steepest climb angle at each speed (nan: none)
    accel_forward: list[float]  # largest level-flight ax at each speed (omega^2 s), nan = none
    accel_backward: list[float]  # most negative ax

    def to_dict(self) -> dict[str, Any]:
        return {k: _jsonable(v) for k, v in asdict(self).items()}


def _jsonable(v: Any) -> Any:
    if isinstance(v, float):
        return None if not math.isfinite(v) else round(v, 6)
    if isinstance(v, list):
        return [_jsonable(x) for x in v]
    return v


def _intervals(x: np.ndarray, mask: np.ndarray) -> list[list[float]]:
    out: list[list[float]] = []
    start = None
    for i, m in enumerate(mask):
        if m and start is None:
            start = i
        if (not m or i == len(mask) - 1) and start is not None:
            end = i if m else i - 1
            out.append([float(x[start]), float(x[end])])
            start = None
    return out


def envelope(table: LookupTable, bird: Bird) -> Envelope:
    """The envelope of ``bird`` flown with ``table`` (built for its reduced bird).

    Args:
        table: the lookup table (reduced units).
        bird: the bird, in its own units (its mass and gravity give the weight).

    Returns:
        An :class:`Envelope`.
    """
    rb = reduced_bird(bird)
    sc = scales(bird)
    w = weight_in_table_units(bird)
    mu = rb.mass
    vmax = float(table.axes["V"][-1])
    speeds = np.round(np.arange(0.0, vmax + 1e-9, V_STEP), 6)
    fz_line = -np.arange(0.0, -float(table.axes["Fz"][0]) + 1e-9, FZ_STEP)

    # largest trimmed lift: contiguous reachable run from Fz = 0 downwards
    FZ, VV = np.meshgrid(fz_line, speeds, indexing="ij")
    D = trim_drag(table, bird, FZ, VV)
    ok = reachable(table, D / 2, FZ, VV)
    deepest = np.where(ok.any(axis=0), np.max(np.where(ok, -FZ, -np.inf), axis=0), np.nan)
    lift = 2.0 * deepest

    # the optimiser's limit: achieved Fz of the most upward demand with Fx = 0
    i_fx0 = int(np.argmin(np.abs(table.axes["Fx"])))
    best = -2.0 * table.achieved[i_fx0, 0, :, 1]

    # level flight at the bird's weight
    fz_w = np.full(speeds.shape, -w / 2)
    d_w = trim_drag(table, bird, fz_w, speeds)
    level = reachable(table, d_w / 2, fz_w, speeds)
    level_iv = _intervals(speeds, level)
    power = 2.0 * table.lookup_many(Fx=d_w / 2, Fz=fz_w, V=speeds, clip=True)["achieved_P"]
    if level.any():
        j = int(np.argmin(np.where(level, power, np.inf)))
        vmp, pmin = float(speeds[j]), float(power[j])
    else:
        vmp = pmin = None

    # steepest climb (wind axes)
    gam = np.radians(np.arange(0.0, 90.0, GAMMA_STEP_DEG))
    G, VC = np.meshgrid(gam, speeds[speeds > 0], indexing="ij")
    fz_c = -w * np.cos(G) / 2
    d_c = trim_drag(table, bird, fz_c, VC)
    ok_c = reachable(table, (w * np.sin(G) + d_c) / 2, fz_c, VC)
    run_c = np.cumprod(ok_c, axis=0).astype(bool)  # contiguous from level flight
    n_ok = run_c.sum(axis=0)
    angles = np.full(speeds.shape, np.nan)
    angles[speeds > 0] = np.where(n_ok > 0, np.degrees(gam[np.maximum(n_ok - 1, 0)]), np.nan)
    climb_angle = climb_rate = climb_speed = None
    if n_ok.any():
        rates = np.where(n_ok > 0, VC[0] * np.sin(gam[np.maximum(n_ok - 1, 0)]), -np.inf)
        j = int(np.argmax(rates))
        climb_angle = float(np.degrees(gam[n_ok[j] - 1]))
        climb_rate, climb_speed = float(rates[j]), float(VC[0, j])

    # level-flight acceleration
    fx_line = np.arange(float(table.axes["Fx"][0]), float(table.axes["Fx"][-1]) + 1e-9, FX_STEP)
    FX, VA = np.meshgrid(fx_line, speeds, indexing="ij")
    ok_a = reachable(table, FX, -w / 2, VA)
    ax_line = (2.0 * FX - d_w[None, :]) / mu  # m ax = 2 Fx_table - D
    acc_f = np.where(ok_a.any(axis=0), np.max(np.where(ok_a, ax_line, -np.inf), axis=0), np.nan)
    acc_b = np.where(ok_a.any(axis=0), np.min(np.where(ok_a, ax_line, np.inf), axis=0), np.nan)

    hover = float(lift[0]) if math.isfinite(lift[0]) else 0.0
    return Envelope(
        model=table.model,
        bird=bird.name,
        mass_ratio=float(mu),
        weight=float(w),
        weight_si=float(bird.mass * bird.gravity),
        speeds=[float(v) for v in speeds],
        lift=[float(x) for x in lift],
        lift_si=[float(x * sc.force) for x in lift],
        best_lift_speeds=[float(v) for v in table.axes["V"]],
        best_lift=[float(x) for x in best],
        hover_weight=hover,
        hover_weight_si=hover * sc.force,
        hover_mass_si=hover * sc.force / bird.gravity if bird.gravity > 0 else None,
        can_hover=bool(level[0]),
        level_speeds=level_iv,
        level_speeds_si=[[a * sc.speed, b * sc.speed] for a, b in level_iv],
        min_power_speed=vmp,
        min_power_speed_si=None if vmp is None else vmp * sc.speed,
        min_power=pmin,
        min_power_si=None if pmin is None else pmin * sc.power,
        climb_angle_deg=climb_angle,
        climb_rate=climb_rate,
        climb_rate_si=None if climb_rate is None else climb_rate * sc.speed,
        climb_speed=climb_speed,
        climb_angles_deg=[float(x) for x in angles],
        accel_forward=[float(x) for x in acc_f],
        accel_backward=[float(x) for x in acc_b],
    )


def achieved_miss(table: LookupTable, Fx: Any, Fz: Any, V: Any) -> np.ndarray:
    """How far the table's achieved force (interpolated like its parameters) misses each
    demand: ``max(|Fx_achieved - Fx|, |Fz_achieved - Fz|)``, demands outside the grid
    measured against the clipped lookup (table force units)."""
    r = table.lookup_many(Fx=Fx, Fz=Fz, V=V, clip=True)
    return np.maximum(np.abs(r["achieved_Fx"] - Fx), np.abs(r["achieved_Fz"] - Fz))


def room(
    table: LookupTable, Fx: Any, Fz: Any, V: Any, delta: float, tol: float = 0.01
) -> np.ndarray:
    """Whether every demand moved by up to ``delta`` in Fx and Fz (the 8 neighbours on the
    square of half-side delta) is still met within ``tol`` by the table's achieved force:
    the room a feedback controller has around a feed-forward demand."""
    Fx, Fz, V = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (Fx, Fz, V)))
    ok = achieved_miss(table, Fx, Fz, V) <= tol
    for ex in (-1, 0, 1):
        for ez in (-1, 0, 1):
            if ex or ez:
                ok &= achieved_miss(table, Fx + ex * delta, Fz + ez * delta, V) <= tol
    return ok


def path_reach(
    path: Any, bird: Bird, table: LookupTable, samples_per_beat: int = 32
) -> dict[str, np.ndarray]:
    """The feed-forward demands of a flight path and whether each is reachable.

    Args:
        path: a :class:`birdsim.flight.path.FlightPath`.
        bird: the bird flying it (reduced internally).
        table: the table flying it.
        samples_per_beat: samples per wingbeat over ``[0, duration]``.

    Returns:
        :func:`birdsim.flight.demand.path_demands` at the samples (earth-axes reading),
        plus ``t`` (reduced time), ``t_beats``, ``ok`` (bool: the demand lies in a cell
        whose corners are all ok, negative speeds are not), and the air-path reading of
        the same samples (:func:`birdsim.flight.demand.air_path_demand`, what the
        controller looks up): ``Fx_air``, ``Fz_air``, ``V_air`` and ``ok_air``.
    """
    from birdsim.flight.demand import air_path_demand, path_demands

    n = int(math.ceil(path.duration_beats * samples_per_beat)) + 1
    t_beats = np.linspace(0.0, path.duration_beats, n)
    d = path_demands(path, bird, table, t_beats * 2.0 * math.pi)
    ok = reachable(table, d["Fx"], d["Fz"], d["V"]) & (d["V"] >= -1e-12)
    args = (d["ax"], d["az"], d["vx"], d["vz"], bird)
    pitch = d["pitch"]
    for _ in range(4):  # the drag's pitch: the table's plus the turn
        fx, fz, v, gamma = air_path_demand(*args, pitch)
        pitch = table.lookup_many(Fx=fx, Fz=fz, V=np.maximum(v, 0.0), clip=True)["pitch"] + gamma
    air = np.stack([fx, fz, v], axis=1)
    ok_air = reachable(table, air[:, 0], air[:, 1], air[:, 2]) & (air[:, 2] >= -1e-12)
    return {
        **d,
        "t": t_beats * 2.0 * math.pi,
        "t_beats": t_beats,
        "ok": ok,
        "Fx_air": air[:, 0],
        "Fz_air": air[:, 1],
        "V_air": air[:, 2],
        "ok_air": ok_air,
    }


__all__ = ["Envelope", "achieved_miss", "envelope", "path_reach", "reachable", "room", "trim_drag"]
