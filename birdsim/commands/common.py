"""What several subcommands share, in one module below them (no command module imports
another command's module; the free flight that render and export both fly is
``render_flight``, and ``tables_info`` is the tables command's second half):
arguments (bird, NAME=VALUE pairs), the translation of the library's Python argument
names into the flags the user typed, output checks (``--out``, ``--still``), and the
bird and table a flying command reads."""

from __future__ import annotations

import argparse
import re
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from pathlib import Path

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird, BirdConfigError
from birdsim.physics.kinematics import MODELS

#: The kinematic models a ``--model`` takes, for help texts: "base, m1, ..., m4 or m5".
MODEL_LIST = ", ".join(list(MODELS)[:-1]) + " or " + list(MODELS)[-1]
#: The shipped presets by name, for help texts (written out: the turning and flock presets'
#: modules take half a second to import; tests/test_new_user.py checks the names).
PRESET_LIST = "hover, cruise, take-off, landing, turn-90, circle, s-turn, u-turn"
FLOCK_LIST = "flock, flock-seed, flock-v"


def parse_pairs(pairs: list[str] | None, arg: str) -> dict[str, str]:
    """``["a=1", "b=2"]`` -> ``{"a": "1", "b": "2"}``; one clear line for a malformed pair."""
    out: dict[str, str] = {}
    for pair in pairs or []:
        name, sep, value = pair.partition("=")
        if not sep or not name.strip():
            raise BirdsimError(f"{arg} {pair!r} is malformed; allowed: NAME=VALUE")
        if name.strip() in out:
            raise BirdsimError(
                f"{arg} {name.strip()} is given twice ({out[name.strip()]!r}, {value.strip()!r}); allowed: once"
            )
        out[name.strip()] = value.strip()
    return out


#: Where :class:`StoreOnce` keeps the options given so far in one parse (removed by
#: :func:`forget_given`).
_GIVEN = "_options_given"


class StoreOnce(argparse._StoreAction):
    """argparse's ``store``, refusing a single-valued option given twice (argparse itself
    silently keeps the last: ``--bird a.toml --bird b.toml`` would fly b)."""

    def __call__(self, parser, namespace, values, option_string=None):  # type: ignore[no-untyped-def]
        given = namespace.__dict__.setdefault(_GIVEN, {})
        if option_string is not None and self.dest in given:
            parser.error(
                f"{option_string} is given twice ({given[self.dest]!r}, {values!r}); allowed: "
                "once (the last would win silently)"
            )
        given[self.dest] = values
        setattr(namespace, self.dest, values)


def forget_given(args: argparse.Namespace) -> argparse.Namespace:
    """``args`` without :class:`StoreOnce`'s bookkeeping."""
    vars(args).pop(_GIVEN, None)
    return args


def add_bird_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--bird",
        metavar="FILE.toml",
        help="bird geometry and coefficients: a TOML file or a shipped bird's name (pigeon, "
        "seed-bird; default: the seed bird)",
    )
    p.add_argument(
        "--set",
        action="append",
        metavar="NAME=VALUE",
        help="override one bird field, e.g. strips=20",
    )


def translate(
    message: str, starts: Mapping[str, str], hints: Mapping[str, str] | None = None
) -> str:
    """The library's one-line ``message`` as the command line says it.

    The library names Python arguments and starts its messages with them
    (``speed=nan is invalid``, ``model 'm9' is unknown``).  ``starts`` maps such a
    start to the flag the user typed (``{"speed=": "--speed="}``), first match wins;
    ``hints`` replaces a Python hint anywhere in the message (``{"clip=True": "--clip"}``).
    """
    for python, flag in starts.items():
        if message.startswith(python):
            message = flag + message[len(python) :]
            break
    for python, flag in (hints or {}).items():
        message = message.replace(python, flag)
    return message


@contextmanager
def flag_names(starts: Mapping[str, str], hints: Mapping[str, str] | None = None) -> Iterator[None]:
    """Re-raise a :class:`BirdsimError` from the block with its message :func:`translate`-d."""
    try:
        yield
    except BirdsimError as exc:
        exc.args = (translate(str(exc), starts, hints),)
        raise


def bird_file(arg: str) -> str:
    """``--bird``'s file: the path as given, or a shipped bird's name (``pigeon``,
    ``seed-bird``: ``models/<name>.toml``) when no such path exists."""
    folder = Path(__file__).resolve().parents[2] / "models"
    if Path(arg).exists() or "/" in arg or arg.endswith(".toml"):
        return arg
    if (folder / f"{arg}.toml").is_file():
        return str(folder / f"{arg}.toml")
    names = ", ".join(sorted(f.stem for f in folder.glob("*.toml")))
    raise BirdConfigError(
        f"path={arg!r} does not exist; allowed: a readable TOML file or a shipped bird ({names})"
    )


def bird_from_args(args: argparse.Namespace, default: Bird | None = None) -> Bird:
    """The bird of ``--bird FILE.toml`` (else ``default``, else the seed bird) with
    ``--set`` applied; a bad file or value is one line naming ``--bird`` or ``--set``."""
    with flag_names({"path=": "--bird "}):
        if getattr(args, "bird", None) is not None:
            bird = Bird.from_toml(bird_file(args.bird))
        else:
            bird = Bird() if default is None else default
    overrides = parse_pairs(getattr(args, "set", None), "--set")
    with flag_names({"overrides: ": "--set "}):
        return bird.with_overrides(overrides) if overrides else bird


# ---- outputs, birds and tables, as every command that flies or writes reads them ----


def slug(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", text).strip("_") or "manoeuvre"


def check_clip_outputs(args: argparse.Namespace, out: Path, at: float | None) -> None:
    """``render``'s outputs checked before any work: the video ``out`` (a .mp4 path, not
    overwritten without ``--force``) unless a still is asked (``at``), and ``--sheet`` (a
    .png path); each refusal one line."""
    if at is None:
        if out.suffix.lower() != ".mp4":
            raise BirdsimError(f"--out {str(out)!r} does not end in .mp4; allowed: a .mp4 path")
        check_writable(out, args.force)
    if args.sheet:
        if Path(args.sheet).suffix.lower() != ".png":
            raise BirdsimError(f"--sheet {args.sheet!r} does not end in .png; allowed: a .png path")
        check_writable(Path(args.sheet), args.force, "--sheet")


def refuse_for_a_log(
    given: tuple[tuple[str, object], ...], log_model: str, model: str | None
) -> None:
    """A flight log records its bird, model and flight: one line for the first option in
    ``given`` (flag, value) that is set, or for a ``--model`` other than ``log_model``."""
    for arg, value in given:
        if value:
            raise BirdsimError(
                f"{arg} does not apply to a flight log (it records its bird, model and flight); allowed: omit {arg}"
            )
    if model and model != log_model:
        raise BirdsimError(
            f"--model {model!r} differs from the log's model {log_model!r}; allowed: omit --model for a log"
        )


def render_log_flags(args: argparse.Namespace) -> tuple[tuple[str, object], ...]:
    """The options ``render`` does not take with a flight log (it records its flight)."""
    return (
        ("--bird", args.bird),
        ("--set", args.set),
        ("--table", args.table),
        ("--kinematic", args.kinematic),
        ("--legs", args.legs),  # the log's flight was flown (or not) with legs already
        ("--strict", args.strict),  # saturation is judged when a flight is flown
    )


def print_time_base(args: argparse.Namespace) -> None:
    """Print the time base ``render`` chose (``args.time_base``), after every check, so
    that a refused command prints nothing but its one error line."""
    note = getattr(args, "time_base", None)
    if note:
        print(note, flush=True)


def check_still(args: argparse.Namespace, clip_beats: float) -> float | None:
    """``--still``/``--at``/``--sheet`` checked before any work; the still's time in
    wingbeats (None when no still is asked for)."""
    if args.at is not None and not args.still:
        raise BirdsimError(f"--at {args.at!r} needs --still FILE.png; allowed: --at with --still")
    if args.sheet and args.still:
        raise BirdsimError("--sheet needs a video; allowed: --sheet without --still")
    if not args.still:
        return None
    at = _at_beats(args.at, clip_beats)
    if Path(args.still).suffix.lower() != ".png":
        raise BirdsimError(f"--still {args.still!r} does not end in .png; allowed: a .png path")
    check_writable(Path(args.still), args.force, "--still")
    return at


def _at_beats(raw: str | None, clip_beats: float) -> float:
    """``--at BEATS`` inside the clip [0, clip_beats] (default: the middle)."""
    if raw is None:
        return 0.5 * clip_beats
    try:
        value = float(raw)
    except ValueError:
        raise BirdsimError(
            f"--at {raw!r} is not a number; allowed: a time in wingbeats in [0, {clip_beats:g}]"
        ) from None
    if not (0.0 <= value <= clip_beats):
        raise BirdsimError(
            f"--at {raw!r} is outside the clip; allowed: a time in wingbeats in [0, {clip_beats:g}]"
        )
    return value


def check_writable(out: Path, force: bool, arg: str = "--out") -> None:
    """Refuse an existing file without --force and a folder we cannot write into
    (probed by creating and removing the temporary sibling the writer will use)."""
    import os

    from birdsim.io import check_output, temporary_sibling

    check_output(out, force, arg)
    try:
        os.unlink(temporary_sibling(out))
    except OSError as exc:
        raise BirdsimError(
            f"{arg} {str(out)!r} is not writable: {exc.strerror}; allowed: a path in a writable folder"
        ) from None


def require_bird(table, bird, table_path: Path) -> None:
    """Refuse, in one line naming the table and both birds, a bird whose reduced bird is
    not the one the table was built for (:meth:`LookupTable.require_bird`; the same line
    as free flight's :func:`load_table_for`)."""
    try:
        table.require_bird(bird)
    except BirdsimError as exc:
        raise BirdsimError(f"--table {str(table_path)!r}: {exc}") from None


def load_model_table(path: Path, model: str, *, explicit: bool):
    from birdsim.flight.playback import check_table_model

    if not path.exists():
        hint = (
            f"build it with `birdsim tables build --model {model}`"
            if not explicit
            else "a table file (.npz)"
        )
        raise BirdsimError(f"--table {str(path)!r} does not exist; allowed: {hint}")
    try:
        from birdsim.tables.lookup import load_table
    except ImportError:  # pragma: no cover - tables land with issue 3
        raise BirdsimError(
            "--table: this birdsim has no table support (birdsim.tables.lookup is missing)"
        ) from None
    table = load_table(path)
    check_table_model(table, model)
    return table


def default_bird_path() -> Path:
    """models/seed-bird.toml (here, else the repository's)."""
    local = Path("models") / "seed-bird.toml"
    return (
        local
        if local.is_file()
        else Path(__file__).resolve().parents[2] / "models" / "seed-bird.toml"
    )


def load_bird(arg: str | None) -> Bird:
    """The bird of ``--bird`` (a bad file: one line naming ``--bird``), else the demo bird
    ``models/seed-bird.toml``."""
    if arg:
        with flag_names({"path=": "--bird "}):
            return Bird.from_toml(bird_file(arg))
    path = default_bird_path()
    return Bird.from_toml(path) if path.is_file() else Bird()


def load_table_for(bird, model: str, table_arg: str | None):
    """The table: --table, else the shipped one for this bird and model; refused with
    one line when built for another model or another reduced bird."""
    from birdsim.tables.lookup import load_table

    if table_arg:
        path = Path(table_arg)
        npz = path if path.suffix in (".npz", ".json") else path.with_name(path.name + ".npz")
        if not npz.with_suffix(".npz").exists():
            raise BirdsimError(
                f"--table {str(path)!r} does not exist; allowed: a table file (.npz) written by `birdsim tables build`"
            )
    else:
        try:
            from birdsim.tables.shipped import shipped_table
        except ImportError:  # pragma: no cover - before the shipped-table finder lands
            path = Path("tables") / f"{model}.npz"
        else:
            path = shipped_table(bird, model)
    table = load_table(path)
    if table.model != model:
        raise BirdsimError(
            f"--table {str(path)!r} was built for model {table.model!r}, not {model!r}; allowed: a table for {model}"
        )
    try:
        table.require_bird(bird)
    except BirdsimError as exc:
        raise BirdsimError(f"--table {str(path)!r}: {exc}") from None
    return table


# ---- units of what a command prints ----

#: The reduced units (the seed bird's, and every table's): s = semispan, c = chord.
REDUCED_UNITS = {
    "length": "semispans (s)",
    "time": "1/omega (a wingbeat is 2 pi)",
    "speed": "omega s",
    "force": "rho omega^2 s^3 c",
    "power": "rho omega^3 s^4 c",
    "mass": "rho s^2 c",
    "angle": "rad",
}
#: A bird file in SI (models/pigeon.toml, ``birdsim bird new``).
SI_UNITS = {
    "length": "m",
    "time": "s",
    "speed": "m/s",
    "force": "N",
    "power": "W",
    "mass": "kg",
    "angle": "rad",
}


def units_of(bird: Bird) -> dict[str, str]:
    """The units of ``bird``'s own figures: SI when its file is in SI (rho, omega, semispan
    or chord other than 1, as ``birdsim bird new`` writes), else :data:`REDUCED_UNITS`."""
    si = bird.rho != 1.0 or bird.omega != 1.0 or bird.semispan != 1.0 or bird.chord != 1.0
    return dict(SI_UNITS if si else REDUCED_UNITS)


def short_length(units: Mapping[str, str]) -> str:
    """The length unit as a one-line summary prints it ("m" or "semispans")."""
    return units["length"].split(" (")[0]
