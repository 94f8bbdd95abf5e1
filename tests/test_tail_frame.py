"""The tail's frame (birdsim.mujoco.tail.tail_frame, written out entry by entry for speed,
issue 27) is the matrix product ``rot_x @ rot_y`` numpy computes, bit for bit, signed
zeros included: random angles within the clipped range, the bounds, zeros of both signs
and subnormals."""

from __future__ import annotations

import math

import numpy as np

from birdsim.mujoco.tail import ELEVATION_MAX, ROLL_MAX, TailControls, tail_frame


def _product(e: float, r: float) -> np.ndarray:
    ce, se, cr, sr = math.cos(e), math.sin(e), math.cos(r), math.sin(r)
    rot_y = np.array([[ce, 0.0, se], [0.0, 1.0, 0.0], [-se, 0.0, ce]])  # trailing edge up
    rot_x = np.array([[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]])  # right side down
    return rot_x @ rot_y


def test_frame_is_the_matrix_product():
    rng = np.random.default_rng(0)
    special = [0.0, -0.0, 5e-324, -5e-324, 1e-300, -1e-300]
    elev = [*rng.uniform(-ELEVATION_MAX, ELEVATION_MAX, 400), ELEVATION_MAX, -ELEVATION_MAX]
    roll = [*rng.uniform(-ROLL_MAX, ROLL_MAX, 40), ROLL_MAX, -ROLL_MAX]
    for e in elev + special:
        for r in roll + special:
            got = tail_frame(TailControls(e, 1.0, r))
            assert got.tobytes() == _product(e, r).tobytes(), (e, r)
