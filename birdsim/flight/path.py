"""Manoeuvres as paths: where the bird should be, and when (issue 9 item 3; in 3-D: issue 23).

A :class:`FlightPath` is a list of keyframes in the bird's *reduced* units: positions in
semispans (x forward, y to the bird's LEFT at the start, z UP above the floor: the MuJoCo
world's axes), keyframe times in wingbeats, and :meth:`FlightPath.state` in reduced time
(``1 / omega``: one wingbeat = 2 pi) with velocities in ``omega s`` and accelerations in
``omega^2 s``. A keyframe gives either a position (``x``, ``z``, optional ``y``, default 0)
or a horizontal speed, a heading and a height (``V``, ``heading``, ``z``; then x and y are
the integral of ``V (cos heading, sin heading)`` from ``x0``, ``y0``). The heading is in
radians from +x towards +y (0 = straight ahead, pi / 2 = a quarter turn to the left); a
keyframe without one keeps the previous keyframe's (0 for the first).

Between keyframes each coordinate (x, y, z; or V, heading, z) is a quintic Hermite segment
with the keyframe's value, a slope and a zero second derivative at both ends -- a
minimum-jerk blend of the keyframes (:mod:`birdsim.flight.path_curves`). The path is
therefore C2 (position, velocity and acceleration continuous; with the speed form even
C3), passes through every keyframe exactly, and accelerations are defined everywhere,
which the inverse dynamics of :mod:`birdsim.flight.demand` needs. Slopes, unless a
keyframe gives them (``vx``, ``vy``, ``vz``; ``dV``, ``turn_rate`` in rad per reduced
time, so a turn of radius R at speed V has ``turn_rate = V / R``), are the harmonic mean
of the two neighbouring secants (zero at an extremum, at most twice the smaller secant:
monotone data stay monotone); at the first and last keyframe ``z``, ``V`` and the heading
are level (slope 0; a turn rate given there must be 0) and ``x``, ``y`` continue at their
secant (0 on a perch). Before the first and after the last keyframe the path continues at
constant velocity (zero acceleration, so still C2).

A path in the vertical plane (no y, no heading) is today's 2-D path bit for bit, with
``y = vy = ay = 0`` exactly. Obstacles: :mod:`birdsim.flight.path_checks`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.interpolate import PPoly

from birdsim.errors import limits_text, magnitude_ok
from birdsim.flight.fast_path import curve_values
from birdsim.flight.path_checks import (
    FLOOR_CLEARANCE,
    PERCH_KEEPOUT,
    PERCH_X,
    PERCH_Y,
    PERCH_Z,
    PathError,
    check_obstacles,
)
from birdsim.flight.path_curves import (
    HeadingTrack,
    eval_extrapolated,
    knot_slopes,
    quintic_hermite,
)
from birdsim.mujoco.perches import DEFAULT_SCENE, GROUND_REST_Z, Scene, check_scene

#: Longest path (wingbeats), as for force manoeuvres.
MAX_BEATS = 10000.0
TWO_PI = 2.0 * math.pi
#: The numbers of a keyframe (besides ``regime``), and which form uses which.
NUMBER_KEYS = ("t", "z", "x", "V", "vx", "vz", "dV", "y", "vy", "heading", "turn_rate")
POSITION_ONLY = ("x", "y", "vx", "vy")
SPEED_ONLY = ("V", "dV", "heading", "turn_rate")


@dataclass(frozen=True)
class PathState:
    """The path at one instant (reduced units, x forward, y left, z up): position [s],
    velocity [omega s], acceleration [omega^2 s]. The first six fields are the 2-D
    path's (positional order kept); y, vy, ay are 0 for a path in the vertical plane."""

    x: float
    z: float
    vx: float
    vz: float
    ax: float
    az: float
    y: float = 0.0
    vy: float = 0.0
    ay: float = 0.0


@dataclass(frozen=True)
class PathKeyframe:
    """One keyframe: time ``t`` [wingbeats]; ``x`` and optional ``y`` [s] (position form)
    or ``V`` [omega s, horizontal speed] and optional ``heading`` [rad, from +x towards
    +y; None = the previous keyframe's] (speed form); height ``z`` [s, up]; optional
    slopes ``vx`` / ``vy`` / ``vz`` [omega s] (position form) or ``dV`` [omega^2 s] and
    ``turn_rate`` [rad per reduced time] (speed form), None = automatic; ``regime``: a
    label for the overlay. Fields after ``regime`` are keyword-only in practice (3-D)."""

    t: float
    z: float
    x: float | None = None
    V: float | None = None
    vx: float | None = None
    vz: float | None = None
    dV: float | None = None
    regime: str = ""
    y: float | None = None
    vy: float | None = None
    heading: float | None = None
    turn_rate: float | None = None


@dataclass(frozen=True)
class FlightPath:
    """A manoeuvre as a path. ``duration_beats``: how long it is flown [wingbeats];
    ``perch_start`` / ``perch_end``: it starts / ends at rest on the perch (the first /
    last keyframe must then be the perched position, checked); ``x0``, ``y0``: the
    position at the first keyframe in the speed form [s] (ignored on a perch: a
    speed-form path starting or ending on a perch is placed so that it does on the
    scene's first perch; a start or end at rest on the ground keeps x0, y0);
    ``scene``: the perches (:mod:`birdsim.mujoco.perches`; default the presets' one);
    ``low_end``: the last segment may come down to the ground's rest height (a landing's
    hover over the ground before the touchdown, :mod:`birdsim.flight.perch_landing`)."""

    name: str
    duration_beats: float
    perch_start: bool
    perch_end: bool
    keyframes: tuple[PathKeyframe, ...]
    description: str = ""
    x0: float = 0.0
    y0: float = 0.0
    scene: Scene = DEFAULT_SCENE
    low_end: bool = False
    _x: PPoly = field(init=False, repr=False, compare=False)
    _y: PPoly | None = field(init=False, repr=False, compare=False)
    _z: PPoly = field(init=False, repr=False, compare=False)
    _track: HeadingTrack | None = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        _validate(self)
        ks = self.keyframes
        t = np.array([k.t for k in ks]) * TWO_PI
        z = np.array([k.z for k in ks])
        zs = knot_slopes(t, z, [k.vz for k in ks], ends="level")
        xp, yp, track = None, None, None
        if self.form == "position":
            ends = (
                "zero" if self.perch_start else "secant",
                "zero" if self.perch_end else "secant",
            )
            x = np.array([k.x for k in ks], dtype=float)
            xp = quintic_hermite(t, x, knot_slopes(t, x, [k.vx for k in ks], ends=ends))
            if self.is_3d:
                y = np.array([0.0 if k.y is None else k.y for k in ks])
                yp = quintic_hermite(t, y, knot_slopes(t, y, [k.vy for k in ks], ends=ends))
        else:
            v = np.array([k.V for k in ks], dtype=float)
            vp = quintic_hermite(t, v, knot_slopes(t, v, [k.dV for k in ks], ends="level"))
            if self.is_3d:
                psi = np.array(self.headings())
                rates = [k.turn_rate for k in ks]
                track = HeadingTrack(
                    vp, quintic_hermite(t, psi, knot_slopes(t, psi, rates, "level")), 0.0, 0.0
                )
                end = track.position(np.array([t[-1]]))
                start = self._start(float(end[0][0]), float(end[1][0]))
                track.cum_x += start[0]
                track.cum_y += start[1]
            else:
                xp = vp.antiderivative()  # x(t_first) = 0
                start = self._start(float(xp(t[-1])), 0.0)
                xp = PPoly(xp.c.copy(), xp.x, extrapolate=False)
                xp.c[-1, :] += start[0]
        object.__setattr__(self, "_x", xp)
        object.__setattr__(self, "_y", yp)
        object.__setattr__(self, "_z", quintic_hermite(t, z, zs))
        object.__setattr__(self, "_track", track)
        check_obstacles(self)

    def _start(self, x_end: float, y_end: float) -> tuple[float, float]:
        """The speed form's position at the first keyframe, given the end's from (0, 0):
        on the scene's first perch at a perched start (or end), else (x0, y0)."""
        ks, ground = self.keyframes, GROUND_REST_Z
        first = self.scene.perches[0] if self.scene.perches else None
        if first is None:
            return self.x0, self.y0
        if self.perch_start and ks[0].z != ground:
            return first.x, first.y
        if self.perch_end and not self.perch_start and ks[-1].z != ground:
            return first.x - x_end, first.y - y_end
        return self.x0, self.y0

    @property
    def form(self) -> str:
        """``position`` (keyframes give x) or ``speed`` (keyframes give V)."""
        return "position" if self.keyframes[0].x is not None else "speed"

    @property
    def is_3d(self) -> bool:
        """Whether the path leaves the vertical plane y = 0 (a y, vy, heading, turn rate or
        y0 that is not 0)."""
        keys = ("y", "vy") if self.form == "position" else ("heading", "turn_rate")
        return bool(self.form == "speed" and self.y0) or any(
            getattr(k, key) for k in self.keyframes for key in keys
        )

    def headings(self) -> list[float]:
        """The heading of every keyframe [rad] (a missing one keeps the previous; 0 first)."""
        out, last = [], 0.0
        for k in self.keyframes:
            last = float(k.heading) if k.heading is not None else last
            out.append(last)
        return out

    @property
    def duration(self) -> float:
        """The duration in reduced time (``2 pi duration_beats``)."""
        return TWO_PI * self.duration_beats

    def sample(self, t: Any) -> dict[str, np.ndarray]:
        """The path at reduced times ``t`` (array): dict of arrays x, z, vx, vz, ax, az
        (the 2-D path's keys first) and y, vy, ay (0 in the vertical plane)."""
        t = np.asarray(t, dtype=float)
        out: dict[str, np.ndarray] = {}
        fast = self._compiled(t)
        if fast is not None:  # the same numbers, compiled (birdsim.flight.fast_path)
            for keys, vals in zip(("x", "z", "y"), fast):
                for k, v in zip((keys, "v" + keys, "a" + keys), range(3)):
                    out[k] = np.zeros(t.shape) if vals is None else vals[v].reshape(t.shape)
            return out
        if self._track is not None:
            tr = self._track.sample(t)
            out.update(x=tr["x"], vx=tr["vx"], ax=tr["ax"])
        else:
            out["x"], out["vx"], out["ax"] = eval_extrapolated(self._x, t)
        out["z"], out["vz"], out["az"] = eval_extrapolated(self._z, t)
        if self._track is not None:
            out.update(y=tr["y"], vy=tr["vy"], ay=tr["ay"])
        elif self._y is not None:
            out["y"], out["vy"], out["ay"] = eval_extrapolated(self._y, t)
        else:
            out["y"], out["vy"], out["ay"] = (np.zeros(t.shape) for _ in range(3))
        return out

    def state(self, t: float) -> PathState:
        """The path at reduced time ``t`` (``1 / omega`` units; one wingbeat = 2 pi)."""
        fast = self._compiled(np.array([float(t)]))
        if fast is not None:
            (x, vx, ax), (z, vz, az) = fast[0][:, 0].tolist(), fast[1][:, 0].tolist()
            y, vy, ay = (0.0, 0.0, 0.0) if fast[2] is None else fast[2][:, 0].tolist()
            return PathState(x, z, vx, vz, ax, az, y, vy, ay)
        s = self.sample(float(t))
        return PathState(
            *(float(s[k]) for k in ("x", "z", "vx", "vz", "ax", "az", "y", "vy", "ay"))
        )

    def _compiled(self, t: np.ndarray) -> tuple | None:
        """(x, z, y or None) curves' (3, t.size) values at ``t`` by
        :func:`birdsim.flight.fast_path.curve_values` (scipy's numbers), or None where
        that does not apply (a speed-form path's track, numba missing)."""
        if self._track is not None:
            return None
        x, z = curve_values(self._x, t), curve_values(self._z, t)
        y = None if self._y is None else curve_values(self._y, t)
        if x is None or z is None or (self._y is not None and y is None):
            return None
        return x, z, y

    def regime(self, t_beats: float) -> str:
        """The label of the latest keyframe at or before ``t_beats`` (blank labels skipped)."""
        label = self.keyframes[0].regime
        for k in self.keyframes:
            if k.t <= t_beats + 1e-12 and k.regime:
                label = k.regime
        return label or self.name

    def keyframe_before(self, t_beats: float) -> int:
        """1-based index of the last keyframe at or before ``t_beats`` (1 before the first)."""
        ts = [k.t for k in self.keyframes]
        return max(1, int(np.searchsorted(ts, t_beats + 1e-12, side="right")))


def _validate(p: FlightPath) -> None:
    where = f"path {p.name!r}"
    check_scene(p.scene, where)
    if not p.keyframes:
        raise PathError(f"{where} has no keyframes; allowed: at least one [[keyframe]]")
    if not (
        isinstance(p.duration_beats, (int, float))
        and math.isfinite(p.duration_beats)
        and 0 < p.duration_beats <= MAX_BEATS
    ):
        raise PathError(
            f"{where}: duration={p.duration_beats!r}; allowed: a number of wingbeats in (0, "
            f"{MAX_BEATS:g}]"
        )
    for name in ("x0", "y0"):
        v = getattr(p, name)
        if not (_is_number(v) and magnitude_ok(v)):
            raise PathError(
                f"{where}: {name}={v!r} is invalid; allowed: a finite number, {limits_text()}"
            )
    forms = {k.x is not None for k in p.keyframes}
    if len(forms) != 1 or any((k.x is None) == (k.V is None) for k in p.keyframes):
        bad = next(
            i
            for i, k in enumerate(p.keyframes, 1)
            if (k.x is None) == (k.V is None) or (k.x is not None) != (p.keyframes[0].x is not None)
        )
        raise PathError(
            f"{where}: keyframe {bad} mixes or lacks x and V; allowed: every keyframe gives "
            "x (position) or every keyframe gives V (speed)"
        )
    for i, k in enumerate(p.keyframes, 1):
        for name in NUMBER_KEYS:
            v = getattr(k, name)
            if v is not None and not _is_number(v):
                unit = " of radians" if name == "heading" else ""
                raise PathError(
                    f"{where}: keyframe {i} {name}={v!r} is not a finite number; allowed: a "
                    f"finite number{unit}, {limits_text()}"
                )
            if v is not None and not magnitude_ok(v):
                raise PathError(
                    f"{where}: keyframe {i} {name}={v!r} is invalid; allowed: {limits_text()}"
                )
        if k.t < 0 or k.t > MAX_BEATS:
            raise PathError(
                f"{where}: keyframe {i} t={k.t:g}; allowed: 0 <= t <= {MAX_BEATS:g} wingbeats"
            )
        if k.V is not None and k.V < 0:
            raise PathError(
                f"{where}: keyframe {i} V={k.V:g} is negative; allowed: V >= 0 (the tables "
                "fly forward)"
            )
        foreign = SPEED_ONLY[1:] if p.form == "position" else POSITION_ONLY[1:]
        extra = [name for name in foreign if getattr(k, name) is not None]
        if extra:
            raise PathError(
                f"{where}: keyframe {i} gives {extra[0]}, which the {p.form} form does not "
                "use; allowed: vx, y, vy with x; dV, heading, turn_rate with V"
            )
    for i in (0, len(p.keyframes) - 1):
        rate = p.keyframes[i].turn_rate
        if rate is not None and rate != 0:
            raise PathError(
                f"{where}: keyframe {i + 1} turn_rate={rate:g} at an end of the path; allowed: "
                "turn_rate 0 (or none) at the first and last keyframe (the path continues "
                "straight outside its keyframes)"
            )
    ts = [k.t for k in p.keyframes]
    if any(b <= a for a, b in zip(ts, ts[1:])):
        raise PathError(
            f"{where}: keyframe times {ts} are not increasing; allowed: strictly increasing t"
        )
    if p.perch_start and ts[0] != 0:
        raise PathError(f"{where}: perch_start needs keyframe 1 at t=0; got t={ts[0]:g}")


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


__all__ = [
    "FLOOR_CLEARANCE",
    "FlightPath",
    "MAX_BEATS",
    "NUMBER_KEYS",
    "PERCH_KEEPOUT",
    "PERCH_X",
    "PERCH_Y",
    "PERCH_Z",
    "PathError",
    "PathKeyframe",
    "PathState",
    "check_obstacles",
    "knot_slopes",
    "quintic_hermite",
]
