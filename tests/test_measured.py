import math

import pytest

from birdsim.cli import main
from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.measured import bird_from_measurements, derived
from birdsim.physics.units import reduced_bird, same_reduced_bird


def test_si_bird_from_measurements():
    b = bird_from_measurements("pigeon", mass=0.45, span=0.65, mean_chord=0.1, frequency=7.0)
    assert (b.rho, b.semispan, b.chord, b.gravity) == (1.225, 0.325, 0.1, 9.81)
    assert b.omega == pytest.approx(2 * math.pi * 7.0)
    d = derived(b)
    assert d.mass_ratio == pytest.approx(
        0.45 / (1.225 * 0.325**2 * 0.1)
    )  # about 30 for a pigeon (issue 9)
    assert d.weight_table == pytest.approx(0.45 * 9.81 / (1.225 * b.omega**2 * 0.325**3 * 0.1))
    assert d.speed_range_si[1] == pytest.approx(b.omega * 0.325)
    # without a body drag area the reduced bird is the seed bird's: the seed tables serve it
    assert same_reduced_bird(b, Bird())
    assert reduced_bird(b).body_drag_area == pytest.approx(1.0)
    assert not same_reduced_bird(
        bird_from_measurements(
            "p", mass=0.45, span=0.65, mean_chord=0.1, frequency=7.0, body_drag_area=0.005
        ),
        Bird(),
    )


@pytest.mark.parametrize(
    "kw, arg",
    [
        (dict(mass=-1.0), "--mass"),
        (dict(mass=float("nan")), "--mass"),
        (dict(span=0.0), "--span"),
        (dict(mean_chord=0.7), "--mean-chord 0.7 is longer than --span"),
        (dict(frequency=-2.0), "--frequency"),
        (dict(body_drag_area=-0.1), "--body-drag-area"),
    ],
)
def test_bad_measurements(kw, arg):
    base = dict(mass=0.45, span=0.65, mean_chord=0.1, frequency=7.0)
    with pytest.raises(BirdsimError, match=arg):
        bird_from_measurements("x", **{**base, **kw})


def test_cli_bird_new(tmp_path, capsys):
    out = tmp_path / "dove.toml"
    argv = [
        "bird",
        "new",
        "dove",
        "--mass",
        "0.45",
        "--span",
        "0.65",
        "--mean-chord",
        "0.1",
        "--frequency",
        "7",
        "--out",
        str(out),
    ]
    assert main(argv) == 0
    text = capsys.readouterr().out
    assert (
        "mass ratio" in text and "weight in table units" in text and "reduced speed range" in text
    )
    body = out.read_text()
    assert body.count("\n# ") >= 2 and "mass ratio" in body  # the derived figures as comments
    b = Bird.from_toml(out)
    assert b.name == "dove" and b.mass == 0.45 and b.gravity == 9.81
    assert main(argv) == 2 and "--force" in capsys.readouterr().err
    for bad, word in ((["--mass", "-1"], "--mass"), (["--mean-chord", "0.7"], "longer than")):
        args = list(argv)
        i = args.index(bad[0])
        args[i + 1] = bad[1]
        args[args.index("--out") + 1] = str(tmp_path / "bad.toml")
        assert main(args) == 2
        err = capsys.readouterr().err
        assert word in err and err.count("\n") == 1 and not (tmp_path / "bad.toml").exists()
