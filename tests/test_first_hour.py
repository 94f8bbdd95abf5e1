"""Issue 28, the first hour of a new user: what the README says the bird can do, the
table a new bird gets, the export's texture folder, units on every printed figure.
(The errors that point at the right place and the repeated options are rows of
``tests/test_bad_input.py``.)"""

from __future__ import annotations

import argparse
import json
import re
from pathlib import Path

import numpy as np
import pytest

import birdsim
from birdsim.cli import build_parser, main
from birdsim.commands import tables as tables_command
from birdsim.flight.manoeuvre import PRESETS
from birdsim.flight.presets import PATH_PRESETS
from birdsim.flight.turn_presets import TURN_PRESETS
from birdsim.tables.grid import Grid

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
HEADING = "## What it does, and what it does not do yet"


# ---- item 1: the README says what the bird can do, and names only what exists ----------


def _paragraph() -> str:
    text = README.read_text()
    assert HEADING in text, f"README.md has no section {HEADING!r}"
    return text.split(HEADING, 1)[1].split("\n## ", 1)[0]


def _subparsers(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return dict(action.choices)
    return {}


def _check_command(span: str) -> None:
    """``birdsim CMD [SUB] [--flag ...]``: CMD (and SUB) exist, every flag is an option."""
    words = span.split()
    assert words[0] == "birdsim", span
    parser = build_parser()
    commands = _subparsers(parser)
    assert len(words) > 1 and words[1] in commands, f"`{span}`: no command {words[1:2]}"
    parser = commands[words[1]]
    rest = words[2:]
    if rest and not rest[0].startswith("-") and _subparsers(parser):
        sub = _subparsers(parser)
        assert rest[0] in sub, f"`{span}`: {words[1]} has no subcommand {rest[0]!r}"
        parser, rest = sub[rest[0]], rest[1:]
    options = {o for a in parser._actions for o in a.option_strings}
    for word in rest:
        if word.startswith("--"):
            assert word.split("=")[0] in options, f"`{span}`: no option {word}"


def test_readme_keeps_its_first_lines() -> None:
    head = README.read_text().splitlines()[:6]
    assert head[0] == "# birdsim"
    assert head[3].startswith("make demo") and head[4].startswith("make test"), head


def test_readme_paragraph_names_only_presets_models_and_commands_that_exist() -> None:
    paragraph = _paragraph()
    spans = re.findall(r"`([^`]+)`", paragraph)
    presets = set(PRESETS) | set(PATH_PRESETS) | set(TURN_PRESETS)
    named = {"preset": set(), "model": set(), "command": set()}
    for span in spans:
        if span.startswith("birdsim "):
            _check_command(span)
            named["command"].add(span.split()[1])
        elif span in presets:
            named["preset"].add(span)
        elif span in birdsim.MODELS:
            named["model"].add(span)
        else:
            pytest.fail(f"README paragraph names `{span}`: no preset, model or command")
    # it says what there is: every preset and model, and the main commands
    assert named["preset"] == presets
    assert named["model"] == set(birdsim.MODELS)
    assert {"fly", "render", "export", "bird", "tables"} <= named["command"]
    # and what there is not yet
    assert "Not yet" in paragraph and "one vertical plane" in paragraph


def test_the_readme_check_catches_a_missing_preset_or_flag() -> None:
    with pytest.raises(AssertionError):
        _check_command("birdsim fly --loop")
    with pytest.raises(AssertionError):
        _check_command("birdsim teleport")
    with pytest.raises(AssertionError):
        _check_command("birdsim tables destroy")
    _check_command("birdsim tables build --bird")


# ---- item 2: the table a new bird's error suggests is the grid of its presets -------------------


def _grid_built(monkeypatch: pytest.MonkeyPatch, tmp_path: Path, *extra: str) -> Grid:
    """The grid ``birdsim tables build`` would build (stopped before any optimisation)."""
    seen = {}

    def stop(cfg, **kwargs):  # type: ignore[no-untyped-def]
        seen["grid"] = cfg.grid
        raise KeyboardInterrupt

    monkeypatch.setattr(tables_command, "build_table", stop)
    out = tmp_path / "t.npz"
    assert main(["tables", "build", "--model", "m3", "--out", str(out), "--quiet", *extra]) == 130
    return seen["grid"]


def _axes(grid: Grid) -> list[np.ndarray]:
    return [np.asarray(getattr(grid, a)) for a in grid.axis_names]


def test_tables_build_for_a_bird_builds_its_presets_grid(monkeypatch, tmp_path) -> None:
    # the grid of the bird's own preset demands (birdsim.flight.preset_grid), not the fixed
    # flight grid: for the zebra finch that grid reaches Fz > 0 (its landing pushes down),
    # where the flight grid stops at 0 (tests/test_preset_grid.py has the numbers)
    from birdsim.flight.preset_grid import preset_grid
    from birdsim.physics.bird import Bird

    for name in ("models/pigeon.toml", "examples/zebra-finch.toml"):
        bird = str(ROOT / name)
        want = Grid.parse(preset_grid(Bird.from_toml(bird)))
        got = _grid_built(monkeypatch, tmp_path, "--bird", bird)
        for a, b in zip(_axes(got), _axes(want)):
            np.testing.assert_array_equal(a, b)
    finch = _grid_built(monkeypatch, tmp_path, "--bird", str(ROOT / "examples/zebra-finch.toml"))
    assert max(finch.Fz) > max(Grid.parse(tables_command.FLIGHT_GRID).Fz) == 0.0
    # a bird without weight (gravity 0) asks nothing of its wings: the flight grid
    bare = tmp_path / "bare.toml"
    bare.write_text('name = "bare"\n')
    flight = Grid.parse(tables_command.FLIGHT_GRID)
    for a, b in zip(_axes(_grid_built(monkeypatch, tmp_path, "--bird", str(bare))), _axes(flight)):
        np.testing.assert_array_equal(a, b)
    # without --bird, or with --size, the general grid as before
    assert [len(a) for a in _axes(_grid_built(monkeypatch, tmp_path))] == [11, 11, 11]
    sized = _grid_built(monkeypatch, tmp_path, "--bird", bird, "--size", "5")
    assert [len(a) for a in _axes(sized)] == [5, 5, 5]


def test_the_flight_grid_is_the_makefiles() -> None:
    make = (ROOT / "Makefile").read_text()
    line = next(x for x in make.splitlines() if x.startswith("FLIGHT_GRID"))
    assert line.split(":=", 1)[1].strip() == tables_command.FLIGHT_GRID


# ---- item 4: what a USD export writes beside the file ------------------------------------


def test_usd_export_names_its_texture_folder(tmp_path, monkeypatch, capsys) -> None:
    pytest.importorskip("pxr")
    monkeypatch.chdir(tmp_path)
    argv = ["export", "cruise", "--format", "usd", "--out", "c.usd", "--kinematic"]
    argv += ["--seconds", "0.2", "--fps", "5"]
    assert main(argv) == 0
    line = capsys.readouterr().out.strip().splitlines()[-1]
    textures = sorted(p.name for p in (tmp_path / "c_assets").iterdir())
    assert textures, "the shipped MJCF has textures: the folder is written"
    assert f"c_assets/ ({len(textures)} textures" in line, line
    assert "together with the file" in line
    # the folder is not overwritten without --force (the file itself is moved away first)
    (tmp_path / "c.usd").unlink()
    assert main(argv) == 2
    assert "texture folder 'c_assets' exists" in capsys.readouterr().err
    assert "_assets/" in (ROOT / "docs" / "export.md").read_text()


# ---- item 5: units on every printed figure ------------------------------------------------


def _json(argv: list[str], capsys) -> dict:
    capsys.readouterr()
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_every_json_summary_has_units(tmp_path, capsys) -> None:
    table = str(ROOT / "tables" / "m4.npz")
    forces = _json(["forces", "--model", "m1", "--speed", "0.5", "--json"], capsys)
    assert forces["units"]["force"] == "rho omega^2 s^3 c"
    pigeon = ["--bird", str(ROOT / "models" / "pigeon.toml")]
    si = _json(["forces", "--model", "m1", "--speed", "0.5", "--json", *pigeon], capsys)
    assert si["units"]["force"] == "N" and si["units"]["power"] == "W"
    for argv in (
        ["tables", "info", table, "--json"],
        ["tables", "lookup", table, "--Fx", "0", "--Fz", "-0.2", "--V", "0.9", "--json"],
        ["envelope", "--json"],
        ["crosscheck", "--model", "base", "--forward", "none", "--samples", "8", "--json"],
    ):
        assert "units" in _json(argv, capsys), argv


def test_the_fly_summary_line_names_its_units(capsys) -> None:
    assert main(["fly", "hover", "--quiet", "--seconds", "12"]) == 0
    line = capsys.readouterr().out.strip()
    assert re.search(r"RMS [\d.e+-]+ semispans, max [\d.e+-]+ semispans", line), line


def test_the_units_follow_the_bird() -> None:
    from birdsim.commands.common import units_of
    from birdsim.physics.bird import Bird

    assert units_of(Bird())["length"].startswith("semispans")
    assert units_of(Bird.from_toml(ROOT / "models" / "pigeon.toml"))["length"] == "m"
