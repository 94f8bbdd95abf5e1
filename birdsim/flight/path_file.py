"""Reading manoeuvre files: flight paths, and today's force-keyframe files as open-loop demands.

A manoeuvre TOML file is a *path* when its ``[[keyframe]]`` tables give positions or
speeds; it is a *force schedule* (:mod:`birdsim.flight.manoeuvre`, flown open loop) when
they give ``Fx``/``Fz`` or when it has a ``[demands]`` table -- every file written for
earlier versions keeps its meaning. A path file (times in wingbeats, lengths in semispans,
x forward, y to the bird's left at the start, z up, speeds in ``omega s``, headings in
radians from +x towards +y, turn rates in rad per reduced time, i.e. ``V / R``)::

    name = "hop"                 # optional (default: the file stem)
    description = ""             # optional
    duration = 12                # optional (default: last keyframe + 1), wingbeats
    perch = "start"              # "start", "end", "both" or "" (optional)
    x0 = 0.0                     # speed form only: x, y at the first keyframe (optional)
    y0 = 0.0
    [[perches]]                  # optional, any number (default: the presets' one perch,
    x = 6.0                      # x = 6, y = 0, height 1.5, radius 0.04); a rest end is
    y = 0.0                      # on one of them (z = height + radius + 0.13) or on the
    height = 1.5                 # ground (z = 0.13), found from its position
    radius = 0.04
    [[keyframe]]                 # position form: t, x, z (optional y, default 0) ...
    t = 0
    x = 6.0
    z = 1.67
    vx = 0.0                     # optional slopes (omega s): vx, vy, vz; default automatic
    regime = "take-off"          # optional overlay label
    [[keyframe]]                 # ... or speed form: t, V, z, optional heading (rad; a
                                 # missing one keeps the previous), dV, turn_rate, vz
"""

from __future__ import annotations

import math
import sys
from pathlib import Path
from typing import Any

from birdsim.errors import BirdsimError
from birdsim.flight.manoeuvre import (
    MAX_BEATS,
    Manoeuvre,
    ManoeuvreError,
    load_manoeuvre,
    read_manoeuvre_toml,
)
from birdsim.flight.path import FlightPath, PathError, PathKeyframe
from birdsim.flight.presets import PATH_PRESETS
from birdsim.mujoco.perches import DEFAULT_SCENE, Perch, Scene, SceneError, check_scene

PATH_KEYS = ("t", "x", "y", "V", "heading", "z", "vx", "vy", "vz", "dV", "turn_rate", "regime")
FORCE_KEYS = ("Fx", "Fz")


def get_flight(name_or_path: str, *, turning: bool = False) -> FlightPath | Manoeuvre:
    """A preset path by name, or a manoeuvre file (a path, or a force schedule).

    Args:
        name_or_path: a preset name or a .toml file.
        turning: accept a path that leaves the vertical plane (y, heading). Off until the
            bank-to-turn flight of issue 23 flies such paths: the commands that fly today
            refuse them in one line rather than fly them in the x-z plane.

    Raises:
        ManoeuvreError: unknown name, unreadable or invalid file, a 3-D path when
            ``turning`` is off (one line).
    """
    if name_or_path in PATH_PRESETS:
        return PATH_PRESETS[name_or_path]
    from birdsim.flight.turn_presets import TURN_PRESETS

    if name_or_path in TURN_PRESETS:
        if not turning:
            raise ManoeuvreError(
                f"manoeuvre {name_or_path!r} turns out of the vertical plane, which this "
                f"command cannot fly yet; allowed: {', '.join(PATH_PRESETS)} or a .toml file "
                "(birdsim fly flies the turning presets)"
            )
        return TURN_PRESETS[name_or_path]
    p = Path(name_or_path)
    names = (*PATH_PRESETS, *(TURN_PRESETS if turning else ()))
    if p.suffix.lower() == ".toml" and not p.exists() and not p.is_symlink():
        raise ManoeuvreError(
            f"manoeuvre file {str(p)!r} does not exist; allowed: {', '.join(names)} or a "
            "readable .toml file"
        )
    if p.suffix.lower() == ".toml" or p.exists():
        flight = load_flight(p)
        if not turning and isinstance(flight, FlightPath) and flight.is_3d:
            i, key = _turning_key(flight)
            raise ManoeuvreError(
                f"manoeuvre file {str(p)!r}: keyframe {i} gives {key}, a path that turns out "
                "of the vertical plane, which this command cannot fly yet; allowed: y, vy, "
                "heading, turn_rate, y0 all 0 (bank-to-turn flight: issue 23)"
            )
        return flight
    raise ManoeuvreError(
        f"manoeuvre {name_or_path!r} is unknown; allowed: {', '.join(names)} or a .toml file"
    )


def _turning_key(flight: FlightPath) -> tuple[int, str]:
    """The first keyframe (1-based) and key that take a path out of the vertical plane."""
    for i, k in enumerate(flight.keyframes, 1):
        for key in ("y", "vy", "heading", "turn_rate"):
            if getattr(k, key):
                return i, key
    return 1, "y0"


def load_flight(path: str | Path) -> FlightPath | Manoeuvre:
    """Read a manoeuvre file: a :class:`FlightPath`, or a force-keyframe :class:`Manoeuvre`.

    Raises:
        ManoeuvreError: the file is missing, not TOML, or invalid (one line naming the key).
        PathError: the path goes below the floor or through the perch (one line naming the
            keyframe).
    """
    p = Path(path)
    arg = f"manoeuvre file {str(p)!r}"
    data = read_manoeuvre_toml(p, PATH_PRESETS)
    rows = data.get("keyframe")
    if (
        "demands" in data
        or not isinstance(rows, list)
        or any(isinstance(r, dict) and any(k in r for k in FORCE_KEYS) for r in rows)
    ):
        return load_manoeuvre(p)
    return _path_from_dict(arg, p.stem, data)


def _path_from_dict(arg: str, stem: str, data: dict[str, Any]) -> FlightPath:
    known = {"name", "description", "duration", "perch", "x0", "y0", "keyframe", "perches"}
    unknown = sorted(set(data) - known)
    if unknown:
        raise ManoeuvreError(
            f"{arg}: key {unknown[0]!r} is unknown; allowed: {', '.join(sorted(known))}"
        )
    rows = data["keyframe"]
    if not rows:
        raise ManoeuvreError(
            f"{arg}: keyframe must be an array of tables ([[keyframe]]) with at least one entry"
        )
    keyframes = []
    for i, row in enumerate(rows, 1):
        where = f"{arg}: keyframe {i}"
        if not isinstance(row, dict):
            raise ManoeuvreError(f"{where} is not a table")
        bad = sorted(set(row) - set(PATH_KEYS))
        if bad:
            raise ManoeuvreError(
                f"{where}: key {bad[0]!r} is unknown; allowed: {', '.join(PATH_KEYS)} (or "
                "Fx, Fz, V for a force schedule)"
            )
        for key in ("t", "z"):
            if key not in row:
                raise ManoeuvreError(f"{where}: {key} is missing; required: t, z and one of x or V")
        vals = {
            k: _number(f"{where}: {k}", row[k], _ALLOWED.get(k, "a finite number"))
            for k in PATH_KEYS
            if k != "regime" and k in row
        }
        regime = row.get("regime", "")
        if not isinstance(regime, str):
            raise ManoeuvreError(f"{where}: regime={regime!r} is not a string; allowed: a label")
        keyframes.append(PathKeyframe(regime=regime, **vals))
    last = keyframes[-1].t
    duration = (
        _number(f"{arg}: duration", data["duration"])
        if "duration" in data
        else min(last + 1.0, MAX_BEATS)
    )
    name = data.get("name", stem)
    if not isinstance(name, str) or not name:
        raise ManoeuvreError(f"{arg}: name={name!r}; allowed: a non-empty string")
    perch = data.get("perch", "")
    if perch not in ("", "start", "end", "both"):
        raise ManoeuvreError(f"{arg}: perch={perch!r}; allowed: start, end, both or empty")
    x0, y0 = (_number(f"{arg}: {k}", data[k]) if k in data else 0.0 for k in ("x0", "y0"))
    description = data.get("description", "")
    scene = _scene(arg, data.get("perches", None))
    try:
        return FlightPath(
            name,
            duration,
            perch in ("start", "both"),
            perch in ("end", "both"),
            tuple(keyframes),
            str(description),
            x0,
            y0,
            scene,
        )
    except PathError as exc:
        raise PathError(f"{arg}: {str(exc)}") from None


def _scene(arg: str, rows: Any) -> Scene:
    """The file's ``[[perches]]`` (x, optional y, height, radius; semispans), or the
    presets' one perch when it lists none."""
    if rows is None:
        return DEFAULT_SCENE
    if not isinstance(rows, list) or not all(isinstance(r, dict) for r in rows):
        raise ManoeuvreError(f"{arg}: perches must be an array of tables ([[perches]])")
    perches = []
    for i, row in enumerate(rows, 1):
        where = f"{arg}: perch {i}"
        bad = sorted(set(row) - set(PERCH_KEYS))
        if bad:
            raise ManoeuvreError(
                f"{where}: key {bad[0]!r} is unknown; allowed: {', '.join(PERCH_KEYS)}"
            )
        if "x" not in row:
            raise ManoeuvreError(f"{where}: x is missing; required: x (y, height, radius optional)")
        perches.append(Perch(**{k: _number(f"{where}: {k}", v) for k, v in row.items()}))
    scene = Scene(tuple(perches))
    try:
        check_scene(scene, arg)
    except SceneError as exc:
        raise ManoeuvreError(str(exc)) from None
    return scene


#: The keys of a ``[[perches]]`` table (semispans).
PERCH_KEYS = ("x", "y", "height", "radius")

#: What a key allows, for its error line.
_ALLOWED = {
    "heading": "a finite number of radians (0 = +x, pi/2 = a quarter turn to the left)",
    "turn_rate": "a finite number of radians per reduced time (V / R for a turn of radius R)",
}


def _number(arg: str, raw: Any, allowed: str = "a finite number") -> float:
    if isinstance(raw, bool) or not isinstance(raw, (int, float)) or not math.isfinite(raw):
        raise ManoeuvreError(f"{arg}={raw!r} is not a finite number; allowed: {allowed}")
    return float(raw)


def attitude_for(flight: object, attitude: str | None, name: str, command: str = "fly") -> str:
    """The attitude to fly: the one asked for, else free for a path that turns out of
    the vertical plane (said on stderr in one line, ``birdsim COMMAND: ...``) and posed
    for any other.

    Raises:
        BirdsimError: ``--attitude posed`` with a turning path (a posed body cannot bank).
    """
    turning = bool(getattr(flight, "is_3d", False))
    if not turning:
        return attitude or "posed"
    if attitude == "posed":
        raise BirdsimError(
            f"--attitude posed cannot fly {name!r}, a path that turns out of the vertical "
            "plane (a posed body cannot bank); allowed: --attitude free (the default for it)"
        )
    if attitude is None:
        print(
            f"birdsim {command}: {name} turns out of the vertical plane: flying it with "
            "--attitude free (bank to turn)",
            file=sys.stderr,
        )
    return "free"


__all__ = ["attitude_for", "get_flight", "load_flight"]
