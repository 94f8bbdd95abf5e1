"""H.264 MP4 out (and ffmpeg's reading of a video back): imageio-ffmpeg in a separate
process, so encoding overlaps rendering; the file appears only when complete."""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from birdsim.io import temporary_sibling
from birdsim.render.options import RenderError


@contextmanager
def mp4_writer(
    path: Path, width: int, height: int, fps: int, *, crf: int = 23, preset: str = "veryfast"
) -> Iterator[Any]:
    """A generator taking RGB frames (H, W, 3 uint8); the MP4 appears at ``path`` only
    when the block ends without an exception (temporary sibling + os.replace).

    Raises:
        RenderError: the folder of ``path`` is not writable.
    """
    import imageio_ffmpeg

    try:
        tmp = temporary_sibling(path)
    except OSError as exc:
        raise RenderError(
            f"--out {str(path)!r} is not writable: {exc.strerror}; allowed: a path in a writable folder"
        ) from None
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
    return {
        "codec": meta.get("codec"),
        "pix_fmt": meta.get("pix_fmt"),
        "size": tuple(meta.get("size", ())),
        "fps": meta.get("fps"),
        "frames": frames,
        "seconds": secs,
    }


__all__ = ["mp4_writer", "video_info"]
