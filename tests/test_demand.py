"""Inverse dynamics: path acceleration -> the table's force (one wing + body drag, seed axes)."""

import math

import numpy as np
import pytest

from birdsim.flight.demand import (
    body_drag_earth,
    demand_from_acceleration,
    path_demands,
    path_schedule,
)
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.physics.aero import body_drag_x
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird, scales, weight_in_table_units

SEED = Bird(mass=30.0, gravity=0.012)
PIGEON = Bird(
    name="pigeon",
    semispan=0.33,
    chord=0.12,
    hand_chord=0.12,
    rho=1.2,
    omega=2 * math.pi * 8.02,
    body_drag_area=0.005,
    disc_area=math.pi * 0.33**2,
    mass=0.483,
    gravity=9.81,
)


@pytest.mark.parametrize("bird", [SEED, PIGEON], ids=["seed", "pigeon"])
@pytest.mark.parametrize("V, pitch", [(0.0, 1.2), (0.5, 0.3), (0.9, 0.1)])
def test_level_unaccelerated_flight(bird, V, pitch):
    # Fz_table = -w/2 exactly, and the whole bird's Fx = 2 Fx_wing + D = 0, with
    # Fx_wing = Fx_table - D (the table carries the body drag once).
    w = weight_in_table_units(bird)
    fx, fz = demand_from_acceleration(0.0, 0.0, V, 0.0, bird, pitch)
    assert float(fz) == pytest.approx(-w / 2, abs=1e-15)
    d = body_drag_x(V, pitch, 1.0, reduced_bird(bird).body_drag_area)
    assert 2 * (float(fx) - d) + d == pytest.approx(0.0, abs=1e-15)


@pytest.mark.parametrize("a", [-0.01, 0.003, 0.02])
def test_vertical_acceleration_adds_minus_m_a_over_2(a):
    mu = reduced_bird(SEED).mass
    _, fz0 = demand_from_acceleration(0.0, 0.0, 0.4, 0.0, SEED, 0.3)
    fx1, fz1 = demand_from_acceleration(0.0, a, 0.4, 0.0, SEED, 0.3)
    assert float(fz1 - fz0) == pytest.approx(-mu * a / 2, rel=1e-13)
    fx0, _ = demand_from_acceleration(0.0, 0.0, 0.4, 0.0, SEED, 0.3)
    assert float(fx1) == float(fx0)


def test_forward_acceleration_adds_m_a_over_2():
    mu = reduced_bird(SEED).mass
    fx0, fz0 = demand_from_acceleration(0.0, 0.0, 0.4, 0.0, SEED, 0.3)
    fx1, fz1 = demand_from_acceleration(0.01, 0.0, 0.4, 0.0, SEED, 0.3)
    assert float(fx1 - fx0) == pytest.approx(mu * 0.01 / 2, rel=1e-13) and float(fz1) == float(fz0)


def test_si_bird_and_its_reduced_bird_agree():
    a = demand_from_acceleration(0.004, -0.002, 0.5, 0.05, PIGEON, 0.25)
    b = demand_from_acceleration(0.004, -0.002, 0.5, 0.05, reduced_bird(PIGEON), 0.25)
    np.testing.assert_allclose(a, b, rtol=1e-12)
    # and in newtons: the weight of 0.483 kg is w * force scale
    w = weight_in_table_units(PIGEON)
    assert w * scales(PIGEON).force == pytest.approx(0.483 * 9.81, rel=1e-12)


def test_body_drag_contract():
    # climb = 0 reproduces eq. 7 bit for bit; climbing, the drag is opposite the velocity
    # (V, -climb) in seed axes with magnitude 1/2 rho Vt^2 A |sin(theta - gamma)|.
    V, pitch = np.array([0.0, 0.3, 0.9]), np.array([1.0, 0.4, 0.1])
    dx, dz = body_drag_earth(SEED, V, 0.0, pitch)
    assert np.array_equal(dx, body_drag_x(V, pitch, 1.0, 1.0)) and np.all(dz == 0)
    dx, dz = body_drag_earth(SEED, 0.4, 0.3, 0.2)
    gamma = math.atan2(0.3, 0.4)
    mag = 0.5 * 0.25 * abs(math.sin(0.2 - gamma))
    assert math.hypot(dx, dz) == pytest.approx(mag, rel=1e-14)
    assert float(dx * (-0.3) - dz * 0.4) == pytest.approx(0.0, abs=1e-15)  # parallel to (0.4, -0.3)
    assert dx < 0 and dz > 0  # backwards and down while climbing


def test_path_demands_of_a_climb():
    # A steady straight climb (constant velocity): the table carries the weight, the drag
    # term uses the table's pitch at the demand.
    from birdsim.tables.lookup import load_table

    table = load_table("tables/m3.npz")
    p = FlightPath(
        "climb",
        4.0,
        False,
        False,
        (
            PathKeyframe(0, 4.0, x=0.0, vx=0.5, vz=0.05),
            PathKeyframe(3, 4.0 + 0.05 * 3 * 2 * math.pi, x=0.5 * 3 * 2 * math.pi, vx=0.5, vz=0.05),
        ),
    )
    t = np.linspace(0, p.duration, 9)
    d = path_demands(p, SEED, table, t)
    assert np.allclose(d["ax"], 0, atol=1e-12) and np.allclose(d["az"], 0, atol=1e-12)
    fx, fz = demand_from_acceleration(0, 0, 0.5, 0.05, SEED, d["pitch"])
    assert np.array_equal(d["Fx"], fx) and np.array_equal(d["Fz"], fz)
    # the pitch is (nearly) the table's own at the demand: the fixed point converged
    again = table.lookup_many(Fx=d["Fx"], Fz=d["Fz"], V=d["V"])["pitch"]
    np.testing.assert_allclose(again, d["pitch"], atol=1e-4)
    assert np.allclose(d["V"], 0.5) and np.allclose(d["climb"], 0.05)


def test_path_schedule_plays_the_paths_demands():
    # the force-keyframe form of a preset: at its keyframes it carries path_demands exactly,
    # and between them (PCHIP) every demand stays reachable in the demo table
    from birdsim.flight.envelope import reachable
    from birdsim.flight.presets import PATH_PRESETS, demo_bird
    from birdsim.tables.lookup import load_table

    table, bird = load_table("tables/seed-m3.npz"), demo_bird()
    path = PATH_PRESETS["landing"]
    m = path_schedule(path, bird, table)
    assert m.perch == "end" and m.duration == path.duration_beats and m.name == "landing"
    kt = np.array([k.t for k in m.keyframes])
    d = path_demands(path, bird, table, kt * 2 * math.pi)
    assert np.allclose([k.Fz for k in m.keyframes], d["Fz"]) and np.allclose(
        [k.V for k in m.keyframes], d["V"]
    )
    dense = m.demands(np.linspace(0, path.duration_beats, 30 * 32))
    assert reachable(table, dense["Fx"], dense["Fz"], dense["V"]).all()
