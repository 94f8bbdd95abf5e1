"""What a rendered video looks like: :class:`RenderOptions` (size, frame rate, camera,
trails, overlay...), the ``--size`` parser and the :class:`RenderResult` of a run.

Every check here is cheap and runs before any work, so a bad option costs nothing and
writes nothing (one :class:`RenderError` line naming the flag).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

from birdsim.errors import BirdsimError
from birdsim.flight.manoeuvre import Manoeuvre

CAMERAS = ("track", "chase", "side", "top", "overview")
#: What each camera shows (``--camera list``).
CAMERA_HELP = {
    "track": "follows the bird from behind, beside and above (critically damped)",
    "chase": "behind and above the bird, looking along its path (critically damped)",
    "side": "beside the bird at its height, the flight path across the frame",
    "top": "straight down on the bird",
    "overview": "fixed, far to the side: keeps the whole manoeuvre in frame",
}


@dataclass(frozen=True)
class Quality:
    """Costly effects of one ``--quality`` level (their measured cost: docs/rendering.md)."""

    name: str
    shadowsize: int  # shadow map side in texels, 0 = no shadows
    samples: int  # multisampling (anti-aliasing) samples, 0 = off
    skybox: bool  # the sky gradient drawn by MuJoCo (else a flat colour behind the scene)
    haze: bool  # the ground fades into the sky at the horizon
    textures: bool  # checker ground, bark


QUALITIES = {
    "draft": Quality("draft", shadowsize=0, samples=0, skybox=False, haze=False, textures=True),
    "good": Quality("good", shadowsize=1024, samples=0, skybox=True, haze=True, textures=True),
    "best": Quality("best", shadowsize=2048, samples=4, skybox=True, haze=True, textures=True),
}
#: Largest frame side accepted (MuJoCo's offscreen buffer is enlarged to fit).
MAX_SIDE = 4096
MAX_SECONDS = 3600.0  # longest video (--seconds, or the whole manoeuvre at --beat-rate)
#: what --fps and --seconds allow (the end of their one-line messages)
FPS_ALLOWED = "an integer in [1, 240]"
SECONDS_ALLOWED = f"a number in (0, {MAX_SECONDS:g}]"


#: How much text the overlay shows (``--overlay``; ``none`` is ``overlay=False``).
OVERLAY_DETAILS = ("short", "full")


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
    overlay_detail: str = "short"  # "short": at most three lines; "full": the engineering view
    reference: bool = True  # draw the reference path (off with --clean)
    quality: str = "good"
    forces: float | None = None  # force arrows: length per weight in semispans (None = no arrows)
    gl: str = "auto"
    crf: int = 23
    preset: str = "veryfast"
    progress: bool = True

    def __post_init__(self) -> None:
        for name in ("width", "height"):
            v = getattr(self, name)
            if not isinstance(v, int) or isinstance(v, bool) or v < 16 or v > MAX_SIDE or v % 16:
                raise RenderError(
                    f"--size {name}={v!r} is invalid; allowed: a multiple of 16 in [16, {MAX_SIDE}] (H.264/yuv420p)"
                )
        if not isinstance(self.fps, int) or isinstance(self.fps, bool) or not 1 <= self.fps <= 240:
            raise RenderError(f"--fps {self.fps!r} is invalid; allowed: {FPS_ALLOWED}")
        if self.seconds is not None and not (
            isinstance(self.seconds, (int, float))
            and math.isfinite(self.seconds)
            and 0 < self.seconds <= MAX_SECONDS
        ):
            raise RenderError(f"--seconds {self.seconds!r} is invalid; allowed: {SECONDS_ALLOWED}")
        if not (math.isfinite(self.beats_per_second) and 0 < self.beats_per_second <= 100):
            raise RenderError(
                f"--beat-rate {self.beats_per_second!r} is invalid; allowed: wingbeats per second in (0, 100]"
            )
        if self.camera not in CAMERAS:
            raise RenderError(f"--camera {self.camera!r} is unknown; allowed: {', '.join(CAMERAS)}")
        if self.overlay_detail not in OVERLAY_DETAILS:
            raise RenderError(
                f"--overlay {self.overlay_detail!r} is unknown; allowed: {', '.join(OVERLAY_DETAILS)} (or none)"
            )
        if self.quality not in QUALITIES:
            raise RenderError(
                f"--quality {self.quality!r} is unknown; allowed: {', '.join(QUALITIES)}"
            )
        if self.forces is not None and not (
            isinstance(self.forces, (int, float))
            and not isinstance(self.forces, bool)
            and math.isfinite(self.forces)
            and 0 < self.forces <= 1e6
        ):
            raise RenderError(
                f"--forces {self.forces!r} is invalid; allowed: a positive number (arrow length of one weight, in semispans)"
            )
        if not (0 <= self.crf <= 51):
            raise RenderError(f"crf={self.crf!r} is invalid; allowed: 0..51")

    @property
    def look(self) -> Quality:
        """The :class:`Quality` of ``quality``."""
        return QUALITIES[self.quality]

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
        raise RenderError(
            f"--size {text!r} is malformed; allowed: WIDTHxHEIGHT, e.g. 640x480 (multiples of 16)"
        )
    w, h = int(m.group(1)), int(m.group(2))
    for v in (w, h):
        if v < 16 or v > MAX_SIDE or v % 16:
            raise RenderError(
                f"--size {text!r} is invalid; allowed: sides that are multiples of 16 in [16, {MAX_SIDE}], e.g. 640x480, 1280x720"
            )
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


__all__ = [
    "CAMERAS",
    "CAMERA_HELP",
    "MAX_SECONDS",
    "MAX_SIDE",
    "QUALITIES",
    "Quality",
    "RenderError",
    "RenderOptions",
    "RenderResult",
    "parse_size",
]
