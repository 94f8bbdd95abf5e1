"""The lateral allocation's reserve in a turn: wider bounds for the differential stroke
plane and flap amplitude, used only where the loop's own bounds leave the roll and yaw
demand far short (by more than :data:`RESERVE_MISS` of it; reduced units, seed body axes).

Why: a side gust in the circle's 39-degree bank (``birdsim fly circle --attitude free
--gust 25:1:0:0.15:0``) rolls the seed bird 16-18 degrees past its bank; the path loop
then asks 1.45 times the turn's force, the table's twist amplitude reaches its upper
bound (so its differential has no room) and the differential inputs stayed at their
0.15-rad bounds for 4 wingbeats while the bird left the undisturbed flight by 2.9
semispans (1.17 with the reserve).  The 0.15-rad bounds are the loop's choice, not a
measured limit (docs/free-body.md); an undisturbed turn never misses by that much, so it
flies as before to the last digit (docs/turning.md, "Gust stage, second pass").
"""

from __future__ import annotations

import numpy as np

#: The inputs (names in ``attitude_jacobians.INPUTS``) whose bounds the reserve widens.
RESERVE_INPUTS = ("flap_amp", "stroke_plane")
#: Their bounds in a turn's reserve, as a multiple of the loop's own (0.15 rad: 0.3 rad of
#: right-left difference).  Measured (seed bird, circle, 30 % side gust for one wingbeat
#: from wingbeat 25 / 25.25 / 25.5 / 25.75, the largest distance from the undisturbed
#: circle in semispans): 1 (none) 2.95 / 0.28 / 0.25 / 0.51, 2 1.17 / 0.22 / 0.25 / 0.48,
#: 3 0.57 / 0.21 / 0.25 / 0.47 (not kept: 0.45 rad of flap amplitude between the wings).
TURN_RESERVE = 2.0
#: The allocation falls back on the reserve where a bound binds and the lateral inputs
#: miss the roll and yaw demand by more than this fraction of it: a large miss only.  The
#: undisturbed presets' few attitude-saturated control steps miss by less (the s-turn's
#: three by 0.18, 0.30 and 0.41; with the reserve there its path RMS rose from 0.0997 to
#: 0.1003, past its target); the gust's by 0.46-0.73.
RESERVE_MISS = 0.5


def reserve_bounds(
    inputs: tuple,
    names: tuple[str, ...],
    limits: dict[str, tuple[float, float]],
    params: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    factor: float,
) -> tuple[np.ndarray, np.ndarray]:
    """(lo, hi) with the bounds of :data:`RESERVE_INPUTS` (rad) multiplied by ``factor``;
    an amplitude's (a wingbeat parameter in ``names`` whose name ends in ``_amp``) still
    keeps both wings within its table bounds ``limits[name]`` = (lower, upper):
    ``2 min(p - lower, upper - p)`` at ``params``, as ``AttitudeLoop.bounds`` does."""
    lo2, hi2 = np.array(lo, dtype=float), np.array(hi, dtype=float)
    for i, (name, _, bound) in enumerate(inputs):
        if name not in RESERVE_INPUTS or hi2[i] <= 0.0:
            continue
        b = factor * bound
        if name.endswith("_amp") and name in names:
            lower, upper = limits[name]
            p = float(params[names.index(name)])
            b = min(b, max(0.0, 2.0 * min(p - lower, upper - p)))
        hi2[i], lo2[i] = max(hi2[i], b), min(lo2[i], -b)
    return lo2, hi2


__all__ = ["RESERVE_INPUTS", "RESERVE_MISS", "TURN_RESERVE", "reserve_bounds"]
