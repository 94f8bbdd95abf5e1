"""``--bird`` takes a shipped bird's name as well as a file (birdsim.commands.common.bird_file)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from birdsim.commands.common import bird_file
from birdsim.physics.bird import Bird, BirdConfigError

MODELS = Path(__file__).resolve().parents[1] / "models"


@pytest.mark.parametrize("name", ["pigeon", "seed-bird"])
def test_a_shipped_name_reads_the_shipped_file(name):
    assert Path(bird_file(name)) == MODELS / f"{name}.toml"
    assert Bird.from_toml(bird_file(name)) == Bird.from_toml(MODELS / f"{name}.toml")


def test_a_path_is_taken_as_given(tmp_path):
    f = tmp_path / "pigeon"  # a file named like a shipped bird wins over the name
    f.write_text((MODELS / "seed-bird.toml").read_text())
    assert bird_file(str(f)) == str(f)
    assert bird_file("missing/pigeon.toml") == "missing/pigeon.toml"  # from_toml says it


def test_an_unknown_name_lists_the_shipped_birds():
    with pytest.raises(BirdConfigError, match=r"'pidgeon' does not exist; .*\(pigeon, seed-bird\)"):
        bird_file("pidgeon")


def test_the_command_says_it_in_one_line():
    r = subprocess.run(
        [sys.executable, "-m", "birdsim.cli", "fly", "cruise", "--bird", "pidgeon", "--json"],
        capture_output=True,
        text=True,
    )
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "--bird 'pidgeon'" in lines[0] and "pigeon, seed-bird" in lines[0]
