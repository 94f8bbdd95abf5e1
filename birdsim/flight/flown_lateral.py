"""The free body's lateral inputs chosen on the flight's own prediction where the held-body
model stops holding (reduced units; docs/free-body.md, "the pigeon's side gust on the flown
prediction"): the lateral counterpart of :mod:`birdsim.flight.flown_pitch`.

The straight attitude loop allocates roll and yaw to the differential inputs (flap and
twist amplitude, stroke plane) and the tail's roll through the held body's wingbeat-mean
Jacobians.  After a side gust the pigeon's loop puts them on their bounds for wingbeats,
and in that rocking, sideslipping flight the inputs do not do what the held body says (the
differential flap's yaw a fifteenth of the held value, a roll input instead; half the roll
gap the inputs' timing within the stroke: docs/free-body.md, "the pigeon's side gust and
the sideslip").  Gate: engaged when the loop's own choice puts a lateral input on its bound
(within :data:`AT_BOUND` of its half range) while the wingbeat-mean yaw error exceeds
:data:`ENGAGE_YAW_RAD`; left after :data:`CALM_STEPS` control steps with every lateral
input off its bounds and the wingbeat-mean roll and yaw errors within :data:`CALM_RAD`.
Engaged, every control step the flight is predicted :data:`WINDOW` ``[1]`` wingbeats ahead
from its state (:func:`birdsim.flight.flown_prediction.predict_root`) with the loop's
inputs and once more per lateral input stepped by :data:`STEP`; the lateral inputs are set
to the least change (weight :data:`MU`, inputs scaled by their bounds) that leaves
:data:`ALPHA` of the predicted wingbeat-mean roll and yaw errors (the loop's rotation
vector onto its command) over wingbeats ``WINDOW`` (in straight flight the differential
flap amplitude and stroke plane within :data:`STRAIGHT_RESERVE` times the loop's bounds);
on the fourth-stage loop (straight flight, the pigeon's turns) the loop's roll and yaw
integral is held where the step before left it (anti-windup: the loop's lateral inputs are
not the flown ones, and its integral would sum the errors of inputs it does not fly; in the
seed bird's turns the hold made the circle's side gusts worse, 16 phases 0.117 -> 0.130).
In a turn (docs/turning.md, "Gust stage, eleventh pass"; the second-stage loop, and the
pigeon's fourth-stage one: :func:`birdsim.flight.turning.flown_lateral_loop`) the gate is
the roll error from the bank command beyond :data:`ENGAGE_ROLL_RAD` with a lateral input on
its bound, the command is followed over the prediction (the path's heading and bank plan:
:func:`birdsim.flight.turning.ahead`), and the inputs keep the turn's reserve; a cruise
turn's gate also opens on a gust in a steady bank, stays longer and takes back the path
loop's lateral integral it held (:mod:`birdsim.flight.turn_gust_gate`).  The symmetric
inputs (pitch) are left as the loop (and :mod:`birdsim.flight.flown_pitch`) set them.  Only
wing and tail targets change; no force or torque on the body.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from birdsim.flight.attitude import LAT_INPUTS
from birdsim.flight.attitude_jacobians import INPUTS, split_inputs
from birdsim.flight.attitude_reserve import TURN_RESERVE, turn_reserve_bounds
from birdsim.flight.bounded_lsq import bounded_lsq
from birdsim.flight.flight_arrays import error_rotvec
from birdsim.flight.flown_prediction import SAMPLES, predict_root
from birdsim.flight.turn_gust_gate import calm_steps, cruise, gust_in_turn
from birdsim.flight.turning import ahead, flown_lateral_loop
from birdsim.mujoco.tail import TailControls

#: Switch for the whole module (freeflight reads it at each flight; tests turn it off).
ENABLED = True
#: The prediction's length and the part of it the mean errors are taken over (wingbeats).
WINDOW = (0.25, 1.0)
#: The inputs' step (rad) of a measured sensitivity.
STEP = 0.01
#: The fraction of the predicted errors left to the next step (the pigeon's +y gust, 24
#: wingbeats: 0.1 back and settled, 0.3 and slower (the roll a few degrees off for longer),
#: 0.5 not back in 16 wingbeats; docs/free-body.md).
ALPHA = 0.1
#: The weight of the least change from the loop's own inputs (scaled by their bounds).
MU = 1e-3
#: A lateral input counts as on its bound within this fraction of its half range.
AT_BOUND = 1e-6
#: The wingbeat-mean yaw error (rad) beyond which a saturated loop hands over: past the
#: largest heading the held-body loop was measured to fly through with its model holding
#: (the seed bird's side gust: yaw 10 degrees, its delivered roll moment within 0.009 of
#: the held body's; the pigeon's 15-19 degrees with 0.027 missing; docs/free-body.md).
ENGAGE_YAW_RAD = 0.2
#: In a turn (:func:`flown_lateral_for` with a track): the wingbeat-mean roll error (rad,
#: from the bank command) beyond which a saturated loop hands over.  The seed bird's calm
#: turns reach 0.047 (circle), 0.077 (s-turn), 0.094 (turn-90), 0.058 (u-turn), with a
#: lateral input on its bound 0.023 / 0.077 / 0.069 / 0.033; the circle's 30 % side gust
#: 0.2-0.38 (docs/turning.md, "Gust stage, eleventh pass").
ENGAGE_ROLL_RAD = 0.15
#: Control steps (one wingbeat) calm before the gate is left, and the errors (rad,
#: wingbeat-mean roll and yaw) that count as calm: within a quarter of the issue's 2
#: degrees (left at 2 degrees, the held-body loop's own lateral oscillation, +-2-5
#: degrees on the pigeon even after a 5 % gust, grew back and the gate re-engaged).
CALM_STEPS = 8
CALM_RAD = 0.01
#: Straight flight, engaged: the bounds of the differential flap amplitude and stroke
#: plane the choice keeps, as a multiple of the loop's own 0.15 rad (amplitudes within the
#: table's bounds: :func:`birdsim.flight.attitude_reserve.reserve_bounds`).  The turn's
#: reserve (:data:`~birdsim.flight.attitude_reserve.TURN_RESERVE`): the loop's bounds are
#: its choice, not a measured limit, and the gate is short of roll authority (on the
#: loop's bounds the pigeon's 30 % side gust, pushed to -0.34 semispan, overshoots to
#: +0.094 in wingbeat 11 and swings the yaw back to -12.4 degrees; with 2: -0.023, -7.4;
#: docs/free-body.md, "the side gust with the turn's reserve").  Calm flight never
#: engages the gate.
STRAIGHT_RESERVE = TURN_RESERVE
#: The rows of the loop's error (rotation vector, seed body axes) the choice meets.
ROWS = (0, 2)
TAIL_ROLL = [name for name, _, _ in INPUTS].index("tail_roll")


class FlownLateral:
    """One flight's gate state (engaged, calm steps) and its predictive lateral choice."""

    def __init__(self, track: Any = None) -> None:
        #: A turning flight's path (its gate: the roll error, any loop), None if straight.
        self.track = track
        self.turn = track is not None
        self.engaged = False
        self.calm = 0
        self.steps = 0  # control steps engaged (for tests and logs)
        #: The loop's integral (roll, pitch, yaw; per unit inertia, reduced units) as the
        #: last control step left it: its roll and yaw are held there while engaged.
        self.held: np.ndarray | None = None
        #: This step's flown lateral inputs (columns of ``INPUTS``, values) or None.
        self.flown_u: tuple[list[int], np.ndarray] | None = None
        #: A turn's lateral path integral (``turning.turn_command``'s, the flight's one list)
        #: and its value where the gate engaged (a cruise turn's is taken back on leaving).
        self.lateral_integral, self.integral_in = [0.0], 0.0

    def _beyond(self, err: np.ndarray) -> bool:
        """Whether the loop's error is beyond the engage limit: the roll error from the
        bank command in a turn (:data:`ENGAGE_ROLL_RAD`), else the yaw error
        (:data:`ENGAGE_YAW_RAD`)."""
        row, limit = (0, ENGAGE_ROLL_RAD) if self.turn else (2, ENGAGE_YAW_RAD)
        return abs(float(err[row])) > limit

    def _gust(self, att, err: np.ndarray, t: float) -> bool:
        """Whether a cruise turn's gate opens on a gust (:func:`gust_in_turn`)."""
        return self.turn and gust_in_turn(self.track, att, err, t)

    def gate(self, att, lo: np.ndarray, hi: np.ndarray, err: np.ndarray, t: float = 0.0) -> bool:
        """Whether the prediction chooses this step's lateral inputs (updates the gate):
        ``att`` the attitude loop (straight, its inputs ``att.u`` this step's own choice),
        ``lo``, ``hi`` the inputs' bounds, ``err`` the loop's wingbeat-mean error (rad),
        ``t`` the reduced time (a turn's bank plan)."""
        # straight flight's loop, or a turn's (turning.flown_lateral_loop)
        if not (att.enabled and flown_lateral_loop(att, self.turn) and att._jac is not None):
            return False
        cols = [c for c in LAT_INPUTS if hi[c] > lo[c]]
        u, tol = att.u[cols], AT_BOUND * (hi[cols] - lo[cols]) / 2
        on_bound = bool(np.any((u <= lo[cols] + tol) | (u >= hi[cols] - tol)))
        if not self.engaged:
            self.engaged = (on_bound and self._beyond(err)) or self._gust(att, err, t)
            self.calm, self.integral_in = 0, self.lateral_integral[0]
        else:
            off = max(abs(float(err[r])) for r in ROWS) > CALM_RAD
            self.calm = 0 if (on_bound or off) else self.calm + 1
            self.engaged = self.calm < calm_steps(att, CALM_STEPS)
            if not self.engaged and self.turn and cruise(att):  # the gust's offset summed
                self.lateral_integral[0] = self.integral_in
        return self.engaged

    def step(
        self, att, fb, args: tuple, params: np.ndarray, cmd3: Any, err: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """Gate and, engaged, choose the lateral inputs for the interval about to be
        flown: ``args`` (right, left wingbeat targets, stroke-plane offset, wind now) as
        the loop made them, ``params`` the table's wingbeat, ``cmd3`` the command's (pitch,
        roll, yaw) (rad) and, turning, the bank correction's filter (value, rate) and the
        body's pitch that set it (followed over the prediction by
        :func:`birdsim.flight.turning.ahead`), ``err`` the loop's error.  Returns the
        (right, left) targets to fly (the loop's when not engaged) and sets the tail's
        roll; ``att.u`` stays the loop's own choice (it feeds the loop), :attr:`flown_u`
        has what is flown (the log's)."""
        self.flown_u = None
        if not (self.engaged or self._beyond(err) or self._gust(att, err, fb.time)):  # shut
            self.held = np.array(att.integral, dtype=float)  # (the gate's work skipped)
            return args[0], args[1]
        lo, hi = att.bounds(params)
        held, engaged = self.held, self.gate(att, lo, hi, err, fb.time)
        if engaged and held is not None and att.straight:  # anti-windup (fourth stage): roll, yaw
            att.integral[list(ROWS)] = held[list(ROWS)]
        self.held = np.array(att.integral, dtype=float)
        if not engaged:
            return args[0], args[1]
        self.steps += 1
        # a turn's reserve as the loop may use it; straight flight's the gate's own
        reserve = att.reserve if self.turn else STRAIGHT_RESERVE
        if reserve > 1.0:
            lo, hi = turn_reserve_bounds(att, INPUTS, params, lo, hi, reserve)
        names = fb.schedule.names
        cols = [c for c in LAT_INPUTS if hi[c] > lo[c]]
        tail, shoulder = fb.cb.tail_controls, np.array(fb.schedule.shoulder_target, dtype=float)
        u0 = np.array(att.u, dtype=float)

        def targets(x: np.ndarray) -> tuple:  # wing targets and tail with lateral inputs x
            u = u0.copy()
            u[cols] = x
            right, left, _, _ = split_inputs(names, params, u)
            return right, left, TailControls(tail.elevation, tail.spread, float(u[TAIL_ROLL]))

        def errors(x: np.ndarray) -> np.ndarray:  # predicted mean roll and yaw errors
            right, left, tl = targets(x)
            q = predict_root(fb, (right, left, *args[2:]), shoulder, tl, WINDOW[1])[1]
            t = np.arange(len(q)) / SAMPLES
            q, t = q[t >= WINDOW[0] - 1e-9, 3:7], t[t >= WINDOW[0] - 1e-9]
            if self.track is not None:  # a turn's command moves over the window
                c = ahead(self.track, fb.time, cmd3[3:5], (cmd3[5], 0.0))(t)
                e = np.vstack([error_rotvec(q[i : i + 1], *c[i]) for i in range(len(t))])
            else:
                e = error_rotvec(q, *cmd3[:3])
            return e[:, list(ROWS)].mean(axis=0)

        x0 = u0[cols]
        base = errors(x0)
        sens = np.zeros((len(ROWS), len(cols)))
        for j in range(len(cols)):
            moved = x0.copy()
            moved[j] += STEP
            sens[:, j] = (errors(moved) - base) / STEP
        s = (hi[cols] - lo[cols]) / 2
        a = np.vstack([sens * s, np.sqrt(MU) * np.eye(len(cols))])
        b = np.concatenate([(ALPHA - 1.0) * base, np.zeros(len(cols))])
        dx, _ = bounded_lsq(a, b, (lo[cols] - x0) / s, (hi[cols] - x0) / s)
        x = x0 + dx * s
        right, left, tl = targets(x)
        fb.cb.tail_controls = tl
        self.flown_u = (cols, x)
        return right, left


def flown_lateral_for(free: bool, track: Any) -> FlownLateral | None:
    """A flight's :class:`FlownLateral`: free flights with :data:`ENABLED`, straight
    (``track`` None) or turning (the turn's gate)."""
    return FlownLateral(track) if ENABLED and free else None


__all__ = [
    "ALPHA",
    "AT_BOUND",
    "CALM_RAD",
    "CALM_STEPS",
    "ENGAGE_ROLL_RAD",
    "MU",
    "STEP",
    "STRAIGHT_RESERVE",
    "WINDOW",
    "FlownLateral",
    "flown_lateral_for",
]
