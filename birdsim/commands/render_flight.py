"""``birdsim render`` in free flight (the default) and of a flight log (``LOG.npz``):
fly the manoeuvre in MuJoCo (birdsim.flight.freeflight), then draw the flown states with
the path as a thin line and the position error and saturation in the overlay."""

from __future__ import annotations

import argparse
import dataclasses
import math
from pathlib import Path

import numpy as np

from birdsim.commands.common import (
    bird_from_args,
    check_clip_outputs,
    check_still,
    load_bird,
    load_table_for,
    print_time_base,
    refuse_for_a_log,
    render_log_flags,
    slug,
)
from birdsim.errors import BirdsimError


def add_flight_arguments(p: argparse.ArgumentParser) -> None:
    """The free-flight options of ``birdsim render``."""
    p.add_argument(
        "--kinematic",
        action="store_true",
        help="prescribed playback of the table (no simulation): the body follows the path exactly",
    )
    p.add_argument(
        "--gust",
        action="append",
        default=[],
        metavar="T0:DURATION:WX:WY:WZ",
        help="free flight: a gust (see birdsim fly)",
    )
    p.add_argument(
        "--open-loop", action="store_true", help="free flight: feed-forward only (no feedback)"
    )
    p.add_argument(
        "--legs",
        action="store_true",
        help="free flight with legs and feet: take-off as a jump from the perch, landing as a touchdown (see birdsim fly)",
    )
    p.add_argument(
        "--attitude",
        choices=("posed", "free"),
        default=None,
        help="free flight: posed (the body's pitch prescribed; the default for a path in the vertical plane) or free (six DOF; the default for a turning path, said on stderr): see birdsim fly",
    )
    p.add_argument(
        "--strict",
        action="store_true",
        help="free flight: saturated wingbeats are an error (exit 2, nothing written); else one warning line",
    )


def free_flight_flags(args: argparse.Namespace) -> tuple[tuple[str, object], ...]:
    """The options of :func:`add_flight_arguments` that only a flight flown now takes
    (flag, value): a flight log and ``--kinematic`` refuse them."""
    return (
        ("--gust", args.gust),
        ("--open-loop", args.open_loop),
        ("--legs", args.legs),
        ("--attitude", args.attitude),
        ("--strict", args.strict),
    )


def refuse_with_kinematic(args: argparse.Namespace) -> None:
    """One line for the first free-flight option given with ``--kinematic`` (it was
    silently ignored by the prescribed playback)."""
    for flag, value in free_flight_flags(args):
        if value:
            raise BirdsimError(f"{flag} needs free flight; allowed: omit {flag} with --kinematic")


def is_log(name: str) -> bool:
    return Path(name).suffix.lower() == ".npz"


def flight_reference(
    source: str,
    model_arg: str | None,
    gust_args: list[str],
    attitude_arg: str | None = None,
    command: str = "render",
):
    """What free flight flies for SOURCE (a preset or a manoeuvre file): the path or the
    demand schedule of a force-keyframe file, the model (default the demo model), the
    gusts and the attitude (``--attitude``, else free for a turning path, said on stderr
    in one line, and posed for any other: :func:`birdsim.flight.path_file.attitude_for`).
    Shared by ``birdsim render`` and ``birdsim export``.

    Returns:
        (reference, model name, gusts, attitude).

    Raises:
        BirdsimError: an unknown preset or file, model or gust, ``--attitude posed`` for a
            turning path (one line).
    """
    from birdsim.flight.freeflight import DemandSchedule, parse_gust
    from birdsim.flight.manoeuvre import Manoeuvre
    from birdsim.flight.path_file import attitude_for, get_flight
    from birdsim.flight.presets import DEMO_MODEL
    from birdsim.physics.kinematics import get_model

    flight = get_flight(source, turning=True)
    model = get_model(model_arg or DEMO_MODEL).name
    gusts = [parse_gust(g) for g in gust_args]
    attitude = attitude_for(flight, attitude_arg, source, command=command)
    reference = DemandSchedule(flight) if isinstance(flight, Manoeuvre) else flight
    return reference, model, gusts, attitude


def flight_bird_and_table(args: argparse.Namespace, model: str) -> tuple:
    """The bird of ``--bird``/``--set`` (default the demo bird) and the table of
    ``--table`` (else the shipped one for that bird), checked for free flight.

    Raises:
        BirdsimError: a bad bird file or value, a bird without gravity, a table missing
            or built for another model or bird (one line).
    """
    bird = bird_from_args(args, default=None if args.bird else load_bird(None))
    if bird.gravity <= 0:
        raise BirdsimError(
            f"--bird {bird.name!r} has gravity={bird.gravity:g}; allowed: a bird file with gravity > 0 for free flight (or --kinematic)"
        )
    return bird, load_table_for(bird, model, args.table)


def fly_reference(
    reference,
    model: str,
    args: argparse.Namespace,
    *,
    beats: float,
    gusts: list,
    bird_and_table: tuple | None = None,
    attitude: str = "posed",
) -> dict:
    """Fly ``reference`` in MuJoCo for ``beats`` wingbeats with ``bird_and_table``
    (default :func:`flight_bird_and_table`), as ``birdsim render`` and ``birdsim
    export`` do; the flight log's arrays (bird units).

    Raises:
        BirdsimError: a bird without gravity, a table for another model or bird.
    """
    from birdsim.flight.flightlog import log_arrays
    from birdsim.flight.freeflight import fly
    from birdsim.flight.simulate import SimConfig

    bird, table = bird_and_table or flight_bird_and_table(args, model)
    if getattr(args, "legs", False):  # issue 25: the contact phases joined to the flight
        from birdsim.commands.fly import fly_with_legs
        from birdsim.flight.path import FlightPath

        if not (
            isinstance(reference, FlightPath) and (reference.perch_start or reference.perch_end)
        ):
            raise BirdsimError(
                f"--legs with {reference.name!r}; allowed: a path that starts or ends at rest on a perch or the ground, e.g. take-off or landing"
            )
        if gusts or args.open_loop:
            raise BirdsimError("--legs with --gust or --open-loop; allowed: --legs alone")
        result = fly_with_legs(reference, table, bird, model, attitude, None)
    else:
        result = fly(
            reference,
            table,
            bird,
            model,
            beats=beats,
            gusts=gusts,
            open_loop=args.open_loop,
            config=SimConfig(attitude=attitude),
        )
    log = log_arrays(result, reference.name)
    from birdsim.flight.saturation import report_saturation

    report_saturation(
        log,
        command=getattr(args, "command", "render"),
        bird_arg=args.bird,
        model=model,
        strict=getattr(args, "strict", False),
    )
    log["bird_obj"] = bird
    return log


def run_flight(args: argparse.Namespace, options_from_args) -> int:
    """Render a log (``args.manoeuvre`` ends in .npz) or a free flight of the manoeuvre.

    ``options_from_args(args, seconds=None)`` builds the RenderOptions as the kinematic
    path does (one place for size, fps, camera, quality...)."""
    from birdsim.flight.flightlog import load_log
    from birdsim.flight.flightstates import flight_states
    from birdsim.render.gl import select_gl

    options = options_from_args(args)
    from birdsim.flight.flock_log import is_flock_log

    if is_flock_log(args.manoeuvre):  # every bird of a flock (issue 27)
        from birdsim.commands.render_flock import run_flock_log

        return run_flock_log(args, options)
    if is_log(args.manoeuvre):
        if args.gust or args.open_loop or args.attitude:
            raise BirdsimError(
                "--gust/--open-loop/--attitude do not apply to a flight log; allowed: a manoeuvre name or file with them"
            )
        log = load_log(args.manoeuvre, "LOG")
        refuse_for_a_log(render_log_flags(args), str(log["model"]), args.model)
        name = str(log.get("manoeuvre", "")) or Path(args.manoeuvre).stem
        default_out = Path("renders") / f"{slug(Path(args.manoeuvre).stem)}.mp4"
        reference = None
    else:
        reference, model, gusts, attitude = flight_reference(
            args.manoeuvre, args.model, args.gust, args.attitude
        )
        name = reference.name
        default_out = Path("renders") / f"{slug(name)}-{model}.mp4"
    if options.seconds is None:  # the whole flight: one line when it would exceed the longest video
        from birdsim.render.options import MAX_SECONDS, RenderError

        omega = float(log["omega"]) if reference is None else None
        beats = (
            float(log["t"][-1]) * omega / (2 * 3.141592653589793)
            if reference is None
            else float(reference.duration_beats)
        )
        if beats / options.beats_per_second > MAX_SECONDS:
            raise RenderError(
                f"{name!r} lasts {beats:g} wingbeats = {beats / options.beats_per_second:g} s of video at --beat-rate "
                f"{options.beats_per_second:g}; allowed: at most {MAX_SECONDS:g} s (give --seconds or a higher --beat-rate)"
            )
    if reference is not None:
        clip_beats = (
            float(reference.duration_beats)
            if options.seconds is None
            else options.seconds * options.beats_per_second
        )
    else:
        clip_beats = float(log["t"][-1]) * float(log["omega"]) / (2 * 3.141592653589793)
    # --legs flies longer than the path (the stand before a take-off, the touchdown and
    # the stand after a landing): --at is checked against the flown log once it is flown
    legs_log = reference is not None and getattr(args, "legs", False) and options.seconds is None
    at = check_still(args, float("inf") if legs_log else clip_beats)
    select_gl(args.gl)  # a missing GL library -> one line; MUJOCO_GL set before the renderer starts
    # the bird and the table before any output is checked (checking makes its folder)
    bird_and_table = flight_bird_and_table(args, model) if reference is not None else None
    out = Path(args.out) if args.out else default_out
    check_clip_outputs(args, out, at)
    print_time_base(args)
    if reference is not None:
        beats = (
            reference.duration_beats
            if options.seconds is None
            else options.seconds * options.beats_per_second
        )
        log = fly_reference(
            reference,
            model,
            args,
            beats=beats,
            gusts=gusts,
            bird_and_table=bird_and_table,
            attitude=attitude,
        )
        if legs_log and at is not None:
            at = _at_in_flown(args.at, log)
    states = flight_states(
        log,
        dataclasses.replace(options, seconds=None) if reference is not None else options,
        title=name,
    )
    if getattr(reference, "scene", None) is not None:  # the path file's perches
        states = dataclasses.replace(states, perches=reference.scene)

    if at is not None:
        from birdsim.render.renderer import write_png
        from birdsim.render.scene import Scene

        with Scene(states, options) as scene:
            frame = min(scene.frames - 1, int(round(at * options.fps / options.beats_per_second)))
            path = write_png(Path(args.still), scene.rgb(frame))
        print(
            f"wrote {path} (frame at {at:g} beats of the free flight, {options.width}x{options.height}, camera {options.camera})"
        )
        return 0
    from birdsim.render.renderer import render_states

    result = render_states(states, out, options, force=args.force)
    print(
        f"wrote {result.path} ({result.frames} frames, {result.width}x{result.height} @ {result.fps} fps, "
        f"{result.video_seconds:.1f} s of video in {result.wall_seconds:.1f} s wall, GL {result.backend}, free flight)"
    )
    if args.sheet:
        from birdsim.render.renderer import contact_sheet

        print(f"wrote {contact_sheet(result.path, args.sheet)} (contact sheet)")
    return 0


def _at_in_flown(raw: str | None, log: dict) -> float:
    """``--at`` (already a number >= 0, or None: the middle) inside the flown log's
    length in wingbeats."""
    t = np.asarray(log["t"], dtype=float)
    flown = float(t[-1] - t[0]) * float(log["omega"]) / (2 * math.pi)
    if raw is None:
        return 0.5 * flown
    if float(raw) > flown:
        raise BirdsimError(
            f"--at {raw!r} is past the flown log; allowed: a time in wingbeats in [0, {flown:g}]"
        )
    return float(raw)
