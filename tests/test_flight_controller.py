"""The controller's parts (birdsim.flight.controller): the wingbeat-averaged estimate,
saturation, and the level table turned into a climbing air path."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim.flight.controller import Controller, ErrorWindow, gains_for
from birdsim.flight.demand import demand_from_acceleration
from birdsim.physics.bird import Bird
from birdsim.tables.lookup import load_table

BIRD = Bird(mass=30.0, gravity=0.012)


def test_window_removes_the_wingbeat_and_predicts_half_a_period():
    n, period = 64, 2 * math.pi
    w = ErrorWindow(n, period)
    dt = period / n
    t = np.arange(3 * n + 1) * dt
    drift_v, bob = 0.01, 0.3
    for tk in t:  # error = slow ramp + a wingbeat oscillation (which must vanish)
        w.add(
            np.array([drift_v * tk + bob * math.sin(tk), 0.0]),
            np.array([drift_v + bob * math.cos(tk), 0.0]),
            0.5 + 0.1 * math.sin(tk),
        )
    ep, ev, vx = w.estimate()
    assert abs(ep[0] - drift_v * t[-1]) < 1e-3 * bob  # the ramp's value now, not T/2 ago
    assert abs(ev[0] - drift_v) < 1e-12 + 1e-3 * bob
    assert abs(vx - 0.5) < 1e-3


def test_window_before_the_first_wingbeat_uses_the_start():
    w = ErrorWindow(8, 1.0)
    w.add(np.array([0.2, 0.0]), np.zeros(2), 0.0)
    ep, ev, _ = w.estimate()
    np.testing.assert_allclose(ep, [0.2, 0.0]) and np.testing.assert_allclose(ev, 0.0)


@pytest.fixture(scope="module")
def ctl():
    return Controller(
        load_table("tables/m4.npz"), BIRD, gains_for(BIRD), to_table=demand_from_acceleration
    )


def test_level_flight_demand_and_saturation(ctl):
    cmd = ctl.lookup(0.0, 0.0, 0.9, 0.0, 0.0)
    assert (
        math.isclose(cmd.Fz, -0.5 * BIRD.mass * BIRD.gravity, rel_tol=1e-12) and abs(cmd.Fx) < 1e-12
    )
    assert not cmd.saturated
    up = ctl.lookup(0.0, 0.2, 0.9, 0.0, 0.0)  # 17 g up: far outside the table
    assert up.saturated and up.Fz < -0.5
    backwards = ctl.lookup(0.0, 0.0, -0.5, 0.0, 0.0)  # airspeed below the table's V = 0
    assert backwards.saturated


def test_climb_is_level_flight_turned(ctl):
    """In a steady climb at gamma the needed force, turned into the air path, is the
    level-flight demand of a bird whose weight is turned by gamma."""
    V, gamma = 0.9, 0.1
    cmd = ctl.lookup(
        0.0, 0.0, V * math.cos(gamma), V * math.sin(gamma), gamma
    )  # body drag at the table's pitch 0
    w = BIRD.mass * BIRD.gravity
    assert math.isclose(cmd.V, V, rel_tol=1e-12)
    assert math.isclose(cmd.Fz, -0.5 * w * math.cos(gamma), rel_tol=1e-9)
    level = ctl.lookup(
        BIRD.gravity * math.sin(gamma), BIRD.gravity * (math.cos(gamma) - 1), V, 0.0, 0.0
    )
    assert math.isclose(cmd.Fx, level.Fx, rel_tol=1e-9) and cmd.Fx > 0  # climbing needs thrust
    pitch = ctl.names.index("pitch")
    assert math.isclose(cmd.params[pitch] - gamma, level.params[pitch], abs_tol=1e-9)
    slow = ctl.lookup(0.0, 0.0, 0.0, 0.05, 0.0)  # hovering up: no turn below the climb speed
    assert slow.params[pitch] == ctl.lookup_table_force(slow.Fx, slow.Fz, 0.0).params[pitch]
