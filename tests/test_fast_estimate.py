"""The compiled attitude error (birdsim.flight.fast_estimate) against the numpy
reference (flight_arrays.error_rotvec): the same formulas, round-off apart (sums of
four and three squares in another order, the C library's cos/sin/atan2): within 1e-15
rad, level and banked commands, small angles (the Taylor branch) and near pi."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.flight import fast_estimate
from birdsim.flight.flight_arrays import error_rotvec

pytestmark = pytest.mark.skipif(fast_estimate.rotvec_kernel is None, reason="numba missing")


def test_compiled_error_is_the_reference():
    rng = np.random.default_rng(11)
    quat = rng.normal(size=(64, 4)) * rng.uniform(0.5, 2.0, size=(64, 1))  # not unit
    small = np.array([np.cos(0.5 * 0.3), 0.0, -np.sin(0.5 * 0.3), 0.0])  # pitch 0.3 exactly
    quat = np.vstack([quat, small, small + 1e-5, -small])
    for cmd in ((0.3, 0.0, 0.0), (0.3001, 0.0, 0.0), (-1.2, 0.4, 0.0), (0.2, -0.3, 2.9)):
        a = fast_estimate.error_rotvec(quat, *cmd)
        b = error_rotvec(quat, *cmd)
        assert a.shape == b.shape == (len(quat), 3)
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-15)
    angles = np.linalg.norm(error_rotvec(quat, 0.3001), axis=1)
    assert angles.min() < 1e-3 < angles.max()  # both branches were compared
