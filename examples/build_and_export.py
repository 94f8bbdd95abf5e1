"""Build a manoeuvre in Python, fly it and export it for an animation tool.

Run from the repository root:  python examples/build_and_export.py [OUT_DIR]
(default OUT_DIR: exports/).  Writes OUT_DIR/dive-and-recover.{csv,bvh} and, when
usd-core is installed (pip install 'birdsim[usd]'), OUT_DIR/dive-and-recover.usd.

"Fly" is today the kinematic playback (the table's wingbeats along the prescribed path,
as `birdsim render` flies it); free flight (`birdsim fly`) writes a log that
`birdsim.export.flightlog` reads into the same frames.
"""

import importlib.util
import sys
from pathlib import Path

from birdsim.export import write
from birdsim.export.frames import from_playback
from birdsim.flight.manoeuvre import Keyframe, Manoeuvre
from birdsim.tables.lookup import load_table

out = Path(sys.argv[1] if len(sys.argv) > 1 else "exports")
out.mkdir(parents=True, exist_ok=True)

# demands per keyframe: t (wingbeats), Fx, Fz (right wing + body drag, Fz < 0 up), V, z (height)
manoeuvre = Manoeuvre(
    name="dive-and-recover",
    keyframes=(
        Keyframe(t=0, Fx=0.0, Fz=-0.2, V=0.9, z=7.0, regime="cruise"),
        Keyframe(t=2, Fx=0.0, Fz=-0.1, V=1.0, z=6.0, regime="dive"),
        Keyframe(t=4, Fx=0.0, Fz=-0.3, V=0.9, z=5.5, regime="pull out"),
        Keyframe(t=6, Fx=0.0, Fz=-0.2, V=0.9, z=5.5, regime="cruise"),
    ),
    duration=8,
)
frames = from_playback(manoeuvre, load_table("tables/m4.npz"), model="m4", fps=30)
print(f"{frames.frames} frames at {frames.fps:g} fps from {frames.source}")

formats = ["csv", "bvh"]
if importlib.util.find_spec("pxr") is not None:
    formats.append("usd")
else:
    print("usd-core is not installed: skipping USD (pip install 'birdsim[usd]')")
for fmt in formats:
    path = write(frames, fmt, out / f"{manoeuvre.name}.{fmt}")
    print(f"wrote {path} ({path.stat().st_size / 1e3:.0f} kB)")
