"""Rendering speed: frames per second of MuJoCo's offscreen renderer alone per
``--quality`` level (draft, good, best) and of the whole ``birdsim render`` command, at
640x480 and 1280x720, OSMesa beside EGL; seconds of animation per wall second; the
four-preset ``make demo`` (default quality) against its 60 s target and the four
presets at ``--quality best`` 1280x720 against 3 minutes.

Each measurement runs in a fresh process: the GL back-end is fixed when mujoco is first
imported, and the command's figure should include its start-up like a user's run.
Uses tables/m4.npz when present, else a small synthetic m4 table (said so below).
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SIZES = ((640, 480), (1280, 720))
PRESETS = ("hover", "cruise", "take-off", "landing")

_RENDER_ONLY = r"""
import json, sys, time
from birdsim.render import gl
gl.select_gl(sys.argv[1])
from birdsim.flight.manoeuvre import PRESETS
from birdsim.render.renderer import RenderOptions, Scene, play_for_video
from birdsim.tables.lookup import load_table
w, h, table, quality = int(sys.argv[2]), int(sys.argv[3]), load_table(sys.argv[4]), sys.argv[5]
opts = RenderOptions(width=w, height=h, fps=30, seconds=3.0, progress=False, quality=quality)
pb = play_for_video(PRESETS["cruise"], table, opts)
with Scene(pb, opts) as scene:
    scene.update(0); scene.renderer.render()  # warm-up (context, shaders)
    t0, c0 = time.perf_counter(), time.process_time()
    for i in range(scene.frames):
        scene.update(i)
        scene.renderer.render()
    dt, cpu = time.perf_counter() - t0, time.process_time() - c0
print(json.dumps({"frames": scene.frames, "seconds": dt, "cpu": cpu}))
"""


def _table_path(tmp: Path) -> tuple[str, str]:
    committed = ROOT / "tables" / "m4.npz"
    if committed.exists():
        return str(committed), "tables/m4.npz"
    sys.path.insert(0, str(ROOT / "tests"))
    from test_render import small_table  # the tests' synthetic table (same class, same file format)

    small_table("m4").save(tmp / "m4")
    return str(tmp / "m4.npz"), "a synthetic 5x3x5 m4 table (tables/m4.npz not built yet)"


def _python() -> str:
    return (
        str(ROOT / ".venv" / "bin" / "python")
        if (ROOT / ".venv" / "bin" / "python").exists()
        else sys.executable
    )


QUALITIES = ("draft", "good", "best")


def render_only(
    backend: str, w: int, h: int, table: str, quality: str = "good"
) -> tuple[float, float]:
    """(frames per wall second, CPU milliseconds per frame) of the renderer alone."""
    out = subprocess.run(
        [_python(), "-c", _RENDER_ONLY, backend, str(w), str(h), table, quality],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    if out.returncode:
        raise RuntimeError(out.stderr.strip().splitlines()[-1])
    r = json.loads(out.stdout.strip().splitlines()[-1])
    return r["frames"] / r["seconds"], 1000.0 * r["cpu"] / r["frames"]


def command(
    backend: str,
    w: int,
    h: int,
    table: str | None,
    tmp: Path,
    preset: str = "cruise",
    seconds: str | None = "3",
    quality: str = "good",
) -> tuple[float, float, int]:
    """(wall seconds, video seconds, frames) of one ``birdsim render`` process: the
    kinematic playback of ``table``, or with ``table=None`` the demo's free flight (demo
    bird, m3, 3 wingbeats per second of video, as ``make demo``)."""
    out = tmp / f"{preset}-{backend}-{w}.mp4"
    source = ["--kinematic", "--table", table] if table else ["--model", "m3", "--beat-rate", "3"]
    argv = [
        _python(),
        "-m",
        "birdsim.cli",
        "render",
        preset,
        *source,
        "--out",
        str(out),
        "--size",
        f"{w}x{h}",
        "--gl",
        backend,
        "--force",
        "--quiet",
        "--quality",
        quality,
    ]
    if seconds:
        argv += ["--seconds", seconds]
    t0 = time.perf_counter()
    res = subprocess.run(argv, capture_output=True, text=True, cwd=ROOT)
    wall = time.perf_counter() - t0
    if res.returncode:
        raise RuntimeError(res.stderr.strip())
    from birdsim.render.renderer import video_info

    info = video_info(out)
    return wall, float(info["frames"]) / float(info["fps"]), int(info["frames"])


def main() -> None:
    sys.path.insert(0, str(ROOT))
    from birdsim.render.gl import library_available

    backends = [b for b in ("osmesa", "egl") if library_available(b)]
    if not backends:
        print("no headless GL (libOSMesa / libEGL): nothing to measure")
        return
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        table, what = _table_path(tmp)
        print(
            f"table: {what}; clip: cruise, 3 s of video at 30 fps (90 frames), trails and overlay on; machine load {_load()}"
        )
        b = backends[0]
        for w, h in SIZES:
            for q in QUALITIES:
                fps_render, cpu_ms = render_only(b, w, h, table, q)
                print(
                    f"{w}x{h} {b:6s} --quality {q:5s}: renderer alone {fps_render:6.1f} frames/s ({cpu_ms:5.1f} CPU ms/frame)"
                )
        rates: dict[tuple[str, int], float] = {}
        for w, h in SIZES:
            for b in backends:
                fps_render, _ = render_only(b, w, h, table)
                wall, video, frames = command(b, w, h, table, tmp)
                rates[(b, w)] = fps_render
                print(
                    f"{w}x{h} {b:6s} good: renderer alone {fps_render:6.1f} frames/s | whole command {frames / wall:5.1f} frames/s "
                    f"({wall:.2f} s wall incl. start-up) | {video / wall:4.2f} s of animation per wall second"
                )
        if len(backends) == 2:
            for w, _ in SIZES:
                print(
                    f"ratio renderer alone EGL/OSMesa at {w} wide: {rates[('egl', w)] / rates[('osmesa', w)]:.2f}"
                )
        b = backends[0]
        for (w, h), quality, target in (((640, 480), "good", 60.0), ((1280, 720), "best", 180.0)):
            t0, c0 = time.perf_counter(), _children_cpu()
            video_total = 0.0
            for preset in PRESETS:
                _, video, _ = command(b, w, h, None, tmp, preset, seconds=None, quality=quality)
                video_total += video
            total, cpu = time.perf_counter() - t0, _children_cpu() - c0
            print(
                f"4 presets in free flight (make demo: m3, {w}x{h}, --quality {quality}, {b}, sequential): {total:.1f} s wall, {cpu:.1f} CPU s, for {video_total:.1f} s "
                f"of video (target < {target:g} s wall: {'met' if total < target else 'NOT met'}; load {_load()})"
            )


def _children_cpu() -> float:
    """User + system CPU seconds of the finished child processes (renderers and ffmpeg):
    the stable figure on a shared machine."""
    import resource

    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _load() -> str:
    try:
        import os

        return f"{os.getloadavg()[0]:.1f} on {os.cpu_count()} cores"
    except OSError:
        return "unknown"


if __name__ == "__main__":
    main()
