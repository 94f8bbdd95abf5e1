"""Issue 27: the pitch observer's control step compiled (``fast_observer``) against its
numpy reference (``PitchObserver.predict`` / ``correct`` with
``flight_arrays.error_rotvec``).

1. One observer stepped by both paths side by side on a synthetic body (a model with a
   stiffness, damping and six inputs, some smoothed; windows shorter than a wingbeat at
   the start, then whole): the pitch, the state, the filters and the history within 1e-15
   (round-off: numba's ``atan2`` / ``sin`` / ``cos`` are the C library's, numpy's may be
   its own SIMD versions); bitwise where numpy's are the C library's and its ``einsum``
   sums in the compiled order (this machine).
2. The pigeon's free hover (slow: the observer's pitch is flown) with the switch on and
   off: every log array within 1e-9 of its scale, bitwise on such a machine.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim.flight import fast_observer
from birdsim.flight.flight_arrays import error_rotvec
from birdsim.flight.pitch_observer import PitchModel, PitchObserver

TWO_PI = 2.0 * math.pi
pytestmark = pytest.mark.skipif(fast_observer.kernel is None, reason="numba missing")


def _numpy_is_the_c_library() -> bool:
    """numpy's arctan2 / sin and einsum's sums of squares are the compiled kernel's."""
    rng = np.random.default_rng(5)
    x, y = rng.normal(size=4096), rng.normal(size=4096)
    same = np.arctan2(y, x).tolist() == [math.atan2(b, a) for a, b in zip(x, y)]
    same = same and np.sin(x).tolist() == [math.sin(a) for a in x]
    q = rng.normal(size=(4096, 4))
    pair = (q[:, 0] * q[:, 0] + q[:, 2] * q[:, 2]) + (q[:, 1] * q[:, 1] + q[:, 3] * q[:, 3])
    return same and np.array_equal(np.einsum("ij,ij->i", q, q), pair)


BITWISE = _numpy_is_the_c_library()


def _pair(per_beat: int) -> tuple[PitchObserver, PitchObserver]:
    smoothed = np.array([False, False, True, False, False, False, True])
    return tuple(PitchObserver(TWO_PI, per_beat, 2.0, smoothed) for _ in range(2))


def test_compiled_step_is_the_reference():
    per_beat, ctl = 64, 8
    samples = per_beat // ctl
    dt_ctl = TWO_PI / ctl
    rng = np.random.default_rng(3)
    fast, ref = _pair(per_beat)
    u0 = rng.normal(size=7) * 0.1
    fast.start(0.1, 0.01, 0.0, u0)
    ref.start(0.1, 0.01, 0.0, u0)
    quat = np.empty((0, 4))
    a = math.exp(-fast.dt / fast.smooth_tau)
    for k in range(3 * ctl):  # windows shorter than a wingbeat, then whole ones
        values = np.array([0.01 * rng.normal(), 0.02, 0.05, -0.3, 1.7])
        jac = rng.normal(size=(3, 7)) * 0.05
        u = rng.normal(size=7) * 0.1
        pitch = rng.normal(size=samples) * 0.2 + 0.3
        new = np.stack([np.cos(pitch / 2), 1e-3 * rng.normal(size=samples),
                        -np.sin(pitch / 2), 1e-3 * rng.normal(size=samples)], axis=1)  # fmt: skip
        quat = np.concatenate([quat, new * rng.uniform(0.9, 1.1)])[-per_beat:]
        omega = rng.normal(size=(len(quat), 3)) * 0.05
        pitch_ref = 0.3 + 0.01 * k
        th = fast_observer.step(fast, values, jac[1], u, samples, (quat, omega), pitch_ref,
                                dt_ctl, a)  # fmt: skip
        model = PitchModel(values[0], jac[1], *values[1:])
        ref.predict(model, u, samples)
        th_ref, _ = ref.correct(pitch_ref - error_rotvec(quat, pitch_ref)[:, 1], omega[:, 1],
                                dt_ctl)  # fmt: skip
        assert th is not None
        for x, y in ((th, th_ref), (fast.state, ref.state), (fast.u1, ref.u1),
                     (fast.u2, ref.u2), (fast.hist, ref.hist)):  # fmt: skip
            assert np.shape(x) == np.shape(y)
            np.testing.assert_allclose(x, y, rtol=0, atol=1e-15)
            assert not BITWISE or np.array_equal(x, y)


def test_switched_off_is_the_reference():
    fast, _ = _pair(64)
    fast.start(0.0, 0.0, 0.0, np.zeros(7))
    window = (np.tile([1.0, 0.0, 0.0, 0.0], (8, 1)), np.zeros((8, 3)))
    args = (np.array([0.0, 0.0, 0.0, 0.0, 1.0]), np.zeros(7), np.zeros(7), 8, window, 0.0,
            TWO_PI / 8, 0.9)  # fmt: skip
    old = fast_observer.ENABLED
    try:
        fast_observer.ENABLED = False
        assert fast_observer.step(fast, *args) is None
    finally:
        fast_observer.ENABLED = old
    assert fast_observer.step(fast, *args) is not None


def test_pigeon_hover_flies_as_the_reference(monkeypatch):
    from birdsim.commands.fly import load_table_for
    from birdsim.flight.freeflight import fly
    from birdsim.flight.presets import PATH_PRESETS
    from birdsim.flight.simulate import SimConfig
    from birdsim.physics.bird import Bird

    bird = Bird.from_toml("models/pigeon.toml")
    table = load_table_for(bird, "m3", None)
    calls = [0]
    step = fast_observer.step

    def counted(*a, **k):
        got = step(*a, **k)
        calls[0] += got is not None
        return got

    monkeypatch.setattr(fast_observer, "step", counted)
    logs = {}
    for compiled in (True, False):
        monkeypatch.setattr(fast_observer, "ENABLED", compiled)
        r = fly(PATH_PRESETS["hover"], table, bird, "m3", config=SimConfig(attitude="free"),
                beats=6.0)  # fmt: skip
        logs[compiled] = r.arrays
    assert calls[0] > 40  # the compiled step ran at (nearly) every control update
    a, b = logs[True], logs[False]
    for k in a:
        scale = max(1.0, float(np.max(np.abs(b[k])))) if np.size(b[k]) else 1.0
        np.testing.assert_allclose(a[k], b[k], rtol=0, atol=1e-9 * scale, err_msg=k)
        assert not BITWISE or np.array_equal(a[k], b[k], equal_nan=True), k
