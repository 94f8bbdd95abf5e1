"""The envelope from a table, checked against direct optimiser calls; the CLI."""

import json

import numpy as np
import pytest

from birdsim.cli import main
from birdsim.flight.envelope import envelope, reachable, trim_drag
from birdsim.physics.bird import Bird
from birdsim.physics.units import weight_in_table_units
from birdsim.tables.lookup import load_table
from birdsim.tables.optimize import ForceProblem, solve

SEED = Bird.from_toml("models/seed-bird.toml")
REACH_TOL = 0.01  # the tables' own: max(|Fx - Fx_d|, |Fz - Fz_d|) of an ok cell


@pytest.fixture(scope="module")
def m3():
    return load_table("tables/m3.npz")


@pytest.fixture(scope="module")
def env_m3(m3):
    return envelope(m3, SEED)


def _optimum(model, fx, fz, v, bird=SEED):
    # a direct optimiser call from 8 Sobol starts (no warm start from the table), 64 samples
    pr = ForceProblem(model, fx, fz, v, bird=Bird(body_drag_area=bird.body_drag_area), n=64)
    sol = solve(pr, "multistart", starts=8, seed=1)
    return pr.achieved(sol.x)


def test_reachable_is_status_at(m3):
    rng = np.random.default_rng(0)
    pts = rng.uniform([-0.5, -0.5, 0.0], [0.5, 0.0, 1.0], (400, 3))
    nodes = np.stack([rng.choice(m3.axes[a], 100) for a in ("Fx", "Fz", "V")], axis=1)
    for p in np.vstack([pts, nodes]):
        assert bool(reachable(m3, *p)) == (m3.status_at(*p) == "ok"), p
    assert not reachable(m3, 0.0, -0.1, 1.5)  # outside the grid


@pytest.mark.parametrize("iv", [0, 5])
def test_best_lift_is_the_optimisers(m3, env_m3, iv):
    # the stored best attempt at the most upward demand equals a fresh optimiser run (1 %)
    V = float(m3.axes["V"][iv])
    _, fz, _ = _optimum("m3", 0.0, -0.5, V, Bird())
    assert env_m3.best_lift[iv] == pytest.approx(-2 * fz, rel=0.01)


def test_hover_limit_and_level_flight_vs_optimiser(m3, env_m3):
    # the heaviest hovering bird's demand is met by the optimiser; 5 % more than the
    # optimiser's own best lift at V = 0 is not
    fx, fz, _ = _optimum("m3", 0.0, -env_m3.hover_weight / 2, 0.0)
    assert max(abs(fx), abs(fz + env_m3.hover_weight / 2)) <= REACH_TOL
    too_much = 1.05 * env_m3.best_lift[0] / 2
    fx, fz, _ = _optimum("m3", 0.0, -too_much, 0.0)
    assert abs(fz + too_much) > REACH_TOL
    # the minimum-power speed: the trimmed level demand is met, with the power the table says
    v = env_m3.min_power_speed
    w = weight_in_table_units(SEED)
    d = float(trim_drag(m3, SEED, -w / 2, v))
    fx, fz, p = _optimum("m3", d / 2, -w / 2, v)
    assert max(abs(fx - d / 2), abs(fz + w / 2)) <= REACH_TOL
    assert 2 * p == pytest.approx(env_m3.min_power, rel=0.1)  # interpolated vs optimal


def test_m4_cannot_hover_with_the_demo_bird():
    # docs/flight.md: m4's flap amplitude is bounded to pi/4; at V = 0 its best lift is
    # about 0.22 (whole bird) < the demo bird's weight 0.36
    env = envelope(load_table("tables/m4.npz"), SEED)
    assert not env.can_hover and env.best_lift[0] < weight_in_table_units(SEED)
    _, fz, _ = _optimum("m4", 0.0, -weight_in_table_units(SEED) / 2, 0.0)
    assert -2 * fz < weight_in_table_units(SEED) - 0.05


def test_envelope_cli_json_and_text(capsys):
    assert main(["envelope", "--model", "m3", "--table", "tables/m3.npz", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert (
        out["model"] == "m3" and out["weight"] == pytest.approx(0.36) and out["can_hover"] is True
    )
    assert main(["envelope", "--bird", "models/pigeon.toml"]) == 0
    text = capsys.readouterr().out
    assert "N" in text and "heaviest bird that can hover" in text and "kg" in text


def test_envelope_cli_refuses_a_table_for_another_bird(capsys):
    assert main(["envelope", "--bird", "models/pigeon.toml", "--table", "tables/m3.npz"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "reduced bird differs" in err
