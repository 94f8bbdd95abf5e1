"""The four presets as paths: what they promise, and that the demo table reaches every sample."""

import math

import numpy as np
import pytest

from birdsim.flight.envelope import path_reach
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
    # are ok (what status_at, the overlay and the flight log's "saturated" use)
    table = load_table(shipped_table(bird, DEMO_MODEL, PACKAGE_TABLES))
    table.require_bird(bird)
    r = path_reach(PATH_PRESETS[name], bird, table)
    bad = np.flatnonzero(~r["ok"])
    assert bad.size == 0, (
        f"{name}: first unreachable sample t={r['t_beats'][bad[0]]:.2f} beats "
        f"Fx={r['Fx'][bad[0]]:+.4f} Fz={r['Fz'][bad[0]]:+.4f} V={r['V'][bad[0]]:.3f}"
    )


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
