"""Rotation matrices of the dissertation's Table 2 and the seed-axes <-> MuJoCo conversion.

Seed axes (earth X forward, Y right, Z down; body x forward, y right wing, z down).
Every matrix here is *passive*, exactly as printed in Table 2: ``v_to = R @ v_from``,
back with the transpose.  A passive matrix of angle ``a`` about an axis describes a
frame turned actively by ``+a`` about that axis:

* ``pitch_matrix(a)`` (body pitch, wing twist, stroke plane, wrist twist): about y,
  nose / leading edge up for ``a > 0``;
* ``flap_matrix(a)``: about x, right wing tip down for ``a > 0``;
* ``sweep_matrix(a)``: about z, right wing tip swept back for ``a > 0``.

The hot path does not build matrices: :func:`rotate` applies the same passive
rotation to vectors stored as three component arrays, which is what lets the
cycle evaluation broadcast over parameter sets and time samples at once.
"""

from __future__ import annotations

from typing import Literal

import numpy as np

Axis = Literal["x", "y", "z"]

#: Seed axes -> MuJoCo world axes (x forward, y left, z up); its own inverse.
SEED_TO_MUJOCO = np.diag([1.0, -1.0, -1.0])

AXIS_VECTORS: dict[str, np.ndarray] = {
    "x": np.array([1.0, 0.0, 0.0]),
    "y": np.array([0.0, 1.0, 0.0]),
    "z": np.array([0.0, 0.0, 1.0]),
}


def pitch_matrix(angle: float) -> np.ndarray:
    """Table 2 'Body Pitch' / 'Wing Twist' / 'Wind to wing': passive rotation about y."""
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, 0.0, -s], [0.0, 1.0, 0.0], [s, 0.0, c]])


def flap_matrix(angle: float) -> np.ndarray:
    """Table 2 'Wing Flap': passive rotation about x."""
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, s], [0.0, -s, c]])


def sweep_matrix(angle: float) -> np.ndarray:
    """Table 2 'Wing Sweep': passive rotation about z."""
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])


AXIS_MATRICES = {"x": flap_matrix, "y": pitch_matrix, "z": sweep_matrix}


def passive_matrix(axis: Axis, angle: float) -> np.ndarray:
    """The Table 2 matrix about ``axis``."""
    return AXIS_MATRICES[axis](angle)


Vec3 = tuple[np.ndarray, np.ndarray, np.ndarray]


def _is_zero(a: object) -> bool:
    return isinstance(a, float) and a == 0.0


def _lin(a: np.ndarray, x: np.ndarray, b: np.ndarray, y: np.ndarray) -> np.ndarray:
    """``a*x + b*y``, skipping the work for components that are the scalar 0.0."""
    if _is_zero(x):
        return 0.0 if _is_zero(y) else b * y
    return a * x if _is_zero(y) else a * x + b * y


def rotate(axis: Axis, cos: np.ndarray, sin: np.ndarray, v: Vec3) -> Vec3:
    """Apply the passive Table 2 rotation (given by cos, sin of its angle) to ``v``.

    ``v`` is a tuple of three broadcastable arrays; a component may be the scalar 0.0,
    which is kept symbolic (the hot path starts from points like (0, r, 0)).  Pass
    ``-sin`` for the transpose (the way back).
    """
    x, y, z = v
    if axis == "y":
        return (_lin(cos, x, -sin, z), y, _lin(sin, x, cos, z))
    if axis == "x":
        return (x, _lin(cos, y, sin, z), _lin(-sin, y, cos, z))
    return (_lin(cos, x, sin, y), _lin(-sin, x, cos, y), z)


def cross_axis(axis: Axis, v: Vec3) -> Vec3:
    """``e_axis x v`` for a unit basis vector, without multiplications (zero parts are scalars)."""
    x, y, z = v
    if axis == "x":
        return (0.0, -z, y)
    if axis == "y":
        return (z, 0.0, -x)
    return (-y, x, 0.0)


def earth_to_body(pitch: np.ndarray | float, v_earth: Vec3) -> Vec3:
    """Seed earth axes -> body axes for body pitch ``pitch`` (R_e1 of Table 2)."""
    return rotate("y", np.cos(pitch), np.sin(pitch), v_earth)


def body_to_earth(pitch: np.ndarray | float, v_body: Vec3) -> Vec3:
    """Body axes -> seed earth axes (R_e1 transposed)."""
    return rotate("y", np.cos(pitch), -np.sin(pitch), v_body)


def seed_to_mujoco(v: np.ndarray) -> np.ndarray:
    """Positions, velocities, forces or torques (..., 3) from seed axes to MuJoCo axes."""
    return np.asarray(v) * np.array([1.0, -1.0, -1.0])


def mujoco_to_seed(v: np.ndarray) -> np.ndarray:
    """The inverse of :func:`seed_to_mujoco` (the same diagonal matrix)."""
    return seed_to_mujoco(v)


def rotation_seed_to_mujoco(r: np.ndarray) -> np.ndarray:
    """A rotation matrix between two seed-axes frames, expressed in MuJoCo axes: C R C."""
    return SEED_TO_MUJOCO @ np.asarray(r) @ SEED_TO_MUJOCO
