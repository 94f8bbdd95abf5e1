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

In a cruise turn the roll and yaw rows are also weighed per unit inertia
(:func:`per_inertia`; docs/turning.md, "Gust stage, ninth pass").
"""

from __future__ import annotations

from typing import Any

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
#: In a cruise turn, solve the attitude loop's roll and yaw rows weighed per unit inertia
#: (:func:`per_inertia`): the miss the bounded and regularised inputs leave is then an
#: angular acceleration, as the loop's gains are placed, not a moment.  Such a loop takes
#: the reference update every control step (the compiled one, ``fast_attitude``, weighs
#: moments): the circle 60 wingbeats in 1.51 s of CPU against 1.43.
PER_INERTIA = True


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


def weighs(loop: Any) -> bool:
    """Whether ``loop`` (an ``AttitudeLoop``) allocates roll and yaw per unit inertia
    (:func:`per_inertia`): where its ``per_inertia`` is set
    (``turning.attitude_loop_for``: a turn that is not slow), with :data:`PER_INERTIA`."""
    return PER_INERTIA and bool(getattr(loop, "per_inertia", False))


def per_inertia(
    a_aug: np.ndarray, b_aug: np.ndarray, inertia: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The allocation's least-squares system (``a_aug`` (k + n, n), ``b_aug`` (k + n,): its
    first k rows the moment rows, then the regularisation) with moment row ``i`` divided
    by ``inertia[i]`` (the rows' principal moments) and multiplied by the largest of them
    (the most inert axis keeps its row exactly, and the regularisation its weight there).

    Why: a moment asked of the seed bird's roll axis (0.85) turns the body 4.5 times as
    fast as the same moment asked of its yaw axis (3.8); weighed as moments, a bound
    allocation gave yaw as much of the shared differential inputs as roll.  In the
    circle's side gust from wingbeat 25 the roll demand got half of what it asked while
    the body rolled 15 degrees past its bank (docs/turning.md, "Gust stage, ninth pass")."""
    i = np.asarray(inertia, dtype=float)
    w = np.ones(len(b_aug))
    w[: len(i)] = i.max() / i
    return a_aug * w[:, None], b_aug * w


def turn_reserve_bounds(
    loop: Any,
    inputs: tuple,
    params: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    factor: float | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`reserve_bounds` for an ``AttitudeLoop`` ``loop`` (its kinematic model's
    parameter names and table bounds; ``factor`` its ``reserve`` unless given)."""
    kin = loop.fb.kin
    limits = {p.name: (p.lower, p.upper) for p in kin.params}
    f = loop.reserve if factor is None else factor
    return reserve_bounds(inputs, kin.param_names, limits, params, lo, hi, f)


__all__ = [
    "PER_INERTIA",
    "RESERVE_INPUTS",
    "RESERVE_MISS",
    "TURN_RESERVE",
    "per_inertia",
    "reserve_bounds",
    "turn_reserve_bounds",
    "weighs",
]
