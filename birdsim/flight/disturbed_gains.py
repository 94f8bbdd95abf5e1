"""The path loop slowed once a gust reaches a free body whose pitch loop is resonant
(reduced units): the outer loop of the cascade kept apart from the inner one.

With the attitude free, the path loop's wingbeat sets the body's pitch command (the
table's pitch), which the pitch attitude loop follows (:mod:`birdsim.flight.attitude`,
:func:`birdsim.flight.attitude_gains.damped_gains`).  That loop's design is a double pole
at ``-omega_a`` (:data:`birdsim.flight.attitude.ATTITUDE_BEATS` wingbeats per time
constant) unless the tail's restoring stiffness per unit inertia ``k / I`` already
exceeds ``omega_a^2``: then the natural frequency ``sqrt(k / I)`` is kept with the
design's damping, a damping ratio ``omega_a / sqrt(k / I)`` below one.  The pigeon's
light body (pitch inertia 0.78 against the seed bird's 3.29, reduced, for about the same
tail stiffness) has ``k / I`` 4.2 times ``omega_a^2`` in cruise (damping ratio 0.49); the
seed bird's is 0.96 times it (ratio 1).  The path loop runs at the posed loop's
:data:`birdsim.flight.controller.TIME_CONSTANT_BEATS`, the same two wingbeats as the
pitch loop: after a gust the pigeon's body swung +-10-35 degrees with a period of 2-5
wingbeats (its 30 % down gust dropped out of the path's 0.05-semispan band again in
wingbeats 15-17, the stroke plane's compensation swinging from -13 to 56 degrees).

A path loop :data:`CASCADE_RATIO` times slower than the pitch loop settles that swing
(docs/free-body.md, "the cascade's separation"), but costs calm flight its tracking (the
pigeon's free landing 0.0209 -> 0.0509 m, take-off's pitch 2.66 -> 3.07 degrees).  So it
is switched in only where needed: in straight free flight, at the first control step
with a wind along or across the path in the sagittal plane (x or z: the air the path loop
already reads for its airspeed and air-path angle; a side wind is the lateral loop's),
when the pitch pair is resonant (damping ratio below :data:`RESONANT_DAMPING`).  That is
decided once, on the calm loop's plant, and kept for the rest of the flight (no switching
back and forth); the integral is carried over bumplessly (its acceleration unchanged).
Calm flights and the seed bird fly as before to the last digit.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.flight.attitude import ATTITUDE_BEATS
from birdsim.flight.controller import gains_for

#: Switch for the whole module (tests turn it off to fly the previous loop).
ENABLED = True
#: The path loop's time constant over the pitch attitude loop's once switched (measured
#: 1 / 1.125 / 1.25 / 1.375 / 1.5 over the pigeon's gust grid, docs/free-body.md).
CASCADE_RATIO = 1.25
#: The pitch pair's damping ratio below which the loop counts as resonant (a second-order
#: pair has a resonant peak for a damping ratio below 1 / sqrt(2)).
RESONANT_DAMPING = 1.0 / math.sqrt(2.0)
PITCH = 1  # the attitude loop's pitch axis


def pitch_damping_ratio(att: Any) -> float:
    """The damping ratio of the pitch pair the attitude loop ``att``
    (:class:`birdsim.flight.attitude.AttitudeLoop`) places: ``s^2 + 2 omega_a s + q`` with
    ``q = max(omega_a^2, k / I)`` (:func:`birdsim.flight.attitude_gains.damped_gains`), so
    ``omega_a / sqrt(q)``: 1 at the design, below it where the tail's stiffness per unit
    inertia ``k / I`` is kept."""
    k = float(np.asarray(att.stiffness)[PITCH]) / float(np.asarray(att.inertia)[PITCH])
    wa = float(np.asarray(att.gains.omega_a)[PITCH])
    return wa / math.sqrt(max(wa * wa, k))


class DisturbedGains:
    """One flight's switch of the path loop's gains: ``ctl`` the
    :class:`birdsim.flight.controller.Controller` whose gains change, ``att`` the attitude
    loop, ``active`` whether the flight may switch (straight and free; gains a caller gave
    :func:`birdsim.flight.freeflight.fly` are kept)."""

    def __init__(self, ctl: Any, att: Any, active: bool) -> None:
        self.ctl, self.att, self.active = ctl, att, active
        self.switched = False

    def step(self, integral: np.ndarray, limit: Any, wind: np.ndarray) -> tuple[np.ndarray, Any]:
        """One control step with the world wind ``wind`` now (x forward, y left, z up; only
        its x and z, the path loop's, count): the path integral and its bound (reduced
        units), rescaled where the gains switch so that ``ki * integral`` (the integral
        term's acceleration) is unchanged."""
        w = np.asarray(wind, dtype=float)
        if not (ENABLED and self.active) or self.switched or not (w[0] != 0.0 or w[2] != 0.0):
            return integral, limit
        self.active = False  # decided at the first step with a wind, on the calm loop's plant
        if not (self.att.enabled and pitch_damping_ratio(self.att) < RESONANT_DAMPING):
            return integral, limit
        old = self.ctl.gains
        new = gains_for(self.ctl.bird, CASCADE_RATIO * ATTITUDE_BEATS)
        if old != gains_for(self.ctl.bird) or new.omega_n >= old.omega_n:  # a caller's own
            return integral, limit  # gains (or none slower) are kept
        self.ctl.gains, self.switched = new, True
        ratio = old.ki / new.ki
        return integral * ratio, limit * ratio


__all__ = ["CASCADE_RATIO", "ENABLED", "RESONANT_DAMPING", "DisturbedGains", "pitch_damping_ratio"]
