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


def main() -> None:
    bird = Bird.from_toml("models/seed-bird.toml")
    for model, table_file, speed in (
        ("m4", "tables/m4.npz", 0.9),
        ("m3", "tables/seed-m3.npz", 0.5),
        ("m5", "tables/m5.npz", 0.9),
    ):
        table = load_table(table_file)
        for steps, attitude in ((128, "posed"), (128, "free"), (512, "posed"), (512, "free")):
            config = SimConfig(steps_per_beat=steps, attitude=attitude)
            path = FlightPath("cruise", BEATS, False, False, (PathKeyframe(0.0, 6.0, V=speed),))
            fly(
                FlightPath("warm", 1.0, False, False, (PathKeyframe(0.0, 6.0, V=speed),)),
                table,
                bird,
                model,
                config=config,
            )
            w0, c0 = time.perf_counter(), time.process_time()
            fly(path, table, bird, model, config=config)
            wall, cpu = time.perf_counter() - w0, time.process_time() - c0
            # the flight includes two probe wingbeats for the trimmed start
            print(
                f"{model} period/{steps} {attitude:5s}: {BEATS / wall:6.1f} wingbeats per wall second, {BEATS / cpu:6.1f} per CPU second ({BEATS:g} wingbeats + 2 probe)"
            )


if __name__ == "__main__":
    main()
