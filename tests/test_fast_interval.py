"""The fused interval (``birdsim.flight.fast_interval``): the schedule's advance and the
steps after it in one compiled call, bit for bit the two calls."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.flight import fast_interval, fast_loop
from birdsim.flight.freeflight import fly
from birdsim.flight.gust import Gust
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.flight.simulate import FreeBird, SimConfig
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.tables.lookup import load_table

BIRD = Bird.from_toml("models/seed-bird.toml")


def _intervals(model: str, fused: bool, monkeypatch) -> tuple[list, list, tuple]:
    """Six intervals of 16 steps of a free bird: differential wings, a stroke-plane
    offset, shoulder targets and a side wind changing between them."""
    monkeypatch.setattr(fast_interval, "ENABLED", fused)
    kin = get_model(model)
    guess = kin.guess("cruise")
    names = kin.param_names
    params = np.array([guess[n] for n in names])
    left = params.copy()
    left[names.index("flap_amp")] -= 0.05
    offset = np.zeros(len(names))
    offset[names.index("stroke_plane")] = 0.02
    record: list = []
    pres_rows = []
    with FreeBird(model, BIRD, params, config=SimConfig(attitude="free")) as fb:
        h = fb.h
        pres0 = fb.schedule.advance(params, np.zeros(1), 0.0, 0.0)
        fb.start(np.array([0.0, 0.0, 6.0]), np.array([0.9, 0.0, 0.0]), pres0)
        for k in range(6):
            fb.schedule.shoulder_target = np.array([0.05, -0.03]) * (k % 3)
            t = fb.time
            lft = None if k == 0 else left + 0.01 * k
            off = None if k < 2 else offset * k
            wind = np.array([0.02 * k, 0.01 * k, -0.01])
            pres = fast_interval.interval(
                fb, params + 0.01 * k, t + np.arange(16) * h, t, 16 * h, lft, off, wind, record, 8
            )
            pres_rows.append((pres.params, pres.pitch, pres.params_left, pres.qpos[:, 7:]))
        assert type(fb.time) is float
        state = (fb.time, fb.P, fb.X, fb.L, fb.root_applied_max, fb.projection_max,
                 fb.d.qpos.copy(), fb.d.qvel.copy(), fb.schedule.filter.x2.copy(),
                 fb.schedule.input_filter.x2.copy(), fb.cb.tail_force_body)  # fmt: skip
    return record, pres_rows, state


def _same(a, b) -> bool:
    if a is None or b is None:
        return a is b
    return np.asarray(a).tobytes() == np.asarray(b).tobytes()


@pytest.mark.parametrize("model", ["m4", "m5"])
def test_fused_interval_is_the_two_calls(monkeypatch, model):
    """Every sample, prescription row, momentum, time and filter state the same bytes as
    ``schedule.advance`` then ``step_many``; the fused call really ran (counted)."""
    assert fast_interval.kernel is not None
    calls = []
    kernel = fast_interval.kernel

    def counted(*a):
        calls.append(1)
        return kernel(*a)

    monkeypatch.setattr(fast_interval, "kernel", counted)
    rec_a, pres_a, state_a = _intervals(model, True, monkeypatch)
    rec_b, pres_b, state_b = _intervals(model, False, monkeypatch)
    assert len(calls) == 6
    assert len(rec_a) == len(rec_b) == 12
    for ra, rb in zip(rec_a, rec_b):
        assert all(_same(x, y) for x, y in zip(ra, rb))
    for pa, pb in zip(pres_a, pres_b):
        assert all(_same(x, y) for x, y in zip(pa, pb))
    assert pres_a[0][2] is None and pres_a[1][2] is not None  # the left wing's own rows
    assert all(_same(x, y) for x, y in zip(state_a, state_b))


def test_fused_flight_is_bitwise_the_two_calls(monkeypatch):
    """A 3-wingbeat m4 free cruise with a gust: every log array the same bytes with the
    fused call on and off."""
    table = load_table("tables/m4.npz")
    path = FlightPath("cruise", 3.0, False, False, (PathKeyframe(0.0, 6.0, V=0.9),))
    out = {}
    for fused in (True, False):
        monkeypatch.setattr(fast_interval, "ENABLED", fused)
        r = fly(path, table, BIRD, "m4", config=SimConfig(attitude="free"),
                gusts=(Gust(1.0, 1.0, 0.1, -0.05, wy=0.05),))  # fmt: skip
        out[fused] = r.arrays
    assert out[True].keys() == out[False].keys()
    for k in out[True]:
        assert _same(out[True][k], out[False][k]), k


def test_fused_interval_steps_nothing_where_the_step_loop_does_not_apply(monkeypatch):
    """The compiled step loop switched off, or a flock's lockstep owning ``step_many``:
    the fused call does not apply (the two calls run)."""
    kin = get_model("m4")
    guess = kin.guess("cruise")
    params = np.array([guess[n] for n in kin.param_names])
    with FreeBird("m4", BIRD, params, config=SimConfig(attitude="free")) as fb:
        assert fast_interval._usable(fb) is not None
        fb.step_many = fb.step_many  # an instance's own step_many (flock_lockstep)
        assert fast_interval._usable(fb) is None
        del fb.step_many
        monkeypatch.setattr(fast_loop, "ENABLED", False)
        assert fast_interval._usable(fb) is None


def test_sample_times_are_the_step_by_step_sums():
    """``fast_loop.sample_times``: the times the reference's loop sums one step after the
    other (``time += h``), bit for bit, over many starts and step sizes (a pairwise or
    ``t0 + k h`` sum differs in the last bit)."""
    rng = np.random.default_rng(5)
    for _ in range(2000):
        t0, h = float(rng.uniform(0.0, 400.0)), float(rng.uniform(1e-3, 0.1))
        n, every = int(rng.integers(1, 40)), int(rng.integers(1, 9))
        times, time = [], t0
        for k in range(n):
            if k % every == 0:
                times.append(time)
            time += h
        got, end = fast_loop.sample_times(t0, h, n, every)
        assert got == times and end == time
        assert all(type(x) is float for x in got)


@pytest.mark.parametrize("bad", ["flap_amp", "pitch"])
def test_fused_interval_names_a_non_finite_target_as_the_two_calls(monkeypatch, bad):
    """A NaN wing parameter (its rows not finite) or pitch: nothing stepped, the same
    error as the schedule's own path (naming the joint, or the pitch)."""
    from birdsim.errors import BirdsimError

    kin = get_model("m4")
    guess = kin.guess("cruise")
    names = kin.param_names
    params = np.array([guess[n] for n in names])
    target = params.copy()
    target[names.index(bad)] = np.nan
    messages = []
    for fused in (True, False):
        monkeypatch.setattr(fast_interval, "ENABLED", fused)
        with FreeBird("m4", BIRD, params, config=SimConfig(attitude="free")) as fb:
            h = fb.h
            pres0 = fb.schedule.advance(params, np.zeros(1), 0.0, 0.0)
            fb.start(np.array([0.0, 0.0, 6.0]), np.array([0.9, 0.0, 0.0]), pres0)
            qpos, time = fb.d.qpos.copy(), fb.time
            with pytest.raises(BirdsimError) as err:
                fast_interval.interval(
                    fb, target, np.arange(16) * h, 0.0, 16 * h, None, None, np.zeros(3), [], 8
                )
            assert fb.time == time and np.array_equal(fb.d.qpos, qpos)
            messages.append(str(err.value))
    assert messages[0] == messages[1]
    assert ("flap" if bad == "flap_amp" else "pitch") in messages[0]
