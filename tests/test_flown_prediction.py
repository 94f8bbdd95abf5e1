"""The flight's own continuation (birdsim.flight.flown_prediction): predicting leaves the
flight bit for bit as it was, and with the inputs held (open loop, no attitude loop, no
stroke-plane compensation, a steady cruise) the prediction is the flight's next
wingbeat; the nose-up angle of a pitch rotation is that angle, past the vertical too."""

from __future__ import annotations

import math

import numpy as np

import birdsim.flight.freeflight as freeflight_mod
from birdsim.commands.fly import load_table_for
from birdsim.flight.flown_prediction import nose_up, predict
from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS, demo_bird
from birdsim.flight.simulate import SimConfig
from birdsim.mujoco.model import pitch_quat

TWO_PI = 2.0 * math.pi


def _fly(monkeypatch, preset, beats, at_call, **kw):
    """The flight, and the prediction made before its ``at_call``-th interval (1 wingbeat,
    the interval's own inputs), or None where ``at_call`` is None."""
    step, got = freeflight_mod.interval, {}
    calls = [0]

    def hooked(fb, right, times, t, dt, left, offset, wind, record, every):
        if calls[0] == at_call:
            args = (right, left, offset, wind)
            sh, tail = fb.schedule.shoulder_target.copy(), fb.cb.tail_controls
            got["pred"] = predict(fb, args, sh, tail, 1.0)
        calls[0] += 1
        return step(fb, right, times, t, dt, left, offset, wind, record, every)

    monkeypatch.setattr(freeflight_mod, "interval", hooked)
    bird = demo_bird()
    table = load_table_for(bird, DEMO_MODEL, None)
    r = freeflight_mod.fly(
        PATH_PRESETS[preset], table, bird, DEMO_MODEL, beats=beats,
        config=SimConfig(attitude="free"), **kw,
    )  # fmt: skip
    return r, got.get("pred")


def test_a_prediction_leaves_the_flight_bit_for_bit(monkeypatch):
    plain, _ = _fly(monkeypatch, "landing", 4.0, None)
    probed, pred = _fly(monkeypatch, "landing", 4.0, 17)
    assert pred is not None and len(pred[0]) == 16
    for k, v in plain.arrays.items():
        if isinstance(v, np.ndarray):
            assert np.array_equal(v, probed.arrays[k]), k


def test_with_the_inputs_held_the_prediction_is_the_next_wingbeat(monkeypatch):
    kw = {"open_loop": True, "attitude_loop": False, "stroke_compensation": False}
    r, (t, quat) = _fly(monkeypatch, "cruise", 4.0, 16, **kw)
    a = r.arrays
    assert math.isclose(t[0], 2 * TWO_PI, abs_tol=1e-9)
    idx = [int(np.argmin(np.abs(a["t"] - ti))) for ti in t]
    assert np.allclose(a["t"][idx], t, atol=1e-9)
    flown = a["qpos"][idx, 3:7]
    assert np.abs(nose_up(quat, flown)).max() < 1e-7  # (8 intervals against 1: 2e-9)
    # the body does pitch over that wingbeat (the comparison is not of a still body)
    assert np.ptp(nose_up(quat)) > 1e-3


def test_nose_up_is_the_pitch_angle_past_the_vertical_too():
    angles = np.array([-0.4, 0.0, 0.3, 1.7, 2.5])
    quat = np.array([pitch_quat(x) for x in angles])
    assert np.allclose(nose_up(quat), angles, atol=1e-12)
    base = np.array([pitch_quat(0.2)] * len(angles))
    assert np.allclose(nose_up(quat, base), angles - 0.2, atol=1e-12)


def test_a_prediction_steps_its_own_bird_not_a_flocks_lockstep(monkeypatch):
    """A flock's lockstep puts its own ``step_many`` on each bird (every bird stepped
    together, one interval each); a prediction is one bird's look-ahead and must step that
    bird alone.  Before, it handed its wingbeat to the lockstep, and a steered flock whose
    bird predicted stopped ("its wind or log interval differs from bird 0's"); the
    lockstep's ``step_many`` is back on the bird after the prediction."""
    step, seen, calls = freeflight_mod.interval, {}, [0]

    def hooked(fb, right, times, t, dt, left, offset, wind, record, every):
        if calls[0] == 17:
            handed, original = [], fb.step_many

            def lockstep(pres, *rest):
                handed.append(len(pres.qpos))
                return original(pres, *rest)

            fb.step_many = lockstep
            sh, tail = fb.schedule.shoulder_target.copy(), fb.cb.tail_controls
            seen["pred"] = predict(fb, (right, left, offset, wind), sh, tail, 1.0)
            seen["handed"], seen["back"] = list(handed), fb.__dict__.get("step_many") is lockstep
            del fb.step_many
        calls[0] += 1
        return step(fb, right, times, t, dt, left, offset, wind, record, every)

    monkeypatch.setattr(freeflight_mod, "interval", hooked)
    bird = demo_bird()
    table = load_table_for(bird, DEMO_MODEL, None)
    freeflight_mod.fly(
        PATH_PRESETS["landing"], table, bird, DEMO_MODEL, beats=4.0,
        config=SimConfig(attitude="free"),
    )  # fmt: skip
    assert len(seen["pred"][0]) == 16
    assert seen["handed"] == []
    assert seen["back"]
