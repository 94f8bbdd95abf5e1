"""Every file in examples/ runs: the manoeuvre through `birdsim export`, the bird through
`birdsim forces` (and it matches `birdsim bird new` from its cited measurements), the
Python script as a user would run it."""

import subprocess
import sys
from pathlib import Path

import pytest

from birdsim.cli import main
from birdsim.physics.bird import Bird
from birdsim.physics.measured import bird_from_measurements

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


def test_every_example_is_covered():
    files = {p.name for p in EXAMPLES.iterdir() if p.suffix in (".toml", ".py")}
    assert files == {"climb-and-level.toml", "zebra-finch.toml", "build_and_export.py"}


def test_force_keyframe_manoeuvre_exports(tmp_path, capsys):
    out = tmp_path / "climb.csv"
    assert main(["export", str(EXAMPLES / "climb-and-level.toml"), "--format", "csv", "--out", str(out)]) == 0
    rows = out.read_text().splitlines()
    assert len(rows) == 1 + 5 * 30 + 1  # 10 wingbeats at 2 per second, 30 fps, both ends
    header = rows[0].split(",")
    z = [float(r.split(",")[header.index("z")]) for r in rows[1:]]
    assert z[-1] - z[0] > 0.9  # it climbs (one semispan)


def test_zebra_finch_is_its_measurements(capsys):
    b = Bird.from_toml(EXAMPLES / "zebra-finch.toml")
    assert b == bird_from_measurements("zebra-finch", mass=0.0133, span=0.161, mean_chord=0.039, frequency=27.0)
    text = (EXAMPLES / "zebra-finch.toml").read_text()
    assert "Journal of Experimental Biology 208, 2895-2901" in text and "unverified" in text
    assert main(["forces", "--model", "m4", "--speed", "0.5", "--bird", str(EXAMPLES / "zebra-finch.toml")]) == 0
    assert "filled from the model's cruise defaults" in capsys.readouterr().out


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX paths")
def test_build_and_export_script(tmp_path):
    r = subprocess.run([sys.executable, str(EXAMPLES / "build_and_export.py"), str(tmp_path)], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    for suffix in ("csv", "bvh"):
        assert (tmp_path / f"dive-and-recover.{suffix}").stat().st_size > 1000
