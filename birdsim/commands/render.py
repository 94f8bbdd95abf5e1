"""``birdsim render``: a manoeuvre (preset or TOML file) driven by a lookup table,
rendered headlessly to an MP4 (H.264, yuv420p)."""

from __future__ import annotations

import argparse
from pathlib import Path

from birdsim.commands.common import (
    MODEL_LIST,
    PRESET_LIST,
    add_bird_arguments,
    bird_from_args,
    check_clip_outputs,
    check_still,
    load_model_table,
    print_time_base,
    require_bird,
    slug,
)
from birdsim.commands.render_flight import (
    add_flight_arguments,
    is_log,
    refuse_with_kinematic,
    run_flight,
)
from birdsim.errors import BirdsimError
from birdsim.render.gl import GL_CHOICES
from birdsim.render.options import FPS_ALLOWED, SECONDS_ALLOWED


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "render",
        help="render a manoeuvre to MP4 (a preset, a TOML file or a flight log)",
        description=__doc__,
    )
    p.add_argument(
        "manoeuvre",
        metavar="MANOEUVRE",
        nargs="*",
        help=f"a preset ({PRESET_LIST}), a manoeuvre .toml file or a flight log LOG.npz (one bird or a flock); several: a batch (--out is then a folder)",
    )
    p.add_argument(
        "--batch", metavar="FILE", help="a batch: a text file with one manoeuvre per line"
    )
    p.add_argument("--jobs", metavar="N", help="a batch's local worker processes")
    p.add_argument(
        "--dask", metavar="SCHEDULER", help="render a batch on Dask: tcp://HOST:PORT or local:N"
    )
    p.add_argument(
        "--model",
        default=None,
        help=f"kinematic model: {MODEL_LIST} (default: the demo model m3 in free flight, m4 with --kinematic)",
    )
    p.add_argument(
        "--table",
        metavar="FILE",
        help="lookup table (default: the shipped table for the bird and model in free flight, tables/seed-m3.npz for the demo bird; tables/<model>.npz with --kinematic)",
    )
    p.add_argument(
        "--out", metavar="FILE.mp4", help="output video (default renders/<manoeuvre>-<model>.mp4)"
    )
    p.add_argument(
        "--size",
        default="640x480",
        metavar="WxH",
        help="frame size, multiples of 16 (default 640x480)",
    )
    p.add_argument("--fps", default="30", metavar="N", help="frames per second (default 30)")
    p.add_argument(
        "--seconds",
        metavar="S",
        help="video length (default: the whole manoeuvre); longer holds the last demands",
    )
    p.add_argument(
        "--beat-rate",
        default=None,
        metavar="HZ",
        help="wingbeats shown per second of video (default: real time for an SI bird, 2 for the seed bird; as birdsim export)",
    )
    p.add_argument(
        "--slow-motion",
        default=None,
        metavar="F",
        help="F times slower than the default time base (e.g. 4 for the pigeon's 8 Hz wingbeat)",
    )
    p.add_argument(
        "--camera",
        default="track",
        help="track, chase, side, top or overview (default track); `--camera list` describes them",
    )
    p.add_argument(
        "--quality",
        default="good",
        help="draft, good or best (default good): shadows, sky, anti-aliasing; costs in docs/rendering.md",
    )
    p.add_argument(
        "--forces",
        nargs="?",
        const="1.5",
        metavar="SCALE",
        help="draw each control point's force and the body drag as arrows; SCALE = semispans per weight (default 1.5)",
    )
    p.add_argument(
        "--still", metavar="FILE.png", help="write one frame as PNG instead of the video (see --at)"
    )
    p.add_argument(
        "--at",
        metavar="BEATS",
        help="time of the --still frame in wingbeats from the start (default: the middle)",
    )
    p.add_argument("--no-trails", action="store_true", help="no control-point pathlines")
    p.add_argument("--no-overlay", action="store_true", help="no text overlay (= --overlay none)")
    p.add_argument(
        "--overlay",
        default="short",
        metavar="WHAT",
        help="short (default: at most three lines: time, position error, saturation), full (the engineering view: forces, parameters, tail moment) or none",
    )
    p.add_argument(
        "--clean",
        action="store_true",
        help="the bird and the world only: no text, plot strip, pathlines or reference path",
    )
    p.add_argument(
        "--gl", default="auto", help="auto (OSMesa if installed, else EGL), osmesa or egl"
    )
    p.add_argument(
        "--sheet", metavar="FILE.png", help="also save a contact sheet (12 frames) of the video"
    )
    p.add_argument("--force", action="store_true", help="overwrite an existing output file")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    add_bird_arguments(p)
    add_flight_arguments(p)
    p.set_defaults(func=run)


def _number(arg: str, raw: str | None, allowed: str, kind: type = float) -> float | int | None:
    """``kind(raw)`` (None when not given), or one line naming ``arg`` and ``allowed``."""
    if raw is None:
        return None
    try:
        return kind(raw)
    except ValueError:
        what = "an integer" if kind is int else "a number"
        raise BirdsimError(f"{arg} {raw!r} is not {what}; allowed: {allowed}") from None


def _options(args: argparse.Namespace):
    """RenderOptions from the command line (one clear line for a bad value)."""
    from birdsim.render.renderer import RenderOptions, parse_size

    if args.gl not in GL_CHOICES:
        raise BirdsimError(f"--gl {args.gl!r} is unknown; allowed: {', '.join(GL_CHOICES)}")
    width, height = parse_size(args.size)
    detail = "none" if args.no_overlay else args.overlay
    if detail not in ("short", "full", "none"):
        raise BirdsimError(f"--overlay {detail!r} is unknown; allowed: short, full or none")
    if args.clean and args.forces is not None:
        raise BirdsimError("--clean draws no force arrows; allowed: --clean or --forces, not both")
    return RenderOptions(
        width=width,
        height=height,
        fps=_number("--fps", args.fps, FPS_ALLOWED, int),  # type: ignore[arg-type]
        seconds=_number("--seconds", args.seconds, SECONDS_ALLOWED),
        beats_per_second=_beat_rate(args, _number("--fps", args.fps, FPS_ALLOWED, int)),
        camera=args.camera,
        quality=args.quality,
        forces=_forces_scale(args.forces),
        trails=not (args.no_trails or args.clean),
        overlay=detail != "none" and not args.clean,
        overlay_detail="full" if detail == "full" else "short",
        reference=not args.clean,
        gl=args.gl,
        progress=not args.quiet,
    )


def _beat_rate(args: argparse.Namespace, fps: int | float | None) -> float:
    """Wingbeats per second of video (birdsim.render.timebase, the same as export's);
    the time base chosen is kept as ``args.time_base``, printed by
    :func:`birdsim.commands.common.print_time_base` once every check has passed."""
    from birdsim.render.timebase import beat_rate_for, check_time_flags, describe

    check_time_flags(args.beat_rate, args.slow_motion)
    if is_log(args.manoeuvre):
        from birdsim.flight.flightlog import load_log
        from birdsim.flight.flock_log import is_flock_log, load_flock_log

        if is_flock_log(args.manoeuvre):  # a flock's birds share their period
            bird = load_flock_log(args.manoeuvre, "LOG")[1][0]["bird_obj"]
        else:
            bird = load_log(args.manoeuvre, "LOG")["bird_obj"]
    else:
        bird = bird_from_args(args)
    rate, words = beat_rate_for(bird, args.beat_rate, args.slow_motion)
    if fps is not None and 1 <= fps <= 240:
        args.time_base = f"birdsim render: {describe(rate, words, fps)}"
    return rate


def run(args: argparse.Namespace) -> int:
    if (
        isinstance(args.manoeuvre, list) and args.camera != "list"
    ):  # from the command line: one source or a batch
        sources = list(args.manoeuvre)
        if getattr(args, "batch", None):
            from birdsim.flight.batch import read_batch

            sources += read_batch(args.batch)
        if not sources:
            raise BirdsimError(
                "no MANOEUVRE; allowed: a preset, a .toml file, a LOG.npz, several, or --batch FILE"
            )
        if len(sources) > 1 or args.batch or args.jobs is not None or args.dask is not None:
            from birdsim.commands.render_batch import run_many

            return run_many(args, sources, run)
        args.manoeuvre = sources[0]
    # every cheap check first, so that a mistake costs nothing and writes nothing
    from birdsim.flight.manoeuvre import get_manoeuvre
    from birdsim.physics.kinematics import get_model
    from birdsim.render.gl import resolve_gl

    if args.camera == "list":
        from birdsim.render.options import CAMERA_HELP

        for name, text in CAMERA_HELP.items():
            print(f"{name:9s} {text}")
        return 0
    if is_log(args.manoeuvre) or not args.kinematic:  # free flight (the default) or a flight log
        return run_flight(args, _options)
    refuse_with_kinematic(args)
    manoeuvre = get_manoeuvre(args.manoeuvre)
    model = get_model(args.model or "m4").name
    options = _options(args)
    seconds = options.duration(manoeuvre)  # a manoeuvre longer than the longest video -> one line
    at = check_still(args, seconds * options.beats_per_second)
    out = Path(args.out) if args.out else Path("renders") / f"{slug(manoeuvre.name)}-{model}.mp4"
    check_clip_outputs(args, out, at)
    resolve_gl(args.gl)  # a missing GL library -> one line, before any work
    from birdsim.tables.shipped import table_folder

    table_path = Path(args.table) if args.table else table_folder() / f"{model}.npz"
    table = load_model_table(table_path, model, explicit=bool(args.table))
    bird = bird_from_args(args) if (args.bird or args.set) else None
    if bird is not None:
        require_bird(table, bird, table_path)
    print_time_base(args)

    if at is not None:
        from birdsim.render.renderer import render_still

        path = render_still(
            manoeuvre, table, args.still, at, options, bird=bird, model=model, force=args.force
        )
        print(
            f"wrote {path} (frame at {at:g} beats, {options.width}x{options.height}, camera {options.camera}, quality {options.quality})"
        )
        return 0
    from birdsim.render.renderer import render_manoeuvre

    result = render_manoeuvre(
        manoeuvre, table, out, options, bird=bird, model=model, force=args.force
    )
    print(
        f"wrote {result.path} ({result.frames} frames, {result.width}x{result.height} @ {result.fps} fps, "
        f"{result.video_seconds:.1f} s of video in {result.wall_seconds:.1f} s wall, GL {result.backend})"
    )
    if args.sheet:
        from birdsim.render.renderer import contact_sheet

        print(f"wrote {contact_sheet(result.path, args.sheet)} (contact sheet)")
    return 0


def _forces_scale(raw: str | None) -> float | None:
    """``--forces SCALE`` as a positive finite number (None when not given)."""
    if raw is None:
        return None
    try:
        value = float(raw)
    except ValueError:
        value = float("nan")
    if not (value > 0 and value <= 1e6):
        raise BirdsimError(
            f"--forces {raw!r} is not a positive number; allowed: semispans per weight in (0, 1e6], e.g. --forces 1.5"
        )
    return value
