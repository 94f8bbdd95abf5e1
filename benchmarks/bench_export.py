"""Export speed and size: a 10 s flight at 30 fps (301 frames) to USD (binary and text),
BVH and CSV.  Targets (issue 16): under 10 s per format on the 2-core machine, the USD
under 20 MB.

Three sources, as ``birdsim export`` makes them:

* free flight of the seed bird (cruise, m3, 2 wingbeats per second of animation: 20
  wingbeats), flown by the code path of ``birdsim render``;
* free flight of the pigeon in real time (cruise, m3, 8.02 Hz: 80 wingbeats);
* the kinematic playback (``--kinematic``: cruise, m4, the seed bird).

A format's time is the flight (or playback) plus its frames plus its writer: what one
``birdsim export`` of that format costs (wall time, and the CPU time of this process,
which is what it costs on an idle machine: the 2 cores are shared with other jobs)."""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

SECONDS = 10.0
FPS = 30


def _free_flight(bird_file: str, beat_rate: float | None):
    from birdsim.commands.fly import load_table_for
    from birdsim.export.flightlog import frames_from_log
    from birdsim.export.frames import time_per_second
    from birdsim.flight.flightlog import log_arrays
    from birdsim.flight.freeflight import fly
    from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS
    from birdsim.physics.bird import Bird

    bird = Bird.from_toml(bird_file)
    c0, t0 = time.process_time(), time.perf_counter()
    beats = (SECONDS + 1.0 / FPS) * time_per_second(bird, beat_rate) / bird.period
    result = fly(
        PATH_PRESETS["cruise"],
        load_table_for(bird, DEMO_MODEL, None),
        bird,
        DEMO_MODEL,
        beats=beats,
    )
    frames = frames_from_log(
        log_arrays(result, "cruise"), fps=FPS, beat_rate=beat_rate, seconds=SECONDS
    )
    return (
        frames,
        time.perf_counter() - t0,
        time.process_time() - c0,
        f"{beats:.1f} wingbeats flown",
    )


def _kinematic():
    from birdsim.export.frames import from_playback
    from birdsim.flight.manoeuvre import get_manoeuvre
    from birdsim.tables.lookup import load_table

    c0, t0 = time.process_time(), time.perf_counter()
    frames = from_playback(
        get_manoeuvre("cruise"), load_table("tables/m4.npz"), model="m4", fps=FPS, seconds=SECONDS
    )
    return frames, time.perf_counter() - t0, time.process_time() - c0, "playback"


def main() -> None:
    from birdsim.export import write

    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--source", choices=("seed", "pigeon", "kinematic", "all"), default="all")
    # run by benchmarks/run.py, sys.argv holds run.py's section names, not these options
    which = ap.parse_args(sys.argv[1:] if __name__ == "__main__" else []).source
    sources = {
        "seed": lambda: _free_flight("models/seed-bird.toml", 2.0),
        "pigeon": lambda: _free_flight("models/pigeon.toml", None),
        "kinematic": _kinematic,
    }
    for name, make in sources.items():
        if which not in (name, "all"):
            continue
        frames, base, cpu_base, note = make()
        print(
            f"{name}: {frames.frames} frames ({note}): flight and frames {base:.2f} s wall, {cpu_base:.2f} s CPU"
        )
        with tempfile.TemporaryDirectory() as tmp:
            for fmt, suffix in (
                ("usd", ".usd"),
                ("usda", ".usda"),
                ("bvh", ".bvh"),
                ("csv", ".csv"),
            ):
                path = Path(tmp) / f"cruise{suffix}"
                c0, t0 = time.process_time(), time.perf_counter()
                write(frames, "usd" if fmt == "usda" else fmt, path)
                dt, dc = time.perf_counter() - t0, time.process_time() - c0
                size = path.stat().st_size / 1e6
                verdict = (
                    "ok"
                    if base + dt < 10 and (not fmt.startswith("usd") or size < 20)
                    else "OVER TARGET (wall)"
                )
                print(
                    f"  {fmt:5s} write {dt:5.2f} s; total {base + dt:5.2f} s wall, {cpu_base + dc:5.2f} s CPU; {size:6.2f} MB  {verdict}"
                )


if __name__ == "__main__":
    main()
