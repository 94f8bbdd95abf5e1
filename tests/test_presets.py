"""The four presets as paths: what they promise, and that the demo table reaches every sample."""

import math

import numpy as np
import pytest

from birdsim.flight.envelope import path_reach, room
from birdsim.flight.path import PERCH_X, PERCH_Z
from birdsim.flight.presets import CRUISE_HEIGHT, CRUISE_SPEED, DEMO_MODEL, PATH_PRESETS, demo_bird
from birdsim.physics.bird import Bird
from birdsim.tables.lookup import load_table
from birdsim.tables.shipped import PACKAGE_TABLES, shipped_table

PIGEON = Bird.from_toml("models/pigeon.toml")


@pytest.mark.parametrize("bird", [demo_bird(), PIGEON], ids=["seed", "pigeon"])
@pytest.mark.parametrize("name", list(PATH_PRESETS))
def test_every_sample_of_every_preset_is_within_reach(bird, name):
    # 32 samples per wingbeat; a sample is reachable when all corners of its table cell
    # are ok (LookupTable.status_at, the overlay's test). Both readings of a climb: earth
    # axes (path_demands) and the air-path frame (air_path_demand, what the controller
    # looks up). Room for the controller: every demand moved by up to 0.02 in Fx and Fz
    # is still met within 0.01 by the table's achieved force.
    table = load_table(shipped_table(bird, DEMO_MODEL, PACKAGE_TABLES))
    table.require_bird(bird)
    r = path_reach(PATH_PRESETS[name], bird, table)
    for ok, fx, fz, v in (("ok", "Fx", "Fz", "V"), ("ok_air", "Fx_air", "Fz_air", "V_air")):
        bad = np.flatnonzero(~r[ok])
        assert bad.size == 0, (
            f"{name} ({ok}): first unreachable sample t={r['t_beats'][bad[0]]:.2f} beats "
            f"Fx={r[fx][bad[0]]:+.4f} Fz={r[fz][bad[0]]:+.4f} V={r[v][bad[0]]:.3f}"
        )
    assert room(table, r["Fx_air"], r["Fz_air"], r["V_air"], 0.02).all()


def test_air_path_reading_is_the_earth_reading_in_level_flight():
    from birdsim.flight.demand import air_path_demand, demand_from_acceleration

    bird = demo_bird()
    for ax, az, vx, pitch in (
        (0.0, 0.0, 0.5, 0.2),
        (0.004, -0.002, 0.3, 0.6),
        (0.001, 0.003, 0.0, 1.2),
    ):
        fx, fz, v, gamma = air_path_demand(ax, az, vx, 0.0, bird, pitch)
        assert (fx, fz) == tuple(
            float(x) for x in demand_from_acceleration(ax, az, vx, 0.0, bird, pitch)
        )
        assert v == vx and gamma == 0.0
    # a steady climb at 10 degrees: the air-path frame sees level flight plus the weight's
    # component along the path, w sin(gamma) / 2 more thrust and w cos(gamma) / 2 lift
    g = math.radians(10.0)
    w = 0.36
    fx, fz, v, gamma = air_path_demand(
        0.0, 0.0, 0.5 * math.cos(g), 0.5 * math.sin(g), bird, 0.3 + g
    )
    fx0, _ = demand_from_acceleration(0.0, 0.0, 0.5, 0.0, bird, 0.3)
    assert gamma == pytest.approx(g) and v == pytest.approx(0.5)
    assert fz == pytest.approx(-w * math.cos(g) / 2, rel=1e-12)
    assert fx == pytest.approx(float(fx0) + w * math.sin(g) / 2, rel=1e-12)


def test_what_the_presets_promise():
    two_pi = 2 * math.pi
    hover = PATH_PRESETS["hover"]
    for t in np.linspace(0, hover.duration, 7):
        s = hover.state(t)
        assert (s.x, s.z, s.vx, s.vz) == (0.0, CRUISE_HEIGHT, 0.0, 0.0)
    cruise = PATH_PRESETS["cruise"]
    s = cruise.sample(np.linspace(0, cruise.duration, 50))
    assert (
        np.all(s["z"] == CRUISE_HEIGHT)
        and np.allclose(s["vx"], CRUISE_SPEED)
        and np.all(s["ax"] == 0)
    )
    take_off, landing = PATH_PRESETS["take-off"], PATH_PRESETS["landing"]
    a, b = take_off.state(0.0), take_off.state(take_off.duration)
    assert (a.x, a.z, a.vx) == pytest.approx((PERCH_X, PERCH_Z, 0.0)) and (
        b.z,
        b.vx,
        b.vz,
    ) == pytest.approx((CRUISE_HEIGHT, CRUISE_SPEED, 0.0))
    a, b = landing.state(0.0), landing.state(landing.keyframes[-1].t * two_pi)
    assert (a.z, a.vx) == pytest.approx((CRUISE_HEIGHT, CRUISE_SPEED)) and (
        b.x,
        b.z,
        b.vx,
    ) == pytest.approx((PERCH_X, PERCH_Z, 0.0), abs=1e-9)
    end = landing.state(landing.duration)  # held at rest on the perch after the last keyframe
    assert (end.x, end.z, end.vx, end.vz) == pytest.approx((PERCH_X, PERCH_Z, 0.0, 0.0), abs=1e-9)
    # speeds never go backwards and heights change monotonically on take-off and landing
    for p, sign in ((take_off, 1), (landing, -1)):
        s = p.sample(np.linspace(0, p.duration, 2000))
        assert s["vx"].min() >= -1e-12 and np.all(sign * np.diff(s["z"]) >= -1e-12)
