"""Every printed force says whose it is, in the same words everywhere: the dissertation's
(the table's) force is "right wing + body drag", the whole bird's "2 wings + body drag"
(issue 16, item 7): forces, tables lookup/info, envelope, fly --json, crosscheck and the
render overlay."""

import json

from birdsim.cli import main

TABLE = "right wing + body drag (the dissertation's flapcost force)"
WHOLE = "2 wings + body drag"


def _out(capsys, *argv):
    assert main(list(argv)) == 0
    return capsys.readouterr().out


def test_every_command_names_its_force(capsys):
    text = _out(capsys, "forces", "--model", "m3", "--speed", "0.5")
    assert TABLE in text and f"whole bird: {WHOLE}" in text
    assert (
        TABLE
        in json.loads(_out(capsys, "forces", "--model", "m3", "--speed", "0.5", "--json"))["force"]
    )
    assert TABLE in _out(
        capsys, "tables", "lookup", "tables/seed-m3.npz", "--Fx", "0", "--Fz", "-0.18", "--V", "0.5"
    )
    assert TABLE in _out(capsys, "tables", "info", "tables/seed-m3.npz")
    env = json.loads(_out(capsys, "envelope", "--json"))
    assert f"whole bird ({WHOLE})" in env["force"] and "right wing + body drag" in env["force"]
    text = _out(capsys, "envelope")
    assert (
        f"whole bird ({WHOLE})" in text
        and "best lift at Fx = 0 per table speed (whole bird)" in text
    )
    fly = json.loads(_out(capsys, "fly", "hover", "--seconds", "1", "--json"))
    assert TABLE in fly["force"] and WHOLE in fly["force"]


def test_crosscheck_and_overlay_name_their_force():
    import numpy as np

    from birdsim.commands.crosscheck import FORCE_NOTE
    from birdsim.render.overlay import force_lines

    assert FORCE_NOTE.startswith(f"whole bird ({WHOLE})")
    line = "".join(text for text, _ in force_lines(np.zeros(3), np.zeros(3))[0])
    assert "demanded" in line and "achieved" in line and "(right wing + body drag)" in line


def test_a_bird_that_does_not_fit_the_table_is_one_line(tmp_path, capsys):
    """render (free flight and --kinematic), fly and export refuse the pigeon on the seed
    bird's tables (LookupTable.require_bird): one line, exit 2, nothing written."""
    cases = [
        ["render", "cruise", "--kinematic", "--out", str(tmp_path / "a.mp4")],
        ["render", "cruise", "--kinematic", "--still", str(tmp_path / "a.png")],
        ["render", "cruise", "--table", "tables/seed-m3.npz", "--out", str(tmp_path / "b.mp4")],
        ["fly", "cruise", "--table", "tables/seed-m3.npz"],
        [
            "export",
            "cruise",
            "--table",
            "tables/seed-m3.npz",
            "--format",
            "csv",
            "--out",
            str(tmp_path / "c.csv"),
        ],
        ["export", "cruise", "--kinematic", "--format", "csv", "--out", str(tmp_path / "d.csv")],
    ]
    for argv in cases:
        assert main([*argv, "--bird", "models/pigeon.toml"]) == 2, argv
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "whose reduced bird differs from bird 'pigeon''s" in err, (
            argv,
            err,
        )
    assert list(tmp_path.iterdir()) == []
