"""The side gust's gate in a cruise turn (docs/turning.md, "Gust stage, thirteenth pass"):
what :class:`birdsim.flight.flown_lateral.FlownLateral` adds to its gate in a turn flown
on the second-stage loop with the roll and yaw rows per unit inertia (``att.per_inertia``:
the seed bird's cruise turns, not the slow ones).

* *Engage*: the wingbeat-mean roll error from the bank command beyond
  :data:`GUST_ROLL_RAD` while the planned bank is steady (its rate within
  :data:`STEADY_BANK_RATE` over :data:`STEADY_BEATS` about now), no input on its bound
  needed.  The calm cruise turns' roll error where the plan is steady: circle 0.031 rad,
  s-turn 0.039 (0.047 / 0.077 with the roll-in and the reversal); the circle's 30 % side
  gust: 0.086-0.38 within 1.4 wingbeats of the gust, three of 16 gusts never with an
  input on its bound beyond the bounded gate's 0.15.
* *Stay*: :data:`TURN_CALM_STEPS` calm control steps before the gate is left (straight
  flight's 8 left the held-body loop a roll bias of 1-2 degrees it trimmed over
  wingbeats, the gust's path offset growing back meanwhile).
* *The lateral path integral*: what it summed while engaged (the gust's own offset, not a
  bias of the bank flown) is taken back when the gate is left; left in, it drove the
  bird 0.1-0.14 semispan to the other side 15-30 wingbeats later.

Only the gate's state and the path loop's integral (one number) change; no force or
torque on the body.
"""

from __future__ import annotations

from typing import Any

import numpy as np

TWO_PI = 2.0 * np.pi
#: The wingbeat-mean roll error (rad) from the bank command beyond which a gust is taken.
GUST_ROLL_RAD = 0.05
#: The planned bank's largest rate (rad per wingbeat) that counts as steady ...
STEADY_BANK_RATE = 0.02
#: ... over this many wingbeats before and after now, sampled every :data:`SAMPLE_BEATS`.
STEADY_BEATS = (1.5, 0.5)
SAMPLE_BEATS = 0.25
#: Calm control steps (5 wingbeats) before a cruise turn's gate is left.
TURN_CALM_STEPS = 40


def cruise(att: Any) -> bool:
    """Whether ``att`` flies a cruise turn (roll and yaw per unit inertia) on the
    second-stage loop (the seed bird's; the pigeon's fourth-stage turn loop keeps the
    gate of :func:`birdsim.flight.turning.flown_lateral_loop` alone: measured without
    this one)."""
    return bool(getattr(att, "per_inertia", False)) and not getattr(att, "straight", False)


def steady_bank(track: Any, t: float) -> bool:
    """Whether ``track``'s planned bank is steady about reduced time ``t``."""
    beats = np.arange(-STEADY_BEATS[0], STEADY_BEATS[1] + 1e-9, SAMPLE_BEATS)
    rates = [abs(track.bank_plan(t + b * TWO_PI)[1][1]) for b in beats]
    return max(rates) * TWO_PI < STEADY_BANK_RATE


def gust_in_turn(track: Any, att: Any, err: np.ndarray, t: float) -> bool:
    """Whether a cruise turn's gate engages on a gust: ``err`` the loop's wingbeat-mean
    error (rotation vector, rad; roll first) at reduced time ``t`` on ``track``."""
    return cruise(att) and abs(float(err[0])) > GUST_ROLL_RAD and steady_bank(track, t)


def calm_steps(att: Any, straight: int) -> int:
    """Calm control steps before the gate is left: :data:`TURN_CALM_STEPS` in a cruise
    turn, else ``straight`` (the straight flight's)."""
    return TURN_CALM_STEPS if cruise(att) else straight


__all__ = [
    "GUST_ROLL_RAD",
    "SAMPLE_BEATS",
    "STEADY_BANK_RATE",
    "STEADY_BEATS",
    "TURN_CALM_STEPS",
    "calm_steps",
    "cruise",
    "gust_in_turn",
    "steady_bank",
]
