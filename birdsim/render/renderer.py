"""Headless rendering of a manoeuvre to MP4: MuJoCo's offscreen renderer, cameras,
control-point pathlines (sec. 4.2.2), a text overlay, H.264 via imageio-ffmpeg.

Pipeline per frame: playback state -> ``birdsim.mujoco.driver.set_pose`` (qpos/qvel)
-> ``mujoco.Renderer.update_scene`` (camera ``track``, ``side``, ``top`` or
``overview`` of the MJCF) -> CP trail line segments appended to the scene -> render ->
overlay drawn into the pixels (Pillow) -> ffmpeg (libx264, yuv420p, a separate process,
so encoding overlaps rendering).  The file is written to a temporary sibling and
renamed into place; a failure or Ctrl-C leaves nothing behind.

Shadows, reflections, skybox and multisampling are off: on the CPU they cost several
times the frame rate.  Import :mod:`birdsim.render.gl` rules: the GL back-end is chosen
(:func:`birdsim.render.gl.select_gl`) before :mod:`mujoco` is imported, so this module imports
mujoco lazily.
"""

from __future__ import annotations

import math
import os
import re
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.errors import BirdsimError
from birdsim.render.gl import select_gl
from birdsim.io import check_output, temporary_sibling
from birdsim.flight.manoeuvre import Manoeuvre
from birdsim.flight.playback import Playback, TableLike, frame_times, play

CAMERAS = ("track", "side", "top", "overview")
#: Largest frame side accepted (MuJoCo's offscreen buffer is enlarged to fit).
MAX_SIDE = 4096
MAX_SECONDS = 3600.0  # longest video (--seconds, or the whole manoeuvre at --beat-rate)


class RenderError(BirdsimError):
    """A bad rendering option (size, fps, camera...)."""


@dataclass(frozen=True)
class RenderOptions:
    """What the video looks like.  ``seconds`` None = the whole manoeuvre; longer holds
    the last demands.  ``beats_per_second``: wingbeats shown per second of video."""

    width: int = 640
    height: int = 480
    fps: int = 30
    seconds: float | None = None
    beats_per_second: float = 2.0
    camera: str = "track"
    trails: bool = True
    trail_beats: float = 1.0
    trail_substeps: int = 4
    overlay: bool = True
    gl: str = "auto"
    crf: int = 23
    preset: str = "veryfast"
    progress: bool = True

    def __post_init__(self) -> None:
        for name in ("width", "height"):
            v = getattr(self, name)
            if not isinstance(v, int) or isinstance(v, bool) or v < 16 or v > MAX_SIDE or v % 16:
                raise RenderError(f"--size {name}={v!r} is invalid; allowed: a multiple of 16 in [16, {MAX_SIDE}] (H.264/yuv420p)")
        if not isinstance(self.fps, int) or isinstance(self.fps, bool) or not 1 <= self.fps <= 240:
            raise RenderError(f"--fps {self.fps!r} is invalid; allowed: an integer in [1, 240]")
        if self.seconds is not None and not (isinstance(self.seconds, (int, float)) and math.isfinite(self.seconds) and 0 < self.seconds <= MAX_SECONDS):
            raise RenderError(f"--seconds {self.seconds!r} is invalid; allowed: a number in (0, {MAX_SECONDS:g}]")
        if not (math.isfinite(self.beats_per_second) and 0 < self.beats_per_second <= 100):
            raise RenderError(f"--beat-rate {self.beats_per_second!r} is invalid; allowed: wingbeats per second in (0, 100]")
        if self.camera not in CAMERAS:
            raise RenderError(f"--camera {self.camera!r} is unknown; allowed: {', '.join(CAMERAS)}")
        if not (0 <= self.crf <= 51):
            raise RenderError(f"crf={self.crf!r} is invalid; allowed: 0..51")

    def duration(self, manoeuvre: Manoeuvre) -> float:
        """Seconds of video; one clear line when the whole manoeuvre would exceed an hour."""
        if self.seconds is not None:
            return self.seconds
        seconds = manoeuvre.duration / self.beats_per_second
        if seconds > MAX_SECONDS:
            raise RenderError(
                f"manoeuvre {manoeuvre.name!r} lasts {manoeuvre.duration:g} wingbeats = {seconds:g} s of video at --beat-rate "
                f"{self.beats_per_second:g}; allowed: at most {MAX_SECONDS:g} s (give --seconds or a higher --beat-rate)"
            )
        return seconds


def parse_size(text: str) -> tuple[int, int]:
    """``"640x480"`` -> (640, 480); one clear line for anything else."""
    m = re.fullmatch(r"\s*(\d+)\s*[xX]\s*(\d+)\s*", str(text))
    if not m:
        raise RenderError(f"--size {text!r} is malformed; allowed: WIDTHxHEIGHT, e.g. 640x480 (multiples of 16)")
    w, h = int(m.group(1)), int(m.group(2))
    for v in (w, h):
        if v < 16 or v > MAX_SIDE or v % 16:
            raise RenderError(f"--size {text!r} is invalid; allowed: sides that are multiples of 16 in [16, {MAX_SIDE}], e.g. 640x480, 1280x720")
    return w, h


@dataclass(frozen=True)
class RenderResult:
    path: Path
    frames: int
    width: int
    height: int
    fps: int
    video_seconds: float
    wall_seconds: float
    render_seconds: float  # inside mujoco's renderer only (update_scene + render)
    backend: str
    clip_note: str

    @property
    def animation_per_wall_second(self) -> float:
        return self.video_seconds / self.wall_seconds if self.wall_seconds > 0 else float("inf")


class Scene:
    """A posed MuJoCo bird with an offscreen renderer; use as a context manager.

    ``Scene(playback, options)`` builds the MJCF for the playback's model and bird,
    enlarges the offscreen buffer when needed, turns the costly effects off and
    precomputes the CP pathlines.  ``playback`` holds ``options.trail_substeps``
    instants per video frame (see :func:`play_for_video`); frame ``i`` is instant
    ``i * trail_substeps``.  ``rgb(i)`` renders frame ``i`` (overlay included),
    ``segmentation(i)`` the (object id, object type) image of the same view."""

    def __init__(self, playback: Playback, options: RenderOptions):
        import mujoco

        from birdsim.mujoco.model import aero_sites, build_model

        self._mj = mujoco
        self.playback = playback
        self.options = options
        self.sub = max(1, int(options.trail_substeps))
        self.frames = -(-playback.frames // self.sub)
        self.m = build_model(playback.model.name, playback.bird)
        self.m.vis.global_.offwidth = max(int(self.m.vis.global_.offwidth), options.width)
        self.m.vis.global_.offheight = max(int(self.m.vis.global_.offheight), options.height)
        self.m.vis.quality.offsamples = 0
        self.m.vis.quality.shadowsize = 0
        floor = mujoco.mj_name2id(self.m, mujoco.mjtObj.mjOBJ_GEOM, "floor")
        if floor >= 0 and self.m.geom_type[floor] == mujoco.mjtGeom.mjGEOM_PLANE:
            self.m.geom_size[floor][:2] = 0.0  # drawn without edges (this copy only renders)
        self.d = mujoco.MjData(self.m)
        self.renderer = mujoco.Renderer(self.m, options.height, options.width, max_geom=4000)
        flags = self.renderer.scene.flags
        for flag in ("mjRND_SHADOW", "mjRND_REFLECTION", "mjRND_SKYBOX", "mjRND_FOG", "mjRND_HAZE"):
            if hasattr(mujoco.mjtRndFlag, flag):
                flags[getattr(mujoco.mjtRndFlag, flag)] = 0
        self.camera = self._camera(options.camera)
        self._qpos, self._qvel = self._batched_state()
        self.option = mujoco.MjvOption()
        self.sites = [s.site for s in aero_sites(playback.model.name, playback.bird)]
        self.site_ids = [mujoco.mj_name2id(self.m, mujoco.mjtObj.mjOBJ_SITE, s) for s in self.sites]
        self.trails = self._trails() if options.trails else None
        self._font = None

    # ---- set-up ----------------------------------------------------------------------

    def _camera(self, name: str) -> Any:
        mj = self._mj
        cid = mj.mj_name2id(self.m, mj.mjtObj.mjOBJ_CAMERA, name)
        if cid < 0:
            raise RenderError(f"--camera {name!r} is not in the MuJoCo model; allowed: {', '.join(CAMERAS)}")
        return cid

    def _batched_state(self) -> tuple[np.ndarray, np.ndarray]:
        """qpos, qvel of every playback instant at once (the driver's vectorised path;
        ``set_pose`` does the same for one instant)."""
        from birdsim.mujoco.driver import set_root, wing_arrays

        pb = self.playback
        qpos, qvel, _ = wing_arrays(self.m, pb.angles, pb.rates, samples=pb.frames)
        set_root(self.m, qpos, qvel, pitch=pb.pitch, position_seed=pb.position_seed, velocity_seed=pb.velocity_seed, pitch_rate=pb.pitch_rate)
        return qpos, qvel

    def pose_instant(self, k: int) -> None:
        """Pose the bird at playback instant ``k``: qpos/qvel, then only what drawing
        needs (kinematics, centre of mass for the tracking cameras, cameras/lights)."""
        mj = self._mj
        self.d.qpos[:] = self._qpos[k]
        self.d.qvel[:] = self._qvel[k]
        mj.mj_kinematics(self.m, self.d)
        mj.mj_comPos(self.m, self.d)
        mj.mj_camlight(self.m, self.d)

    def _trails(self) -> np.ndarray:
        """World positions of the CP sites at every playback instant, (instants, sites, 3)."""
        out = np.empty((self.playback.frames, len(self.site_ids), 3))
        for k in range(self.playback.frames):
            self.pose_instant(k)
            out[k] = self.d.site_xpos[self.site_ids]
        return out

    # ---- per frame -------------------------------------------------------------------

    def update(self, i: int) -> None:
        """Pose frame ``i`` and build its scene (bird, camera, pathlines)."""
        self.pose_instant(i * self.sub)
        self.renderer.update_scene(self.d, camera=self.camera, scene_option=self.option)
        if self.trails is not None:
            self._add_trails(i)

    def _add_trails(self, i: int) -> None:
        mj = self._mj
        sub = self.sub
        per_frame_beats = self.options.beats_per_second / self.options.fps
        n_keep = max(2, int(round(self.options.trail_beats / per_frame_beats * sub)))
        end = i * sub + 1
        pts = self.trails[max(0, end - n_keep) : end]
        scn = self.renderer.scene
        for s in range(pts.shape[1]):
            base = (0.1, 0.35, 0.95) if "hand" in self.sites[s] else (0.95, 0.15, 0.1)  # hand CP blue, arm/wing CP red
            for k in range(len(pts) - 1):
                if scn.ngeom >= scn.maxgeom:
                    return
                g = scn.geoms[scn.ngeom]
                age = (k + 1) / (len(pts) - 1)
                mj.mjv_initGeom(g, mj.mjtGeom.mjGEOM_LINE, np.zeros(3), np.zeros(3), np.eye(3).ravel(), np.array([*base, 0.25 + 0.75 * age], dtype=np.float32))
                mj.mjv_connector(g, mj.mjtGeom.mjGEOM_LINE, 3.0, pts[k, s], pts[k + 1, s])
                g.segid = -1  # decoration: not an object of the model (segmentation skips it)
                scn.ngeom += 1

    def rgb(self, i: int) -> np.ndarray:
        self.update(i)
        img = self.renderer.render()
        fill_sky(img)
        if self.options.overlay:
            draw_overlay(img, overlay_lines(self.playback, i * self.sub), self._get_font())
        return img

    def segmentation(self, i: int) -> np.ndarray:
        """(H, W, 2): object id and object type per pixel (-1 where nothing)."""
        self.update(i)
        self.renderer.enable_segmentation_rendering()
        try:
            return self.renderer.render().copy()
        finally:
            self.renderer.disable_segmentation_rendering()

    def bird_geoms(self) -> np.ndarray:
        """Geom ids of the bird (every body below the torso) and, separately, its wings."""
        mj = self._mj
        torso = mj.mj_name2id(self.m, mj.mjtObj.mjOBJ_BODY, "torso")
        return np.flatnonzero(self.m.body_rootid[self.m.geom_bodyid] == torso)

    def wing_geoms(self) -> np.ndarray:
        mj = self._mj
        torso = mj.mj_name2id(self.m, mj.mjtObj.mjOBJ_BODY, "torso")
        g = self.bird_geoms()
        return g[self.m.geom_bodyid[g] != torso]

    def _get_font(self) -> Any:
        if self._font is None:
            from PIL import ImageFont

            size = max(10, self.options.height // 36)
            try:
                self._font = ImageFont.load_default(size=size)
            except TypeError:  # Pillow < 10.1: fixed bitmap font
                self._font = ImageFont.load_default()
        return self._font

    def close(self) -> None:
        self.renderer.close()

    def __enter__(self) -> "Scene":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def play_for_video(
    manoeuvre: Manoeuvre, table: TableLike, options: RenderOptions, *, bird: Bird | None = None, model: str | None = None
) -> Playback:
    """The playback at ``trail_substeps`` instants per video frame, the body placed so
    that a perched start or end sits on the scene's perch."""
    sub = max(1, int(options.trail_substeps))
    frames = len(frame_times(options.duration(manoeuvre), options.fps, options.beats_per_second))
    t_beats = np.arange(frames * sub) * (options.beats_per_second / (options.fps * sub))
    bird = bird or getattr(table, "bird", None) or Bird()
    kin = play(manoeuvre, table, t_beats[:1], bird=bird, model=model).model  # validates model and table first
    return play(manoeuvre, table, t_beats, bird=bird, model=model, perch_seed=perch_seed_position(kin.name, bird))


SKY_RGB = np.array([150, 190, 230], dtype=np.uint8)


def fill_sky(img: np.ndarray) -> None:
    """Paint the empty background (exactly black: nothing drawn there; the skybox is off
    for speed) a flat sky colour, in place."""
    empty = (img[..., 0] | img[..., 1] | img[..., 2]) == 0  # 5x faster than any(axis=2)
    img.reshape(-1, 3)[np.flatnonzero(empty)] = SKY_RGB  # rows by index: 3x faster than a mask


def overlay_lines(pb: Playback, i: int) -> list[tuple[str, tuple[int, int, int]]]:
    """Text of the overlay for frame ``i``: time, regime, V, Fx, Fz and the parameters."""
    white, amber = (255, 255, 255), (255, 190, 60)
    used = {k: float(v[i]) for k, v in pb.demand_used.items()}
    lines = [
        (f"t = {pb.t_beats[i]:5.2f} beats   {pb.manoeuvre.name}: {pb.regime[i]}   model {pb.model.name}", white),
        (f"V = {used['V']:.2f}   Fx = {used['Fx']:+.2f}   Fz = {used['Fz']:+.2f}  (right wing + body)", white),
    ]
    names = list(pb.params)
    half = (len(names) + 1) // 2
    for chunk in (names[:half], names[half:]):
        if chunk:
            lines.append(("   ".join(f"{n} {round(float(pb.params[n][i]), 2) + 0.0:.2f}" for n in chunk), white))
    if pb.clipped[i]:
        req = {k: float(v[i]) for k, v in pb.demand.items()}
        lines.append((f"clipped to table: asked V={req['V']:.2f} Fx={req['Fx']:+.2f} Fz={req['Fz']:+.2f}", amber))
    if pb.status[i] != "ok":
        lines.append((f"table cell: {pb.status[i]}", amber))
    return lines


def draw_overlay(img: np.ndarray, lines: list[tuple[str, tuple[int, int, int]]], font: Any) -> None:
    """Draw ``lines`` top-left on a darkened band of ``img`` (in place)."""
    from PIL import Image, ImageDraw

    h, w = img.shape[:2]
    size = getattr(font, "size", 11)
    step = int(size * 1.3) + 1
    band_h = min(h, step * len(lines) + 8)
    band = img[:band_h]
    band //= 2
    pil = Image.fromarray(band)
    draw = ImageDraw.Draw(pil)
    for k, (text, colour) in enumerate(lines):
        draw.text((6, 4 + k * step), text, fill=colour, font=font)
    img[:band_h] = np.asarray(pil)


@contextmanager
def mp4_writer(path: Path, width: int, height: int, fps: int, *, crf: int = 23, preset: str = "veryfast") -> Iterator[Any]:
    """A generator taking RGB frames (H, W, 3 uint8); the MP4 appears at ``path`` only
    when the block ends without an exception (temporary sibling + os.replace)."""
    import imageio_ffmpeg

    try:
        tmp = temporary_sibling(path)
    except OSError as exc:
        raise RenderError(f"--out {str(path)!r} is not writable: {exc.strerror}; allowed: a path in a writable folder") from None
    writer = imageio_ffmpeg.write_frames(
        str(tmp),
        (width, height),
        fps=fps,
        codec="libx264",
        pix_fmt_in="rgb24",
        pix_fmt_out="yuv420p",
        quality=None,
        macro_block_size=16,
        ffmpeg_log_level="error",
        output_params=["-crf", str(crf), "-preset", preset, "-movflags", "+faststart"],
    )
    ok = False
    try:
        writer.send(None)
        yield writer
        ok = True
    finally:
        try:
            writer.close()
        except Exception:
            ok = False
            raise
        finally:
            if ok:
                umask = os.umask(0)
                os.umask(umask)
                os.chmod(tmp, 0o666 & ~umask)  # mkstemp made it 0600; a video is for sharing
                os.replace(tmp, path)
            elif tmp.exists():
                tmp.unlink()


def video_info(path: str | Path) -> dict[str, Any]:
    """Codec, pixel format, size, fps and frame count of a video (ffmpeg's own reading)."""
    import imageio_ffmpeg

    gen = imageio_ffmpeg.read_frames(str(path))
    meta = next(gen)
    gen.close()
    frames, secs = imageio_ffmpeg.count_frames_and_secs(str(path))
    return {"codec": meta.get("codec"), "pix_fmt": meta.get("pix_fmt"), "size": tuple(meta.get("size", ())), "fps": meta.get("fps"), "frames": frames, "seconds": secs}


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
    """Render ``manoeuvre`` driven by ``table`` to the MP4 ``out``."""
    wall0 = time.perf_counter()
    out = check_output(Path(out), force)
    if out.suffix.lower() != ".mp4":
        raise RenderError(f"--out {str(out)!r} does not end in .mp4; allowed: a .mp4 path")
    backend = select_gl(options.gl)
    seconds = options.duration(manoeuvre)
    pb = play_for_video(manoeuvre, table, options, bird=bird, model=model)
    log = log if log is not None else sys.stderr
    if pb.clip_note:
        print(f"render: {pb.clip_note}", file=log)
    from tqdm import tqdm

    render_s = 0.0
    with Scene(pb, options) as scene, mp4_writer(out, options.width, options.height, options.fps, crf=options.crf, preset=options.preset) as writer:
        for i in tqdm(range(scene.frames), desc=f"render {manoeuvre.name}", unit="frame", disable=not options.progress, file=log):
            t0 = time.perf_counter()
            scene.update(i)
            img = scene.renderer.render()
            render_s += time.perf_counter() - t0
            fill_sky(img)
            if options.overlay:
                draw_overlay(img, overlay_lines(pb, i * scene.sub), scene._get_font())
            writer.send(np.ascontiguousarray(img))
    return RenderResult(out, scene.frames, options.width, options.height, options.fps, seconds, time.perf_counter() - wall0, render_s, backend, pb.clip_note)


def perch_seed_position(model_name: str, bird: Bird) -> tuple[float, float]:
    """(X, Z) in seed axes of the torso when it sits on the MJCF's perch."""
    import mujoco

    from birdsim.mujoco.model import build_model

    m = build_model(model_name, bird)
    d = mujoco.MjData(m)
    mujoco.mj_kinematics(m, d)
    sid = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_SITE, "perch_top")
    gid = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, "torso_body")
    if sid < 0:
        return (0.0, -3.0)
    top = d.site_xpos[sid]
    clearance = float(m.geom_size[gid][2]) if gid >= 0 else 0.1 * bird.semispan
    return (float(top[0]), -float(top[2] + clearance))


__all__ = ["CAMERAS", "RenderError", "RenderOptions", "RenderResult", "Scene", "draw_overlay", "mp4_writer", "overlay_lines", "parse_size", "perch_seed_position", "render_manoeuvre", "video_info"]


def contact_sheet(video: str | Path, out: str | Path, *, count: int = 12, columns: int = 4, thumb_width: int = 320) -> Path:
    """A PNG grid of ``count`` evenly spaced frames of ``video`` (for looking at a clip)."""
    import imageio_ffmpeg
    from PIL import Image

    info = video_info(video)
    total = int(info["frames"])
    wanted = set(np.linspace(0, total - 1, min(count, total)).round().astype(int).tolist())
    w, h = info["size"]
    gen = imageio_ffmpeg.read_frames(str(video))
    next(gen)
    thumbs = []
    for k, raw in enumerate(gen):
        if k in wanted:
            img = Image.frombuffer("RGB", (w, h), raw, "raw", "RGB", 0, 1)
            thumbs.append(img.resize((thumb_width, int(h * thumb_width / w))))
    gen.close()
    rows = -(-len(thumbs) // columns)
    th = thumbs[0].height
    sheet = Image.new("RGB", (columns * thumb_width, rows * th), (0, 0, 0))
    for k, t in enumerate(thumbs):
        sheet.paste(t, ((k % columns) * thumb_width, (k // columns) * th))
    import io

    from birdsim.io import write_atomic

    buf = io.BytesIO()
    sheet.save(buf, format="PNG")
    out = Path(out)
    write_atomic(out, buf.getvalue())
    return out
