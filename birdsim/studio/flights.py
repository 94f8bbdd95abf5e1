"""Flying for the view and the studio: the same code path as ``birdsim fly`` (the bird
and table loaders of :mod:`birdsim.commands.fly`, :func:`birdsim.flight.freeflight.fly`,
:func:`birdsim.flight.flightlog.log_arrays`), with the request checked for size first.

The only imports of command-module helpers in the studio are here (one place to follow
when they move).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

from birdsim.errors import BirdsimError

#: The longest flight the studio or the view flies (wingbeats): a few minutes of work.
MAX_STUDIO_BEATS = 400.0
#: The most keyframes and gusts a request may carry.
MAX_KEYFRAMES = 200
MAX_GUSTS = 50


@dataclass(frozen=True)
class FlightRequest:
    """One flight: ``source`` a preset name or a manoeuvre file (already checked to be
    inside the allowed folder), or a path given as ``path`` (the dict of a path TOML
    file); ``bird`` a bird file or None (the seed bird); gusts as T0:DURATION:WX:WZ."""

    source: str | None
    model: str | None = None
    bird: str | None = None
    path: dict[str, Any] | None = None
    gusts: Sequence[str] = field(default_factory=tuple)
    open_loop: bool = False
    seconds: float | None = None


def check_sizes(req: FlightRequest) -> None:
    """Refuse absurd sizes before any work (one line naming the field).

    Raises:
        BirdsimError: too many keyframes or gusts, or a duration beyond the limit.
    """
    if len(req.gusts) > MAX_GUSTS:
        raise BirdsimError(f"gusts: {len(req.gusts)} given; allowed: at most {MAX_GUSTS}")
    if req.path is not None:
        rows = req.path.get("keyframe", [])
        if not isinstance(rows, list) or len(rows) > MAX_KEYFRAMES:
            n = len(rows) if isinstance(rows, list) else rows
            raise BirdsimError(f"keyframes: {n} given; allowed: a list of 1 to {MAX_KEYFRAMES}")
        dur = req.path.get("duration")
        if isinstance(dur, (int, float)) and not (
            math.isfinite(dur) and 0 < dur <= MAX_STUDIO_BEATS
        ):
            raise BirdsimError(
                f"duration={dur!r} wingbeats; allowed: more than 0 and at most {MAX_STUDIO_BEATS:g}"
            )
    if req.seconds is not None and not (math.isfinite(req.seconds) and req.seconds > 0):
        raise BirdsimError(f"seconds={req.seconds!r}; allowed: a finite time > 0")


def load_path(data: dict[str, Any], name: str = "studio-path"):
    """A path from the dict of a path file (the table the page edits), read by the same
    reader as a manoeuvre file (:func:`birdsim.flight.path_file.load_flight`)."""
    import tempfile
    from pathlib import Path

    import tomli_w

    from birdsim.flight.path_file import load_flight

    try:
        text = tomli_w.dumps(data)
    except (TypeError, ValueError) as exc:
        raise BirdsimError(f"path: not a table of keyframes ({exc})") from None
    with tempfile.TemporaryDirectory() as tmp:
        p = Path(tmp) / f"{name}.toml"
        p.write_text(text)
        try:
            return load_flight(p)
        except BirdsimError as exc:
            raise BirdsimError(str(exc).replace(repr(str(p)), "(the page's path)")) from None


def path_dict(flight: Any) -> dict[str, Any] | None:
    """A path (FlightPath) as the dict of a path file (None for a force schedule)."""
    from birdsim.flight.path import FlightPath

    if not isinstance(flight, FlightPath):
        return None
    rows = []
    for k in flight.keyframes:
        row = {"t": k.t, "z": k.z}
        for key in ("x", "y", "V", "heading", "vx", "vy", "vz", "dV", "turn_rate"):
            v = getattr(k, key)
            if v is not None:
                row[key] = v
        if k.regime:
            row["regime"] = k.regime
        rows.append(row)
    perch = {(True, True): "both", (True, False): "start", (False, True): "end"}.get(
        (flight.perch_start, flight.perch_end), ""
    )
    out: dict[str, Any] = {"name": flight.name, "duration": flight.duration_beats}
    if perch:
        out["perch"] = perch
    if flight.x0:
        out["x0"] = flight.x0
    if flight.y0:
        out["y0"] = flight.y0
    out["keyframe"] = rows
    return out


def fly_request(
    req: FlightRequest, progress: Callable[[float], None] | None = None
) -> tuple[dict, dict]:
    """Fly ``req`` as ``birdsim fly`` does.

    Returns:
        (the flight log's arrays, with ``bird_obj``; the summary ``fly --json`` prints).

    Raises:
        BirdsimError: any bad input (one line), a flight beyond :data:`MAX_STUDIO_BEATS`.
    """
    from birdsim.commands.fly import load_bird, load_table_for
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.flock import is_flock
    from birdsim.flight.freeflight import DemandSchedule, fly, parse_gust
    from birdsim.flight.manoeuvre import Manoeuvre
    from birdsim.flight.path_file import get_flight
    from birdsim.flight.presets import DEMO_MODEL
    from birdsim.flight.simulate import SimConfig
    from birdsim.physics.kinematics import get_model

    check_sizes(req)
    if req.path is None and is_flock(str(req.source)):
        from birdsim.studio.flock_flights import fly_flock_request

        return fly_flock_request(req, MAX_STUDIO_BEATS, progress)
    flight = (
        load_path(req.path) if req.path is not None else get_flight(str(req.source), turning=True)
    )
    # a path out of the vertical plane flies free (bank to turn), as `birdsim fly` chooses
    attitude = "free" if getattr(flight, "is_3d", False) else "posed"
    model = get_model(req.model or DEMO_MODEL).name
    gusts = [parse_gust(g) for g in req.gusts]
    bird = load_bird(req.bird)
    if bird.gravity <= 0:
        raise BirdsimError(
            f"bird {bird.name!r} has gravity={bird.gravity:g}; allowed: a bird file with gravity > 0 for free flight"
        )
    reference = DemandSchedule(flight) if isinstance(flight, Manoeuvre) else flight
    beats = (
        req.seconds / bird.period if req.seconds is not None else float(reference.duration_beats)
    )
    if beats > MAX_STUDIO_BEATS:
        raise BirdsimError(
            f"the flight is {beats:g} wingbeats; allowed: at most {MAX_STUDIO_BEATS:g} wingbeats here (birdsim fly flies longer ones)"
        )
    table = load_table_for(bird, model, None)
    result = fly(
        reference,
        table,
        bird,
        model,
        beats=beats,
        gusts=gusts,
        open_loop=req.open_loop,
        progress=progress,
        config=SimConfig(attitude=attitude),
    )
    log = log_arrays(result, reference.name)
    phases = flight.regime if isinstance(flight, Manoeuvre) else getattr(reference, "regime", None)
    from birdsim.flight.summary_units import with_units

    info = with_units(summary(log, phases=phases), bird)
    log["bird_obj"] = bird
    return log, info


__all__ = [
    "MAX_GUSTS",
    "MAX_KEYFRAMES",
    "MAX_STUDIO_BEATS",
    "FlightRequest",
    "check_sizes",
    "fly_request",
    "load_path",
    "path_dict",
]
