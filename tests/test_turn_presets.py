"""The turning presets as data (issue 23 item 3): their geometry, not yet their flight."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim.flight.path import PERCH_X, PERCH_Y, PERCH_Z
from birdsim.flight.presets import CRUISE_SPEED, PATH_PRESETS
from birdsim.flight.turn_presets import (
    CIRCLE_RADIUS,
    SLOW_RADIUS,
    SLOW_SPEED,
    TURN_PRESETS,
    U_TURN_THETA,
)

TWO_PI = 2 * math.pi


def _heading(s) -> np.ndarray:
    return np.unwrap(np.arctan2(s["vy"], s["vx"]))


def test_names_and_kept_apart_from_the_straight_presets():
    assert list(TURN_PRESETS) == ["turn-90", "circle", "s-turn", "u-turn"]
    assert list(PATH_PRESETS) == ["hover", "cruise", "take-off", "landing"]  # not registered
    assert all(p.is_3d and p.form == "speed" for p in TURN_PRESETS.values())


def test_turn_90_turns_90_degrees_level_at_slow_speed():
    p = TURN_PRESETS["turn-90"]
    s = p.sample(np.linspace(0.0, p.duration, 2001))
    psi = _heading(s)
    assert psi[0] == 0.0 and math.degrees(psi[-1]) == pytest.approx(90.0, abs=1e-12)
    assert np.all(np.diff(psi) >= -1e-15)  # one way only, to the left
    np.testing.assert_allclose(np.hypot(s["vx"], s["vy"]), SLOW_SPEED, rtol=1e-13)
    assert np.ptp(s["z"]) == 0.0 and np.all(s["vz"] == 0.0)
    # the steady arc: radius SLOW_RADIUS (5 semispans = 1.65 m for the pigeon at 3.3 m/s;
    # 3 semispans, the 1 m, does not fly: docs/turning.md)
    a = np.hypot(s["ax"], s["ay"])
    assert a.max() == pytest.approx(SLOW_SPEED**2 / SLOW_RADIUS, rel=1e-12)
    assert SLOW_SPEED * 16.63 == pytest.approx(
        3.33, abs=0.01
    )  # pigeon speed scale, docs/turning.md
    assert SLOW_RADIUS * 0.33 == pytest.approx(1.65)


def test_circle_closes():
    # 360 degrees at cruise speed; the loop ends on the line and heading it entered on, at
    # the entry speed and with no acceleration (to 1e-9 semispan)
    p = TURN_PRESETS["circle"]
    t0, t1 = p.keyframes[1].t * TWO_PI, p.keyframes[-1].t * TWO_PI
    a, b = p.state(t0), p.state(t1)
    s = p.sample(np.linspace(t0, t1, 4001))
    assert _heading(s)[-1] - _heading(s)[0] == pytest.approx(TWO_PI, abs=1e-12)
    assert abs(b.y - a.y) < 1e-9 and abs(b.vy) < 1e-12 and b.vx == pytest.approx(CRUISE_SPEED)
    assert abs(b.ax) < 1e-12 and abs(b.ay) < 1e-12 and a.ax == 0.0 and a.ay == 0.0
    # a circle: the steady part lies on radius CIRCLE_RADIUS about one centre
    v = CRUISE_SPEED
    cx, cy = s["x"] - CIRCLE_RADIUS * s["vy"] / v, s["y"] + CIRCLE_RADIUS * s["vx"] / v
    steady = np.hypot(s["ax"], s["ay"]) > v * v / CIRCLE_RADIUS * (1 - 1e-12)
    assert steady.sum() > 3000
    assert np.ptp(cx[steady]) < 1e-9 and np.ptp(cy[steady]) < 1e-9
    assert s["y"].max() == pytest.approx(2 * CIRCLE_RADIUS, rel=0.02)


def test_s_turn_ends_on_its_first_heading_offset_left():
    p = TURN_PRESETS["s-turn"]
    s = p.sample(np.linspace(0.0, p.duration, 3001))
    psi = _heading(s)
    assert abs(psi[-1]) < 1e-12 and math.degrees(psi.max()) == pytest.approx(45.0, abs=1e-9)
    assert s["y"][-1] > 5.0 and abs(s["vy"][-1]) < 1e-12


def test_u_turn_ends_at_its_start_at_rest_on_the_perch():
    p = TURN_PRESETS["u-turn"]
    assert p.perch_start and p.perch_end
    a, b = p.state(0.0), p.state(p.keyframes[-1].t * TWO_PI)
    for st in (a, b):
        assert (st.x, st.y, st.z) == pytest.approx((PERCH_X, PERCH_Y, PERCH_Z), abs=1e-9)
        assert max(abs(st.vx), abs(st.vy), abs(st.vz), abs(st.ax), abs(st.ay), abs(st.az)) < 1e-12
    s = p.sample(np.linspace(0.0, p.duration, 4001))
    back = p.state(p.keyframes[-2].t * TWO_PI)  # ... and back, braking towards the perch
    assert math.degrees(math.atan2(back.vy, back.vx)) == pytest.approx(180.0, abs=1e-9)
    assert p.headings()[-1] == math.pi and back.vx < 0
    assert s["x"].max() > PERCH_X + 5.0  # it goes out ...
    assert math.degrees(U_TURN_THETA) == pytest.approx(28.3, abs=0.1)  # the keyhole's side turns
    assert np.hypot(s["vx"], s["vy"]).max() == pytest.approx(SLOW_SPEED, rel=1e-12)
    assert s["z"].min() >= PERCH_Z - 1e-12


@pytest.mark.parametrize("name", list(TURN_PRESETS))
def test_minimum_jerk_continuity(name):
    # position, velocity and acceleration continuous to 1e-9 across every keyframe
    # (+-1e-10 reduced time); velocities are the derivative of the positions (1e-7)
    p = TURN_PRESETS[name]
    keys = ("x", "y", "z", "vx", "vy", "vz", "ax", "ay", "az")
    for k in p.keyframes:
        t = k.t * TWO_PI
        lo, hi = p.sample(t - 1e-10), p.sample(t + 1e-10)
        for key in keys:
            assert abs(float(hi[key] - lo[key])) < 1e-9, (name, k.t, key)
    t = np.linspace(0.0, p.duration, 1501)
    s, sp, sm = p.sample(t), p.sample(t + 1e-6), p.sample(t - 1e-6)
    for pos, vel, acc in (("x", "vx", "ax"), ("y", "vy", "ay"), ("z", "vz", "az")):
        np.testing.assert_allclose((sp[pos] - sm[pos]) / 2e-6, s[vel], atol=1e-7)
        np.testing.assert_allclose((sp[vel] - sm[vel]) / 2e-6, s[acc], atol=1e-7)


@pytest.mark.parametrize("name", list(TURN_PRESETS))
def test_a_turn_preset_round_trips_through_a_path_file(name):
    # the studio's dict of a path file (path_dict) and back: the same keyframes and samples
    pytest.importorskip("tomli_w")
    from birdsim.studio.flights import load_path, path_dict

    p = TURN_PRESETS[name]
    q = load_path(path_dict(p), name)
    assert q.keyframes == p.keyframes and q.perch_start == p.perch_start
    t = np.linspace(0.0, p.duration, 300)
    a, b = p.sample(t), q.sample(t)
    for key in a:
        np.testing.assert_array_equal(a[key], b[key])


def _bank_plane_demand(p, bird, table, per_beat: int = 32):
    """The feed-forward demand of a turning path read in the bank plane (issue 23 item 2's
    plan: the symmetric table gives the force in the body's symmetry plane, the body rolls
    to point it): the along-track acceleration is the 2-D path's ax, the force in the
    plane grows by sqrt(1 + (a_n / (az + g))^2) with a_n the horizontal centripetal
    acceleration. A sketch of what the controller will ask, not its own reading."""
    from birdsim.flight.demand import demand_from_acceleration
    from birdsim.physics.units import reduced_bird

    t = np.linspace(0.0, p.duration, int(p.duration_beats * per_beat) + 1)
    s = p.sample(t)
    v = np.hypot(s["vx"], s["vy"])
    moving = v > 1e-9
    safe = np.where(moving, v, 1.0)
    a_t = np.where(
        moving, (s["vx"] * s["ax"] + s["vy"] * s["ay"]) / safe, np.hypot(s["ax"], s["ay"])
    )
    a_n = np.where(moving, (s["vx"] * s["ay"] - s["vy"] * s["ax"]) / safe, 0.0)
    g = reduced_bird(bird).gravity
    pitch = np.zeros_like(v)
    for _ in range(4):  # the body drag's pitch: the table's
        fx, fz = demand_from_acceleration(a_t, s["az"], v, s["vz"], bird, pitch)
        fz = fz * np.sqrt(1.0 + (a_n / (s["az"] + g)) ** 2)
        pitch = table.lookup_many(Fx=fx, Fz=fz, V=v, clip=True)["pitch"]
    return fx, fz, v


@pytest.mark.parametrize("bird_name", ["seed", "pigeon"])
def test_turn_presets_lie_inside_the_demo_tables_envelope(bird_name):
    # every sample's bank-plane demand lies in table cells whose corners are all ok, with
    # the room of the straight presets (moved by 0.02 in Fx and Fz, still met within 0.01):
    # the turn-90 asks for 1.20 times the weight (a_c = 0.67 g on R = 5 semispans)
    from birdsim.flight.envelope import reachable, room
    from birdsim.flight.presets import PIGEON_FILE, demo_bird
    from birdsim.physics.bird import Bird
    from birdsim.tables.lookup import load_table
    from birdsim.tables.shipped import shipped_table

    bird = demo_bird() if bird_name == "seed" else Bird.from_toml(PIGEON_FILE)
    table = load_table(shipped_table(bird, "m3"))
    for name, p in TURN_PRESETS.items():
        fx, fz, v = _bank_plane_demand(p, bird, table)
        assert reachable(table, fx, fz, v).all(), name
        assert room(table, fx, fz, v, 0.02).all(), name
    fz90 = _bank_plane_demand(TURN_PRESETS["turn-90"], bird, table)[1].min()
    level = (
        -0.5 * bird.mass * bird.gravity / (bird.rho * bird.omega**2 * bird.semispan**3 * bird.chord)
    )
    assert fz90 / level == pytest.approx(
        math.hypot(
            1.0, SLOW_SPEED**2 / SLOW_RADIUS / (bird.gravity / (bird.omega**2 * bird.semispan))
        ),
        rel=1e-6,
    )
