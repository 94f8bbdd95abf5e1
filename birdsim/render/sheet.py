"""Contact sheets: a PNG grid of evenly spaced frames of a video, for looking at a clip."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from birdsim.io import write_atomic
from birdsim.render.encode import video_info


def contact_sheet(
    video: str | Path, out: str | Path, *, count: int = 12, columns: int = 4, thumb_width: int = 320
) -> Path:
    """A PNG grid of ``count`` evenly spaced frames of ``video``, written atomically.

    Args:
        video: an MP4 (any ffmpeg-readable video).
        out: the PNG to write.
        count, columns, thumb_width: frames shown, per row, and their width in pixels.

    Returns:
        ``out`` as a Path.
    """
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
    buf = io.BytesIO()
    sheet.save(buf, format="PNG")
    out = Path(out)
    write_atomic(out, buf.getvalue())
    return out


__all__ = ["contact_sheet"]
