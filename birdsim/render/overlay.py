"""The text overlay drawn into each frame's pixels (Pillow): time, regime, demanded and
achieved force, wingbeat parameters; and the flat sky painted behind the scene.

An overlay is a list of lines, each ``(text, (r, g, b))`` or a plain ``str`` (white).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Union

import numpy as np

from birdsim.flight.playback import Playback

#: One overlay line: text and its colour, or text alone (white).
OverlayLine = Union[tuple[str, tuple[int, int, int]], str, list]  # a list: (text, colour) segments
WHITE, AMBER, GREY = (255, 255, 255), (255, 190, 60), (215, 215, 215)
DEMANDED, ACHIEVED = (200, 230, 255), (255, 215, 120)

SKY_RGB = np.array([150, 190, 230], dtype=np.uint8)


def fill_sky(img: np.ndarray) -> None:
    """Paint the empty background (exactly black: nothing drawn there; the skybox is off
    for speed) a flat sky colour, in place."""
    empty = (img[..., 0] | img[..., 1] | img[..., 2]) == 0  # 5x faster than any(axis=2)
    img.reshape(-1, 3)[np.flatnonzero(empty)] = SKY_RGB  # rows by index: 3x faster than a mask


#: Short names of the wingbeat parameters in the overlay.
SHORT = {
    "flap_amp": "flap",
    "twist_amp": "twist",
    "stroke_plane": "stroke",
    "sweep": "sweep",
    "wrist_amp": "wrist",
    "wrist_bias": "bias",
    "wrist_lag": "lag",
    "heave_amp": "heave",
}


def overlay_lines(pb: Playback, i: int) -> list[OverlayLine]:
    """Text of the overlay for playback instant ``i``: manoeuvre, regime, time, speed and
    what was clipped; the wingbeat parameters (the forces are added by the scene)."""
    used = {k: float(v[i]) for k, v in pb.demand_used.items()}
    title: list = [
        (
            f"{pb.manoeuvre.name}: {pb.regime[i]}   t {pb.t_beats[i]:5.2f} beats   V {used['V']:.2f}   {pb.model.name}",
            WHITE,
        )
    ]
    if pb.status[i] != "ok":
        title.append((f"   cell {pb.status[i]}", AMBER))
    lines: list[OverlayLine] = [title]
    lines.append(
        (
            "  ".join(
                f"{SHORT.get(n, n)} {round(float(pb.params[n][i]), 2) + 0.0:.2f}" for n in pb.params
            ),
            GREY,
        )
    )
    if pb.clipped[i]:
        req = {k: float(v[i]) for k, v in pb.demand.items()}
        lines.append(
            (
                f"clipped to table: asked V={req['V']:.2f} Fx={req['Fx']:+.2f} Fz={req['Fz']:+.2f}",
                AMBER,
            )
        )
    return lines


def force_lines(demanded: np.ndarray | None, achieved: np.ndarray) -> list[OverlayLine]:
    """Demanded and achieved force (the dissertation's: right wing + body drag, seed
    axes, Fz < 0 is up; achieved = wingbeat mean of the drawn state), table units."""

    def f(v: float) -> str:
        return f"{round(float(v), 2) + 0.0:+.2f}"  # + 0.0: no "-0.00"

    ach = [("achieved ", GREY), (f"Fx {f(achieved[0])} Fz {f(achieved[2])}", ACHIEVED)]
    dem = (
        []
        if demanded is None
        else [("demanded ", GREY), (f"Fx {f(demanded[0])} Fz {f(demanded[2])}   ", DEMANDED)]
    )
    return [dem + ach + [("  (right wing + body drag)", GREY)]]


def legend_line(unit_name: str, scale: float) -> OverlayLine:
    """The force arrows' colours and scale."""
    return [
        ("arrows ", GREY),
        ("arm ", (242, 90, 26)),
        ("hand ", (60, 120, 255)),
        ("drag   ", (200, 90, 240)),
        (f"{unit_name} = {scale:g} semispans", GREY),
    ]


def font_for_height(height: int) -> Any:
    """Pillow's default font at a size that reads at ``height`` pixels (a 30th of it)."""
    from PIL import ImageFont

    size = max(10, height // 30)
    try:
        return ImageFont.load_default(size=size)
    except TypeError:  # Pillow < 10.1: fixed bitmap font
        return ImageFont.load_default()


def draw_overlay(img: np.ndarray, lines: Sequence[OverlayLine], font: Any) -> None:
    """Draw ``lines`` top-left on a darkened band of ``img`` (in place); a line is a
    ``str``, a ``(text, colour)`` pair or a list of such pairs drawn side by side."""
    from PIL import Image

    if not lines:
        return
    h, w = img.shape[:2]
    size = getattr(font, "size", 11)
    step = int(size * 1.25) + 1
    band_h = min(h, step * len(lines) + 6)
    band = img[:band_h]
    band[:] = (band.astype(np.uint16) * 2 // 5).astype(np.uint8)
    pil = Image.fromarray(band)
    for k, line in enumerate(lines):
        parts = (
            [(line, WHITE)]
            if isinstance(line, str)
            else (line if isinstance(line, list) else [line])
        )
        x = 6
        for text, colour in parts:
            sprite = _text_sprite(text, tuple(colour), font)
            pil.paste(sprite, (x, 3 + k * step), sprite)
            x += sprite.width
    img[:band_h] = np.asarray(pil)


_SPRITES: dict = {}


def _text_sprite(text: str, colour: tuple, font: Any) -> Any:
    """``text`` rendered once in ``colour`` on a transparent image (cached: most of an
    overlay's words and numbers repeat from frame to frame)."""
    from PIL import Image, ImageDraw

    key = (text, colour, id(font))
    sprite = _SPRITES.get(key)
    if sprite is None:
        if len(_SPRITES) > 4096:
            _SPRITES.clear()
        probe = ImageDraw.Draw(Image.new("RGBA", (1, 1)))
        width = max(1, int(probe.textlength(text, font=font)))
        size = getattr(font, "size", 11)
        sprite = Image.new("RGBA", (width, int(size * 1.3) + 2), (0, 0, 0, 0))
        ImageDraw.Draw(sprite).text((0, 0), text, fill=colour, font=font)
        _SPRITES[key] = sprite
    return sprite


class PlotStrip:
    """A strip along the bottom of the frame plotting series over the whole clip, with
    a cursor at the current instant; drawn once, composited per frame.

    Args:
        width, height: of the frame (the strip is a seventh of the height).
        t: (N,) times of the series; series: [(label, values (N,), rgb)].
        font: for the labels.
    """

    def __init__(
        self,
        width: int,
        height: int,
        t: np.ndarray,
        series: Sequence[tuple[str, np.ndarray, tuple[int, int, int]]],
        font: Any,
    ):
        from PIL import Image, ImageDraw

        # the legend has its own row above the curves, so that they never over-print it
        self.label_h = int(font.getbbox("Fg")[3]) + 4 if hasattr(font, "getbbox") else 14
        self.h = max(24, height // 7) + self.label_h
        self.w = width
        self.t0, self.t1 = float(t[0]), float(t[-1]) if len(t) > 1 else float(t[0]) + 1.0
        vals = np.concatenate([np.asarray(v, dtype=float) for _, v, _ in series] + [np.zeros(1)])
        lo, hi = float(vals.min()), float(vals.max())
        pad = 0.1 * max(hi - lo, 1e-9)
        self.lo, self.hi = lo - pad, hi + pad
        layer = Image.new("RGBA", (width, self.h), (0, 0, 0, 0))
        draw = ImageDraw.Draw(layer)
        draw.rectangle([(0, 0), (width, self.label_h - 1)], fill=(0, 0, 0, 150))
        y0 = self._y(0.0)
        draw.line([(0, y0), (width, y0)], fill=(200, 200, 200, 140), width=1)
        for _label, v, rgb in series:
            if len(v) < 2:  # a label only
                continue
            pts = list(
                zip(self._x(np.asarray(t, dtype=float)), self._y(np.asarray(v, dtype=float)))
            )
            draw.line(pts, fill=(*rgb, 255), width=max(1, height // 240))
        x = 6
        for label, _, rgb in series:
            draw.text((x, 2), label, fill=(*rgb, 255), font=font)
            x += int(draw.textlength(label + "   ", font=font))
        self.layer = layer
        self._rgb: np.ndarray | None = None
        self._alpha: np.ndarray | None = None

    def _x(self, t):
        return ((np.asarray(t) - self.t0) / max(self.t1 - self.t0, 1e-12) * (self.w - 1)).tolist()

    def _y(self, v):
        """Pixel rows of values: the curves' area lies below the legend row."""
        rows = self.h - 1 - self.label_h
        return (self.label_h + (self.hi - np.asarray(v)) / (self.hi - self.lo) * rows).tolist()

    def draw(self, img: np.ndarray, t_now: float) -> None:
        """Composite the strip and a cursor at ``t_now`` into the bottom of ``img``
        (numpy on the cached layer: well under a millisecond at 640x480)."""
        if self._rgb is None:
            layer = np.asarray(self.layer, dtype=np.float32)
            self._alpha = layer[..., 3:4] / 255.0
            self._rgb = layer[..., :3] * self._alpha
        band = img[-self.h :]
        dark = band.astype(np.float32) * 0.4
        band[:] = (dark * (1.0 - self._alpha) + self._rgb).astype(np.uint8)
        x = int(round(self._x(t_now)))
        band[:, max(0, min(self.w - 1, x))] = 255


__all__ = [
    "OverlayLine",
    "PlotStrip",
    "SKY_RGB",
    "draw_overlay",
    "fill_sky",
    "font_for_height",
    "force_lines",
    "legend_line",
    "overlay_lines",
]
