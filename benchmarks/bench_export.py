"""Export speed and size: a 10 s flight at 30 fps (cruise, m4, the seed bird at 2 wingbeats
per second = 20 wingbeats, 301 frames) to USD, BVH and CSV.  Targets (issue 16): under
10 s per format on the 2-core machine, the USD under 20 MB."""

from __future__ import annotations

import tempfile
import time
from pathlib import Path


def main() -> None:
    from birdsim.export import write
    from birdsim.export.frames import from_playback
    from birdsim.flight.manoeuvre import get_manoeuvre
    from birdsim.tables.lookup import load_table

    t0 = time.perf_counter()
    frames = from_playback(get_manoeuvre("cruise"), load_table("tables/m4.npz"), model="m4", fps=30, seconds=10)
    t_frames = time.perf_counter() - t0
    print(f"frame source (kinematic playback, {frames.frames} frames): {t_frames:.2f} s")
    with tempfile.TemporaryDirectory() as tmp:
        for fmt, suffix in (("usd", ".usd"), ("usda", ".usda"), ("bvh", ".bvh"), ("csv", ".csv")):
            path = Path(tmp) / f"cruise{suffix}"
            t0 = time.perf_counter()
            write(frames, "usd" if fmt == "usda" else fmt, path)
            dt = time.perf_counter() - t0
            size = path.stat().st_size / 1e6
            verdict = "ok" if dt + t_frames < 10 and (not fmt.startswith("usd") or size < 20) else "OVER TARGET"
            print(f"{fmt:5s} write {dt:6.2f} s (+ frames {t_frames:.2f} s)  {size:7.2f} MB  {verdict}")
