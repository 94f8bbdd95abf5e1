"""docs/your-bird.md end to end on a coarse grid: bird new -> its own table -> envelope ->
fly -> render (a still) -> export (a manoeuvre to USD/CSV, the flight log to BVH)."""

import csv
import json

import numpy as np
import pytest

from birdsim.cli import main
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird
from birdsim.tables.lookup import load_table

GRID = "Fx=-0.1:0.2:4,Fz=-0.2:0:5,V=0:0.6:4"  # the doc's coarse grid: 80 cells


def test_walk_from_measurements_to_exports(tmp_path, capsys):
    bird_file = tmp_path / "finch.toml"
    assert (
        main(
            [
                "bird",
                "new",
                "finch",
                "--mass",
                "0.0133",
                "--span",
                "0.161",
                "--mean-chord",
                "0.039",
                "--frequency",
                "27",
                "--body-drag-area",
                "0.0004",
                "--out",
                str(bird_file),
            ]
        )
        == 0
    )
    bird = Bird.from_toml(bird_file)
    # 2. its own table (its reduced drag area is not the seed bird's)
    table = tmp_path / "finch-m3.npz"
    assert (
        main(
            [
                "tables",
                "build",
                "--model",
                "m3",
                "--bird",
                str(bird_file),
                "--grid",
                GRID,
                "--out",
                str(table),
                "--quiet",
            ]
        )
        == 0
    )
    t = load_table(table)
    assert t.model == "m3" and t.bird == reduced_bird(bird)  # tables are non-dimensional
    t.require_bird(bird)
    common = ["--bird", str(bird_file), "--table", str(table)]
    capsys.readouterr()
    # 3. envelope: the finch (weight 0.18 table units) can hover with this table
    assert main(["envelope", "--model", "m3", *common, "--json"]) == 0
    env = json.loads(capsys.readouterr().out)
    assert env["bird"] == "finch" and env["can_hover"]
    assert env["weight"] == pytest.approx(0.1819, abs=1e-4) and env["hover_weight"] > env["weight"]
    # 4. fly: cruise, closed loop, in the finch's units (metres, seconds)
    log = tmp_path / "finch-cruise.npz"
    assert main(["fly", "cruise", *common, "--out", str(log), "--json"]) == 0
    info = json.loads(capsys.readouterr().out)
    assert info["saturated_samples"] == 0 and info["rms_error"] < 0.05 * bird.semispan  # metres
    # 5. render: a still of the log
    png = tmp_path / "finch.png"
    assert (
        main(["render", str(log), "--still", str(png), "--size", "160x128", "--quality", "draft"])
        == 0
    )
    assert png.stat().st_size > 1000
    # 6. export: the manoeuvre (flown again, as render flies it) and the log
    out = tmp_path / "finch.csv"
    assert main(["export", "cruise", *common, "--format", "csv", "--out", str(out)]) == 0
    assert main(["export", str(log), "--format", "bvh", "--out", str(tmp_path / "finch.bvh")]) == 0
    rows = list(csv.DictReader(out.open()))
    assert len(rows) == 12  # 10 wingbeats at 27 Hz = 0.370 s at 30 fps, both ends: real time
    time = np.array([float(r["time"]) for r in rows])
    assert np.allclose(np.diff(time), 1 / 30)  # seconds
    x = np.array([float(r["x"]) for r in rows])
    speed = (x[-1] - x[0]) / (time[-1] - time[0])
    assert speed == pytest.approx(
        0.5 * bird.omega * bird.semispan, rel=0.02
    )  # cruise: 0.5 omega s, in m/s
    q = np.array([[float(r[f"r_shoulder_q{c}"]) for c in "wxyz"] for r in rows])
    assert np.ptp(q[:, 1]) > 0.01  # the wing moves
    capsys.readouterr()
