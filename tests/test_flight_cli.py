"""``birdsim fly`` and the flight log (birdsim.commands.fly, birdsim.flight.flightlog):
the log's arrays and units, atomic writes, --force, the JSON summary, one-line errors."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from birdsim.cli import main
from birdsim.flight.flightlog import LOG_FORMAT, LogError, load_log, summary
from birdsim.physics.bird import Bird

SEED = Bird(mass=30.0, gravity=0.012)
PIGEON = Bird(
    name="pigeon",
    semispan=0.33,
    chord=0.12,
    hand_chord=0.12,
    rho=1.2,
    omega=50.0,
    body_drag_area=0.12 * 0.33,
    disc_area=math.pi * 0.33**2,
    mass=30.0 * 1.2 * 0.33**2 * 0.12,
    gravity=0.012 * 50.0**2 * 0.33,
)

ISSUE_ARRAYS = (
    "t",
    "x",
    "z",
    "vx",
    "vz",
    "x_ref",
    "z_ref",
    "pitch",
    "Fx_demand",
    "Fz_demand",
    "V_air",
    "saturated",
    "pitch_moment",
)
ISSUE_SCALARS = ("mass", "gravity", "model", "bird", "omega")


@pytest.fixture(scope="module")
def birds(tmp_path_factory):
    d = tmp_path_factory.mktemp("birds")
    SEED.to_toml(d / "seed.toml")
    PIGEON.to_toml(d / "pigeon.toml")
    return d


def fly(args, capsys):
    code = main(["fly", *args, "--quiet"])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_log_has_the_issue_arrays(birds, tmp_path, capsys):
    log = tmp_path / "cruise.npz"
    code, out, err = fly(
        [
            "cruise",
            "--model",
            "m4",
            "--table",
            "tables/m4.npz",
            "--bird",
            str(birds / "seed.toml"),
            "--out",
            str(log),
            "--seconds",
            str(3 * 2 * math.pi),
            "--json",
        ],
        capsys,
    )
    assert code == 0, err
    info = json.loads(out)
    data = load_log(log)
    for k in ISSUE_ARRAYS + ISSUE_SCALARS + ("flap_amp", "twist_amp", "wrist_lag"):
        assert k in data, k
    assert str(data["format"]) == LOG_FORMAT and str(data["model"]) == "m4"
    n = data["t"].size
    assert n >= 32 * 3 and all(data[k].shape == (n,) for k in ISSUE_ARRAYS)
    assert math.isclose(float(data["mass"]), 30.0) and math.isclose(float(data["gravity"]), 0.012)
    assert Bird.from_dict(__import__("tomllib").loads(str(data["bird"]))) == SEED
    assert info["samples"] == n and info["wingbeats_saturated"] == 0
    for k in (
        "rms_error",
        "max_error",
        "final_position",
        "final_speed",
        "wingbeats_saturated",
        "mean_power",
        "pitch_moment_per_wingbeat",
    ):
        assert k in info
    assert info["rms_error"] < 0.05 and info["mean_power"] > 0


def test_pigeon_log_is_in_seconds_and_metres(birds, tmp_path, capsys):
    """The pigeon here has the seed bird's reduced bird: the same flight in SI."""
    seed_log, pigeon_log = tmp_path / "s.npz", tmp_path / "p.npz"
    beats = 2.0
    for bird, log, period in (
        ("seed", seed_log, 2 * math.pi),
        ("pigeon", pigeon_log, 2 * math.pi / 50.0),
    ):
        code, _, err = fly(
            [
                "cruise",
                "--model",
                "m4",
                "--table",
                "tables/m4.npz",
                "--bird",
                str(birds / f"{bird}.toml"),
                "--out",
                str(log),
                "--seconds",
                str(beats * period),
            ],
            capsys,
        )
        assert code == 0, err
    s, p = load_log(seed_log), load_log(pigeon_log)
    np.testing.assert_allclose(p["t"], s["t"] / 50.0, rtol=1e-12)
    np.testing.assert_allclose(p["z"], s["z"] * 0.33, rtol=1e-9)
    np.testing.assert_allclose(p["vx"], s["vx"] * 50.0 * 0.33, rtol=1e-9)
    np.testing.assert_allclose(
        p["Fz_demand"], s["Fz_demand"], rtol=1e-9
    )  # table units, unconverted
    assert float(p["omega"]) == 50.0


def test_existing_log_needs_force_and_nothing_is_written_on_error(birds, tmp_path, capsys):
    log = tmp_path / "x.npz"
    log.write_bytes(b"keep")
    code, _, err = fly(
        [
            "cruise",
            "--table",
            "tables/m4.npz",
            "--bird",
            str(birds / "seed.toml"),
            "--out",
            str(log),
        ],
        capsys,
    )
    assert code == 2 and "--force" in err and log.read_bytes() == b"keep"
    other = tmp_path / "new.npz"
    code, _, err = fly(
        [
            "cruise",
            "--table",
            "tables/m4.npz",
            "--bird",
            str(birds / "seed.toml"),
            "--out",
            str(other),
            "--gust",
            "1:1:0",
        ],
        capsys,
    )
    assert code == 2 and not other.exists() and len(err.strip().splitlines()) == 1
    assert not list(tmp_path.glob(".*partial*"))


@pytest.mark.parametrize(
    "args, needle",
    [
        (["nowhere"], "manoeuvre 'nowhere' is unknown"),
        (["cruise", "--model", "m7"], "model 'm7' is unknown"),
        (["cruise", "--gust", "1:1:0"], "T0:DURATION:WX:WZ"),
        (["cruise", "--gust", "1:x:0:0"], "is not numbers"),
        (["cruise", "--gust", "1:1:0:0:0:0"], "has 6 field(s)"),
        (["cruise", "--gust", "1:1:0:nan:0"], "finite"),
        (["cruise", "--gust", "1:1:inf:0"], "finite"),
        (["cruise", "--seconds", "nan"], "--seconds"),
        (["cruise", "--seconds", "-1"], "--seconds"),
        (["cruise", "--out", "log.txt"], ".npz"),
        (["cruise", "--model", "m3", "--table", "tables/m4.npz"], "built for model 'm4'"),
    ],
)
def test_bad_input_is_one_line(birds, args, needle, capsys):
    code, out, err = fly([*args, "--bird", str(birds / "seed.toml")], capsys)
    assert (
        code == 2
        and needle in err
        and len(err.strip().splitlines()) == 1
        and "Traceback" not in err
    )


def test_table_for_another_bird_is_refused(tmp_path, capsys):
    other = Bird(chord=0.5, mass=30.0, gravity=0.012)
    other.to_toml(tmp_path / "b.toml")
    code, _, err = fly(
        ["cruise", "--model", "m4", "--table", "tables/m4.npz", "--bird", str(tmp_path / "b.toml")],
        capsys,
    )
    assert code == 2 and "reduced bird" in err


def test_weightless_bird_is_refused(tmp_path, capsys):
    Bird().to_toml(tmp_path / "w.toml")
    code, _, err = fly(
        ["cruise", "--table", "tables/m4.npz", "--bird", str(tmp_path / "w.toml")], capsys
    )
    assert code == 2 and "gravity" in err


def test_log_from_another_program_is_refused(tmp_path):
    p = tmp_path / "other.npz"
    np.savez(p, t=np.zeros(3))
    with pytest.raises(LogError, match="not a birdsim flight log"):
        load_log(p)
    (tmp_path / "junk.npz").write_text("not a zip")
    with pytest.raises(LogError, match="not a .npz"):
        load_log(tmp_path / "junk.npz")
    with pytest.raises(LogError, match="does not exist"):
        load_log(tmp_path / "missing.npz")


def test_summary_counts_saturated_wingbeats():
    t = np.arange(128) * (2 * math.pi / 64)  # two wingbeats of the seed bird
    arrays = {
        k: np.zeros(128) for k in ("x", "z", "x_ref", "z_ref", "vx", "vz", "pitch_moment", "power")
    }
    arrays.update(
        t=t,
        omega=np.array(1.0),
        model=np.array("m4"),
        bird=np.array('name = "seed"\n'),
        saturated=np.zeros(128, bool),
    )
    arrays["saturated"][70] = True
    arrays["z"][:] = 0.1
    arrays["pitch_moment"][5] = -2.0
    info = summary(arrays)
    assert info["wingbeats_saturated"] == 1 and info["saturated_samples"] == 1
    assert math.isclose(info["rms_error"], 0.1) and info["pitch_moment_peak"] == 2.0
    assert info["pitch_moment_per_wingbeat"]["peak"] == [2.0, 0.0]


def test_json_is_strict_when_a_figure_does_not_exist(capsys):
    """A flight shorter than its start (12 time units < 2 wingbeats) has no error after
    the start: the JSON says null, not NaN (which strict JSON parsers refuse)."""
    code = main(["fly", "hover", "--seconds", "12", "--json"])
    out = capsys.readouterr().out
    assert code == 0

    def refuse(constant: str) -> None:
        raise ValueError(f"non-standard JSON constant {constant}")

    info = json.loads(out, parse_constant=refuse)
    assert info["rms_error_after_start"] is None
    assert math.isfinite(info["rms_error"])
