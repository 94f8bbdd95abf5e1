"""``birdsim export``: a flight to USD, BVH or CSV for animation tools (docs/export.md).

SOURCE is a preset or a manoeuvre .toml, flown exactly as ``birdsim render`` flies it (free
flight in MuJoCo by default, the same code path; ``--kinematic`` for the prescribed
playback), or a flight log .npz from ``birdsim fly``."""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from birdsim.commands.common import MODEL_LIST, PRESET_LIST, add_bird_arguments, bird_from_args
from birdsim.commands.render_flight import add_flight_arguments, refuse_with_kinematic
from birdsim.errors import BirdsimError, limits_text, magnitude_ok


def register(sub: argparse._SubParsersAction) -> None:

    p = sub.add_parser(
        "export",
        help="export a flight to USD, BVH or CSV (for Blender, Maya, Houdini...)",
        description=__doc__,
    )
    p.add_argument(
        "source",
        metavar="SOURCE",
        help=f"a preset ({PRESET_LIST}), a manoeuvre .toml or a flight log .npz (one bird or a flock)",
    )
    p.add_argument(
        "--format", required=True, metavar="FMT", help="usd (needs birdsim[usd]), bvh or csv"
    )
    p.add_argument(
        "--out", required=True, metavar="PATH", help="output file (.usd/.usda/.usdc, .bvh, .csv)"
    )
    p.add_argument(
        "--fps", default="30", metavar="N", help="frames per second of animation (default 30)"
    )
    p.add_argument(
        "--model",
        default=None,
        help=f"kinematic model for a manoeuvre: {MODEL_LIST} (default: the demo model m3 in free flight, m4 with --kinematic; a log names its own)",
    )
    p.add_argument(
        "--table",
        metavar="FILE",
        help="lookup table for a manoeuvre (default: the shipped table for the bird in free flight, tables/<model>.npz with --kinematic)",
    )
    p.add_argument(
        "--seconds",
        metavar="S",
        help="animation length for a manoeuvre (default: the whole manoeuvre)",
    )
    p.add_argument(
        "--beat-rate",
        metavar="HZ",
        help="wingbeats per second of animation (default: real time for an SI bird, 2 for the seed bird; as birdsim render)",
    )
    p.add_argument(
        "--slow-motion",
        metavar="F",
        help="F times slower than the default time base (e.g. 4 for the pigeon's 8 Hz wingbeat)",
    )
    p.add_argument(
        "--metres-per-unit",
        default="1",
        metavar="M",
        help="metres per bird length unit (default 1: the pigeon in metres, the seed bird's semispan as 1 m)",
    )
    p.add_argument("--force", action="store_true", help="overwrite an existing output file")
    add_bird_arguments(p)
    add_flight_arguments(p)
    p.set_defaults(func=run)


def _positive(arg: str, raw: str | None) -> float | None:
    import math

    if raw is None:
        return None
    try:
        v = float(raw)
    except ValueError:
        raise BirdsimError(f"{arg} {raw!r} is not a number; allowed: a number > 0") from None
    if not (math.isfinite(v) and magnitude_ok(v, positive=True)):
        raise BirdsimError(
            f"{arg} {raw!r} is invalid; allowed: a number > 0, {limits_text(positive=True)}"
        )
    return v


def run(args: argparse.Namespace) -> int:
    from birdsim import export
    from birdsim.commands.common import (
        check_writable,
        load_model_table,
        refuse_for_a_log,
        require_bird,
    )
    from birdsim.export.frames import check_fps

    # every cheap check first: a mistake costs nothing and writes nothing
    export.check_format(args.format, Path(args.out))
    fps = check_fps(args.fps)
    from birdsim.render.timebase import beat_rate_for, check_time_flags, describe

    check_time_flags(args.beat_rate, args.slow_motion)

    def time_base(bird) -> tuple[float, str]:  # the time base of birdsim render, its line
        from birdsim.physics.bird import Bird

        rate, words = beat_rate_for(bird or Bird(), args.beat_rate, args.slow_motion)
        return rate, f"birdsim export: {describe(rate, words, fps)}"

    def rate_for(bird) -> float:  # printed after every check, before the work
        rate, line = time_base(bird)
        print(line, flush=True)
        return rate

    metres = _positive("--metres-per-unit", args.metres_per_unit)
    seconds = _positive("--seconds", args.seconds)
    out = Path(args.out)
    if args.format == "usd":
        from birdsim.export.usd import require_usd

        require_usd()
        if usd_assets(out).exists() and not args.force:
            raise BirdsimError(
                f"--out {str(out)!r}: its texture folder {str(usd_assets(out))!r} exists; "
                "allowed: a new path, or --force to overwrite"
            )
    if args.format == "bvh":
        from birdsim.export.bvh import check_bvh_model, require_bvh

        require_bvh()
        check_bvh_model(args.model)  # before the flight, not after it
    check_writable(out, args.force)
    wall0 = time.perf_counter()
    if args.source.lower().endswith(".npz"):
        from birdsim.export.flightlog import frames_from_log, read_flight_log

        for_a_log = (
            ("--table", args.table),
            ("--seconds", args.seconds),
            ("--bird", args.bird),
            ("--set", args.set),
            ("--gust", args.gust),
            ("--open-loop", args.open_loop),
            ("--attitude", args.attitude),
            ("--kinematic", args.kinematic),
            ("--legs", args.legs),
            ("--strict", args.strict),
        )
        refuse_for_a_log(for_a_log, "", None)
        from birdsim.flight.flock_log import is_flock_log

        if is_flock_log(args.source):  # every bird (issue 27): birdsim.commands.export_flock
            from birdsim.commands.export_flock import export_flock_log

            return export_flock_log(args, fps, rate_for, metres)
        log = read_flight_log(args.source)
        refuse_for_a_log((), str(log["model"]), args.model)
        if args.format == "bvh":
            check_bvh_model(str(log["model"]))
        frames = frames_from_log(
            log,
            fps=fps,
            beat_rate=rate_for(log["bird_obj"]),
            metres_per_unit=metres,
            source=f"flight log {Path(args.source).name}",
        )  # type: ignore[arg-type]
    elif not args.kinematic:  # free flight, the default: flown as `birdsim render` flies it
        from birdsim.commands.render_flight import (
            flight_bird_and_table,
            flight_reference,
            fly_reference,
        )
        from birdsim.export.flightlog import frames_from_log
        from birdsim.export.frames import time_per_second
        from birdsim.flight.manoeuvre import MAX_BEATS

        reference, model, gusts, attitude = flight_reference(
            args.source, args.model, args.gust, args.attitude, command="export"
        )
        bird_and_table = flight_bird_and_table(args, model)  # --bird and --set, as flown
        bird = bird_and_table[0]
        beat_rate, time_base_line = time_base(bird)
        per_s = time_per_second(bird, beat_rate)
        if seconds is None:
            seconds = float(reference.duration_beats) * bird.period / per_s
        # one frame's time more than asked, so that the last frame (at `seconds`) is flown
        beats = (seconds + 1.0 / fps) * per_s / bird.period
        if not beats <= MAX_BEATS:
            raise BirdsimError(
                f"--seconds {args.seconds} is {beats:g} wingbeats of flight; allowed: at most {MAX_BEATS:g} wingbeats"
            )
        print(time_base_line, flush=True)
        log = fly_reference(
            reference,
            model,
            args,
            beats=beats,
            gusts=gusts,
            bird_and_table=bird_and_table,
            attitude=attitude,
        )
        frames = frames_from_log(
            log,
            fps=fps,
            beat_rate=beat_rate,
            metres_per_unit=metres,
            seconds=seconds,
            source=f"manoeuvre {reference.name} (free flight)",
        )  # type: ignore[arg-type]
    else:
        from birdsim.export.frames import from_playback
        from birdsim.flight.manoeuvre import get_manoeuvre
        from birdsim.physics.kinematics import get_model

        refuse_with_kinematic(args)
        manoeuvre = get_manoeuvre(args.source)
        model = get_model(args.model or "m4").name
        from birdsim.tables.shipped import table_folder

        table_path = Path(args.table) if args.table else table_folder() / f"{model}.npz"
        table = load_model_table(table_path, model, explicit=bool(args.table))
        bird = bird_from_args(args) if (args.bird or args.set) else None
        if bird is not None:
            require_bird(table, bird, table_path)
        beat_rate, time_base_line = time_base(bird)
        frames = from_playback(  # checks --seconds; fast (no simulation)
            manoeuvre,
            table,
            bird=bird,
            model=model,
            fps=fps,
            beat_rate=beat_rate,
            seconds=seconds,
            metres_per_unit=metres,
        )  # type: ignore[arg-type]
        print(time_base_line, flush=True)
    path = export.write(frames, args.format, out)
    size = path.stat().st_size
    print(
        f"wrote {path} ({args.format}, {frames.frames} frames @ {fps:g} fps = {(frames.frames - 1) / fps:.2f} s, "
        f"{size / 1e6:.2f} MB, model {frames.model}, bird {frames.bird.name}, in {time.perf_counter() - wall0:.1f} s)"
        + (assets_note(path) if args.format == "usd" else "")
    )
    return 0


def usd_assets(out: Path) -> Path:
    """The folder beside a USD file that holds the textures it references (``c.usd`` ->
    ``c_assets/``; :func:`birdsim.export.usd.write_usd`)."""
    return out.with_name(out.stem + "_assets")


def assets_note(out: Path) -> str:
    """The end of the output line: the texture folder that must travel with the file."""
    folder = usd_assets(out)
    files = sorted(p.name for p in folder.iterdir()) if folder.is_dir() else []
    if not files:
        return ""
    return (
        f"; and {folder}/ ({len(files)} textures the file references by relative path: "
        "move or copy it together with the file)"
    )
