"""Build a manoeuvre in Python, fly it (free flight in MuJoCo) and export it for an
animation tool.

Run from the repository root:  python examples/build_and_export.py [OUT_DIR]
(default OUT_DIR: exports/).  Writes OUT_DIR/step-up.npz (the flight log, as
`birdsim fly --out` writes it), OUT_DIR/step-up.{csv,bvh} and, when usd-core is
installed (pip install 'birdsim[usd]'), OUT_DIR/step-up.usd.

The same from the command line, with the manoeuvre in a TOML file:
    birdsim fly FILE.toml --out step-up.npz
    birdsim export step-up.npz --format usd --out step-up.usd
"""

import importlib.util
import sys
from pathlib import Path

from birdsim.export import write
from birdsim.export.flightlog import frames_from_log
from birdsim.flight.flightlog import log_arrays, save_log, summary
from birdsim.flight.freeflight import fly
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.physics.bird import Bird
from birdsim.tables.lookup import load_table
from birdsim.tables.shipped import shipped_table

out = Path(sys.argv[1] if len(sys.argv) > 1 else "exports")
out.mkdir(parents=True, exist_ok=True)

# The demo bird (mass ratio 30, weight 0.36 in table units) and the demo model m3 with
# the shipped table built for this bird (tables/seed-m3.npz).
bird = Bird.from_toml("models/seed-bird.toml")
model = "m3"
table = load_table(shipped_table(bird, model))

# A path in the speed form (docs/flight.md): t in wingbeats, V horizontal speed in omega s,
# z height in semispans (up). Cruise, step up one semispan, cruise on.
path = FlightPath(
    name="step-up",
    duration_beats=14.0,
    perch_start=False,
    perch_end=False,
    keyframes=(
        PathKeyframe(t=0, V=0.5, z=5.0, regime="cruise"),
        PathKeyframe(t=3, V=0.5, z=5.0, regime="climb"),
        PathKeyframe(t=10, V=0.5, z=6.0, regime="cruise"),
    ),
)

# Fly it under the bird's own forces (closed loop), as `birdsim fly` does.
result = fly(path, table, bird, model)
log = log_arrays(result, path.name)
info = summary(log)
print(
    f"flew {path.name}: {info['wingbeats']:g} wingbeats, position error RMS {info['rms_error']:.3f} "
    f"semispans, saturated in {info['wingbeats_saturated']} wingbeat(s)"
)
save_log(log, out / f"{path.name}.npz", force=True)

# Export: 30 frames per second, 2 wingbeats per second of animation (the seed bird is
# non-dimensional; an SI bird such as the pigeon plays in real time).
frames = frames_from_log(log, fps=30, beat_rate=2.0)
print(f"{frames.frames} frames at {frames.fps:g} fps from {frames.source}")
formats = ["csv", "bvh"]
if importlib.util.find_spec("pxr") is not None:
    formats.append("usd")
else:
    print("usd-core is not installed: skipping USD (pip install 'birdsim[usd]')")
for fmt in formats:
    written = write(frames, fmt, out / f"{path.name}.{fmt}")
    print(f"wrote {written} ({written.stat().st_size / 1e3:.0f} kB)")
