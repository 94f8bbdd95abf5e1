"""The compiled path curves (birdsim.flight.fast_path) are scipy's PPoly numbers to the
bit: every key of ``FlightPath.sample`` and ``FlightPath.state`` inside the knots, on
them, before the first and after the last (the end tangent), for position and speed
paths with and without y."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.flight import fast_path
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.flight.presets import PATH_PRESETS

pytestmark = pytest.mark.skipif(fast_path.values_kernel is None, reason="numba missing")


def _paths() -> list[FlightPath]:
    out = list(PATH_PRESETS.values())
    out.append(FlightPath("v", 20.0, False, False, (PathKeyframe(0.0, 6.0, V=0.9),)))
    keys = (PathKeyframe(0.0, 6.0, x=0.0), PathKeyframe(3.0, 6.5, x=4.0, y=0.7))
    out.append(FlightPath("xy", 6.0, False, False, keys + (PathKeyframe(5.0, 6.2, x=9.0),)))
    return out


def test_compiled_curves_are_scipys(monkeypatch):
    rng = np.random.default_rng(3)
    for path in _paths():
        knots = np.asarray(path._z.x)
        t = np.concatenate([knots, rng.uniform(knots[0] - 5.0, knots[-1] + 5.0, 200), [-1.0, 1e4]])
        monkeypatch.setattr(fast_path, "ENABLED", True)
        assert fast_path.curve_values(path._z, t) is not None
        got = {}
        for compiled in (True, False):
            monkeypatch.setattr(fast_path, "ENABLED", compiled)
            got[compiled] = (
                path.sample(t),
                path.sample(float(t[7])),
                [path.state(float(ti)) for ti in t[::17]],
            )
        (a, a0, sa), (b, b0, sb) = got[True], got[False]
        assert list(a) == list(b)  # the same keys in the same order
        for k in b:
            assert a[k].shape == b[k].shape == t.shape
            assert np.array_equal(a[k], b[k]), (path.name, k)
            assert np.shape(a0[k]) == np.shape(b0[k]) == ()
            assert float(a0[k]) == float(b0[k])
        assert sa == sb


def test_unusable_curves_keep_scipy():
    from scipy.interpolate import PPoly

    flat = PPoly(np.zeros((6, 2)), np.array([0.0, 1.0, 1.0]))  # a repeated knot
    assert fast_path.curve_values(flat, np.zeros(3)) is None
