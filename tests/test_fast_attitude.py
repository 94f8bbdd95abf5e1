"""Issue 27: the attitude loop's update after its Jacobians (bounds, integral, demand,
allocation) compiled (``fast_attitude``) flies bit for bit as the reference's numpy and
Python: straight flight (the pitch row's split) with a gust that drives inputs to their
bounds (the reference then runs the update: its ``lsq_linear``), and a turn (the
symmetric inputs by least squares, the (1, n) pitch row's dot product): a slow one, since a
cruise turn's roll and yaw are allocated per unit inertia by the reference every control
step (``attitude_reserve.per_inertia``; that case checks it does)."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.flight import fast_attitude
from birdsim.flight.freeflight import fly
from birdsim.flight.gust import Gust
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.flight.simulate import SimConfig
from birdsim.flight.turn_presets import TURN_PRESETS
from birdsim.physics.bird import Bird
from birdsim.tables.lookup import load_table

BIRD = Bird.from_toml("models/seed-bird.toml")
pytestmark = pytest.mark.skipif(fast_attitude.kernel is None, reason="numba missing")


def _cruise(v: float) -> FlightPath:
    return FlightPath("cruise", 6.0, False, False, (PathKeyframe(0.0, 6.0, V=v),))


CASES = {
    "m4 cruise, gust": ("m4", _cruise(0.9), (Gust(2.0, 1.0, 0.1, -0.05, wy=0.05),), None),
    "m3 cruise, strong gust": ("m3", _cruise(0.5), (Gust(2.0, 1.0, -0.3, 0.2, wy=0.2),), None),
    "m3 turn-90": ("m3", TURN_PRESETS["turn-90"], (), 6.0),
}


@pytest.fixture
def allocations(monkeypatch) -> dict[bool, int]:
    """How often the compiled allocation was taken (True) or declined (False)."""
    calls = {True: 0, False: 0}
    allocate = fast_attitude.allocate

    def counted(*a, **k):
        done = allocate(*a, **k)
        calls[done] += 1
        return done

    monkeypatch.setattr(fast_attitude, "allocate", counted)
    return calls


@pytest.mark.parametrize("case", list(CASES))
def test_compiled_update_flies_as_the_reference(monkeypatch, allocations, case):
    model, path, gusts, beats = CASES[case]
    table = load_table(f"tables/{model}.npz")
    calls = allocations
    logs = {}
    for compiled in (True, False):
        monkeypatch.setattr(fast_attitude, "ENABLED", compiled)
        r = fly(
            path, table, BIRD, model, config=SimConfig(attitude="free"), gusts=gusts, beats=beats
        )
        logs[compiled] = r.arrays
    a, b = logs[True], logs[False]
    assert calls[True] > 20  # the compiled update flew
    if "strong" in case:
        assert calls[False] > 5 and np.any(a["attitude_saturated"])  # bounds bound
    for k in a:
        assert np.array_equal(a[k], b[k], equal_nan=True), k  # bitwise
    assert np.max(np.abs(b["y"])) > 1e-4  # the lateral loop acted


def test_a_cruise_turn_takes_the_reference_update_per_unit_inertia(allocations):
    calls = allocations
    table = load_table("tables/m3.npz")
    fly(TURN_PRESETS["circle"], table, BIRD, "m3", config=SimConfig(attitude="free"), beats=12.0)
    assert calls[True] == 0 and calls[False] == 0  # never offered to the compiled update
