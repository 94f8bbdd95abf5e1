"""Manoeuvres: demand schedules Fx(t), Fz(t), V(t) and a flight path height z(t).

A manoeuvre is a list of keyframes.  Time is counted in **wingbeats** from the start
(one wingbeat = ``2 pi / omega`` of the bird's non-dimensional time), so a schedule
means the same for every bird.  Demands are the dissertation's force (right wing +
body drag, seed axes: Fz < 0 is up) and the flight speed V; between keyframes they
follow a monotone C1 cubic (PCHIP slopes, zero slope at the first and last keyframe: no
overshoot, no kinks), before the first
and after the last keyframe they hold.

The height ``z`` (up, semispans above the floor) is prescribed by the keyframes too
(the dissertation neglects vertical velocity in the force balance, sec. 4.2.3
footnote 26); horizontal motion is integrated from V by :mod:`birdsim.flight.playback`.

Presets (sec. 4.1 regimes): ``hover`` (V=0, Fx=0, Fz=-0.5), ``cruise`` (V=0.9, Fx=0,
Fz=-0.2), ``take-off`` (from the perch, V rising from 0 with Fx=0.5, Fz=-0.5, easing to
cruise) and ``landing`` (sec. 4.2.3: from cruise, rising negative Fx and Fz and falling
speed, to a perched landing).  User files are TOML; see :func:`load_manoeuvre` and
docs/rendering.md.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from scipy.interpolate import CubicHermiteSpline, PchipInterpolator

from birdsim.errors import BirdsimError, limits_text, magnitude_ok

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib


class ManoeuvreError(BirdsimError):
    """An unknown preset or a bad manoeuvre file."""


#: Height (semispans above the floor) of the perch top and of the default flight path.
PERCH_HEIGHT = 3.0
CRUISE_HEIGHT = 6.0

DEMANDS = ("Fx", "Fz", "V")

#: Longest manoeuvre (wingbeats): keyframe times and durations beyond it are refused
#: (playback samples the schedule 64 times per wingbeat; 1e9 beats would need 477 GiB).
MAX_BEATS = 10000.0


@dataclass(frozen=True)
class Keyframe:
    """Demands at time ``t`` (wingbeats).  ``z``: height of the body (semispans, up);
    ``regime``: a label for the overlay (hover, cruise, take-off, flare, perch...)."""

    t: float
    Fx: float
    Fz: float
    V: float
    z: float
    regime: str = ""


@dataclass(frozen=True)
class Manoeuvre:
    """A named demand schedule; ``perch``: "start" (take-off from the perch), "end"
    (land on it) or "" (no perch in the shot)."""

    name: str
    keyframes: tuple[Keyframe, ...]
    duration: float  # wingbeats
    description: str = ""
    perch: str = ""

    def __post_init__(self) -> None:
        if not self.keyframes:
            raise ManoeuvreError(
                f"manoeuvre {self.name!r} has no keyframes; allowed: at least one [[keyframe]]"
            )
        ts = [k.t for k in self.keyframes]
        if any(b <= a for a, b in zip(ts, ts[1:])):
            raise ManoeuvreError(
                f"manoeuvre {self.name!r}: keyframe times {ts} are not increasing; allowed: strictly increasing t"
            )
        if ts[-1] > MAX_BEATS:
            raise ManoeuvreError(
                f"manoeuvre {self.name!r}: keyframe t={ts[-1]:g}; allowed: t <= {MAX_BEATS:g} wingbeats"
            )
        if not (math.isfinite(self.duration) and 0 < self.duration <= MAX_BEATS):
            raise ManoeuvreError(
                f"manoeuvre {self.name!r}: duration={self.duration!r}; allowed: a number of wingbeats in (0, {MAX_BEATS:g}]"
            )
        if self.perch not in ("", "start", "end"):
            raise ManoeuvreError(
                f"manoeuvre {self.name!r}: perch={self.perch!r}; allowed: start, end or empty"
            )
        from birdsim.flight.path import (
            FLOOR_CLEARANCE,
        )  # one floor rule for paths and force keyframes

        for i, k in enumerate(self.keyframes):
            for field in ("t", "Fx", "Fz", "V", "z"):
                v = getattr(k, field)
                if not (math.isfinite(v) and magnitude_ok(v)):
                    raise ManoeuvreError(
                        f"manoeuvre {self.name!r}: keyframe {i + 1} {field}={v!r} is invalid; allowed: a finite number, {limits_text()}"
                    )
            if not (math.isfinite(k.z) and k.z >= FLOOR_CLEARANCE):
                raise ManoeuvreError(
                    f"manoeuvre {self.name!r}: keyframe {i + 1} (t={k.t:g}) has z={k.z:g}, below the floor; "
                    f"allowed: z >= {FLOOR_CLEARANCE:g} semispans (a wing's length above the ground)"
                )

    def demands(self, t_beats: np.ndarray | float) -> dict[str, np.ndarray]:
        """Fx, Fz, V and z at times ``t_beats`` (C1 in time, held outside the keyframes)."""
        t = np.asarray(t_beats, dtype=float)
        kt = np.array([k.t for k in self.keyframes])
        tc = np.clip(t, kt[0], kt[-1])
        out = {}
        for key in (*DEMANDS, "z"):
            vals = np.array([getattr(k, key) for k in self.keyframes])
            out[key] = np.full(t.shape, vals[0]) if len(kt) == 1 else _hermite(kt, vals)(tc)
        return out

    def regime(self, t_beats: float) -> str:
        """The label of the latest keyframe at or before ``t_beats`` (blank labels skipped)."""
        label = self.keyframes[0].regime
        for k in self.keyframes:
            if k.t <= t_beats + 1e-12 and k.regime:
                label = k.regime
        return label or self.name

    def with_duration(self, beats: float) -> "Manoeuvre":
        return Manoeuvre(self.name, self.keyframes, beats, self.description, self.perch)


def _hermite(t: np.ndarray, y: np.ndarray) -> CubicHermiteSpline:
    """PCHIP slopes inside, zero slope at the first and last keyframe: monotone data stay
    monotone (Fritsch-Carlson allows zero slopes) and holding beyond the ends is C1."""
    slopes = PchipInterpolator(t, y).derivative()(t)
    slopes[0] = slopes[-1] = 0.0
    return CubicHermiteSpline(t, y, slopes)


def _kf(t: float, Fx: float, Fz: float, V: float, z: float, regime: str = "") -> Keyframe:
    return Keyframe(float(t), float(Fx), float(Fz), float(V), float(z), regime)


PRESETS: dict[str, Manoeuvre] = {
    m.name: m
    for m in (
        Manoeuvre(
            "hover",
            (_kf(0, 0.0, -0.5, 0.0, CRUISE_HEIGHT, "hover"),),
            6.0,
            "hover in place: V=0, Fx=0, Fz=-0.5 (sec. 4.1)",
        ),
        Manoeuvre(
            "cruise",
            (_kf(0, 0.0, -0.2, 0.9, CRUISE_HEIGHT, "cruise"),),
            8.0,
            "level cruise: V=0.9, Fx=0, Fz=-0.2 (sec. 4.1)",
        ),
        Manoeuvre(
            "take-off",
            (
                _kf(0, 0.5, -0.5, 0.0, PERCH_HEIGHT, "take-off"),
                _kf(1, 0.5, -0.5, 0.0, PERCH_HEIGHT + 0.5),  # a hop clear of the perch
                _kf(4, 0.5, -0.5, 0.4, PERCH_HEIGHT + 1.8, "climb-out"),
                _kf(7, 0.2, -0.35, 0.75, CRUISE_HEIGHT - 0.3),
                _kf(9, 0.0, -0.2, 0.9, CRUISE_HEIGHT, "cruise"),
            ),
            10.0,
            "from the perch: V rising from 0 with Fx=0.5, Fz=-0.5, easing into cruise (sec. 4.1)",
            perch="start",
        ),
        Manoeuvre(
            "landing",
            (
                _kf(0, 0.0, -0.2, 0.9, CRUISE_HEIGHT, "cruise"),
                _kf(2, 0.0, -0.2, 0.9, CRUISE_HEIGHT),
                _kf(5, -0.2, -0.35, 0.55, CRUISE_HEIGHT - 1.2, "approach"),
                _kf(8, -0.5, -0.5, 0.15, PERCH_HEIGHT + 0.4, "flare"),
                _kf(9.5, -0.5, -0.5, 0.0, PERCH_HEIGHT, "perched"),
            ),
            10.5,
            "from cruise to a perched landing: rising negative Fx and Fz, falling speed (sec. 4.2.3)",
            perch="end",
        ),
    )
}


def get_manoeuvre(name_or_path: str) -> Manoeuvre:
    """A preset by name, or a TOML manoeuvre file; one clear line otherwise."""
    if name_or_path in PRESETS:
        return PRESETS[name_or_path]
    p = Path(name_or_path)
    if p.suffix.lower() == ".toml" or p.exists():
        return load_manoeuvre(p)
    raise ManoeuvreError(
        f"manoeuvre {name_or_path!r} is unknown; allowed: {', '.join(PRESETS)} or a .toml file"
    )


def read_manoeuvre_toml(p: Path, presets: Any) -> dict[str, Any]:
    """The TOML of a manoeuvre or path file ``p``; a missing, unreadable or non-TOML file
    is one line naming it and what is allowed (``presets``: the names a source may be
    instead)."""
    arg = f"manoeuvre file {str(p)!r}"
    allowed = f"allowed: {', '.join(presets)} or a readable .toml file"
    try:
        return tomllib.loads(p.read_text())
    except FileNotFoundError:
        raise ManoeuvreError(f"{arg} does not exist; {allowed}") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise ManoeuvreError(f"{arg} cannot be read: {exc}; {allowed}") from None
    except tomllib.TOMLDecodeError as exc:
        raise ManoeuvreError(f"{arg} is not valid TOML ({exc}); {allowed}") from None


def load_manoeuvre(path: str | Path) -> Manoeuvre:
    """Read a manoeuvre TOML file.  Two forms (times in wingbeats)::

    name = "climb"                      # optional (default: file stem)
    duration = 8                        # optional (default: last keyframe + 1), <= MAX_BEATS
    perch = ""                          # "start", "end" or "" (optional)
    [[keyframe]]                        # one table per keyframe ...
    t = 0
    Fx = 0.0
    Fz = -0.2
    V = 0.9
    z = 6.0                             # optional, held from the previous keyframe
    regime = "cruise"                   # optional overlay label

    [demands]                           # ... or columns of equal length
    t = [0, 4, 8]
    Fx = [0, 0, 0]
    Fz = [-0.2, -0.4, -0.2]
    V = [0.9, 0.9, 0.9]
    """
    p = Path(path)
    arg = f"manoeuvre file {str(p)!r}"
    data = read_manoeuvre_toml(p, PRESETS)
    known = {"name", "description", "duration", "perch", "keyframe", "demands"}
    unknown = sorted(set(data) - known)
    if unknown:
        raise ManoeuvreError(
            f"{arg}: key {unknown[0]!r} is unknown; allowed: {', '.join(sorted(known))}"
        )
    if ("keyframe" in data) == ("demands" in data):
        raise ManoeuvreError(
            f"{arg}: has {'both [[keyframe]] tables and a [demands] table' if 'keyframe' in data else 'no [[keyframe]] table and no [demands] table'}; "
            "allowed: either [[keyframe]] tables or one [demands] table"
        )
    rows = data["keyframe"] if "keyframe" in data else _columns_to_rows(arg, data["demands"])
    if not isinstance(rows, list) or not rows:
        raise ManoeuvreError(
            f"{arg}: keyframe must be an array of tables ([[keyframe]]) with at least one entry"
        )
    keyframes = []
    z_prev = CRUISE_HEIGHT
    for i, row in enumerate(rows):
        where = f"{arg}: keyframe {i + 1}"
        if not isinstance(row, dict):
            raise ManoeuvreError(f"{where} is not a table")
        allowed = {"t", "Fx", "Fz", "V", "z", "regime"}
        bad = sorted(set(row) - allowed)
        if bad:
            raise ManoeuvreError(
                f"{where}: key {bad[0]!r} is unknown; allowed: {', '.join(sorted(allowed))}"
            )
        vals: dict[str, Any] = {}
        for key in ("t", "Fx", "Fz", "V"):
            if key not in row:
                raise ManoeuvreError(f"{where}: {key} is missing; required: t, Fx, Fz, V")
            vals[key] = _number(f"{where}: {key}", row[key])
        if vals["V"] < 0:
            raise ManoeuvreError(f"{where}: V={vals['V']:g} is negative; allowed: V >= 0")
        if vals["t"] < 0:
            raise ManoeuvreError(
                f"{where}: t={vals['t']:g} is negative; allowed: t >= 0 (wingbeats)"
            )
        z_prev = _number(f"{where}: z", row["z"]) if "z" in row else z_prev
        regime = row.get("regime", "")
        if not isinstance(regime, str):
            raise ManoeuvreError(f"{where}: regime={regime!r} is not a string")
        keyframes.append(Keyframe(vals["t"], vals["Fx"], vals["Fz"], vals["V"], z_prev, regime))
    last = keyframes[-1].t
    duration = (
        _number(f"{arg}: duration", data["duration"])
        if "duration" in data
        else min(last + 1.0, MAX_BEATS)
    )
    name = data.get("name", p.stem)
    if not isinstance(name, str) or not name:
        raise ManoeuvreError(f"{arg}: name={name!r}; allowed: a non-empty string")
    perch = data.get("perch", "")
    try:
        return Manoeuvre(
            name,
            tuple(keyframes),
            duration,
            str(data.get("description", "")),
            perch if isinstance(perch, str) else repr(perch),
        )
    except ManoeuvreError as exc:
        raise ManoeuvreError(f"{arg}: {str(exc).split(': ', 1)[-1]}") from None


def _columns_to_rows(arg: str, table: Any) -> list[dict[str, Any]]:
    if not isinstance(table, dict):
        raise ManoeuvreError(
            f"{arg}: demands must be a table of equal-length arrays t, Fx, Fz, V (z optional)"
        )
    scalars = [k for k, v in table.items() if not isinstance(v, list)]
    if scalars:
        raise ManoeuvreError(
            f"{arg}: [demands] {scalars[0]}={table[scalars[0]]!r} is not an array; allowed: arrays of one length, e.g. {scalars[0]} = [0, 1]"
        )
    lengths = {k: len(v) for k, v in table.items()}
    if set(lengths) != set(table) or len(set(lengths.values())) != 1:
        raise ManoeuvreError(
            f"{arg}: [demands] columns must be arrays of one length; got {lengths or table}"
        )
    n = next(iter(lengths.values()))
    return [{k: v[i] for k, v in table.items()} for i in range(n)]


def _number(arg: str, raw: Any) -> float:
    if isinstance(raw, bool) or not isinstance(raw, (int, float)) or not math.isfinite(raw):
        raise ManoeuvreError(f"{arg}={raw!r} is not a finite number")
    return float(raw)


__all__ = [
    "CRUISE_HEIGHT",
    "Keyframe",
    "MAX_BEATS",
    "Manoeuvre",
    "ManoeuvreError",
    "PERCH_HEIGHT",
    "PRESETS",
    "get_manoeuvre",
    "load_manoeuvre",
]
