"""The pitch plan's smoothing compiled (``birdsim.flight.fast_smooth``): bit for bit the
Python filter run step by step."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.flight import fast_smooth, pitch_plan


def _both(values: np.ndarray, tau: float, dt: float, monkeypatch) -> tuple:
    monkeypatch.setattr(fast_smooth, "ENABLED", False)
    ref = pitch_plan._smooth(values, tau, dt)
    monkeypatch.setattr(fast_smooth, "ENABLED", True)
    return ref, fast_smooth.smooth(values, tau, dt)


@pytest.mark.skipif(fast_smooth.kernel is None, reason="numba missing")
@pytest.mark.parametrize("seed", range(4))
def test_smooth_bitwise(seed: int, monkeypatch) -> None:
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 400))
    # a table's pitch with jumps between branches (landing's flare), on a control grid
    values = np.cumsum(rng.normal(0.0, 0.02, n)) + np.where(rng.random(n) < 0.05, 0.6, 0.0)
    tau, dt = float(rng.uniform(0.5, 30.0)) / np.sqrt(2.0), float(rng.uniform(0.1, 1.2))
    ref, fast = _both(values, tau, dt, monkeypatch)
    assert fast is not None
    assert fast.tobytes() == ref.tobytes()


@pytest.mark.skipif(fast_smooth.kernel is None, reason="numba missing")
def test_smooth_arguments_matter(monkeypatch) -> None:
    """The filter's tau ** 2 is Python's (C pow), passed in beside tau: the two swapped
    give another plan (the test can tell them apart)."""
    values = np.linspace(0.1, 1.3, 200) ** 2
    ref, fast = _both(values, 8.485281374238571, 0.7853981633974483, monkeypatch)
    assert np.array_equal(fast, ref)
    swapped = np.empty_like(values)
    tau, dt = 8.485281374238571, 0.7853981633974483
    fast_smooth.kernel(values, tau**2, tau, dt / 8, 8, swapped)
    assert not np.array_equal(swapped, ref)


def test_smooth_falls_back() -> None:
    assert fast_smooth.smooth(np.ones(3), 0.0, 0.5) is None
    assert fast_smooth.smooth(np.ones((2, 2)), 1.0, 0.5) is None
