"""Manoeuvres as paths: where the bird should be, and when (issue 9, item 3).

A :class:`FlightPath` is a list of keyframes in the sagittal plane, in the bird's
*reduced* units: positions in semispans (x forward, z UP above the floor, the MuJoCo
world's axes), keyframe times in wingbeats, and :meth:`FlightPath.state` in reduced time
(``1 / omega``: one wingbeat = 2 pi) with velocities in ``omega s`` and accelerations in
``omega^2 s``. A keyframe gives either a position (``x``, ``z``) or a horizontal speed and
a height (``V``, ``z``; then ``x`` is the integral of the speed from ``x0``).

Between keyframes each coordinate (x or V, and z) is a quintic Hermite segment with the
keyframe's value, a slope and a zero second derivative at both ends -- a minimum-jerk blend
of the keyframes. The path is therefore C2 (position, velocity and acceleration
continuous; with the speed form even C3), passes through every keyframe exactly, and
accelerations are defined everywhere, which the inverse dynamics of
:mod:`birdsim.flight.demand` needs. Slopes, unless a keyframe gives them (``vx``, ``vz``
or ``dV`` per wingbeat... see :func:`knot_slopes`), are the harmonic mean of the two
neighbouring secants (zero at an extremum, at most twice the smaller secant: monotone data
stay monotone); at the first and last keyframe ``z`` and ``V`` are level (slope 0) and
``x`` continues at its secant (0 on a perch). Before the first and after the last
keyframe the path continues at constant velocity (zero acceleration, so still C2).

Obstacles (one line naming the keyframe before the offending sample): the floor (the body
must stay :data:`FLOOR_CLEARANCE` semispans above it, a wing's length) and the perch (a
post at :data:`PERCH_X` whose top holds the body at :data:`PERCH_Z`; the body may not be
within :data:`PERCH_KEEPOUT` of the post horizontally below the perched height).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.interpolate import PPoly

from birdsim.errors import BirdsimError, limits_text, magnitude_ok

#: Where the torso origin sits when the bird is perched (semispans, x forward, z up):
#: the scene's perch post at x = 6 s, its top site at 1.54 s, plus the torso's half
#: height 0.13 s (birdsim/mujoco/model.py; ``test_path.py`` checks both against
#: ``render.renderer.perch_seed_position``).
PERCH_X = 6.0
PERCH_Z = 1.67
#: Horizontal distance from the perch post within which the body may not be below
#: ``PERCH_Z`` (the torso's half length 0.55 s), except at a perched end (semispans).
PERCH_KEEPOUT = 0.55
#: Lowest allowed height of the body above the floor (semispans): a wing's length, so a
#: wing flapped straight down does not reach the floor.
FLOOR_CLEARANCE = 1.0
#: Slack for touching the perch height (semispans).
PERCH_TOL = 0.02
#: Samples per wingbeat of the obstacle check.
CHECK_SAMPLES_PER_BEAT = 64
#: Longest path (wingbeats), as for force manoeuvres.
MAX_BEATS = 10000.0
TWO_PI = 2.0 * math.pi


class PathError(BirdsimError):
    """A flight path that cannot be flown (below the floor, through the perch, bad keyframes)."""


@dataclass(frozen=True)
class PathState:
    """The path at one instant (reduced units, x forward, z up): position [s], velocity
    [omega s], acceleration [omega^2 s]."""

    x: float
    z: float
    vx: float
    vz: float
    ax: float
    az: float


@dataclass(frozen=True)
class PathKeyframe:
    """One keyframe: time ``t`` [wingbeats]; ``x`` [s] (position form) or ``V``
    [omega s, horizontal speed] (speed form); height ``z`` [s, up]; optional slopes
    ``vx`` / ``vz`` [omega s] (position form) or ``dV`` [omega^2 s] (speed form), None =
    automatic; ``regime``: a label for the overlay."""

    t: float
    z: float
    x: float | None = None
    V: float | None = None
    vx: float | None = None
    vz: float | None = None
    dV: float | None = None
    regime: str = ""


@dataclass(frozen=True)
class FlightPath:
    """A manoeuvre as a path. ``duration_beats``: how long it is flown [wingbeats];
    ``perch_start`` / ``perch_end``: it starts / ends at rest on the perch (the first /
    last keyframe must then be the perched position, checked); ``x0``: x at the first
    keyframe in the speed form [s] (ignored on a perch: a speed-form path starting or
    ending on the perch is placed so that it does)."""

    name: str
    duration_beats: float
    perch_start: bool
    perch_end: bool
    keyframes: tuple[PathKeyframe, ...]
    description: str = ""
    x0: float = 0.0
    _x: PPoly = field(init=False, repr=False, compare=False)
    _z: PPoly = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        _validate(self)
        t = np.array([k.t for k in self.keyframes]) * TWO_PI
        z = np.array([k.z for k in self.keyframes])
        zs = knot_slopes(t, z, [k.vz for k in self.keyframes], ends="level")
        if self.form == "position":
            x = np.array([k.x for k in self.keyframes], dtype=float)
            ends = (
                "zero" if self.perch_start else "secant",
                "zero" if self.perch_end else "secant",
            )
            xs = knot_slopes(t, x, [k.vx for k in self.keyframes], ends=ends)
            xp = quintic_hermite(t, x, xs)
        else:
            v = np.array([k.V for k in self.keyframes], dtype=float)
            vs = knot_slopes(t, v, [k.dV for k in self.keyframes], ends="level")
            xp = quintic_hermite(t, v, vs).antiderivative()  # x(t_first) = 0
            if self.perch_start:
                start = PERCH_X
            elif self.perch_end:
                start = PERCH_X - float(xp(t[-1]))
            else:
                start = self.x0
            xp = PPoly(xp.c.copy(), xp.x, extrapolate=False)
            xp.c[-1, :] += start
        object.__setattr__(self, "_x", xp)
        object.__setattr__(self, "_z", quintic_hermite(t, z, zs))
        check_obstacles(self)

    @property
    def form(self) -> str:
        """``position`` (keyframes give x) or ``speed`` (keyframes give V)."""
        return "position" if self.keyframes[0].x is not None else "speed"

    @property
    def duration(self) -> float:
        """The duration in reduced time (``2 pi duration_beats``)."""
        return TWO_PI * self.duration_beats

    def sample(self, t: Any) -> dict[str, np.ndarray]:
        """The path at reduced times ``t`` (array): dict of arrays x, z, vx, vz, ax, az."""
        t = np.asarray(t, dtype=float)
        out = {}
        for name, pp in (("x", self._x), ("z", self._z)):
            out[name], out["v" + name], out["a" + name] = _eval_extrapolated(pp, t)
        return out

    def state(self, t: float) -> PathState:
        """The path at reduced time ``t`` (``1 / omega`` units; one wingbeat = 2 pi)."""
        s = self.sample(float(t))
        return PathState(*(float(s[k]) for k in ("x", "z", "vx", "vz", "ax", "az")))

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
    if not (isinstance(p.x0, (int, float)) and math.isfinite(p.x0) and magnitude_ok(p.x0)):
        raise PathError(
            f"{where}: x0={p.x0!r} is invalid; allowed: a finite number, {limits_text()}"
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
        for name in ("t", "z", "x", "V", "vx", "vz", "dV"):
            v = getattr(k, name)
            if v is not None and not (isinstance(v, (int, float)) and math.isfinite(v)):
                raise PathError(f"{where}: keyframe {i} {name}={v!r} is not a finite number")
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
        if (p.form == "position" and k.dV is not None) or (p.form == "speed" and k.vx is not None):
            raise PathError(
                f"{where}: keyframe {i} gives {'dV' if k.dV is not None else 'vx'}, which "
                f"the {p.form} form does not use; allowed: vx with x, dV with V"
            )
    ts = [k.t for k in p.keyframes]
    if any(b <= a for a, b in zip(ts, ts[1:])):
        raise PathError(
            f"{where}: keyframe times {ts} are not increasing; allowed: strictly increasing t"
        )
    if p.perch_start and ts[0] != 0:
        raise PathError(f"{where}: perch_start needs keyframe 1 at t=0; got t={ts[0]:g}")


def knot_slopes(
    t: np.ndarray, y: np.ndarray, given: list[float | None], ends: str | tuple[str, str] = "level"
) -> np.ndarray:
    """Slopes dy/dt at the knots: ``given`` where not None, else the harmonic mean of the
    neighbouring secants (0 at an extremum or flat data: at most twice the smaller secant,
    which keeps a quintic minimum-jerk segment monotone). End slopes: ``level`` / ``zero``
    = 0, ``secant`` = the adjacent segment's secant. One knot: slope 0 (or given).

    Args:
        t: knot times, increasing (n,).
        y: knot values (n,).
        given: per knot a slope or None (n,).
        ends: rule for the first and last knot (one string for both, or a pair).

    Returns:
        Slopes (n,).
    """
    n = len(t)
    first, last = (ends, ends) if isinstance(ends, str) else ends
    m = np.zeros(n)
    if n > 1:
        d = np.diff(y) / np.diff(t)
        for i in range(1, n - 1):
            a, b = d[i - 1], d[i]
            m[i] = 2.0 * a * b / (a + b) if a * b > 0 else 0.0
        m[0] = d[0] if first == "secant" else 0.0
        m[-1] = d[-1] if last == "secant" else 0.0
    for i, g in enumerate(given):
        if g is not None:
            m[i] = float(g)
    return m


def quintic_hermite(t: np.ndarray, y: np.ndarray, dy: np.ndarray) -> PPoly:
    """Piecewise quintic through ``(t, y)`` with slopes ``dy`` and zero second derivative
    at every knot (C2; a minimum-jerk blend). One knot gives a constant (a segment of
    length 1 is added so that PPoly has an interval). Not extrapolating: callers continue
    linearly outside (see :func:`_eval_extrapolated`)."""
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    dy = np.asarray(dy, dtype=float)
    if len(t) == 1:
        t = np.array([t[0], t[0] + 1.0])
        y = np.array([y[0], y[0] + dy[0]])
        dy = np.array([dy[0], dy[0]])
    n = len(t) - 1
    c = np.zeros((6, n))
    for i in range(n):
        h = t[i + 1] - t[i]
        y0, y1, v0, v1 = y[i], y[i + 1], dy[i] * h, dy[i + 1] * h  # in local s = (t - t_i) / h
        # p(s) = y0 + v0 s + a3 s^3 + a4 s^4 + a5 s^5 with p(1) = y1, p'(1) = v1, p''(1) = 0
        rhs = np.array([y1 - y0 - v0, v1 - v0, 0.0])
        a3, a4, a5 = np.linalg.solve(
            np.array([[1.0, 1.0, 1.0], [3.0, 4.0, 5.0], [6.0, 12.0, 20.0]]), rhs
        )
        coef_s = np.array([a5, a4, a3, 0.0, v0, y0])  # highest power first
        c[:, i] = coef_s / h ** np.arange(5, -1, -1)
    return PPoly(c, t, extrapolate=False)


def _eval_extrapolated(pp: PPoly, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Value, first and second derivative of ``pp`` at ``t``; outside the knots the
    curve continues on its end tangent (zero second derivative: the knots' own)."""
    t0, t1 = pp.x[0], pp.x[-1]
    tc = np.clip(t, t0, t1)
    y, v, a = pp(tc), pp(tc, 1), pp(tc, 2)
    a = np.where((t < t0) | (t > t1), 0.0, a)
    return y + v * (t - tc), v, a


def _where_bad(path: FlightPath, tb: np.ndarray, bad: np.ndarray) -> tuple[str, int]:
    """The place to fix and the sample to show: the first keyframe that is itself in the
    way (its own sample), else the segment (between two keyframes, before the first or
    after the last) where the path first is (the first offending sample)."""
    ks = path.keyframes
    for j, k in enumerate(ks, 1):
        i = int(np.searchsorted(tb, k.t - 1e-12))
        if i < len(tb) and abs(tb[i] - k.t) < 1e-9 and bad[i]:
            return f"keyframe {j} (t={k.t:g}) is", i
    i = int(np.argmax(bad))
    if tb[i] < ks[0].t:
        return f"the path before keyframe 1 (t={ks[0].t:g}) goes", i
    k = path.keyframe_before(tb[i])
    if k >= len(ks):
        return f"the path after keyframe {k} (t={ks[k - 1].t:g}) goes", i
    return (
        f"the segment from keyframe {k} (t={ks[k - 1].t:g}) to keyframe {k + 1} "
        f"(t={ks[k].t:g}) goes",
        i,
    )


def check_obstacles(path: FlightPath) -> None:
    """Refuse a path below the floor or through the perch, in one line naming the first
    keyframe that is itself in the way, else the segment where the path first is.

    Raises:
        PathError: the first sample closer to the floor than ``FLOOR_CLEARANCE`` or within
            ``PERCH_KEEPOUT`` of the perch post below the perched height.
    """
    n = max(2, int(math.ceil(path.duration_beats * CHECK_SAMPLES_PER_BEAT)) + 1)
    tb = np.linspace(0.0, path.duration_beats, n)
    tb = np.union1d(tb, [k.t for k in path.keyframes if k.t <= path.duration_beats])
    s = path.sample(tb * TWO_PI)
    low = s["z"] < FLOOR_CLEARANCE - 1e-9
    perch = (np.abs(s["x"] - PERCH_X) < PERCH_KEEPOUT) & (s["z"] < PERCH_Z - PERCH_TOL)
    for bad, what in (
        (low, f"below the floor clearance z >= {FLOOR_CLEARANCE:g} semispans"),
        (perch, f"through the perch (|x - {PERCH_X:g}| < {PERCH_KEEPOUT:g} below z = {PERCH_Z:g})"),
    ):
        if np.any(bad):
            place, i = _where_bad(path, tb, bad)
            raise PathError(
                f"path {path.name!r}: {place} {what}: at t={tb[i]:.3g} wingbeats "
                f"x={s['x'][i]:.3g}, z={s['z'][i]:.3g} semispans; allowed: a path above the "
                "floor and around the perch"
            )
    for flag, idx, label in (
        (path.perch_start, 0, "perch_start"),
        (path.perch_end, -1, "perch_end"),
    ):
        if flag:
            k = path.keyframes[idx]
            st = path.state(k.t * TWO_PI)
            if (
                abs(st.x - PERCH_X) > 1e-6
                or abs(st.z - PERCH_Z) > 1e-6
                or abs(st.vx) > 1e-9
                or abs(st.vz) > 1e-9
            ):
                num = 1 if idx == 0 else len(path.keyframes)
                raise PathError(
                    f"path {path.name!r}: {label} but keyframe {num} is at x={st.x:g}, "
                    f"z={st.z:g}, speed ({st.vx:g}, {st.vz:g}); "
                    f"allowed: at rest on the perch, x={PERCH_X:g}, z={PERCH_Z:g}"
                )


__all__ = [
    "FLOOR_CLEARANCE",
    "FlightPath",
    "PERCH_KEEPOUT",
    "PERCH_X",
    "PERCH_Z",
    "PathError",
    "PathKeyframe",
    "PathState",
    "check_obstacles",
    "knot_slopes",
    "quintic_hermite",
]
