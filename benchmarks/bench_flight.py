"""Free flight speed: wingbeats simulated per second (simulation alone, no rendering) for
m4, m5 and the demo model m3, at the default time step (period / 128) and at period / 512.

Issue 9's target: >= 20 wingbeats per wall second for m4 on the 2-core machine.  Issue
22's: the six-degree-of-freedom free flight (attitude free, tail, attitude loop) at
least 40 m4 wingbeats per CPU second, side by side with the posed (two-dimensional)
loop.  Issue 24's: >= 30 wingbeats per CPU second for m5 (the folding wing, on the
default m5 table).  Wall time depends on what else runs; process CPU time is printed
beside it."""

from __future__ import annotations

import time

from birdsim.flight.freeflight import fly
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.flight.simulate import SimConfig
from birdsim.physics.bird import Bird
from birdsim.tables.lookup import load_table

BEATS = 20.0
#: Each flight is flown this many times, posed and free alternated, and the best taken:
#: on the shared 2-core VM one run's figure moves by up to 30 % from the next.
REPEATS = 3


def _rate(path, table, bird, model, config) -> tuple[float, float]:
    w0, c0 = time.perf_counter(), time.process_time()
    fly(path, table, bird, model, config=config)
    return BEATS / (time.perf_counter() - w0), BEATS / (time.process_time() - c0)


def main() -> None:
    bird = Bird.from_toml("models/seed-bird.toml")
    for model, table_file, speed in (
        ("m4", "tables/m4.npz", 0.9),
        ("m3", "tables/seed-m3.npz", 0.5),
        ("m5", "tables/m5.npz", 0.9),
    ):
        table = load_table(table_file)
        path = FlightPath("cruise", BEATS, False, False, (PathKeyframe(0.0, 6.0, V=speed),))
        warm = FlightPath("warm", 1.0, False, False, (PathKeyframe(0.0, 6.0, V=speed),))
        for steps in (128, 512):
            configs = {a: SimConfig(steps_per_beat=steps, attitude=a) for a in ("posed", "free")}
            for config in configs.values():
                fly(warm, table, bird, model, config=config)
            best = {a: (0.0, 0.0) for a in configs}
            for _ in range(REPEATS):
                for a, config in configs.items():
                    wall, cpu = _rate(path, table, bird, model, config)
                    best[a] = (max(best[a][0], wall), max(best[a][1], cpu))
            for a, (wall, cpu) in best.items():
                # the trimmed start flies probe wingbeats (2 posed; free 3 to 7 until the
                # rotation's bias converges, trim_rotation: m4 cruise 5) on top
                print(
                    f"{model} period/{steps} {a:5s}: {wall:6.1f} wingbeats per wall second, "
                    f"{cpu:6.1f} per CPU second (best of {REPEATS}, {BEATS:g} wingbeats + probes)"
                )
            print(
                f"{model} period/{steps} free / posed: {best['free'][1] / best['posed'][1]:.2f} "
                "(CPU, side by side)"
            )


if __name__ == "__main__":
    main()
