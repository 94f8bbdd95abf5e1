"""docs/your-bird.md end to end on a coarse grid: bird new -> its own table -> export
(the steps that need free flight, envelope and fly, are not in this version)."""

import csv

import numpy as np

from birdsim.cli import main
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird
from birdsim.tables.lookup import load_table

GRID = "Fx=-0.2:0.2:3,Fz=-0.3:0:3,V=0:1:3"


def test_walk_from_measurements_to_exports(tmp_path, capsys):
    bird_file = tmp_path / "finch.toml"
    assert main(["bird", "new", "finch", "--mass", "0.0133", "--span", "0.161", "--mean-chord", "0.039",
                 "--frequency", "27", "--body-drag-area", "0.0004", "--out", str(bird_file)]) == 0
    table = tmp_path / "finch-m1.npz"
    assert main(["tables", "build", "--model", "m1", "--bird", str(bird_file), "--grid", GRID, "--out", str(table),
                 "--jobs", "1", "--quiet"]) == 0
    t = load_table(table)
    assert t.model == "m1" and t.bird == reduced_bird(Bird.from_toml(bird_file))  # tables are non-dimensional
    t.require_bird(Bird.from_toml(bird_file))
    out = tmp_path / "finch.csv"
    common = ["--model", "m1", "--table", str(table), "--bird", str(bird_file), "--seconds", "0.5"]
    assert main(["export", "cruise", *common, "--format", "csv", "--out", str(out)]) == 0
    assert main(["export", "cruise", *common, "--format", "bvh", "--out", str(tmp_path / "finch.bvh")]) == 0
    rows = list(csv.DictReader(out.open()))
    assert len(rows) == 16  # 0.5 s at 30 fps, both ends: an SI bird plays in real time
    time = np.array([float(r["time"]) for r in rows])
    assert np.allclose(np.diff(time), 1 / 30)  # seconds
    # the wing moves (its shoulder quaternion changes from frame to frame)
    q = np.array([[float(r[f"r_shoulder_q{c}"]) for c in "wxyz"] for r in rows])
    assert np.ptp(q[:, 1]) > 0.01
    capsys.readouterr()
