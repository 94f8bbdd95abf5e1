"""Playback: a manoeuvre's demands + a lookup table -> joint angles and rates over time.

The chain, per instant ``t``:

1. demands Fx, Fz, V (and the prescribed height z) from the manoeuvre (C1 in time);
2. clipped to the table's grid (reported in :attr:`Playback.clipped`), looked up;
3. the wingbeat parameters are smoothed by two cascaded first-order low-pass filters
   (time constant ``smoothing_beats`` each; the output of a step is C1 and never
   leaves the range of its input, so parameters stay inside their bounds) and
   represented by cubic splines p(t), with exact derivatives p'(t);
4. the wingbeat phase is the integral of omega over time (omega = the bird's, the one
   the table was built for): ``phi(t) = omega t``, continuous whatever the demands do;
5. each joint follows the model's own sinusoid mapping
   (:meth:`KinematicModel.joint_motion`), now with slowly varying coefficients:
   ``q = a(t) sin(phi + c(t)) + b(t)`` and
   ``q' = a' sin(.) + a (omega + c') cos(.) + b'`` -- so with constant parameters the
   playback equals the analytic wingbeat of :mod:`birdsim.physics.cycle`, and rates are the
   exact time derivative of the angles;
6. body pitch = the table's ``pitch`` parameter (smoothed likewise), the body moves
   forward at the (table-clipped) V, ``x = integral of V dt``, and at the prescribed
   height z(t) (vertical velocity is neglected in the force balance, as in the
   dissertation's landing, sec. 4.2.3 footnote 26).

Times: ``t_beats`` in wingbeats, ``time`` in the bird's non-dimensional time
(``time = t_beats * 2 pi / omega``); rates are per unit of ``time``.  Positions are in
seed earth axes (X forward, Y right, Z down), semispans.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.signal import lfilter

from birdsim.errors import BirdsimError
from birdsim.flight.manoeuvre import DEMANDS, PERCH_HEIGHT, Manoeuvre
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import KinematicModel, get_model


class TableLike(Protocol):
    """What playback needs of a lookup table (birdsim.tables.lookup.LookupTable)."""

    model: str
    param_names: Sequence[str]
    axes: Any

    def lookup(
        self, *, Fx: Any, Fz: Any, V: Any, clip: bool = False
    ) -> Mapping[str, np.ndarray]: ...


class TableMismatchError(BirdsimError):
    """A table built for a different kinematic model."""


@dataclass(frozen=True)
class PlaybackConfig:
    """Smoothing and sampling of the parameter schedule."""

    smoothing_beats: float = 0.25  # time constant of each of the two cascaded filters
    samples_per_beat: int = 64  # grid on which demands are looked up and filtered

    def __post_init__(self) -> None:
        if not (math.isfinite(self.smoothing_beats) and self.smoothing_beats >= 0):
            raise BirdsimError(f"smoothing_beats={self.smoothing_beats!r}; allowed: a number >= 0")
        if not (isinstance(self.samples_per_beat, int) and self.samples_per_beat >= 4):
            raise BirdsimError(
                f"samples_per_beat={self.samples_per_beat!r}; allowed: an integer >= 4"
            )


@dataclass(frozen=True)
class Playback:
    """Everything the renderer needs at each requested instant (arrays over frames)."""

    model: KinematicModel
    bird: Bird
    manoeuvre: Manoeuvre
    t_beats: np.ndarray  # (F,)
    time: np.ndarray  # (F,) non-dimensional
    phase: np.ndarray  # (F,) wingbeat phase phi = integral of omega dt (rad)
    demand: dict[str, np.ndarray]  # requested Fx, Fz, V
    demand_used: dict[str, np.ndarray]  # clipped to the table's grid
    clipped: np.ndarray  # (F,) bool: a demand was outside the table
    params: dict[str, np.ndarray]  # smoothed wingbeat parameters
    param_rates: dict[str, np.ndarray]
    angles: dict[str, np.ndarray]  # joint name -> angle (rad) or slide (semispans)
    rates: dict[str, np.ndarray]  # per unit non-dimensional time
    pitch: np.ndarray  # body pitch theta, nose up (rad)
    pitch_rate: np.ndarray
    position_seed: np.ndarray  # (F, 3) body position, seed earth axes (X fwd, Y right, Z down)
    velocity_seed: np.ndarray  # (F, 3)
    regime: tuple[str, ...]
    status: tuple[str, ...]  # the table's cell status at the used demands
    clip_note: str = ""  # one line naming what was clipped, "" when nothing was
    axes: dict[str, np.ndarray] = field(default_factory=dict)

    @property
    def frames(self) -> int:
        return len(self.t_beats)

    def frame(self, i: int) -> dict[str, Any]:
        """The state of frame ``i`` as plain floats (for the driver and the overlay)."""
        return {
            "angles": {k: float(v[i]) for k, v in self.angles.items()},
            "rates": {k: float(v[i]) for k, v in self.rates.items()},
            "pitch": float(self.pitch[i]),
            "pitch_rate": float(self.pitch_rate[i]),
            "position_seed": self.position_seed[i].copy(),
            "velocity_seed": self.velocity_seed[i].copy(),
        }


def table_axes(table: TableLike) -> dict[str, np.ndarray]:
    """The table's demand axes as {"Fx": ..., "Fz": ..., "V": ...} (mapping or (Fx, Fz, V))."""
    axes = table.axes
    if isinstance(axes, Mapping):
        return {k: np.asarray(axes[k], dtype=float) for k in DEMANDS}
    return {k: np.asarray(a, dtype=float) for k, a in zip(DEMANDS, axes)}


def lookup_params(table: TableLike, demands: Mapping[str, np.ndarray]) -> Mapping[str, np.ndarray]:
    """Vectorised lookup (``lookup_many`` when the table has it, else ``lookup``)."""
    fn = getattr(table, "lookup_many", None) or table.lookup
    return fn(Fx=demands["Fx"], Fz=demands["Fz"], V=demands["V"], clip=True)


def table_status(table: TableLike, demands: Mapping[str, np.ndarray]) -> tuple[str, ...]:
    """Per instant the table's cell status (``ok``, ``unreachable``, ``failed``), or all
    ``ok`` when the table does not record one."""
    fn = getattr(table, "status_at", None)
    n = len(demands["Fx"])
    if fn is None:
        return ("ok",) * n
    return tuple(
        str(fn(float(demands["Fx"][i]), float(demands["Fz"][i]), float(demands["V"][i]), clip=True))
        for i in range(n)
    )


def check_table_model(table: TableLike, model: str | None, arg: str = "--table") -> KinematicModel:
    """The table's model; one clear line when it is not ``model``."""
    if model is not None and table.model != model:
        get_model(model)  # unknown model -> its own message
        raise TableMismatchError(
            f"{arg} was built for model {table.model!r}, not {model!r}; allowed: a table built for {model} "
            f"(e.g. tables/{model}.npz)"
        )
    return get_model(table.model)


def play(
    manoeuvre: Manoeuvre,
    table: TableLike,
    t_beats: np.ndarray | Sequence[float],
    *,
    bird: Bird | None = None,
    model: str | None = None,
    perch_seed: tuple[float, float] = (0.0, -PERCH_HEIGHT),
    config: PlaybackConfig = PlaybackConfig(),
) -> Playback:
    """Play ``manoeuvre`` with ``table`` at the instants ``t_beats`` (wingbeats).

    ``perch_seed``: (X, Z) seed-axes position of the body when perched; a manoeuvre
    that starts (ends) on the perch is shifted so that its first (last) keyframe is
    there.  Other manoeuvres keep their heights and are centred on X = 0 (over the
    manoeuvre's duration).
    """
    kin = check_table_model(table, model)
    bird = bird or Bird()
    t_out = np.asarray(t_beats, dtype=float)
    if t_out.ndim != 1 or not np.all(np.isfinite(t_out)):
        raise BirdsimError("t_beats must be a 1-D array of finite times (wingbeats)")
    period = bird.period
    axes = table_axes(table)

    # 1-2. demands on a fine grid, clipped to the table and looked up
    t_end = max(float(manoeuvre.duration), float(t_out.max(initial=0.0)), manoeuvre.keyframes[-1].t)
    t_start = min(0.0, float(t_out.min(initial=0.0)))
    # a fixed spacing from t = 0, so that any set of requested instants sees the same
    # filtered schedule (a frame and the sub-frame instants of its pathline agree)
    h = 1.0 / config.samples_per_beat
    grid = np.arange(math.floor(t_start / h) - 1, math.ceil(t_end / h) + 2) * h
    n = len(grid)
    dem = manoeuvre.demands(grid)
    used = {k: np.clip(dem[k], axes[k].min(), axes[k].max()) for k in DEMANDS}
    raw = lookup_params(table, used)
    names = kin.param_names
    missing = [p for p in names if p not in raw]
    if missing:
        raise TableMismatchError(
            f"--table lacks parameter {missing[0]!r} of model {kin.name}; allowed: a table for {kin.name}"
        )
    P = np.stack([np.asarray(raw[p], dtype=float).reshape(n) for p in names], axis=1)  # (n, nP)
    if not np.all(np.isfinite(P)):
        bad = int(np.argmax(~np.all(np.isfinite(P), axis=1)))
        raise BirdsimError(
            f"--table has no solution at Fx={used['Fx'][bad]:g}, Fz={used['Fz'][bad]:g}, V={used['V'][bad]:g} "
            f"(t={grid[bad]:.2f} beats); allowed: demands inside the table's solved region"
        )

    # 3. smoothing: two cascaded first-order filters, started in steady state
    if config.smoothing_beats > 0:
        dt = (grid[1] - grid[0]) if n > 1 else 1.0
        alpha = 1.0 - math.exp(-dt / config.smoothing_beats)
        for _ in range(2):
            zi = (1.0 - alpha) * P[:1]
            P, _zf = lfilter([alpha], [1.0, alpha - 1.0], P, axis=0, zi=zi)
    time_grid = grid * period
    spline = CubicSpline(time_grid, P, axis=0)
    time = t_out * period
    p_now = spline(time)
    p_dot = spline(time, 1)
    params = {name: p_now[:, i] for i, name in enumerate(names)}
    param_rates = {name: p_dot[:, i] for i, name in enumerate(names)}

    # 4-5. integrated phase and joint sinusoids with time-varying coefficients
    omega = bird.omega
    phase = omega * time  # = integral of omega dt (omega is the bird's, constant)
    angles, rates = joint_series(kin, bird, params, param_rates, phase, omega)

    # 6. body path: forward at the table's V, prescribed height z (up)
    v_spline = CubicSpline(time_grid, used["V"])
    x_of = v_spline.antiderivative()
    z_spline = CubicSpline(time_grid, dem["z"])
    x = x_of(time) - x_of(0.0)
    z_up = z_spline(time)
    dz = z_spline(time, 1)
    x_perch, z_perch_seed = perch_seed
    dz_shift = (-z_perch_seed) - PERCH_HEIGHT
    if manoeuvre.perch == "end":
        x = x - (x_of(manoeuvre.keyframes[-1].t * period) - x_of(0.0)) + x_perch
    elif manoeuvre.perch == "start":
        x = x - (x_of(manoeuvre.keyframes[0].t * period) - x_of(0.0)) + x_perch
    if manoeuvre.perch:
        z_up = z_up + dz_shift
    else:  # no perch: the path is centred on X = 0 (it stays in the middle of the scene)
        span = x_of(manoeuvre.duration * period) - x_of(0.0)
        x = x - 0.5 * span
    pos = np.stack([x, np.zeros_like(x), -z_up], axis=1)
    vel = np.stack([v_spline(time), np.zeros_like(x), -dz], axis=1)

    dem_out = manoeuvre.demands(t_out)
    used_out = {k: np.clip(dem_out[k], axes[k].min(), axes[k].max()) for k in DEMANDS}
    clipped = np.zeros(len(t_out), dtype=bool)
    notes = []
    for k in DEMANDS:
        off = ~np.isclose(used_out[k], dem_out[k], rtol=0, atol=1e-12)
        clipped |= off
        if np.any(off):
            lo, hi = axes[k].min(), axes[k].max()
            worst = dem_out[k][off][np.argmax(np.abs(dem_out[k][off] - used_out[k][off]))]
            notes.append(f"{k}={worst:g} outside [{lo:g}, {hi:g}]")
    clip_note = ("demands clipped to the table's grid: " + "; ".join(notes)) if notes else ""
    return Playback(
        model=kin,
        bird=bird,
        manoeuvre=manoeuvre,
        t_beats=t_out,
        time=time,
        phase=phase,
        demand={k: dem_out[k] for k in DEMANDS},
        demand_used=used_out,
        clipped=clipped,
        params=params,
        param_rates=param_rates,
        angles=angles,
        rates=rates,
        pitch=params["pitch"],
        pitch_rate=param_rates["pitch"],
        position_seed=pos,
        velocity_seed=vel,
        regime=tuple(manoeuvre.regime(float(t)) for t in t_out),
        status=table_status(table, used_out),
        clip_note=clip_note,
        axes=axes,
    )


def joint_series(
    kin: KinematicModel,
    bird: Bird,
    params: Mapping[str, np.ndarray],
    param_rates: Mapping[str, np.ndarray],
    phase: np.ndarray,
    omega: float,
) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray]]:
    """Joint angles and their exact time derivatives for parameters p(t) with rates p'(t).

    The coefficients' rates come from a central difference of ``joint_motion`` along
    p'(t) (exact for the affine maps the models use, O(h^2) otherwise)."""
    angles, rates, _ = joint_derivatives(kin, bird, params, param_rates, None, phase, omega)
    return angles, rates


def joint_derivatives(
    kin: KinematicModel,
    bird: Bird,
    params: Mapping[str, np.ndarray],
    param_rates: Mapping[str, np.ndarray],
    param_accels: Mapping[str, np.ndarray] | None,
    phase: np.ndarray,
    omega: float,
) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray], dict[str, np.ndarray]]:
    """Joint angles, rates and (when ``param_accels`` p''(t) is given) accelerations of
    ``q = a(p) sin(phase + c(p)) + b(p)`` with ``phase' = omega``.

    Args:
        params, param_rates, param_accels: p(t), p'(t), p''(t) per parameter name (rad,
            per unit of the bird's time).
        phase: wingbeat phase (rad), the integral of omega.
    Returns:
        (angles, rates, accelerations) per joint name; accelerations are {} without
        ``param_accels``.  Coefficient derivatives are central differences of
        ``joint_motion`` along p' and p'' (exact for the affine maps the models use; the
        curvature term p'^T (d2 c/dp2) p' of a non-affine map is left out).
    """
    h = 1e-6
    motion = kin.joint_motion(params, bird)

    def along(
        direction: Mapping[str, np.ndarray],
    ) -> dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]]:
        plus = kin.joint_motion({k: params[k] + h * direction[k] for k in params}, bird)
        minus = kin.joint_motion({k: params[k] - h * direction[k] for k in params}, bird)
        return {
            name: tuple(
                _difference(getattr(plus[name], f), getattr(minus[name], f), 2 * h, shape)
                for f in ("amp", "phase", "bias")
            )
            for name in motion
        }

    shape = np.shape(phase)
    first = along(param_rates)
    second = along(param_accels) if param_accels is not None else None
    angles, rates, accels = {}, {}, {}
    for name, s in motion.items():
        a, c, b = (_shaped(np.asarray(v, dtype=float), shape) for v in (s.amp, s.phase, s.bias))
        da, dc, db = first[name]
        arg = phase + c
        sn, cs = np.sin(arg), np.cos(arg)
        angles[name] = a * sn + b
        rates[name] = da * sn + a * (omega + dc) * cs + db
        if second is not None:
            dda, ddc, ddb = second[name]
            w = omega + dc
            accels[name] = dda * sn + 2.0 * da * w * cs + a * ddc * cs - a * w * w * sn + ddb
    return angles, rates, accels


def _difference(a: object, b: object, step: float, shape: tuple[int, ...]) -> Any:
    """``(a - b) / step``: on Python floats when both are (a coefficient that does not
    depend on the parameters; the same IEEE arithmetic as numpy's), else on arrays."""
    if type(a) is float and type(b) is float:
        return (a - b) / step
    return _shaped((np.asarray(a, dtype=float) - np.asarray(b, dtype=float)) / step, shape)


def _shaped(x: np.ndarray, shape: tuple[int, ...]) -> np.ndarray:
    """``np.broadcast_to(x, shape)``, skipped when ``x`` has that shape already or is a
    number (every use is elementwise against the phase: the same numbers)."""
    return x if x.shape == shape or x.ndim == 0 else np.broadcast_to(x, shape)


def frame_times(seconds: float, fps: int, beats_per_second: float) -> np.ndarray:
    """Animation times (wingbeats) of the ``round(seconds * fps)`` video frames when the
    video shows ``beats_per_second`` wingbeats per second."""
    frames = max(1, int(round(seconds * fps)))
    return np.arange(frames) * (beats_per_second / fps)


__all__ = [
    "Playback",
    "PlaybackConfig",
    "TableLike",
    "TableMismatchError",
    "check_table_model",
    "frame_times",
    "joint_derivatives",
    "joint_series",
    "play",
    "table_axes",
]
