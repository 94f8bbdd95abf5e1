"""The JIT decorator: numba's njit with a disk cache and no NaN-dropping fastmath."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim.physics import jit, kernel


def test_kernels_are_cached_on_disk_and_keep_nan():
    if jit.numba is None:
        pytest.skip("numba is not installed: the numpy path is used")
    assert not {"nnan", "ninf", "afn", "fast"} & set(jit._FAST)
    coeffs = np.array([2.0, 0.05, 1.0])
    fx, fz = kernel._polar_force(0, coeffs, float("nan"), 1.0, 1.0, 1.0)
    assert math.isnan(fx) and math.isnan(fz)
    fx, fz = kernel._polar_force(1, coeffs, 1.0, float("nan"), 1.0, 1.0)
    assert math.isnan(fx) and math.isnan(fz)
    # cache=True: a FunctionCache (files in __pycache__), not numba's NullCache
    assert type(kernel._polar_force._cache).__name__ == "FunctionCache"
    assert type(kernel._means_kernel._cache).__name__ == "FunctionCache"
