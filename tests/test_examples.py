"""Every file in examples/ runs: the manoeuvres through `birdsim fly` and `birdsim export`
(free flight, as `birdsim render` flies them), the bird through `birdsim forces` (and it
matches `birdsim bird new` from its cited measurements), the Python script as a user
would run it."""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from birdsim.cli import main
from birdsim.physics.bird import Bird
from birdsim.physics.measured import bird_from_measurements

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


def test_every_example_is_covered():
    files = {p.name for p in EXAMPLES.iterdir() if p.suffix in (".toml", ".py")}
    assert files == {
        "climb-and-level.toml",
        "perch-climb-level.toml",
        "zebra-finch.toml",
        "build_and_export.py",
        # issue 25's "anywhere" files: flown in tests/test_scene_perches.py
        "perch-to-perch.toml",
        "perch-to-ground.toml",
    }


def _fly_json(capsys, name):
    assert main(["fly", str(EXAMPLES / name), "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_path_manoeuvre_flies_without_saturation(tmp_path, capsys):
    """Take off from the perch, climb, fly level: the demo bird (seed bird, m3) flies it
    closed loop without a saturated sample and follows it within 0.15 semispan."""
    info = _fly_json(capsys, "perch-climb-level.toml")
    assert info["model"] == "m3" and info["bird"] == "seed" and info["wingbeats"] == 32
    assert info["saturated_samples"] == 0
    assert info["max_error"] < 0.15 and info["rms_error"] < 0.06
    assert info["final_position"][1] == pytest.approx(6.0, abs=0.05)  # level at 6 semispans
    out = tmp_path / "perch.csv"
    assert (
        main(
            [
                "export",
                str(EXAMPLES / "perch-climb-level.toml"),
                "--format",
                "csv",
                "--out",
                str(out),
            ]
        )
        == 0
    )
    rows = np.genfromtxt(out, delimiter=",", names=True)
    assert len(rows) == 16 * 30 + 1  # 32 wingbeats at 2 per second, 30 fps, both ends
    assert rows["x"][0] == pytest.approx(6.0, abs=0.02) and rows["z"][0] == pytest.approx(
        1.67, abs=0.02
    )  # on the perch
    assert rows["z"][-1] == pytest.approx(6.0, abs=0.05)


def test_force_keyframe_manoeuvre_flies_and_exports(tmp_path, capsys):
    info = _fly_json(capsys, "climb-and-level.toml")
    assert info["open_loop"] and info["saturated_samples"] == 0
    out = tmp_path / "climb.csv"
    assert (
        main(
            ["export", str(EXAMPLES / "climb-and-level.toml"), "--format", "csv", "--out", str(out)]
        )
        == 0
    )
    rows = np.genfromtxt(out, delimiter=",", names=True)
    assert len(rows) == 1 + 5 * 30  # 10 wingbeats at 2 per second, 30 fps, both ends
    assert rows["z"][-1] - rows["z"][0] > 0.9  # it climbs (one semispan) ...
    assert abs(rows["z"][-1] - rows["z"][-16]) < 0.02  # ... and is level over the last wingbeat


def test_zebra_finch_is_its_measurements(capsys):
    b = Bird.from_toml(EXAMPLES / "zebra-finch.toml")
    assert b == bird_from_measurements(
        "zebra-finch", mass=0.0133, span=0.161, mean_chord=0.039, frequency=27.0
    )
    text = (EXAMPLES / "zebra-finch.toml").read_text()
    assert "Journal of Experimental Biology 208, 2895-2901" in text
    assert "ASSUMPTION" in text and "unverified" in text  # the frequency is not a cited value
    assert (
        main(
            [
                "forces",
                "--model",
                "m4",
                "--speed",
                "0.5",
                "--bird",
                str(EXAMPLES / "zebra-finch.toml"),
            ]
        )
        == 0
    )
    assert "filled from the model's cruise defaults" in capsys.readouterr().out


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX paths")
def test_build_and_export_script(tmp_path):
    r = subprocess.run(
        [sys.executable, str(EXAMPLES / "build_and_export.py"), str(tmp_path)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert r.returncode == 0, r.stderr
    assert "free flight step-up" in r.stdout and "saturated in 0 wingbeat(s)" in r.stdout
    for suffix in ("npz", "csv", "bvh"):
        assert (tmp_path / f"step-up.{suffix}").stat().st_size > 1000
    rows = np.genfromtxt(tmp_path / "step-up.csv", delimiter=",", names=True)
    assert rows["z"][-1] - rows["z"][0] == pytest.approx(1.0, abs=0.1)  # the step up
