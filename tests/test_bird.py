"""Bird configuration: validation, TOML round trip, --set overrides."""

import pytest

from birdsim import Bird, RoboflyPolar, SeedPolar
from birdsim.errors import BirdConfigError


def test_toml_round_trip(tmp_path):
    bird = Bird(name="thrush", semispan=1.3, strips=5, polar=RoboflyPolar())
    path = tmp_path / "bird.toml"
    bird.to_toml(path)
    assert Bird.from_toml(path) == bird


def test_overrides():
    b = Bird().with_overrides({"strips": "12", "induced_velocity": "true", "polar.cl_max": "1.5"})
    assert b.strips == 12 and b.induced_velocity and b.polar == SeedPolar(cl_max=1.5)
    # switching the polar kind must not carry the seed polar's coefficients along
    assert Bird().with_overrides({"polar.kind": "robofly"}).polar == RoboflyPolar()
    back = Bird(polar=RoboflyPolar()).with_overrides({"polar.kind": "seed", "polar.cd0": "0.1"})
    assert back.polar == SeedPolar(cd0=0.1)


@pytest.mark.parametrize(
    "kwargs, text",
    [
        ({"semispan": 0.0}, "bird.semispan=0.0 is invalid"),
        ({"chord": float("nan")}, "bird.chord=nan is invalid"),
        ({"hand_span_fraction": 1.5}, r"allowed: a number in \[0, 1\]"),
        ({"strips": 0}, "bird.strips=0"),
    ],
)
def test_invalid_values(kwargs, text):
    with pytest.raises(BirdConfigError, match=text):
        Bird(**kwargs)


def test_bad_files_and_keys(tmp_path):
    with pytest.raises(BirdConfigError, match="does not exist"):
        Bird.from_toml(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("semispan = [")
    with pytest.raises(BirdConfigError, match="not valid TOML"):
        Bird.from_toml(bad)
    bad.write_text("wingspan = 2.0")
    with pytest.raises(BirdConfigError, match="'wingspan' is unknown"):
        Bird.from_toml(bad)
    with pytest.raises(BirdConfigError, match="overrides: strips='x' is not an integer"):
        Bird().with_overrides({"strips": "x"})
    with pytest.raises(BirdConfigError, match="names no bird field"):
        Bird().with_overrides({"wingspan": "2"})
