"""``birdsim fly``: free flight in MuJoCo along a manoeuvre's path, closed loop, with an
optional flight log (.npz) and a JSON summary."""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

from birdsim.commands.common import (
    FLOCK_LIST,
    MODEL_LIST,
    PRESET_LIST,
    check_writable,
    load_bird,
    load_table_for,
    short_length,
    units_of,
)
from birdsim.errors import BirdsimError
from birdsim.flight.presets import DEMO_MODEL as DEFAULT_MODEL


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "fly",
        help="fly a manoeuvre in MuJoCo under the bird's own forces (closed loop) and log it",
        description=__doc__,
    )
    p.add_argument(
        "manoeuvre",
        metavar="MANOEUVRE",
        nargs="*",
        help=f"a preset ({PRESET_LIST}; flocks: {FLOCK_LIST}) or a manoeuvre or flock .toml file; several: a batch (--out is then a folder)",
    )
    p.add_argument(
        "--batch",
        metavar="FILE",
        help="a batch: a text file with one manoeuvre per line (# comments), flown as with several MANOEUVREs",
    )
    p.add_argument(
        "--jobs",
        metavar="N",
        help="a batch's local worker processes (default: one per core); a flock's: its "
        "birds split between them (a steered flock: default one process)",
    )
    p.add_argument(
        "--dask",
        metavar="SCHEDULER",
        help="fly a batch on a Dask cluster: tcp://HOST:PORT or local:N, as `tables build` (needs birdsim[cluster])",
    )
    p.add_argument(
        "--model",
        default=DEFAULT_MODEL,
        help=f"kinematic model: {MODEL_LIST} (default {DEFAULT_MODEL})",
    )
    p.add_argument(
        "--bird",
        metavar="FILE.toml",
        help="the bird: a TOML file or a shipped bird's name (pigeon, seed-bird; default seed-bird)",
    )
    p.add_argument(
        "--table",
        metavar="FILE",
        help="lookup table (default: the shipped table for the bird and model)",
    )
    p.add_argument("--out", metavar="LOG.npz", help="write the flight log here")
    p.add_argument(
        "--json",
        action="store_true",
        help="print a JSON summary (errors, final state, saturation, power)",
    )
    p.add_argument(
        "--gust",
        action="append",
        default=[],
        metavar="T0:DURATION:WX:WY:WZ",
        help="wind from T0 for DURATION wingbeats, WX forward, WY to the bird's left and WZ up in the bird's velocity units; the four-number form T0:DURATION:WX:WZ has no side wind (repeatable; they add up)",
    )
    p.add_argument(
        "--attitude",
        choices=("posed", "free"),
        default=None,
        help="posed: the body's pitch prescribed (default for a path in the vertical plane); free: all six DOF free, held by the attitude loop (docs/free-body.md; the default for a turning path, which a posed body cannot fly)",
    )
    p.add_argument(
        "--legs",
        action="store_true",
        help="legs and feet (issue 25): a path that starts at rest on the perch is a standing start and a jump; one that ends there, a touchdown and standing (docs/legs.md)",
    )
    p.add_argument(
        "--open-loop",
        action="store_true",
        help="feed-forward only (no feedback): see why feedback is needed",
    )
    p.add_argument(
        "--seconds",
        metavar="S",
        help="simulated time in the bird's time units (default: the manoeuvre's length)",
    )
    p.add_argument(
        "--strict",
        action="store_true",
        help="a flight with saturated wingbeats is an error (exit 2, nothing written); else one warning line on stderr",
    )
    p.add_argument("--force", action="store_true", help="overwrite an existing --out")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=run)


def parse_seconds(raw: str | None) -> float | None:
    if raw is None:
        return None
    try:
        v = float(raw)
    except ValueError:
        raise BirdsimError(
            f"--seconds {raw!r} is not a number; allowed: a time > 0 in the bird's time units"
        ) from None
    if not (math.isfinite(v) and v > 0):
        raise BirdsimError(
            f"--seconds {raw!r} is invalid; allowed: a finite time > 0 in the bird's time units"
        )
    return v


def legs_check(flight: object, name: str, args: argparse.Namespace) -> None:
    """``--legs`` needs a path starting or ending at rest on a perch or the ground, no
    gusts, no --seconds, closed loop."""
    from birdsim.flight.path import FlightPath

    perched = isinstance(flight, FlightPath) and (flight.perch_start or flight.perch_end)
    if not perched:
        raise BirdsimError(
            f"--legs with {name!r}; allowed: a path that starts or ends at rest on a perch or the ground, e.g. take-off or landing"
        )
    for flag, bad in (
        ("--gust", args.gust),
        ("--seconds", args.seconds),
        ("--open-loop", args.open_loop),
    ):
        if bad:
            raise BirdsimError(
                f"--legs with {flag}; allowed: --legs alone (the contact phases take neither)"
            )


def fly_with_legs(flight, table, bird, model, attitude, progress):  # type: ignore[no-untyped-def]
    from birdsim.flight.perch_landing import land
    from birdsim.flight.perched import take_off
    from birdsim.flight.simulate import SimConfig

    config = SimConfig(attitude=attitude)
    if flight.perch_start:  # (and at rest at the end too: the flight ends in a touchdown)
        return take_off(flight, table, bird, model, config=config, progress=progress, land=land)
    return land(flight, table, bird, model, config=config, progress=progress)


def legs_summary(legs: dict, bird: object) -> dict:
    """The legs' figures (reduced units) with the speeds in the bird's units too."""
    from birdsim.physics.units import scales

    out = dict(legs)
    speed = scales(bird).speed  # type: ignore[arg-type]
    for key in ("touchdown_speed", "touchdown_speed_target"):
        if key in out:
            out[key + "_bird_units"] = out[key] * speed
    if "liftoff_velocity" in out:
        out["liftoff_speed_bird_units"] = (
            float(sum(v * v for v in out["liftoff_velocity"]) ** 0.5) * speed
        )
    return out


def run(args: argparse.Namespace) -> int:
    from birdsim.flight.freeflight import DemandSchedule, fly, parse_gust
    from birdsim.flight.manoeuvre import MAX_BEATS, Manoeuvre
    from birdsim.flight.path_file import attitude_for, get_flight
    from birdsim.flight.simulate import SimConfig
    from birdsim.physics.kinematics import get_model

    sources = list(args.manoeuvre)
    if args.batch:
        from birdsim.flight.batch import read_batch

        sources += read_batch(args.batch)
    if not sources:
        raise BirdsimError(
            "no MANOEUVRE; allowed: a preset, a manoeuvre .toml file, several, or --batch FILE"
        )
    seconds = parse_seconds(args.seconds)
    from birdsim.flight.flock import is_flock

    if len(sources) == 1 and not args.batch and is_flock(sources[0]):  # a flock (issue 27)
        from birdsim.commands.fly_flock import run_flock

        return run_flock(args, sources[0], seconds)
    if len(sources) > 1 or args.batch or args.jobs is not None or args.dask is not None:
        from birdsim.commands.fly_batch import run_many

        return run_many(args, sources, seconds)
    flight = get_flight(sources[0], turning=True)
    attitude = attitude_for(flight, args.attitude, sources[0])
    model = get_model(args.model).name
    gusts = [parse_gust(g) for g in args.gust]
    out = Path(args.out) if args.out else None
    if out is not None:
        if out.suffix.lower() != ".npz":
            raise BirdsimError(f"--out {str(out)!r} does not end in .npz; allowed: a .npz path")
        check_writable(out, args.force)
    bird = load_bird(args.bird)
    if bird.gravity <= 0:
        raise BirdsimError(
            f"--bird {bird.name!r} has gravity={bird.gravity:g}; allowed: a bird file with gravity > 0 for free flight (e.g. models/seed-bird.toml)"
        )
    table = load_table_for(bird, model, args.table)
    reference = DemandSchedule(flight) if isinstance(flight, Manoeuvre) else flight
    beats = seconds / bird.period if seconds is not None else float(reference.duration_beats)
    if beats > MAX_BEATS:
        raise BirdsimError(
            f"--seconds {args.seconds} is {beats:g} wingbeats; allowed: at most {MAX_BEATS:g} wingbeats"
        )

    from tqdm import tqdm

    bar = tqdm(
        total=round(beats, 3),
        desc=f"fly {reference.name}",
        unit="beat",
        disable=True if (args.quiet or args.json) else None,  # None: only on a terminal
        file=sys.stderr,
    )

    def progress(done: float) -> None:
        bar.n = round(min(done, beats), 3)
        bar.refresh()

    if args.legs:
        legs_check(flight, sources[0], args)
    try:
        if args.legs:
            result = fly_with_legs(flight, table, bird, model, attitude, progress)
        else:
            result = fly(
                reference,
                table,
                bird,
                model,
                beats=beats,
                gusts=gusts,
                open_loop=args.open_loop,
                progress=progress,
                config=SimConfig(attitude=attitude),
            )
    finally:
        bar.close()
    from birdsim.flight.flightlog import log_arrays, save_log, summary

    arrays = log_arrays(result, reference.name)
    phases = getattr(reference, "regime", None)
    if isinstance(flight, Manoeuvre):
        phases = flight.regime
    info = summary(arrays, phases=phases)
    from birdsim.flight.saturation import report_saturation
    from birdsim.flight.summary_units import with_units

    report_saturation(arrays, command="fly", bird_arg=args.bird, model=model, strict=args.strict)
    info = with_units(info, bird)
    from birdsim.flight.turn_summary import turn_figures

    turn = turn_figures(arrays)
    if turn is not None:
        info["turn"] = turn
    if "legs" in result.meta:
        info["legs"] = legs_summary(result.meta["legs"], bird)
    if out is not None:
        save_log(arrays, out, args.force)
        info["log"] = str(out)
    if args.json:  # strict JSON: a figure that does not exist (NaN) is null
        from birdsim.json_values import finite_or_none

        print(json.dumps(finite_or_none(info), indent=2, allow_nan=False))
    else:
        m = short_length(units_of(bird))
        sat = (
            f", saturated in {info['wingbeats_saturated']} wingbeat(s)"
            if info["wingbeats_saturated"]
            else ""
        )
        print(
            f"flew {reference.name} ({model}, {bird.name}, {'open loop' if result.open_loop else 'closed loop'}): "
            f"{info['wingbeats']:.1f} wingbeats, position error RMS {info['rms_error']:.3g} {m}, "
            f"max {info['max_error']:.3g} {m}"
            + (
                f" (after 2 wingbeats RMS {info['rms_error_after_start']:.3g} {m})"
                if info["wingbeats"] > 2
                else ""
            )
            + sat
            + (f"; wrote {out}" if out else "")
        )
    return 0
