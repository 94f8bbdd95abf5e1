"""Checks of the flight-state inputs of a wingbeat evaluation (climb, body rate) and the
cross product of vectors stored as component arrays: helpers of
:mod:`birdsim.physics.cycle` and :mod:`birdsim.physics.moments`."""

from __future__ import annotations

import numpy as np

from birdsim.errors import BirdsimError, check_numbers
from birdsim.physics.frames import Vec3


def cross(a: Vec3, b: Vec3) -> Vec3:
    """``a x b`` for vectors stored as three broadcastable component arrays."""
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def check_body_rate(body_rate: object) -> np.ndarray:
    """``body_rate`` as a float array of shape (..., 3); one line for anything else."""
    try:
        w = np.asarray(body_rate, dtype=float)
    except (TypeError, ValueError):
        raise BirdsimError(
            f"body_rate={body_rate!r} is not a vector; allowed: (p, q, r) in rad per unit time"
        ) from None
    if w.ndim == 0 or w.shape[-1] != 3:
        raise BirdsimError(
            f"body_rate has shape {w.shape}; allowed: (3,) or (..., 3): (p, q, r) in body axes"
        )
    return check_numbers("body_rate", w, "finite rates (p, q, r) in rad per unit time")


def _check_climb(climb: object) -> np.ndarray:
    """``climb`` as a float array; one line naming a non-number, non-finite or absurd value."""
    return check_numbers("climb", climb, "a finite number (positive up)")
