"""``birdsim render FLOCK_LOG.npz``: a flock's log (``birdsim fly FLOCK --out``) drawn with
every bird (:class:`birdsim.render.flock_scene.FlockScene`): the leader (bird 0) with the
overlay, its reference path and trails, the others beside it, the camera framing the
whole flock.  ``--still F.png --at BEATS`` draws one frame."""

from __future__ import annotations

import argparse
import dataclasses
import math
from pathlib import Path

from birdsim.errors import BirdsimError


def run_flock_log(args: argparse.Namespace, options) -> int:
    """Render the flock log ``args.manoeuvre`` (video, or a still with ``--still``)."""
    from birdsim.commands.common import (
        check_clip_outputs,
        check_still,
        print_time_base,
        refuse_for_a_log,
        render_log_flags,
        slug,
    )
    from birdsim.flight.flock_log import load_flock_log
    from birdsim.render.flock_scene import FlockScene, flock_states, scene_factory
    from birdsim.render.gl import select_gl
    from birdsim.render.options import MAX_SECONDS, RenderError

    if args.gust or args.open_loop or args.attitude:
        raise BirdsimError(
            "--gust/--open-loop/--attitude do not apply to a flight log; allowed: a manoeuvre name or file with them"
        )
    data, birds = load_flock_log(args.manoeuvre, "LOG")
    refuse_for_a_log(render_log_flags(args), str(birds[0]["model"]), args.model)
    name = f"flock {str(data['flock'])} ({len(birds)} birds)"
    lead = birds[0]
    beats = float(lead["t"][-1]) * float(lead["omega"]) / (2 * math.pi)
    if options.seconds is None and beats / options.beats_per_second > MAX_SECONDS:
        raise RenderError(
            f"{name!r} lasts {beats:g} wingbeats = {beats / options.beats_per_second:g} s of video at --beat-rate "
            f"{options.beats_per_second:g}; allowed: at most {MAX_SECONDS:g} s (give --seconds or a higher --beat-rate)"
        )
    at = check_still(args, beats)
    select_gl(args.gl)
    out = Path(args.out) if args.out else Path("renders") / f"{slug(Path(args.manoeuvre).stem)}.mp4"
    check_clip_outputs(args, out, at)
    print_time_base(args)
    states = flock_states(birds, options, title=name)
    leader, others = states[0], states[1:]
    if at is not None:
        from birdsim.render.renderer import write_png

        with FlockScene(leader, options, others) as scene:
            frame = min(scene.frames - 1, int(round(at * options.fps / options.beats_per_second)))
            path = write_png(Path(args.still), scene.rgb(frame))
        print(
            f"wrote {path} (frame at {at:g} beats of {name}, {options.width}x{options.height}, camera {options.camera})"
        )
        return 0
    from birdsim.render.renderer import render_states

    result = render_states(
        dataclasses.replace(leader, title=name),
        out,
        options,
        force=args.force,
        make_scene=scene_factory(others),
    )
    print(
        f"wrote {result.path} ({result.frames} frames, {result.width}x{result.height} @ {result.fps} fps, "
        f"{result.video_seconds:.1f} s of video in {result.wall_seconds:.1f} s wall, GL {result.backend}, {name})"
    )
    if args.sheet:
        from birdsim.render.renderer import contact_sheet

        print(f"wrote {contact_sheet(result.path, args.sheet)} (contact sheet)")
    return 0


__all__ = ["run_flock_log"]
