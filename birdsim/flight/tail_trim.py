"""The tail's operating point for the attitude loop's Jacobians (reduced units, rad).

The tail's slender-wing lift is capped beyond :data:`birdsim.mujoco.tail.ALPHA_MAX`
(20 degrees; the theory's valid range).  The loop measures its Jacobians on the held
body at the commanded pitch with the air along the path, where the tail's angle of
attack is the body's pitch less the elevation (trailing edge up lowers it).  In slow
flight the table's body is steep (take-off 30-65 degrees, landing's flare to 88): at
zero elevation the tail sits beyond the cap, its measured derivative and stiffness are
zero, and the shoulders' offsets, which pump the light body's rocking within the
wingbeat, carry the whole pitch demand (docs/free-body.md, "The pigeon's attitude,
fifth stage").  So the Jacobians are measured with the tail elevated just enough to
bring its angle of attack to :data:`TRIM_ALPHA` (half the valid range, so that it can
act both ways), the loop's tail input then moving about that point within the range
where the tail's lift is not capped (:func:`tail_elevation_range`); where the body is
within :data:`TRIM_ALPHA` of level, the operating point is zero elevation, as before."""

from __future__ import annotations

import numpy as np

from birdsim.flight.attitude_jacobians import INPUTS, JAC_STEP
from birdsim.mujoco.tail import ALPHA_MAX, ELEVATION_MAX

#: The tail's angle of attack (rad) at the operating point when the body is steeper.
TRIM_ALPHA = 0.5 * ALPHA_MAX
_TAIL = [name for name, _, _ in INPUTS].index("tail_elevation")


def tail_operating_elevation(pitch: float) -> float:
    """The tail elevation (rad) that brings the held body's tail (body pitch ``pitch``
    rad, the air along the path) within :data:`TRIM_ALPHA` of zero angle of attack:
    zero where it already is, within the elevation's bounds less one Jacobian step."""
    top = ELEVATION_MAX - JAC_STEP
    e = min(max(0.0, float(pitch) - TRIM_ALPHA), float(pitch) + TRIM_ALPHA)
    return min(max(e, -top), top)


def tail_elevation_range(pitch: float) -> tuple[float, float]:
    """The tail elevations (rad) within the elevation's bounds at which the held body's tail
    (pitch ``pitch``) is within its valid angle of attack (+-ALPHA_MAX), where its lift
    is not capped and the measured derivative holds: ``[pitch - ALPHA_MAX, pitch +
    ALPHA_MAX]`` clipped to +-ELEVATION_MAX (one point, the bound, when the body is too
    steep for any elevation to bring the tail within its range)."""
    lo = min(max(float(pitch) - ALPHA_MAX, -ELEVATION_MAX), ELEVATION_MAX)
    hi = min(max(float(pitch) + ALPHA_MAX, -ELEVATION_MAX), ELEVATION_MAX)
    return lo, hi


def operating_point(pitch: float) -> np.ndarray:
    """The attitude inputs' operating point (:data:`INPUTS`' order): every input zero but
    the tail elevation, :func:`tail_operating_elevation`."""
    u0 = np.zeros(len(INPUTS))
    u0[_TAIL] = tail_operating_elevation(pitch)
    return u0


__all__ = ["TRIM_ALPHA", "operating_point", "tail_elevation_range", "tail_operating_elevation"]
