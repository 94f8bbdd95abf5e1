"""The rocking's rectified moment in the fourth-stage pitch loop after the slow loop hands
back (docs/free-body.md, "The pigeon's attitude, eleventh stage").

The slow straight flight's pitch loop (:mod:`birdsim.flight.pitch_section`) counts the
body's rocking's rectified pitching moment
(:func:`birdsim.flight.pitch_rocking.rocking_pitch_moment`) in its model's ``M_0``.
When it hands the pitch back to the attitude loop (a take-off's climb-out, where the
tail's pitch stiffness appears), the tenth stage put that moment into the attitude
loop's pitch integral, where it stayed while the wingbeat changed under it: the pigeon's
take-off turns from its climbing wingbeat (flap amplitude about 1.1 rad, rocking 12-20
degrees) into the cruise's (0.2-0.4 rad) within two wingbeats, and the integral's stale
share then left the body 5-11 degrees off the command (nose down, then up).

Here the moment stays a measured part of the loop's ``M_0`` instead: measured again with
every Jacobian measurement of the loop and whenever the flap amplitude has moved by
:data:`ROCK_DFLAP` since, and followed through a first-order lag of
:data:`ROCK_LAG_BEATS` wingbeats (empirical, measured below: the moment stepped to the
cruise wingbeat's left the take-off's end 10.5 degrees nose down; the flown rocking does
not follow the wingbeat at once).  Reduced
units (table units of moment, time in 1 / omega), seed body axes (pitch nose up).
"""

from __future__ import annotations

import math

import numpy as np

from birdsim.flight.pitch_rocking import rocking_pitch_moment

#: Flap amplitude change (rad) since the last measurement that measures the moment again.
#: Measured (pigeon take-off, pitch degrees RMS, with ROCK_LAG_BEATS 1): 0.15 -> 4.01,
#: 0.3 -> 3.81; never (only with the loop's Jacobians): 4.38 without the lag.
ROCK_DFLAP = 0.3
#: Wingbeats per time constant of the lag the loop's ``M_0`` follows the moment with.
#: Measured (pigeon take-off, pitch degrees RMS): 0 (stepped) 4.32, 0.5 4.01, 1 3.81,
#: 1.5 3.86, 2 3.92, 3 4.02.
ROCK_LAG_BEATS = 1.0


class RockingShare:
    """The moment's share of one hand-back: ``moment`` the slow loop's last measurement
    (table units), ``flap`` the flap amplitude it was measured at (rad; None: the bird's
    wingbeat has none)."""

    def __init__(self, moment: float, flap: float | None):
        self.target = self.used = float(moment)
        self.flap = flap

    def stale(self, flap: float | None) -> bool:
        """Whether the flap amplitude ``flap`` has moved by :data:`ROCK_DFLAP` since the
        last measurement."""
        return flap is not None and self.flap is not None and abs(flap - self.flap) > ROCK_DFLAP

    def measure(
        self, fb, params: np.ndarray, pitch: float, speed: float, inertia: float, flap: float | None
    ) -> None:
        """Measure the moment again at ``params`` (the wingbeat), ``pitch`` (rad), airspeed
        ``speed`` and pitch ``inertia`` (:func:`rocking_pitch_moment`); ``flap`` its flap
        amplitude."""
        self.target = rocking_pitch_moment(fb, params, pitch, speed, inertia)[0]
        self.flap = flap

    def step(self, dt: float, period: float) -> np.ndarray:
        """The share of ``M_0`` (3,) for a control step of ``dt`` (time units; ``period``
        the wingbeat's): the lagged moment on the pitch axis."""
        a = 1.0 - math.exp(-dt / (ROCK_LAG_BEATS * period))
        self.used += a * (self.target - self.used)
        return np.array([0.0, self.used, 0.0])


__all__ = ["ROCK_DFLAP", "ROCK_LAG_BEATS", "RockingShare"]
