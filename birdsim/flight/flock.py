"""Flock files (issue 27, item 2): N birds by one leader path, at offsets or steered.

A flock file (TOML; lengths in the birds' own length unit, e.g. metres)::

    name = "flock"                # optional (default: the file stem)
    path = "cruise"               # the leader's path: a preset or a path .toml (relative
                                  # to the flock file); not perched (offsets would put a
                                  # bird inside the perch or the floor)
    model = "m3"                  # optional, as `birdsim fly --model`
    attitude = "posed"            # optional: posed or free (as `birdsim fly --attitude`)
    seconds = 10                  # optional: simulated time (default: the path's length)
    rule = "offsets"              # optional: offsets (default) or steer (Reynolds' rules,
                                  # the attitude free; birdsim.flight.steering)
    [steering]                    # optional: SteeringConfig's fields (rule steer)
    separation_radius = 2.5
    [[bird]]
    file = "../models/pigeon.toml"   # optional (default: the seed bird); relative to the file
    offset = [0.0, 0.0, 0.0]         # the bird's place by the leader's path: x forward, y
                                     # left, z up (along its track on a turning path)
    path = "my-path.toml"            # optional: the bird's own path instead of the
                                     # leader's (then shifted by its offset)
    [[bird]]
    ...

Rule "offsets": bird ``i`` flies its place by the leader's path (its start is the
path's start plus the offset); a bird with its own ``path`` flies that one, shifted by
its offset.  Rule "steer": that place is the goal of Reynolds' steering
(:mod:`birdsim.flight.steering`), the birds in lockstep
(:mod:`birdsim.flight.flock_lockstep`).  Every bird flies for the flock's ``seconds``
(default: the leader path's length).  The birds of one flock share their semispan and
wingbeat period (the path is written in reduced units, semispans and wingbeats: the same
path in the world for every bird); their masses, inertia and tails may differ.  Bad
input is one line naming the entry (:class:`FlockError`): more than :data:`MAX_BIRDS`
birds, two start positions closer than :data:`MIN_START_SEPARATION` semispans, a bird
file that does not parse (named with its index), a perched or force-keyframe leader
path, an unknown rule or steering key, the rule steer with the posed attitude.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from birdsim.errors import BirdsimError
from birdsim.flight.steering import STEERING_KEYS, SteeringConfig
from birdsim.physics.bird import Bird

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

#: At most this many birds in one flock (the issue's largest target: 100 birds).
MAX_BIRDS = 100
#: Two birds' start positions at least this many semispans apart (a bird's wings reach
#: one semispan from its centreline: closer, the wingtips of two birds would touch).
MIN_START_SEPARATION = 1.0
#: The shipped flock preset's file (``birdsim fly flock``).
PRESET_FOLDER = Path(__file__).resolve().parent.parent / "data" / "flocks"
FLOCK_KEYS = (
    *("name", "path", "model", "attitude", "seconds", "bird", "description"),
    *("rule", "steering"),
)
#: Group rules: follow the leader path with offsets; or that plus Reynolds steering.
RULES = ("offsets", "steer")
BIRD_KEYS = ("file", "offset", "path")


class FlockError(BirdsimError):
    """A flock file that cannot be flown (one line naming the entry)."""


@dataclass(frozen=True)
class FlockBird:
    """One bird of a flock: its bird file (None: the seed bird) and its offset from the
    leader's path (the bird's length unit; x forward, y left, z up)."""

    index: int
    file: str | None
    offset: tuple[float, float, float]
    #: the bird's own path (a preset or a path .toml), None: the leader's
    path: str | None = None


@dataclass(frozen=True)
class Flock:
    """A parsed flock file (paths resolved; picklable: strings and numbers only)."""

    name: str
    path: str
    birds: tuple[FlockBird, ...]
    model: str | None = None
    attitude: str | None = None
    seconds: float | None = None
    description: str = ""
    #: "offsets" (each bird the leader path with its offset) or "steer" (that as the
    #: goal of Reynolds steering, the birds in lockstep: birdsim.flight.steering)
    rule: str = "offsets"
    steering: SteeringConfig = SteeringConfig()

    @property
    def n_birds(self) -> int:
        return len(self.birds)


def preset_names() -> list[str]:
    """The shipped flock presets (``birdsim fly flock``)."""
    return sorted(p.stem for p in PRESET_FOLDER.glob("*.toml"))


def is_flock(source: str) -> bool:
    """Whether ``source`` names a flock: a shipped flock preset, or a .toml file with
    ``[[bird]]`` tables."""
    if source in preset_names():
        return True
    p = Path(source)
    if p.suffix != ".toml" or not p.is_file():
        return False
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError):
        return False
    return "bird" in data


def load_flock(source: str) -> Flock:
    """Read and check a flock file (or a preset by name).

    Raises:
        FlockError: one line naming the entry and what is allowed.
    """
    p = PRESET_FOLDER / f"{source}.toml" if source in preset_names() else Path(source)
    arg = f"flock file {source!r}"
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise FlockError(f"{arg} does not exist; allowed: a flock .toml file or a preset") from None
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise FlockError(f"{arg} is not readable TOML: {exc}") from None
    unknown = sorted(set(data) - set(FLOCK_KEYS))
    if unknown:
        raise FlockError(f"{arg}: key {unknown[0]!r} is unknown; allowed: {', '.join(FLOCK_KEYS)}")
    if not isinstance(data.get("path"), str) or not data["path"]:
        raise FlockError(
            f"{arg}: path={data.get('path')!r}; allowed: a preset name or a path .toml"
        )
    path = data["path"]
    if path.endswith(".toml") and not Path(path).is_absolute():
        path = str(p.parent / path)
    rows = data.get("bird")
    if not isinstance(rows, list) or not rows:
        raise FlockError(
            f"{arg}: bird must be an array of tables ([[bird]]) with at least one entry"
        )
    if len(rows) > MAX_BIRDS:
        raise FlockError(f"{arg} has {len(rows)} birds; allowed: at most {MAX_BIRDS} birds")
    birds = tuple(_bird_entry(arg, p.parent, i, row) for i, row in enumerate(rows))
    seconds = data.get("seconds")
    if seconds is not None and (
        isinstance(seconds, bool)
        or not isinstance(seconds, (int, float))
        or not (math.isfinite(seconds) and seconds > 0)
    ):
        raise FlockError(f"{arg}: seconds={seconds!r}; allowed: a finite time > 0")
    attitude = data.get("attitude")
    if attitude not in (None, "posed", "free"):
        raise FlockError(f"{arg}: attitude={attitude!r}; allowed: posed, free")
    model = data.get("model")
    if model is not None and not isinstance(model, str):
        raise FlockError(f"{arg}: model={model!r}; allowed: base, m1, m2, m3, m4, m5")
    name = data.get("name", p.stem)
    if not isinstance(name, str) or not name:
        raise FlockError(f"{arg}: name={name!r}; allowed: a non-empty string")
    rule = data.get("rule", "offsets")
    if rule not in RULES:
        raise FlockError(f"{arg}: rule={rule!r}; allowed: {', '.join(RULES)}")
    if rule == "steer" and attitude == "posed":
        raise FlockError(
            f"{arg}: rule 'steer' with attitude 'posed'; allowed: attitude free (a steered "
            "bird moves sideways by banking)"
        )
    return Flock(
        name,
        path,
        birds,
        model,
        attitude,
        None if seconds is None else float(seconds),
        str(data.get("description", "")),
        rule,
        _steering(arg, data.get("steering", {})),
    )


def _steering(arg: str, table: Any) -> SteeringConfig:
    """The [steering] table: positive finite numbers for SteeringConfig's fields."""
    if not isinstance(table, dict):
        raise FlockError(f"{arg}: steering must be a table ([steering])")
    bad = sorted(set(table) - set(STEERING_KEYS))
    if bad:
        raise FlockError(
            f"{arg}: steering key {bad[0]!r} is unknown; allowed: {', '.join(STEERING_KEYS)}"
        )
    for k, v in table.items():
        if (
            isinstance(v, bool)
            or not isinstance(v, (int, float))
            or not (
                math.isfinite(v)
                and v >= 0
                and (v > 0 or k in ("separation", "cohesion", "alignment"))
            )
        ):
            raise FlockError(
                f"{arg}: steering {k}={v!r}; allowed: a finite number > 0 (the weights "
                "separation, cohesion, alignment: >= 0)"
            )
    return SteeringConfig(**{k: float(v) for k, v in table.items()})


def _bird_entry(arg: str, folder: Path, i: int, row: Any) -> FlockBird:
    where = f"{arg}: bird {i}"
    if not isinstance(row, dict):
        raise FlockError(f"{where} is not a table")
    bad = sorted(set(row) - set(BIRD_KEYS))
    if bad:
        raise FlockError(f"{where}: key {bad[0]!r} is unknown; allowed: {', '.join(BIRD_KEYS)}")
    off = row.get("offset")
    if (
        not isinstance(off, list)
        or len(off) != 3
        or not all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
            for v in off
        )
    ):
        raise FlockError(f"{where}: offset={off!r}; allowed: three finite numbers [x, y, z]")
    path = row.get("path")
    if path is not None:
        if not isinstance(path, str) or not path:
            raise FlockError(f"{where}: path={path!r}; allowed: a preset name or a path .toml")
        if path.endswith(".toml") and not Path(path).is_absolute():
            path = str(folder / path)
    file = row.get("file")
    if file is not None:
        if not isinstance(file, str) or not file:
            raise FlockError(f"{where}: file={file!r}; allowed: a bird .toml file")
        if not Path(file).is_absolute():
            file = str(folder / file)
    return FlockBird(i, file, (float(off[0]), float(off[1]), float(off[2])), path)


def load_bird(flock: Flock, index: int) -> Bird:
    """Bird ``index`` of the flock; a file that does not parse is one line naming it."""
    from birdsim.commands.common import default_bird_path

    src = flock.birds[index].file or str(default_bird_path())
    try:
        return Bird.from_toml(src)
    except BirdsimError as exc:
        raise FlockError(f"flock {flock.name!r}: bird {index} ({src}): {exc}") from None
    except (OSError, ValueError, TypeError, tomllib.TOMLDecodeError) as exc:
        raise FlockError(
            f"flock {flock.name!r}: bird {index} ({src}) does not parse: {exc}"
        ) from None


def load_birds(flock: Flock) -> list[Bird]:
    """Every bird of the flock; a bird file that does not parse is one line naming its
    index.  Checks the shared semispan and period and the start separations."""
    cache: dict[str | None, Bird] = {}  # a file shared by many birds parsed once
    birds = []
    for fb in flock.birds:
        if fb.file not in cache:
            cache[fb.file] = load_bird(flock, fb.index)
        birds.append(cache[fb.file])
    lead = birds[0]
    for fb, b in zip(flock.birds, birds):
        if not (math.isclose(b.semispan, lead.semispan) and math.isclose(b.period, lead.period)):
            raise FlockError(
                f"flock {flock.name!r}: bird {fb.index} has semispan {b.semispan:g}, period "
                f"{b.period:g}; allowed: those of bird 0 ({lead.semispan:g}, {lead.period:g})"
            )
    check_starts(flock, lead.semispan)
    return birds


def start_position(flock: Flock, bird: FlockBird, semispan: float) -> tuple[float, ...]:
    """The bird's start relative to the leader path's start (the bird's length unit)."""
    if bird.path is None:
        return bird.offset
    from birdsim.flight.path import FlightPath
    from birdsim.flight.path_file import get_flight

    own, lead = get_flight(bird.path, turning=True), get_flight(flock.path, turning=True)
    if not isinstance(own, FlightPath) or not isinstance(lead, FlightPath):
        return bird.offset
    a, b = own.state(0.0), lead.state(0.0)
    d = ((a.x - b.x) * semispan, (a.y - b.y) * semispan, (a.z - b.z) * semispan)
    return tuple(o + e for o, e in zip(bird.offset, d))


def check_starts(flock: Flock, semispan: float) -> None:
    """Two start positions closer than MIN_START_SEPARATION semispans: one line.  The
    start is the offset plus the start of the bird's own path (the leader's: 0)."""
    offs = [start_position(flock, b, semispan) for b in flock.birds]
    for i in range(len(offs)):
        for j in range(i):
            d = math.dist(offs[i], offs[j])
            if d < MIN_START_SEPARATION * semispan:
                raise FlockError(
                    f"flock {flock.name!r}: birds {j} and {i} start {d:.3g} apart (offsets "
                    f"{list(offs[j])}, {list(offs[i])}); allowed: at least "
                    f"{MIN_START_SEPARATION:g} semispan ({MIN_START_SEPARATION * semispan:g})"
                )


__all__ = [
    "MAX_BIRDS",
    "MIN_START_SEPARATION",
    "RULES",
    "Flock",
    "FlockBird",
    "FlockError",
    "check_starts",
    "is_flock",
    "load_bird",
    "load_birds",
    "load_flock",
    "preset_names",
]
