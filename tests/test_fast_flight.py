"""Issue 27's compiled free flight flies as the reference path.

The reference: the Python step loop with the Python aero callback
(``fast_loop.ENABLED = False``), the numpy prescription (``fast_prescription``), scipy's
table interpolation (``fast_lookup``), ``lsq_linear`` (``bounded_lsq``), scipy's path curves
(``fast_path``, bitwise), the numpy attitude error (``fast_estimate``, round-off) and the
schedule's numpy filters and the error window's means (``fast_schedule``, ``fast_window``:
bitwise).  The compiled
loop does the same operations in the same order except two sums (the tail's
``xmat @ f``, which numpy hands to BLAS, and the wings' power ``applied[W] @ qvel[W]``),
summed naively; the prescription's ball joint sums two 3-term products in another order
than numpy's einsum and stacked matmul; the lookup is bitwise scipy's, the allocation's
unbounded solve numba's ``lstsq`` (the same gelsd: round-off).  Tolerances: one wingbeat from one state, every log entry within 1e-12 (an ulp
of the tail force grown over 128 steps stays far below); the prescription's rows within
1e-15 (measured 6e-17); a closed-loop flight of 10 wingbeats with a gust, every
switch on against every switch off: the path within 1e-9 semispan (issue 27's bound;
measured 7e-15) and every log array within 1e-9 of its scale."""

from __future__ import annotations

import copy
import dataclasses

import numpy as np
import pytest
from scipy.optimize import lsq_linear

from birdsim.flight import bounded_lsq as bounded_lsq_module
from birdsim.flight import (
    fast_estimate,
    fast_loop,
    fast_path,
    fast_prescription,
    fast_schedule,
    fast_window,
)
from birdsim.flight.bounded_lsq import bounded_lsq
from birdsim.flight.freeflight import fly
from birdsim.flight.gust import Gust
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.flight.simulate import FreeBird, SimConfig
from birdsim.mujoco import aero_kernel
from birdsim.mujoco.tail import TailControls
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.tables import fast_lookup
from birdsim.tables.lookup import load_table

BIRD = Bird.from_toml("models/seed-bird.toml")
pytestmark = pytest.mark.skipif(fast_loop.run_steps is None, reason="numba or libmujoco missing")


def _params(model: str) -> np.ndarray:
    kin = get_model(model)
    guess = kin.guess("cruise")
    return np.array([guess[n] for n in kin.param_names])


def _beat(fb: FreeBird, params: np.ndarray, left: np.ndarray, wind: np.ndarray) -> list:
    n = fb.config.steps_per_beat
    pres = fb.schedule.advance(params, np.arange(n) * fb.h, 0.0, n * fb.h, left)
    fb.start(np.array([0.0, 0.0, 6.0]), np.array([0.5, 0.0, 0.0]), pres)
    rec: list = []
    for part in range(4):  # four control intervals, the tail moved between them
        fb.cb.tail_controls = TailControls(0.1 * part - 0.1, 0.8, 0.05 * part)
        k = n // 4
        times = fb.time + np.arange(k) * fb.h
        fb.step_many(fb.schedule.advance(params, times, fb.time, k * fb.h, left), wind, rec, 2)
    return rec


@pytest.mark.parametrize("model", ["m3", "m4", "m5"])
def test_compiled_loop_steps_as_the_reference(monkeypatch, model):
    params = _params(model)
    left = params.copy()
    left[get_model(model).param_names.index("flap_amp")] -= 0.05  # an asymmetric wingbeat
    wind = np.array([0.05, -0.02, 0.03])  # a gust: the air's velocity enters every force
    out = {}
    for compiled in (True, False):
        monkeypatch.setattr(fast_loop, "ENABLED", compiled)
        with FreeBird(model, BIRD, params, config=SimConfig(attitude="free")) as fb:
            assert fast_loop.usable(fb, slice(0, 6), slice(6, fb.m.nv)) is compiled
            # m5: the hand's sites fold (their area follows the wrist sweep)
            assert bool((aero_kernel.fold_addresses(fb.cb) >= 0).any()) is (model == "m5")
            rec = _beat(fb, params, left, wind)
            calls = fb.cb.calls
            out[compiled] = (rec, fb.P, fb.X, fb.L, fb.projection_max, fb.root_applied_max)
            out[compiled] += (fb.time, fb.cb.tail_force_body.copy(), fb.cb.tail_alpha, calls)
    (ra, *sa), (rb, *sb) = out[True], out[False]
    assert len(ra) == len(rb) == 64
    for a, b in zip(ra, rb):
        assert a[0] == b[0]  # time
        for x, y in zip(a[1:], b[1:]):
            np.testing.assert_allclose(x, y, rtol=0, atol=1e-12)
    for x, y in zip(sa[:3], sb[:3]):
        np.testing.assert_allclose(x, y, rtol=0, atol=1e-12)
    assert sa[3] == pytest.approx(sb[3], rel=1e-6)  # the projection's size
    assert sa[4] == sb[4] == 0.0  # no force or torque on the root, exactly
    assert sa[5] == sb[5]  # the time, summed step by step
    np.testing.assert_allclose(sa[6], sb[6], rtol=0, atol=1e-12)  # the tail's last force
    assert sa[7] == pytest.approx(sb[7], abs=1e-12)
    assert sb[8] - sa[8] == 128  # the Python callback ran in the reference's steps only
    assert abs(ra[-1][1][1]) > 1e-6  # the asymmetric wingbeat moved the body sideways
    assert np.any(np.abs([r[6] for r in ra]) > 1e-4)  # the tail worked


@pytest.mark.parametrize("model", ["m4", "m5"])
def test_compiled_flight_follows_the_reference_flight(monkeypatch, model):
    """m5: the folding hand's area and the fold's joints compiled too (issue 24)."""
    table = load_table(f"tables/{model}.npz")
    path = FlightPath("cruise", 10.0, False, False, (PathKeyframe(0.0, 6.0, V=0.9),))
    gust = (Gust(4.0, 1.0, 0.1, -0.05, wy=0.05),)  # lateral too: the roll loop acts
    logs = {}
    for compiled in (True, False):
        for switch in (
            fast_loop,
            fast_prescription,
            fast_lookup,
            bounded_lsq_module,
            fast_path,
            fast_estimate,
            fast_schedule,
            fast_window,
        ):
            monkeypatch.setattr(switch, "ENABLED", compiled)
        r = fly(path, table, BIRD, model, config=SimConfig(attitude="free"), gusts=gust)
        logs[compiled] = r.arrays
    a, b = logs[True], logs[False]
    assert a["t"][-1] == pytest.approx(10 * 2 * np.pi, abs=0.1)
    for k in ("x", "y", "z"):  # reduced units: semispans
        assert np.max(np.abs(a[k] - b[k])) < 1e-9, k
    assert np.max(np.abs(b["y"])) > 1e-4  # the gust moved the bird sideways
    for k, va in a.items():
        va, vb = np.asarray(va, dtype=float), np.asarray(b[k], dtype=float)
        scale = max(1.0, float(np.max(np.abs(vb)))) if vb.size else 1.0
        assert np.max(np.abs(va - vb), initial=0.0) <= 1e-9 * scale, k


def test_unsupported_callbacks_keep_the_reference_path():
    strips = dataclasses.replace(BIRD, strips=3)
    with FreeBird("m4", strips, _params("m4"), config=SimConfig(attitude="free")) as fb:
        assert not aero_kernel.supported(fb.cb)
    with FreeBird("m4", BIRD, _params("m4"), config=SimConfig(attitude="posed")) as fb:
        assert not fast_loop.usable(fb, slice(0, 3), slice(3, fb.m.nv))


@pytest.mark.parametrize("model", ["base", "m1", "m2", "m3", "m4", "m5"])
def test_compiled_prescription_is_the_reference(monkeypatch, model):
    """Rows within 1e-15 (two 3-term sums of the ball joint in another order: measured
    up to 6e-17); m5's fold (elbow, wrist sweep, supination) compiled too."""
    params = _params(model)
    names = get_model(model).param_names
    left = params.copy()
    left[names.index("flap_amp")] -= 0.05
    with FreeBird(model, BIRD, params, config=SimConfig(attitude="free")) as fb:
        has_spec = fast_prescription.spec(fb.kin, fb.red) is not None
        assert has_spec and fast_prescription.geometry(fb.m) is not None
        out = {}
        for compiled in (True, False):
            monkeypatch.setattr(fast_prescription, "ENABLED", compiled)
            sc = copy.deepcopy(fb.schedule)
            rows = []
            for k, (lft, sh) in enumerate(((None, (0, 0)), (left, (0, 0)), (left, (0.05, -0.03)))):
                sc.shoulder_target = np.array(sh, dtype=float)
                times = k * 0.4 + np.arange(16) * 0.05
                rows.append(sc.advance(params + 0.01 * k, times, k * 0.4, 0.8, lft, None))
            out[compiled] = rows
    for a, b in zip(out[True], out[False]):
        for x, y in ((a.qpos, b.qpos), (a.qvel, b.qvel), (a.qacc, b.qacc)):
            np.testing.assert_allclose(x, y, rtol=0, atol=1e-15)
        assert (a.params_left is None) == (b.params_left is None)
    assert np.any(out[True][2].qvel != out[True][0].qvel)


def test_bounded_lsq_is_lsq_linear():
    rng = np.random.default_rng(7)
    for scale in (0.1, 1.0, 10.0):  # inside the bounds, then more and more outside
        a = rng.normal(size=(6, 3))
        b = scale * rng.normal(size=6)
        lb, ub = -np.ones(3), np.ones(3)
        x, mask = bounded_lsq(a, b, lb, ub)
        ref = lsq_linear(a, b, bounds=(lb, ub))
        assert np.array_equal(x, ref.x) and np.array_equal(mask, ref.active_mask)
    for rows in (3, 5, 8):  # numpy's LAPACK call made directly: np.linalg.lstsq's numbers
        a, b = rng.normal(size=(rows, 3)), rng.normal(size=rows)
        assert np.array_equal(bounded_lsq_module._lstsq(a, b), np.linalg.lstsq(a, b, rcond=-1)[0])


def test_compiled_table_lookup_is_scipys():
    """Bitwise: the same operations in scipy's order (random points, grid nodes, both
    ends of every axis); outside the grid or NaN: None (scipy refuses or fills)."""
    table = load_table("tables/m4.npz")
    rgi = table._interpolator()
    fast = fast_lookup.Interpolant(rgi.grid, rgi.values)
    rng = np.random.default_rng(8)
    pts = np.stack([rng.uniform(g[0], g[-1], 500) for g in rgi.grid], axis=1)
    nodes = np.stack([rng.choice(g, 100) for g in rgi.grid], axis=1)
    ends = np.array([[g[0] for g in rgi.grid], [g[-1] for g in rgi.grid]])
    pts = np.concatenate([pts, nodes, ends])
    got = fast_lookup.interpolate(fast, pts)
    assert got is not None and np.array_equal(got, rgi(pts))
    outside = ends[1:] + 1e-9
    assert fast_lookup.interpolate(fast, outside) is None
    assert fast_lookup.interpolate(fast, np.full((1, 3), np.nan)) is None
    one = table.lookup_many(-0.1, -0.2, 0.45)  # through the table's own call
    assert one["flap_amp"].shape == ()


def test_one_float_demand_is_looked_up_as_an_array_demand():
    """The scalar path (fast_lookup.scalar_point) gives the array path's numbers bit for
    bit, inside and outside the grid (clipped), and leaves refusals to the array path."""
    table = load_table("tables/m4.npz")
    rng = np.random.default_rng(9)
    for _ in range(200):
        fx, fz, v = (float(x) for x in rng.uniform([-0.7, -0.7, -0.2], [0.7, 0.2, 1.2]))
        a = table.lookup_many(fx, fz, v, clip=True)
        b = table.lookup_many(np.array(fx), np.array(fz), np.array(v), clip=True)
        assert a.keys() == b.keys()
        assert all(np.array_equal(a[k], b[k]) and a[k].shape == () for k in a)
    with pytest.raises(Exception, match="outside the table grid"):
        table.lookup_many(0.9, -0.2, 0.5)
