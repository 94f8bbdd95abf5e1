"""Headless rendering to MP4: any :class:`~birdsim.render.states.StateSequence`
(:func:`render_states`) or a manoeuvre driven by a lookup table
(:func:`render_manoeuvre`).

The parts live in their own modules: options (:mod:`birdsim.render.options`), what is
drawn (:mod:`~birdsim.render.states`), the MuJoCo scene and cameras
(:mod:`~birdsim.render.scene`), pathlines and reference path
(:mod:`~birdsim.render.decor`), text overlay (:mod:`~birdsim.render.overlay`), H.264
encoding (:mod:`~birdsim.render.encode`) and contact sheets
(:mod:`~birdsim.render.sheet`).  Their public names are re-exported here.

The MP4 is written to a temporary sibling and renamed into place; a failure or Ctrl-C
leaves nothing behind.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

from birdsim.flight.manoeuvre import Manoeuvre
from birdsim.flight.playback import TableLike
from birdsim.io import check_output
from birdsim.physics.bird import Bird
from birdsim.render.encode import mp4_writer, video_info
from birdsim.render.gl import select_gl
from birdsim.render.options import (
    CAMERAS,
    MAX_SECONDS,
    MAX_SIDE,
    RenderError,
    RenderOptions,
    RenderResult,
    parse_size,
)
from birdsim.render.overlay import SKY_RGB, draw_overlay, fill_sky, overlay_lines
from birdsim.render.scene import Scene
from birdsim.render.sheet import contact_sheet
from birdsim.render.states import (
    StateSequence,
    perch_seed_position,
    play_for_video,
    states_from_playback,
)


def render_states(
    states: StateSequence,
    out: str | Path,
    options: RenderOptions = RenderOptions(),
    *,
    force: bool = False,
    log: Any = None,
    make_scene: Any = None,
) -> RenderResult:
    """Render every frame of ``states`` to the MP4 ``out``.

    Args:
        states: what to draw (see :mod:`birdsim.render.states`).
        out: a ``.mp4`` path; refused when it exists unless ``force``.
        options: size, fps, camera, trails, overlay, GL back-end (``seconds`` and
            ``beats_per_second`` are not used: the states fix the frames).
        force: overwrite an existing ``out``.
        log: where the clip note and the progress bar go (default stderr).
        make_scene: a factory ``(states, options) -> Scene`` (default: Scene; a flock's:
            :func:`birdsim.render.flock_scene.scene_factory`).

    Returns:
        A :class:`RenderResult` (frames, wall and render seconds, back-end).

    Raises:
        RenderError: bad ``out`` (suffix, unwritable) or states that do not fit the model.
        birdsim.io errors: ``out`` exists without ``force``.
    """
    wall0 = time.perf_counter()
    out = check_output(Path(out), force)
    if out.suffix.lower() != ".mp4":
        raise RenderError(f"--out {str(out)!r} does not end in .mp4; allowed: a .mp4 path")
    backend = select_gl(options.gl)
    log = log if log is not None else sys.stderr
    if states.clip_note:
        print(f"render: {states.clip_note}", file=log)
    from tqdm import tqdm

    render_s = 0.0
    with (
        (make_scene or Scene)(states, options) as scene,
        mp4_writer(
            out, options.width, options.height, options.fps, crf=options.crf, preset=options.preset
        ) as writer,
    ):
        for i in tqdm(
            range(scene.frames),
            desc=f"render {states.title}".rstrip(),
            unit="frame",
            disable=None if options.progress else True,
            file=log,
        ):
            t0 = time.perf_counter()
            scene.update(i)
            img = scene.renderer.render()
            render_s += time.perf_counter() - t0
            writer.send(np.ascontiguousarray(scene.finish(img, i)))
    return RenderResult(
        out,
        scene.frames,
        options.width,
        options.height,
        options.fps,
        scene.frames / options.fps,
        time.perf_counter() - wall0,
        render_s,
        backend,
        states.clip_note,
    )


def render_manoeuvre(
    manoeuvre: Manoeuvre,
    table: TableLike,
    out: str | Path,
    options: RenderOptions = RenderOptions(),
    *,
    bird: Bird | None = None,
    model: str | None = None,
    force: bool = False,
    log: Any = None,
) -> RenderResult:
    """Render ``manoeuvre`` driven by ``table`` to the MP4 ``out`` (see
    :func:`render_states`; the output is checked before the playback is computed)."""
    out = check_output(Path(out), force)
    if out.suffix.lower() != ".mp4":
        raise RenderError(f"--out {str(out)!r} does not end in .mp4; allowed: a .mp4 path")
    select_gl(options.gl)
    pb = play_for_video(manoeuvre, table, options, bird=bird, model=model)
    states = states_from_playback(pb, max(1, int(options.trail_substeps)))
    return render_states(states, out, options, force=force, log=log)


def render_still(
    manoeuvre: Manoeuvre,
    table: TableLike,
    out: str | Path,
    at_beats: float,
    options: RenderOptions = RenderOptions(),
    *,
    bird: Bird | None = None,
    model: str | None = None,
    force: bool = False,
) -> Path:
    """One frame of ``manoeuvre`` at ``at_beats`` wingbeats, as a PNG at ``out``.

    The whole clip is played (the cameras' smoothing and the wingbeat-mean force need
    it); the frame nearest to ``at_beats`` is drawn.

    Raises:
        RenderError: ``at_beats`` outside the clip, ``out`` not a writable .png.
    """
    out = check_output(Path(out), force, "--still")
    if out.suffix.lower() != ".png":
        raise RenderError(f"--still {str(out)!r} does not end in .png; allowed: a .png path")
    clip_beats = options.duration(manoeuvre) * options.beats_per_second
    if not (0.0 <= at_beats <= clip_beats):
        raise RenderError(
            f"--at {at_beats!r} is outside the clip; allowed: a time in wingbeats in [0, {clip_beats:g}]"
        )
    select_gl(options.gl)
    pb = play_for_video(manoeuvre, table, options, bird=bird, model=model)
    states = states_from_playback(pb, max(1, int(options.trail_substeps)))
    with Scene(states, options) as scene:
        frame = min(scene.frames - 1, int(round(at_beats * options.fps / options.beats_per_second)))
        return write_png(out, scene.rgb(frame))


def write_png(out: Path, img: np.ndarray) -> Path:
    """``img`` (H, W, 3 uint8) as an optimised PNG, written atomically."""
    import io

    from PIL import Image

    from birdsim.io import write_atomic

    buf = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(img)).save(buf, format="PNG", optimize=True)
    write_atomic(Path(out), buf.getvalue())
    return Path(out)


__all__ = [
    "CAMERAS",
    "MAX_SECONDS",
    "MAX_SIDE",
    "RenderError",
    "RenderOptions",
    "RenderResult",
    "SKY_RGB",
    "Scene",
    "StateSequence",
    "contact_sheet",
    "draw_overlay",
    "fill_sky",
    "mp4_writer",
    "overlay_lines",
    "parse_size",
    "perch_seed_position",
    "play_for_video",
    "render_manoeuvre",
    "render_states",
    "render_still",
    "states_from_playback",
    "video_info",
    "write_png",
]
