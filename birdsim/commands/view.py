"""``birdsim view``: a flight as ONE self-contained HTML file (scripts, styles and data
inlined; it works with the network off): the dressed bird in 3-D with orbit, zoom and
pan, a timeline (play, pause, scrub, playback speed), camera presets and plots linked to
the timeline (docs/studio.md).

SOURCE is a flight log .npz (``birdsim fly --out``; a flock's log draws every bird, the
cameras framing the flock) or a preset / manoeuvre .toml, flown first exactly as
``birdsim fly`` flies it. Playback at 1x is real time for an SI bird
(the pigeon) and 2 wingbeats per second for the non-dimensional seed bird."""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from birdsim.commands.common import FLOCK_LIST, MODEL_LIST, PRESET_LIST
from birdsim.errors import BirdsimError


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "view",
        help="write a flight as one self-contained 3-D HTML page (offline)",
        description=__doc__,
    )
    p.add_argument(
        "source",
        metavar="SOURCE",
        help=f"a flight log .npz (one bird or a flock), a preset ({PRESET_LIST}; flocks: {FLOCK_LIST}) or a manoeuvre or flock .toml",
    )
    p.add_argument("--out", required=True, metavar="FILE.html", help="the page to write")
    p.add_argument(
        "--fps",
        default="60",
        metavar="N",
        help="frames per second of playback at 1x, 1 to 240 (default 60; at least 24 per wingbeat)",
    )
    p.add_argument(
        "--model", default=None, help=f"kinematic model for a manoeuvre: {MODEL_LIST} (default m3)"
    )
    p.add_argument(
        "--bird",
        metavar="FILE.toml",
        help="the bird for a manoeuvre: a TOML file or a shipped bird's name (pigeon, "
        "seed-bird; default: the seed bird)",
    )
    p.add_argument(
        "--gust",
        action="append",
        default=[],
        metavar="T0:DURATION:WX:WY:WZ",
        help="a gust for a manoeuvre (see birdsim fly)",
    )
    p.add_argument("--open-loop", action="store_true", help="a manoeuvre flown feed-forward only")
    p.add_argument("--force", action="store_true", help="overwrite an existing --out")
    p.set_defaults(func=run)


def parse_fps(raw: str) -> float:
    try:
        v = float(raw)
    except ValueError:
        raise BirdsimError(f"--fps {raw!r} is not a number; allowed: 1 to 240") from None
    if not (math.isfinite(v) and 1 <= v <= 240):
        raise BirdsimError(f"--fps {raw!r} is out of range; allowed: 1 to 240")
    return v


def run(args: argparse.Namespace) -> int:
    from birdsim.io import check_output
    from birdsim.studio.page import MAX_VIEW_BYTES
    from birdsim.studio.scene import ViewOptions, flight_scene

    fps = parse_fps(args.fps)
    out = Path(args.out)
    if out.suffix.lower() not in (".html", ".htm"):
        raise BirdsimError(f"--out {str(out)!r} does not end in .html; allowed: a .html path")
    check_output(out, args.force, "--out")
    if args.source.lower().endswith(".npz"):
        from birdsim.flight.flightlog import load_log

        for flag, value in (
            ("--model", args.model),
            ("--bird", args.bird),
            ("--gust", args.gust),
            ("--open-loop", args.open_loop),
        ):
            if value:
                raise BirdsimError(
                    f"{flag} does not apply to a flight log; allowed: a preset or manoeuvre file with it"
                )
        from birdsim.flight.flock_log import is_flock_log

        if is_flock_log(args.source):
            return _view_flock(args, out, fps)
        log = load_log(args.source, "SOURCE")
        how = "from the log"
    else:
        from birdsim.studio.flights import FlightRequest, fly_request

        req = FlightRequest(
            args.source,
            model=args.model,
            bird=args.bird,
            gusts=tuple(args.gust),
            open_loop=args.open_loop,
        )
        log, _ = fly_request(req)
        how = "flown in MuJoCo"
        if "n_birds" in log:  # a flock preset or file, flown as `birdsim fly FLOCK` flies it
            from birdsim.studio.flock_flights import flock_birds

            return _view_birds(args, out, fps, flock_birds(log), "flown in MuJoCo")
        from birdsim.flight.saturation import report_saturation

        model = str(log.get("model", args.model))
        report_saturation(log, command="view", bird_arg=args.bird, model=model, strict=False)
    scene = flight_scene(log, ViewOptions(fps=fps), title=Path(args.source).stem)
    _write_view(scene, out, args.force, ("the view", MAX_VIEW_BYTES, "lower --fps"), "", how)
    return 0


def _write_view(
    scene: dict, out: Path, force: bool, limit: tuple[str, int, str], birds: str, how: str
) -> None:
    """Write ``scene``'s page to ``out`` atomically (refused above ``limit``: its name, the
    bytes allowed and the hint) and print the one line (``birds``: "N birds, " or "")."""
    from birdsim.io import check_output, write_atomic
    from birdsim.studio.page import view_html

    name, most, hint = limit
    page = view_html(scene).encode("utf-8")
    if len(page) > most:
        raise BirdsimError(
            f"{name} would be {len(page) / 1e6:.1f} MB; allowed: at most {most / 1e6:g} MB ({hint})"
        )
    check_output(out, force, "--out")
    write_atomic(out, page)
    tb = scene["time_base"]
    print(
        f"wrote {out} ({len(page) / 1e6:.2f} MB, {birds}{len(scene['t'])} frames over "
        f"{scene['duration']:.3g} {scene['units']['time']}, {how}; playback 1x = {tb['label']})"
    )


def _view_flock(args: argparse.Namespace, out: Path, fps: float) -> int:
    """A flock's log: every bird drawn (birdsim.studio.flock_view)."""
    from birdsim.flight.flock_log import load_flock_log

    data, birds = load_flock_log(args.source, "SOURCE")
    return _view_birds(args, out, fps, birds, "from the flock's log")


def _view_birds(args: argparse.Namespace, out: Path, fps: float, birds: list, how: str) -> int:
    """Every bird of a flock (each bird's own log) as one page."""
    from birdsim.studio.flock_view import MAX_FLOCK_VIEW_BYTES, flock_scene
    from birdsim.studio.scene import ViewOptions

    scene = flock_scene(birds, ViewOptions(fps=fps), title=Path(args.source).stem)
    limit = ("the flock's view", MAX_FLOCK_VIEW_BYTES, "lower --fps, or a shorter log")
    _write_view(scene, out, args.force, limit, f"{len(birds)} birds, ", how)
    return 0
