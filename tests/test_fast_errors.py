"""Issue 27: a straight free flight's per-sample path errors and airspeeds compiled
(``fast_errors``) are the numpy reference's bit for bit: random samples and winds, and
a gusty m4 cruise flown with the switch on and off (every log array equal)."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.flight import fast_errors
from birdsim.flight.freeflight import fly
from birdsim.flight.gust import Gust
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.flight.simulate import SimConfig
from birdsim.physics.bird import Bird
from birdsim.tables.lookup import load_table

pytestmark = pytest.mark.skipif(fast_errors.kernel is None, reason="numba missing")


def test_compiled_errors_are_the_reference(monkeypatch):
    rng = np.random.default_rng(7)
    for n in (1, 8, 64):
        q, v = rng.normal(size=(n, 22)), rng.normal(size=(n, 21))
        refs = {k: rng.normal(size=n) for k in ("x", "z", "vx", "vz")}
        wind = rng.normal(size=3) * 0.1
        got = fast_errors.straight_errors(refs, q, v, wind)
        monkeypatch.setattr(fast_errors, "ENABLED", False)
        ref = fast_errors.straight_errors(refs, q, v, wind)
        monkeypatch.setattr(fast_errors, "ENABLED", True)
        for a, b in zip(got, ref):
            assert np.array_equal(a, b)  # bitwise
        assert isinstance(got[3], list) and isinstance(got[3][0], float)


def test_gusty_cruise_flies_as_the_reference(monkeypatch):
    path = FlightPath("cruise", 4.0, False, False, (PathKeyframe(0.0, 6.0, V=0.9),))
    table = load_table("tables/m4.npz")
    bird = Bird.from_toml("models/seed-bird.toml")
    gusts = (Gust(1.0, 1.0, 0.1, -0.05, wy=0.05),)
    logs = {}
    for compiled in (True, False):
        monkeypatch.setattr(fast_errors, "ENABLED", compiled)
        r = fly(path, table, bird, "m4", config=SimConfig(attitude="free"), gusts=gusts)
        logs[compiled] = r.arrays
    for k in logs[True]:
        assert np.array_equal(logs[True][k], logs[False][k], equal_nan=True), k


def test_path_errors_are_sampling_then_errors(monkeypatch):
    """The fused call (the straight path's curves at the samples' times, then the
    errors) against ``sample_reference`` and the errors: bitwise, inside the keyframes
    and past the path's end (its tangent), and the compiled call really ran."""
    from birdsim.flight.trim import sample_reference

    keys = (PathKeyframe(0.0, 6.0, V=0.9), PathKeyframe(2.0, 6.4, V=0.7))
    path = FlightPath("climb", 4.0, False, False, keys)
    assert fast_errors.path_kernel is not None
    calls: list = []
    kernel = fast_errors.path_kernel
    monkeypatch.setattr(fast_errors, "path_kernel", lambda *a: calls.append(1) or kernel(*a))
    rng = np.random.default_rng(11)
    for n in (1, 2, 16):
        t = np.sort(rng.uniform(-1.0, 4.0 * 2 * np.pi + 3.0, n))
        q, v = rng.normal(size=(n, 22)), rng.normal(size=(n, 21))
        wind = rng.normal(size=3) * 0.1
        refs, *got = fast_errors.path_errors(path, t, q, v, wind)
        want_refs = sample_reference(path, t)
        want = fast_errors.straight_errors(want_refs, q, v, wind)
        for k in ("x", "z"):
            assert np.array_equal(refs[k], want_refs[k]), k
        for a, b in zip(got, want):
            assert np.array_equal(a, b)
    assert len(calls) == 3


def test_straight_samples_are_errors_then_windows(monkeypatch):
    """The fused call also appends the samples to the attitude window (quat, ``C_SEED``
    omega) and the lateral one (y, vy) and keeps their last ``n_fit`` rows: bitwise
    ``path_errors`` and ``keep_last``, from empty, partial and full windows."""
    from birdsim.flight.flight_arrays import keep_last
    from birdsim.flight.simulate import C_SEED

    path = FlightPath("cruise", 4.0, False, False, (PathKeyframe(0.0, 6.0, V=0.9),))
    calls: list = []
    kernel = fast_errors.samples_kernel
    monkeypatch.setattr(fast_errors, "samples_kernel", lambda *a: calls.append(1) or kernel(*a))
    rng = np.random.default_rng(13)
    for old, n, n_fit in ((0, 2, 16), (5, 2, 16), (15, 2, 16), (16, 2, 16), (3, 8, 4), (0, 1, 1)):
        t = np.sort(rng.uniform(0.0, 20.0, n))
        q, v = rng.normal(size=(n, 22)), rng.normal(size=(n, 21))
        wind = rng.normal(size=3) * 0.1
        att = (rng.normal(size=(old, 4)), rng.normal(size=(old, 3)))
        lat = rng.normal(size=(old, 2))
        refs, e_pos, e_vel, v_air, att_new, lat_new = fast_errors.straight_samples(
            path, t, q, v, wind, att, lat, n_fit
        )
        want = fast_errors.path_errors(path, t, q, v, wind)
        for a, b in zip(
            (refs["x"], refs["z"], e_pos, e_vel, v_air), (*want[0].values(), *want[1:3], want[4])
        ):
            assert np.array_equal(a, b)
        want_att = keep_last(att, (q[:, 3:7], C_SEED * v[:, 3:6]), n_fit)
        want_lat = keep_last((lat,), (want[3],), n_fit)[0]
        for a, b in zip((*att_new, lat_new), (*want_att, want_lat)):
            assert a.shape == b.shape and np.array_equal(a, b)
    assert len(calls) == 6
