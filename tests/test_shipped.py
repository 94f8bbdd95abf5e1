"""Shipped tables: found by bird and model; a table refuses a bird it was not built for."""

import math

import pytest

from birdsim.physics.bird import Bird
from birdsim.physics.units import mass_ratio, reduced_bird, scales, weight_in_table_units
from birdsim.tables.lookup import TableError, load_table
from birdsim.tables.shipped import PACKAGE_TABLES, shipped_table

SEED = Bird.from_toml("models/seed-bird.toml")
PIGEON = Bird.from_toml("models/pigeon.toml")


def test_shipped_birds_numbers():
    # The values docs/flight.md and the TOML comments quote (3 significant digits).
    assert mass_ratio(SEED) == 30.0 and weight_in_table_units(SEED) == pytest.approx(
        0.36, abs=1e-12
    )
    assert mass_ratio(PIGEON) == pytest.approx(30.8, abs=0.05)
    assert weight_in_table_units(PIGEON) == pytest.approx(0.361, abs=0.0005)
    sc = scales(PIGEON)
    assert sc.force == pytest.approx(13.14, abs=0.005) and sc.speed == pytest.approx(
        16.63, abs=0.005
    )
    assert PIGEON.omega == pytest.approx(2 * math.pi * 8.02, rel=1e-12)
    assert reduced_bird(PIGEON).body_drag_area == pytest.approx(0.126, abs=0.0005)


def test_the_pigeon_finds_its_own_table():
    p = shipped_table(PIGEON, "m3", PACKAGE_TABLES)
    assert p.name.startswith("pigeon-")
    t = load_table(p)
    t.require_bird(PIGEON)  # the SI bird: same reduced bird
    with pytest.raises(TableError, match="reduced bird differs") as exc:
        t.require_bird(SEED)
    assert "\n" not in str(exc.value)


def test_the_seed_bird_gets_a_seed_table():
    t = load_table(shipped_table(SEED, "m3", PACKAGE_TABLES))
    t.require_bird(SEED)
    t.require_bird(Bird())  # the weightless default bird: same aerodynamics
    with pytest.raises(TableError):
        t.require_bird(PIGEON)


def test_no_table_for_this_bird_is_one_line(tmp_path):
    odd = Bird(name="odd", chord=0.5)
    with pytest.raises(
        TableError, match="no table in .* was built for this bird and model m3"
    ) as exc:
        shipped_table(odd, "m3", PACKAGE_TABLES)
    assert "\n" not in str(exc.value)


def test_tables_build_reduces_an_si_bird(tmp_path):
    # `tables build --bird pigeon.toml` builds for the pigeon's reduced bird: the table is
    # in table units (here 8 reachable cells of Fz -0.2/-0.1, which in newtons would be a
    # fiftieth of the pigeon's weight) and serves the SI pigeon
    from birdsim.cli import main

    out = tmp_path / "p.npz"
    grid = "Fx=0:0.1:2,Fz=-0.2:-0.1:2,V=0.4:0.5:2"
    argv = ["tables", "build", "--model", "base", "--bird", "models/pigeon.toml", "--grid", grid]
    assert main([*argv, "--out", str(out), "--jobs", "1", "--quiet"]) == 0
    t = load_table(out)
    assert t.bird == reduced_bird(PIGEON)
    t.require_bird(PIGEON)
    assert (t.status_code == 0).all()
