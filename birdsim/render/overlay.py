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
OverlayLine = Union[tuple[str, tuple[int, int, int]], str]
WHITE, AMBER = (255, 255, 255), (255, 190, 60)

SKY_RGB = np.array([150, 190, 230], dtype=np.uint8)


def fill_sky(img: np.ndarray) -> None:
    """Paint the empty background (exactly black: nothing drawn there; the skybox is off
    for speed) a flat sky colour, in place."""
    empty = (img[..., 0] | img[..., 1] | img[..., 2]) == 0  # 5x faster than any(axis=2)
    img.reshape(-1, 3)[np.flatnonzero(empty)] = SKY_RGB  # rows by index: 3x faster than a mask


def overlay_lines(pb: Playback, i: int) -> list[tuple[str, tuple[int, int, int]]]:
    """Text of the overlay for playback instant ``i``: time, regime, V, Fx, Fz and the
    parameters."""
    used = {k: float(v[i]) for k, v in pb.demand_used.items()}
    lines = [
        (f"t = {pb.t_beats[i]:5.2f} beats   {pb.manoeuvre.name}: {pb.regime[i]}   model {pb.model.name}", WHITE),
        (f"V = {used['V']:.2f}   Fx = {used['Fx']:+.2f}   Fz = {used['Fz']:+.2f}  (right wing + body)", WHITE),
    ]
    names = list(pb.params)
    half = (len(names) + 1) // 2
    for chunk in (names[:half], names[half:]):
        if chunk:
            lines.append(("   ".join(f"{n} {round(float(pb.params[n][i]), 2) + 0.0:.2f}" for n in chunk), WHITE))
    if pb.clipped[i]:
        req = {k: float(v[i]) for k, v in pb.demand.items()}
        lines.append((f"clipped to table: asked V={req['V']:.2f} Fx={req['Fx']:+.2f} Fz={req['Fz']:+.2f}", AMBER))
    if pb.status[i] != "ok":
        lines.append((f"table cell: {pb.status[i]}", AMBER))
    return lines


def font_for_height(height: int) -> Any:
    """Pillow's default font at a size that reads at ``height`` pixels (a 36th of it)."""
    from PIL import ImageFont

    size = max(10, height // 36)
    try:
        return ImageFont.load_default(size=size)
    except TypeError:  # Pillow < 10.1: fixed bitmap font
        return ImageFont.load_default()


def draw_overlay(img: np.ndarray, lines: Sequence[OverlayLine], font: Any) -> None:
    """Draw ``lines`` top-left on a darkened band of ``img`` (in place)."""
    from PIL import Image, ImageDraw

    if not lines:
        return
    h, w = img.shape[:2]
    size = getattr(font, "size", 11)
    step = int(size * 1.3) + 1
    band_h = min(h, step * len(lines) + 8)
    band = img[:band_h]
    band //= 2
    pil = Image.fromarray(band)
    draw = ImageDraw.Draw(pil)
    for k, line in enumerate(lines):
        text, colour = (line, WHITE) if isinstance(line, str) else line
        draw.text((6, 4 + k * step), text, fill=tuple(colour), font=font)
    img[:band_h] = np.asarray(pil)


__all__ = ["OverlayLine", "SKY_RGB", "draw_overlay", "fill_sky", "font_for_height", "overlay_lines"]
