"""``birdsim forces`` and ``birdsim examples``: output and one-line errors."""

import json
import subprocess
import sys

import pytest

from birdsim import evaluate_cycle
from birdsim.cli import main

HOVER = ["--param", "pitch=1.5", "--param", "flap_amp=1.5", "--param", "twist_amp=0.7"]


def test_forces_json_matches_api(capsys):
    assert main(["forces", "--model", "m1", "--speed", "0.2", *HOVER, "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    c = evaluate_cycle("m1", dict(pitch=1.5, flap_amp=1.5, twist_amp=0.7), 0.2)
    for k in ("Fx", "Fy", "Fz", "P"):
        assert out["mean"][k] == pytest.approx(float(getattr(c.mean, k)), abs=1e-15)
    assert "right wing + body drag" in out["force"]


def test_forces_geometry_override_changes_result(capsys):
    main(["forces", "--model", "m1", "--speed", "0", *HOVER, "--json"])
    base = json.loads(capsys.readouterr().out)["mean"]["Fz"]
    main(["forces", "--model", "m1", "--speed", "0", *HOVER, "--set", "strips=50", "--json"])
    strips = json.loads(capsys.readouterr().out)["mean"]["Fz"]
    assert strips == pytest.approx(4 / 3 * base, rel=1e-3)  # sec. 3.5.1


@pytest.mark.parametrize(
    "args, text",
    [
        (["--model", "m9", "--speed", "0", *HOVER], "model 'm9' is unknown"),
        (["--model", "m1", "--speed", "0", *HOVER, "--param", "sweep=0.1"], "'sweep' is unknown"),
        (["--model", "m1", "--speed", "0", *HOVER[:-1], "twist_amp=2"], "out of bounds"),
        (["--model", "m1", "--speed", "nan", *HOVER], "speed=nan is invalid"),
        (["--model", "m1", "--speed", "-1", *HOVER], "speed=-1.0 is invalid"),
        (["--model", "m1", "--speed", "0", *HOVER[:-1], "twist_amp=nan"], "not finite"),
        (["--model", "m1", "--speed", "0", *HOVER, "--param", "oops"], "malformed"),
        (["--model", "m1", "--speed", "0", *HOVER, "--param", "pitch=0.2"], "pitch is given twice"),
        (["--model", "m1", "--speed", "0", *HOVER[:-1], "twist_amp=x"], "not a number; allowed"),
        (
            ["--model", "m1", "--speed", "0", *HOVER, "--bird", "/nonexistent.toml"],
            "does not exist",
        ),
        (
            ["--model", "m1", "--speed", "0", *HOVER, "--samples", "0"],
            "--samples 0 is invalid; allowed: an integer >= 2",
        ),
        (["--model", "m1", "--speed", "0", *HOVER, "--climb", "nan"], "--climb nan is invalid"),
        (
            ["--model", "m1", "--speed", "0", *HOVER, "--climb", "up"],
            "--climb='up' is not a number",
        ),
    ],
)
def test_forces_bad_input_one_line(args, text, capsys):
    assert main(["forces", *args]) == 2
    err = capsys.readouterr().err
    assert text in err and err.count("\n") == 1 and "Traceback" not in err


def test_missing_subcommand_names_the_choices(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["tables"])
    err = capsys.readouterr().err
    assert (
        exc.value.code == 2
        and err.count("\n") == 1
        and "{build,info,lookup,jacobians}" in err
        and "tables_command" not in err
    )


def test_console_script_usage_error_is_one_line():
    r = subprocess.run(
        [sys.executable, "-m", "birdsim.cli", "forces", "--speed", "0"],
        capture_output=True,
        text=True,
    )
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "--model" in r.stderr


def test_examples_table(capsys):
    assert main(["examples"]) == 0
    out = capsys.readouterr().out
    assert out.count("\n") == 13 and " 88 m4" in out and "units: V in omega s" in out


def test_forces_fills_missing_parameters_from_the_defaults(capsys):
    """A parameter not given takes the model's default (hover at V = 0, cruise otherwise),
    the output says which, and the result equals giving them all."""
    import json

    from birdsim.physics.kinematics import get_model

    assert (
        main(["forces", "--model", "m3", "--speed", "0.5", "--param", "pitch=0.2", "--json"]) == 0
    )
    partial = json.loads(capsys.readouterr().out)
    cruise = get_model("m3").guess("cruise")
    assert partial["filled"] == {k: v for k, v in cruise.items() if k != "pitch"}
    full = ["--param", "pitch=0.2"] + [
        a for k, v in partial["filled"].items() for a in ("--param", f"{k}={v!r}")
    ]
    assert main(["forces", "--model", "m3", "--speed", "0.5", *full, "--json"]) == 0
    given = json.loads(capsys.readouterr().out)
    assert given["filled"] == {} and given["mean"] == partial["mean"]
    assert main(["forces", "--model", "m1", "--speed", "0", "--param", "pitch=0.1"]) == 0
    assert (
        "filled from the model's hover defaults (not given): flap_amp = 1.5708, twist_amp = 0.785398"
        in capsys.readouterr().out
    )


def test_forces_climb_matches_api(capsys):
    assert (
        main(["forces", "--model", "m1", "--speed", "0.4", "--climb", "-0.3", *HOVER, "--json"])
        == 0
    )
    out = json.loads(capsys.readouterr().out)
    c = evaluate_cycle("m1", dict(pitch=1.5, flap_amp=1.5, twist_amp=0.7), 0.4, climb=-0.3)
    assert out["climb"] == -0.3 and out["body_drag_z"] == pytest.approx(
        float(c.body_drag_z), abs=1e-15
    )
    for k in ("Fx", "Fz", "P"):
        assert out["mean"][k] == pytest.approx(float(getattr(c.mean, k)), abs=1e-15)
    assert out["body_drag_z"] < 0  # sinking: the air comes from below, the drag pushes up
