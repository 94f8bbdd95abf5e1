"""Table 2 matrices and the seed <-> MuJoCo conversion."""

import numpy as np
import pytest

from birdsim.physics import frames


@pytest.mark.parametrize("axis", ["x", "y", "z"])
def test_rotate_equals_table2_matrix(axis):
    rng = np.random.default_rng(1)
    for a in rng.uniform(-3, 3, 10):
        v = rng.normal(size=3)
        r = frames.passive_matrix(axis, a)
        np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-15)
        assert np.linalg.det(r) == pytest.approx(1.0)
        got = frames.rotate(axis, np.cos(a), np.sin(a), tuple(v))
        np.testing.assert_allclose(got, r @ v, atol=1e-15)
        back = frames.rotate(axis, np.cos(a), -np.sin(a), tuple(r @ v))
        np.testing.assert_allclose(back, v, atol=1e-15)
        np.testing.assert_allclose(
            frames.cross_axis(axis, tuple(v)), np.cross(frames.AXIS_VECTORS[axis], v)
        )


def test_signs_of_table2():
    # body pitch nose up: body x seen from earth points up (-Z)
    nose = frames.pitch_matrix(0.3).T @ [1, 0, 0]
    assert nose[2] < 0
    # flap > 0 moves the right wing tip down (+z)
    tip = frames.flap_matrix(0.3).T @ [0, 1, 0]
    assert tip[2] > 0
    # sweep > 0 (an active turn about z, which points down) moves the right wing tip back (-x)
    tip = frames.sweep_matrix(0.3).T @ [0, 1, 0]
    assert tip[0] < 0


def test_earth_body_round_trip_and_mujoco():
    v = (np.array(0.3), np.array(-1.2), np.array(0.5))
    back = frames.body_to_earth(0.7, frames.earth_to_body(0.7, v))
    np.testing.assert_allclose(back, v, atol=1e-15)
    np.testing.assert_allclose(frames.seed_to_mujoco([1.0, 2.0, 3.0]), [1.0, -2.0, -3.0])
    np.testing.assert_allclose(
        frames.mujoco_to_seed(frames.seed_to_mujoco([1.0, 2.0, 3.0])), [1.0, 2.0, 3.0]
    )
    r = frames.pitch_matrix(0.4)
    m = frames.rotation_seed_to_mujoco(r)
    np.testing.assert_allclose(
        m @ frames.seed_to_mujoco([1, 2, 3]), frames.seed_to_mujoco(r @ [1, 2, 3])
    )
