"""Fly a path (or an open-loop demand schedule) in MuJoCo: the loop that ties the
simulation (:mod:`birdsim.flight.simulate`), the controller
(:mod:`birdsim.flight.controller`) and the wingbeat schedule together.

Everything here is in REDUCED units (lengths in semispans, time in 1 / omega, one
wingbeat = 2 pi, velocities in semispan omega, table forces); :mod:`birdsim.flight.flightlog`
converts a result to the bird's own units.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError, limits_text, magnitude_ok
from birdsim.flight.controller import Controller, ErrorWindow, Gains, gains_for
from birdsim.flight.simulate import FreeBird, SimConfig
from birdsim.flight.wingbeat import WingbeatSchedule
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird, scales

TWO_PI = 2.0 * math.pi
#: The integral term's acceleration is bounded by this fraction of gravity (the
#: table-vs-flight mismatch it trims is ~4 % of the weight in cruise).
INTEGRAL_LIMIT = 0.1
#: The integral only runs while the estimated position error is below this (semispans).
INTEGRAL_BAND = 0.1


class GustError(BirdsimError):
    """A malformed --gust."""


@dataclass(frozen=True)
class Gust:
    """Wind ``(wx, wz)`` (the bird's velocity units; x forward, z up) from ``t0`` for
    ``duration`` wingbeats after the start."""

    t0: float
    duration: float
    wx: float
    wz: float

    def __post_init__(self) -> None:
        for name in ("t0", "duration", "wx", "wz"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and magnitude_ok(v)):
                raise GustError(
                    f"gust {name}={v!r} is invalid; allowed: a finite number, {limits_text()}"
                )
        if self.t0 < 0 or self.duration < 0:
            raise GustError(
                f"gust t0={self.t0:g}, duration={self.duration:g}; allowed: times >= 0 (wingbeats)"
            )


def parse_gust(text: str) -> Gust:
    """``"T0:DURATION:WX:WZ"`` -> Gust; one clear line otherwise."""
    parts = str(text).split(":")
    if len(parts) != 4:
        raise GustError(
            f"--gust {text!r} has {len(parts)} field(s); allowed: T0:DURATION:WX:WZ (four numbers: wingbeats, wingbeats, velocity x, velocity z)"
        )
    try:
        vals = [float(p) for p in parts]
    except ValueError:
        raise GustError(
            f"--gust {text!r} is not four numbers; allowed: T0:DURATION:WX:WZ, e.g. 4:1:0:0.27"
        ) from None
    if not all(math.isfinite(v) for v in vals):
        raise GustError(
            f"--gust {text!r} is not finite; allowed: T0:DURATION:WX:WZ, four finite numbers"
        )
    try:
        return Gust(*vals)
    except GustError as exc:
        raise GustError(f"--gust {text!r}: {exc}") from None


def wind_at(gusts: Sequence[Gust], t_beats: float, speed_scale: float = 1.0) -> np.ndarray:
    """The summed gust wind at ``t_beats`` (world x, y, z; reduced: divided by
    ``speed_scale``)."""
    w = np.zeros(3)
    for g in gusts:
        if g.t0 <= t_beats < g.t0 + g.duration:
            w[0] += g.wx / speed_scale
            w[2] += g.wz / speed_scale
    return w


@dataclass(frozen=True)
class RefState:
    """A reference state (reduced units, x forward, z up): PathState's fields."""

    x: float
    z: float
    vx: float
    vz: float
    ax: float
    az: float


class DemandSchedule:
    """A force-keyframe manoeuvre (birdsim.flight.manoeuvre.Manoeuvre) as an open-loop
    reference: demands Fx, Fz, V straight from the keyframes (table units); the
    reference path is x = integral of V, z = the keyframes' height."""

    open_loop_demands = True

    def __init__(self, manoeuvre: Any, x0: float = 0.0):
        self.manoeuvre = manoeuvre
        self.name = manoeuvre.name
        self.duration_beats = float(manoeuvre.duration)
        self.x0 = x0
        self._grid = np.linspace(
            0.0, self.duration_beats * TWO_PI, max(2, int(self.duration_beats * 64) + 1)
        )
        v = manoeuvre.demands(self._grid / TWO_PI)["V"]
        dx = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(self._grid))])
        self._x = dx

    def demands(self, t: float) -> tuple[float, float, float]:
        d = self.manoeuvre.demands(t / TWO_PI)
        return float(d["Fx"]), float(d["Fz"]), float(d["V"])

    def state(self, t: float) -> RefState:
        d = self.manoeuvre.demands(np.array([t, t + 1e-3]) / TWO_PI)
        x = (
            self.x0
            + float(np.interp(t, self._grid, self._x))
            + max(0.0, t - self._grid[-1]) * float(d["V"][0])
        )
        vz = (float(d["z"][1]) - float(d["z"][0])) / 1e-3
        return RefState(x, float(d["z"][0]), float(d["V"][0]), vz, 0.0, 0.0)


@dataclass
class FlightResult:
    """Per log sample arrays (reduced units) and what produced them."""

    arrays: dict[str, np.ndarray]
    bird: Bird
    model: str
    param_names: tuple[str, ...]
    gains: Gains
    open_loop: bool
    projection_max: float
    meta: dict[str, Any] = field(default_factory=dict)


def fly(
    reference: Any,
    table: Any,
    bird: Bird,
    model: str,
    *,
    beats: float | None = None,
    gusts: Sequence[Gust] = (),
    open_loop: bool = False,
    config: SimConfig = SimConfig(),
    gains: Gains | None = None,
    to_table: Any = None,
    aero: bool = True,
    gravity: bool = True,
    progress: Any = None,
    trim: bool = True,
) -> FlightResult:
    """Fly ``reference`` (a FlightPath in reduced units, or a DemandSchedule) with
    ``table`` for ``beats`` wingbeats (default: the reference's duration).

    Args:
        bird: the bird in its own units (the simulation uses its reduced bird).
        gusts: winds in the bird's velocity units, times in wingbeats.
        open_loop: feed-forward only (no feedback).
        progress: optional callable(beats_done) for a progress bar.
        trim: start on the periodic orbit of the first wingbeat (see :func:`_trim`).
    Returns:
        FlightResult with arrays t, x, y, z, vx, vz, x_ref, z_ref, pitch, <params>,
        Fx_demand, Fz_demand, climb_demand (the table's climb; 0 for a level table),
        V_air, saturated, pitch_moment, power, force_x, force_z,
        qpos, qvel (reduced units).
    Raises:
        BirdsimError: non-finite demands, a diverging simulation.
    """
    red = reduced_bird(bird)
    speed = scales(bird).speed
    beats = float(reference.duration_beats if beats is None else beats)
    if not (math.isfinite(beats) and beats > 0 and magnitude_ok(beats)):
        raise BirdsimError(
            f"beats={beats!r} is invalid; allowed: a positive finite number of wingbeats, {limits_text()}"
        )
    gains = gains or gains_for(red)
    demands_only = bool(getattr(reference, "open_loop_demands", False))
    ctl = Controller(
        table,
        red,
        gains,
        open_loop=open_loop or demands_only,
        to_table=to_table or _identity_if(demands_only),
    )
    names = ctl.names
    per_beat_ctl = config.control_per_beat
    steps_ctl = config.steps_per_beat // per_beat_ctl
    every = config.steps_per_beat // config.log_per_beat
    n_ctl = int(math.ceil(beats * per_beat_ctl - 1e-9))

    def command(t: float, est: Any, integral: np.ndarray, pitch: float) -> Any:
        w = wind_at(gusts, t / TWO_PI, speed)
        if demands_only:
            fx, fz, v = reference.demands(t)
            return ctl.lookup_table_force(fx, fz, v - float(w[0]))
        return ctl.command(reference.state(t), est, integral, pitch, (float(w[0]), float(w[2])))

    ref0 = reference.state(0.0)
    pitch0 = 0.0
    cmd = command(0.0, None, np.zeros(2), pitch0)
    if "pitch" in names:
        cmd = command(0.0, None, np.zeros(2), float(cmd.params[names.index("pitch")]))
    window = ErrorWindow(config.log_per_beat, TWO_PI)
    rows: dict[str, list] = {
        k: []
        for k in (
            "Fx_demand",
            "Fz_demand",
            "climb_demand",
            "V_air",
            "saturated",
            "x_ref",
            "z_ref",
            "params",
            "pitch",
        )
    }
    record: list = []
    with FreeBird(model, bird, cmd.params, config=config, aero=aero, gravity=gravity) as fb:
        h = fb.h
        times = np.arange(steps_ctl) * h
        pres = fb.schedule.prescribe(
            times[:1], cmd.params[None, :], np.zeros((1, len(names))), np.zeros((1, len(names)))
        )
        pos0, vel0 = np.array([ref0.x, 0.0, ref0.z]), np.array([ref0.vx, 0.0, ref0.vz])
        integral = np.zeros(2)
        if trim:
            if not ctl.open_loop and gains.ki > 0:
                # the wingbeat's real mean force differs a little from the table's (the body
                # bobs, the wings weigh): start the integral where it cancels that difference
                *_, bias = _trim(fb, reference, cmd.params, pos0, vel0, config, every)
                limit = INTEGRAL_LIMIT * red.gravity / gains.ki if red.gravity > 0 else np.inf
                integral = np.clip(bias / gains.ki, -limit, limit)
                cmd = command(
                    0.0,
                    (np.zeros(2), np.zeros(2), ref0.vx),
                    integral,
                    float(cmd.params[names.index("pitch")]) if "pitch" in names else 0.0,
                )
                fb.schedule = WingbeatSchedule(
                    fb.m, fb.kin, fb.red, cmd.params, smoothing=config.smoothing_beats * TWO_PI
                )
            pos0, vel0, history, _ = _trim(fb, reference, cmd.params, pos0, vel0, config, every)
            for e_pos, e_vel, vx in history:  # the wingbeat before the start, on the orbit
                window.add(e_pos, e_vel, vx)
        fb.start(pos0, vel0, pres)
        dt_ctl = steps_ctl * h
        for k in range(n_ctl):
            t = fb.time
            pitch = (
                float(fb.schedule.filter.output[names.index("pitch")]) if "pitch" in names else 0.0
            )
            est = window.estimate() if window.ep else None
            cmd = command(t, est, integral, pitch)
            if (
                est is not None
                and not cmd.saturated
                and not ctl.open_loop
                and gains.ki > 0
                and np.max(np.abs(est[0])) < INTEGRAL_BAND
            ):
                # anti-windup: frozen while saturated or far off the path (a gust), and
                # bounded: the integral only trims the small mismatch between the table's
                # mean force and the flown one
                limit = INTEGRAL_LIMIT * red.gravity / gains.ki if red.gravity > 0 else np.inf
                integral = np.clip(integral + dt_ctl * est[0], -limit, limit)
            step_times = t + np.arange(steps_ctl) * h
            pres = fb.schedule.advance(cmd.params, step_times, t, dt_ctl)
            wind = wind_at(gusts, t / TWO_PI, speed)
            start = len(record)
            fb.step_many(pres, wind, record, every)
            new = record[start:]
            refs = sample_reference(reference, np.array([r[0] for r in new]))
            for j, rec in enumerate(new):
                qpos, qvel = rec[1], rec[2]
                window.add(
                    np.array([refs["x"][j] - qpos[0], refs["z"][j] - qpos[2]]),
                    np.array([refs["vx"][j] - qvel[0], refs["vz"][j] - qvel[2]]),
                    float(qvel[0]),
                )
                rows["V_air"].append(float(np.hypot(qvel[0] - wind[0], qvel[2] - wind[2])))
                rows["params"].append(pres.params[j * every])
                rows["pitch"].append(pres.pitch[j * every])
            n_new = len(new)
            rows["x_ref"].extend(refs["x"].tolist())
            rows["z_ref"].extend(refs["z"].tolist())
            rows["Fx_demand"].extend([cmd.Fx] * n_new)
            rows["Fz_demand"].extend([cmd.Fz] * n_new)
            rows["climb_demand"].extend([cmd.climb] * n_new)
            rows["saturated"].extend([cmd.saturated] * n_new)
            if progress is not None:
                progress((k + 1) / per_beat_ctl)
        projection = fb.projection_max
    keep = sum(
        1 for r in record if r[0] <= beats * TWO_PI + 1e-9
    )  # whole control intervals were flown
    record = record[:keep]
    rows = {k: v[:keep] for k, v in rows.items()}
    t = np.array([r[0] for r in record])
    qpos = np.array([r[1] for r in record])
    qvel = np.array([r[2] for r in record])
    force = np.array([r[4] for r in record])
    params = np.array(rows.pop("params"))
    arrays = {
        "t": t,
        "x": qpos[:, 0],
        "y": qpos[:, 1],
        "z": qpos[:, 2],
        "vx": qvel[:, 0],
        "vz": qvel[:, 2],
        **{k: np.asarray(v, dtype=bool if k == "saturated" else float) for k, v in rows.items()},
        **{n: params[:, i] for i, n in enumerate(names)},
        "pitch_moment": np.array([r[3] for r in record]),
        "power": np.array([r[5] for r in record]),
        "force_x": force[:, 0],
        "force_z": force[:, 2],
        "qpos": qpos,
        "qvel": qvel,
    }
    return FlightResult(arrays, bird, model, names, gains, open_loop or demands_only, projection)


def sample_reference(reference: Any, t: np.ndarray) -> dict[str, np.ndarray]:
    """x, z, vx, vz, ax, az of ``reference`` at reduced times ``t`` (vectorised when the
    reference has ``sample``, as FlightPath does)."""
    t = np.asarray(t, dtype=float)
    fn = getattr(reference, "sample", None)
    if fn is not None:
        s = fn(t)
        return {
            k: np.broadcast_to(np.asarray(s[k], dtype=float), t.shape)
            for k in ("x", "z", "vx", "vz", "ax", "az")
        }
    states = [reference.state(float(ti)) for ti in t]
    return {
        k: np.array([getattr(st, k) for st in states], dtype=float)
        for k in ("x", "z", "vx", "vz", "ax", "az")
    }


def _trim(
    fb: FreeBird,
    reference: Any,
    params: np.ndarray,
    pos0: np.ndarray,
    vel0: np.ndarray,
    config: SimConfig,
    every: int,
) -> tuple[np.ndarray, np.ndarray, list, np.ndarray]:
    """The start state whose first wingbeat (at the starting wingbeat, no feedback)
    has the reference's mean velocity and mean position.

    A wingbeat's force oscillates; started at a phase where it is not at its mean, the
    body would carry a velocity offset of the oscillation's integral for ever.  One probe
    wingbeat measures the mean velocity and position errors; the start is moved by them
    (exact for the oscillating part, which does not depend on the start state to first
    order).  The filter is in steady state, so the probe leaves the schedule unchanged.
    Returns the start position and velocity and the error samples (x, z) of the
    corrected probe, the wingbeat "before" the start for the controller's window, and
    the wingbeat-mean acceleration the reference asks for minus the one flown (x, z).
    """
    n = config.steps_per_beat
    h = fb.h
    times = np.arange(n) * h
    pres = fb.schedule.advance(params, times, 0.0, n * h)
    fb.start(pos0, vel0, pres)
    rec: list = []
    p_start = fb.P.copy()
    fb.step_many(pres, np.zeros(3), rec, every)
    a_flown = (fb.P - p_start) / (fb.total_mass * n * h)
    t = np.array([r[0] for r in rec])
    pos = np.array([r[1][:3] for r in rec])
    vel = np.array([r[2][:3] for r in rec])
    ref = sample_reference(reference, t)
    zero = np.zeros_like(t)
    ref_pos = np.stack([ref["x"], zero, ref["z"]], axis=1)
    ref_vel = np.stack([ref["vx"], zero, ref["vz"]], axis=1)
    dv = (vel - ref_vel).mean(axis=0)
    # with the start velocity lowered by dv, the positions lose dv * t
    dx = (pos - ref_pos - dv[None, :] * t[:, None]).mean(axis=0)
    dv[1] = dx[1] = 0.0
    fb.time = 0.0
    fb.projection_max = 0.0
    e_pos = ref_pos - (pos - dx[None, :] - dv[None, :] * t[:, None])
    e_vel = ref_vel - (vel - dv[None, :])
    history = [
        (e_pos[k, [0, 2]], e_vel[k, [0, 2]], float(vel[k, 0] - dv[0])) for k in range(len(t))
    ]
    a_ref = np.array([ref["ax"].mean(), ref["az"].mean()])
    return pos0 - dx, vel0 - dv, history, a_ref - a_flown[[0, 2]]


def _identity_if(flag: bool) -> Any:
    return (lambda *a, **k: (0.0, 0.0)) if flag else None


__all__ = [
    "DemandSchedule",
    "FlightResult",
    "Gust",
    "GustError",
    "RefState",
    "fly",
    "sample_reference",
    "parse_gust",
    "wind_at",
]
