"""The compiled path-controller lookup (``birdsim.flight.fast_command``): the Python
lookup's numbers within round-off, and flights within 1e-9 semispan of the reference's
path over 10 wingbeats (issue 27: a compiled path that need not be bitwise)."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.flight import fast_command
from birdsim.flight.controller import Controller, gains_for
from birdsim.flight.freeflight import fly
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.flight.presets import PATH_PRESETS, demo_bird
from birdsim.flight.simulate import SimConfig
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird
from birdsim.tables.lookup import load_table

BIRD = Bird.from_toml("models/seed-bird.toml")
PATH_TOL = 1e-9  # semispan (reduced units), the tolerance


def _counted(monkeypatch) -> list:
    calls: list = []
    kernel = fast_command.kernel

    def counted(*a):
        calls.append(1)
        return kernel(*a)

    monkeypatch.setattr(fast_command, "kernel", counted)
    return calls


def test_compiled_lookup_is_the_python_lookup(monkeypatch):
    """Demands around the m4 table's cruise, climbs, descents, hover and backwards
    airspeeds: the same saturation flags, forces, speed and parameters within 1e-12."""
    table = load_table("tables/m4.npz")
    red = reduced_bird(BIRD)
    ctl = Controller(table, red, gains_for(red))
    calls = _counted(monkeypatch)
    rng = np.random.default_rng(3)
    n_sat = 0
    for _ in range(400):
        ax, az = rng.normal(0.0, 0.02, 2)
        vx, vz = rng.uniform(-0.2, 1.3), rng.normal(0.0, 0.15)
        args = (float(ax), float(az), float(vx), float(vz), float(rng.normal(0.0, 0.2)))
        monkeypatch.setattr(fast_command, "ENABLED", True)
        a = ctl.lookup(*args)
        monkeypatch.setattr(fast_command, "ENABLED", False)
        b = ctl.lookup(*args)
        assert a.saturated == b.saturated, args
        n_sat += a.saturated
        for x, y in ((a.Fx, b.Fx), (a.Fz, b.Fz), (a.V, b.V)):
            assert type(x) is float and abs(x - y) <= 1e-12, args
        assert np.abs(a.params - b.params).max() <= 1e-12, args
        assert a.a_cmd == b.a_cmd and a.climb == b.climb == 0.0
    assert len(calls) == 400 and 0 < n_sat < 400


def test_non_finite_demand_is_named_by_the_reference(monkeypatch):
    """A NaN speed: the compiled call declines and the Python lookup names the demand."""
    from birdsim.errors import BirdsimError

    table = load_table("tables/m4.npz")
    red = reduced_bird(BIRD)
    ctl = Controller(table, red, gains_for(red))
    with pytest.raises(BirdsimError, match="non-finite demand"):
        ctl.lookup(0.0, 0.0, float("nan"), 0.0, 0.0)


def _paths(monkeypatch, fly_it) -> dict:
    calls = _counted(monkeypatch)
    out = {}
    for on in (True, False):
        monkeypatch.setattr(fast_command, "ENABLED", on)
        n0 = len(calls)
        out[on] = fly_it().arrays
        assert (len(calls) > n0) == on  # the compiled lookup really flew (or not)
    return out


@pytest.mark.parametrize("case", ["m4 cruise", "seed cruise"])
def test_flights_agree_within_a_nanosemispan(monkeypatch, case):
    """10 wingbeats flown free with the compiled lookup and with the Python one: the
    paths (x, y, z) within 1e-9 semispan at every sample, the same saturated samples."""
    if case == "m4 cruise":
        table = load_table("tables/m4.npz")
        path = FlightPath("cruise", 10.0, False, False, (PathKeyframe(0.0, 6.0, V=0.9),))

        def fly_it():
            return fly(path, table, BIRD, "m4", config=SimConfig(attitude="free"))
    else:
        table = load_table("tables/seed-m3.npz")

        def fly_it():
            return fly(PATH_PRESETS["cruise"], table, demo_bird(), "m3", beats=10.0,
                       config=SimConfig(attitude="free"))  # fmt: skip

    out = _paths(monkeypatch, fly_it)
    a, b = out[True], out[False]
    assert len(a["t"]) == len(b["t"]) >= 10 * 8
    for k in ("x", "y", "z"):
        assert np.abs(np.asarray(a[k]) - np.asarray(b[k])).max() <= PATH_TOL, k
    assert np.array_equal(a["saturated"], b["saturated"])


@pytest.mark.parametrize("open_loop", [False, True])
def test_path_command_is_the_command_at_the_path_state(monkeypatch, open_loop):
    """The path's state, the feedback and the lookup in one call
    (``Controller.command_at``) against ``command(path.state(t), ...)``: a climbing path
    inside and past its keyframes, random errors, integrals and winds, feedback on and
    off; the same flags and accelerations, the rest within 1e-12."""
    table = load_table("tables/m4.npz")
    red = reduced_bird(BIRD)
    ctl = Controller(table, red, gains_for(red), open_loop=open_loop)
    keys = (PathKeyframe(0.0, 6.0, V=0.9), PathKeyframe(3.0, 6.6, V=0.6))
    path = FlightPath("climb", 6.0, False, False, keys)
    calls: list = []
    kernel = fast_command.path_kernel
    monkeypatch.setattr(fast_command, "path_kernel", lambda *a: calls.append(1) or kernel(*a))
    rng = np.random.default_rng(5)
    for i in range(200):
        t = float(rng.uniform(-1.0, 6.0 * 2 * np.pi + 4.0))
        est = None if i % 5 == 0 else (rng.normal(0, 0.02, 2), rng.normal(0, 0.02, 2), 0.8)
        integral, pitch = rng.normal(0, 0.05, 2), float(rng.normal(0.0, 0.2))
        wind = (float(rng.normal(0, 0.1)), float(rng.normal(0, 0.05)))
        a = ctl.command_at(path, t, est, integral, pitch, wind)
        b = ctl.command(path.state(t), est, integral, pitch, wind)
        assert a.saturated == b.saturated and a.climb == b.climb == 0.0
        assert a.a_cmd == b.a_cmd and all(type(x) is float for x in a.a_cmd)
        for x, y in ((a.Fx, b.Fx), (a.Fz, b.Fz), (a.V, b.V)):
            assert type(x) is float and abs(x - y) <= 1e-12, (t, est)
        assert np.abs(a.params - b.params).max() <= 1e-12
    assert len(calls) == 200
