"""The studio's downloads of one flight: the log (.npz), CSV, USD and BVH (``birdsim
export``), MP4 (``birdsim render``) and the self-contained 3-D view (``birdsim view``).

Each is made by the same command a user would run, on the flight's log, inside a
temporary folder that is deleted afterwards (the bytes go to the browser, nothing is
left on disk): the exports in this process (``birdsim export``'s own ``run``), the video
in a child process (its own OpenGL context).
"""

from __future__ import annotations

import io
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError

#: kind -> (file suffix, MIME type).
KINDS = {
    "log": (".npz", "application/octet-stream"),
    "csv": (".csv", "text/csv"),
    "usd": (".usda", "text/plain"),
    "bvh": (".bvh", "text/plain"),
    "mp4": (".mp4", "video/mp4"),
    "html": (".html", "text/html"),
}
#: Seconds a child command may take (a long flight's video takes a while).
CHILD_TIMEOUT = 600.0


def log_bytes(log: dict[str, Any]) -> bytes:
    """The flight log as ``birdsim fly --out`` writes it."""
    buf = io.BytesIO()
    np.savez_compressed(buf, **{k: v for k, v in log.items() if k != "bird_obj"})
    return buf.getvalue()


def _child(args: list[str], cwd: Path) -> None:
    """Run ``birdsim ARGS`` in ``cwd``; its one-line error becomes ours."""
    try:
        done = subprocess.run(
            [sys.executable, "-m", "birdsim.cli", *args],
            cwd=cwd,
            capture_output=True,
            text=True,
            timeout=CHILD_TIMEOUT,
        )
    except subprocess.TimeoutExpired:
        raise BirdsimError(
            f"birdsim {args[0]} took over {CHILD_TIMEOUT:g} s; allowed: a shorter flight"
        ) from None
    if done.returncode != 0:
        lines = [ln for ln in done.stderr.strip().splitlines() if ln.strip()]
        raise BirdsimError(lines[-1] if lines else f"birdsim {args[0]} failed ({done.returncode})")


def _export(args: list[str]) -> None:
    """Run ``birdsim ARGS`` (an export) in this process; its BirdsimError propagates."""
    from birdsim.cli import build_parser

    ns = build_parser().parse_args(args)
    ns.func(ns)


def make(kind: str, log: dict[str, Any], scene_html: Any = None, **opts: str) -> bytes:
    """The bytes of download ``kind`` (:data:`KINDS`) of a flight ``log``.

    ``scene_html``: a callable returning the view's HTML text (the studio caches the
    scene). ``opts``: ``size`` (WxH) for the video.

    Raises:
        BirdsimError: an unknown kind, or the command's own one-line error.
    """
    if kind not in KINDS:
        raise BirdsimError(f"download {kind!r} is unknown; allowed: {', '.join(KINDS)}")
    if kind == "log":
        return log_bytes(log)
    if kind == "html":
        return scene_html().encode("utf-8")
    if kind in ("bvh", "csv") and "n_birds" in log:
        raise BirdsimError(
            f"download {kind!r} of a flock: one file per bird; allowed: log, usd, mp4, html "
            f"(or `birdsim export LOG --format {kind}` on the flock's log)"
        )
    suffix = KINDS[kind][0]
    with tempfile.TemporaryDirectory(prefix="birdsim-studio-") as tmp:
        folder = Path(tmp)
        (folder / "flight.npz").write_bytes(log_bytes(log))
        out = folder / f"flight{suffix}"
        if kind == "mp4":
            size = opts.get("size") or "480x320"
            _child(["render", "flight.npz", "--out", out.name, "--size", size, "--quiet"], folder)
        else:
            _export(["export", str(folder / "flight.npz"), "--format", kind, "--out", str(out)])
        return out.read_bytes()


__all__ = ["CHILD_TIMEOUT", "KINDS", "log_bytes", "make"]
