"""Turning flight's commands, one control step at a time (reduced units; the path in its
track frame, :class:`birdsim.flight.track.TrackFrame`; the attitude of
:mod:`birdsim.flight.bank`).

* **bank**: the path's planned bank ``atan2(-a_lat, g + az)`` (its centripetal
  acceleration tilting the force that carries the weight) with its rate and acceleration
  fed forward, plus the lateral loop's correction (:func:`bank.lateral_acceleration`: a
  triple pole of ``bank.LATERAL_BEATS`` on the wingbeat-mean side offset, with an
  integral), filtered over :data:`BANK_BEATS`;
* **heading**: the path's heading (the body's yaw follows the track; commanding the
  bird's own air-velocity heading instead, zero sideslip by construction, fed the
  lateral error back through the yaw and made a slow oscillation: circle RMS 0.42
  against 0.195 semispan);
* **rates fed forward** from the plan :data:`FF_LEAD` wingbeats ahead: the moments of
  the attitude loop reach the body late (the inputs' smoothing, the wingbeat-mean
  response, the one-wingbeat estimate), measured on the circle (first pass, before the
  attitude gains included the flapping's damping): lead 0, 0.25, 0.5, 0.75 and 1
  wingbeat gave 16-wingbeat path RMS 5.0 (diverging), 1.5, 0.82, 0.25 and 0.24
  semispan; with those gains 0.5 is best (:data:`FF_LEAD`; docs/turning.md).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any

import numpy as np

from birdsim.flight.attitude import AXIS_BEATS, LATERAL_INTEGRAL_RAD, AttitudeLoop, attitude_gains
from birdsim.flight.attitude_commands import command_filter
from birdsim.flight.attitude_reserve import TURN_RESERVE
from birdsim.flight.bank import TurnAttitude, lateral_acceleration, lateral_fit, turn_attitude
from birdsim.flight.path_integral import INTEGRAL_BAND, TURN_INTEGRAL_BAND

TWO_PI = 2.0 * math.pi
#: Time constant (wingbeats) of the filter on the lateral loop's bank correction.
BANK_BEATS = 0.5
#: Largest bank correction (rad, 14 degrees) of the lateral loop about the path's planned
#: bank; the side offset's integral is held while it is reached.  A side gust of 30 %
#: for a wingbeat in the circle rolls the body 16 degrees past its command with the roll
#: inputs at their bounds; the lateral loop then asked 70 degrees of correction, the roll
#: loop (authority-bound against the flapping's damping) lagged it by 30-50 degrees and
#: the flight diverged.  Bounded at 0.25 rad it is back within 0.3 semispan 16 wingbeats
#: after the gust (peak 3.1), none saturated; at 0.15: 3.4 and still 3 semispans off 16
#: wingbeats after.  Undisturbed turns never reach it (circle, s-turn unchanged).
BANK_CORRECTION_MAX = 0.25
#: Wingbeats ahead of now that the plan's body rates and accelerations are fed forward.
#: 0.75 was chosen before the attitude loop's gains were placed for the flapping's
#: measured damping (which is now fed forward on the commanded rates: the loop answers
#: sooner); after that (6-wingbeat ramps, lateral loop 5), leads 0.4, 0.5, 0.6, 0.75,
#: 0.9 gave circle path RMS 0.079, 0.083, 0.081, 0.095, 0.110 and s-turn 0.114, 0.099,
#: 0.111, 0.174, - semispan.
FF_LEAD = 0.5
#: The attitude loop's time constants in a turn (roll, pitch, yaw; wingbeats): the roll
#: loop faster than straight flight's 2 (measured on the circle, lateral loop of 10
#: wingbeats: roll 2 -> path RMS diverging after 20 wingbeats, 1.5 -> 0.76, 1.25 ->
#: 0.47 / 0.195 (with the heading of the path), 1 -> diverging).
TURN_AXIS_BEATS = (1.25, 3.0, 2.0)
#: The attitude loop's time constants in a slow turn (a path with a slow turn,
#: :attr:`birdsim.flight.track.TrackFrame.slow_turn`): the yaw loop slower.  In the
#: lowered posture (:func:`turn_pitch`) the heading's rotation is mostly about the body's
#: z axis, whose authority in flight is about a quarter of the held body's Jacobian
#: (docs/free-body.md); asked at 2 wingbeats the yaw takes the differential inputs the
#: roll needs.  Measured (slow turn, R = 4 / 4.5 semispans, 4-wingbeat ramps, roll 1.25):
#: yaw 2 -> path RMS 0.60 / 0.31, 3 -> 0.25 / -, 4 -> 0.19 / 0.16; then roll 1 instead of
#: 1.25 (R = 5, 5-wingbeat ramps): 0.079 against 0.108 (docs/turning.md).
SLOW_TURN_AXIS_BEATS = (1.0, 3.0, 4.0)
#: Plan the body's pitch command along the turn (:class:`birdsim.flight.pitch_plan.PitchPlan`
#: from the table's pitch for the track's banked-plane force), as straight flight does,
#: instead of filtering the table's pitch over 3 wingbeats (lagging the turn's entry).
#: Measured (lateral loop of 5 wingbeats): s-turn path RMS 0.174 against 0.353, circle
#: 0.095 both, its steady bank's largest miss 4.6 against 5.9 degrees.
TURN_PITCH_PLAN = True


#: The body's pitch in a slow turn (rad, 21 degrees): see :func:`turn_pitch`.
#: (Measured on the seed bird's slow 90-degree turn, R = 4 semispans, 4-wingbeat ramps,
#: the attitude loop of the cruise turns: the body's pitch command lowered by 0.65 / 0.8
#: rad from the table's 58 degrees: heading change 96.5 / 121 degrees, path RMS 0.18 /
#: 0.56; held at 0.30 / 0.37 / 0.45 rad: 0.27 (saturated) / 0.60 / 1.45; the settings of
#: SLOW_TURN_AXIS_BEATS then made 0.37 fly; docs/turning.md.)
SLOW_TURN_PITCH = 0.37
#: Feed the rigid body's gyroscopic moment ``w x (I w)`` of the commanded body rates
#: forward (:func:`turn_command`).  A body turning about the vertical while pitched up
#: and banked rotates about all three of its axes; with unequal principal moments Euler's
#: equations ask ``(I_z - I_x) p r`` of nose-up moment to hold the pitch (the seed bird:
#: ``I = (0.85, 3.29, 3.81)``; the slow turn's body sagged from its 21-degree posture to
#: 15 degrees) and ``(I_y - I_x) p q`` in yaw.  Measured (seed bird, path RMS after two
#: wingbeats, without / with): turn-90 0.0785 / 0.0718, circle 0.0826 / 0.0797, s-turn
#: 0.1073 / 0.1049, u-turn 0.0666 / 0.0484 (docs/turning.md, "Fourth pass").
GYRO_FEEDFORWARD = True
#: The body's pitch swing within a wingbeat (rad, peak to peak, the trim's probe
#: wingbeat: ``FreeBird.start_rocking``) above which a turn takes the straight flight's
#: fourth-stage pitch loop (:func:`fourth_stage_pitch`): the attitude loop's Jacobians
#: are re-measured when the estimated pitch moves by ``attitude.JAC_DPITCH`` (0.1 rad),
#: so a swing larger than that leaks into the one-wingbeat estimate and makes ``M_0``
#: jump with it (docs/free-body.md, "The pigeon's attitude, fourth stage").
ROCKING_LIMIT = 0.1


def fourth_stage_pitch(track: Any, fb: Any) -> bool:
    """Whether a flight on ``track`` (None: straight) takes the fourth-stage pitch loop
    (``AttitudeLoop.straight``: Jacobians at the commanded pitch, the tail's stiffness in
    the gains, the pitch integral bounded by authority, the pitch allocated slow to fast):
    straight flight always; a turn when the body rocks by more than :data:`ROCKING_LIMIT`
    within a wingbeat (``fb.start_rocking``), except a slow turn.

    Why: the seed bird rocks 1.7 (cruise) and 3.7 (V = 0.2) degrees and keeps the second
    stage's loop in its turns (with the fourth: s-turn 0.127 against 0.105 semispan); the
    pigeon rocks 6.6 and 13.9 degrees, and with the second stage's loop its pitch
    alternated by 20-40 degrees from wingbeat to wingbeat in every turn (its cruise turns
    of 23 degrees of bank diverged; with the fourth stage they fly: docs/turning.md).  A
    slow turn keeps the second stage: its lowered posture puts the compensated stroke
    plane within 0.25 rad of its bound, the pigeon's body overshoots the posture by 15
    degrees, the stroke plane clips, and the tail's stiffness the fourth stage's gains
    count on (measured with the stroke plane holding the wings in the world) is not
    there: the body sank nose down with the stroke plane at its bound (turn-90 3.5
    semispans RMS against 0.31)."""
    if track is None:
        return True
    return not track.slow_turn and float(getattr(fb, "start_rocking", 0.0)) > ROCKING_LIMIT


def turn_pitch(
    track: Any, t: float, pitch: tuple[float, float, float]
) -> tuple[float, float, float]:
    """The body's pitch command (value, rate, acceleration) in a turn: the planned
    ``pitch`` lowered towards :data:`SLOW_TURN_PITCH` by the slow turn's posture weight
    ``w`` (:meth:`birdsim.flight.track.TrackFrame.posture`): ``p - w (p - c)`` where the
    plan is steeper than ``c``; the stroke plane takes the difference (the wings beat in
    the world as the table's wingbeat), so the force is the table's.

    Why: at the slow turn's table pitch (55-60 degrees at V = 0.2) a bank about the
    horizontal heading is mostly a rotation about the body's z axis (``sin(pitch)`` of
    it), whose inertia is the largest (3.8 against 0.85 in roll, seed bird) and whose
    authority the smallest: a 48-degree bank over a 3-wingbeat ramp asks about 0.045
    weight x semispan of yaw moment, the differential flap and twist give a few
    thousandths; the body rolled about its steep x axis instead, sideslipped by up to 80
    degrees and left the path.  Lowered, the bank is mostly a roll (``cos(pitch)``)."""
    w, dw, ddw = track.posture(t)
    p, dp, ddp = pitch
    if w <= 0.0 or p <= SLOW_TURN_PITCH:
        return pitch
    e = p - SLOW_TURN_PITCH
    return p - w * e, dp - dw * e - w * dp, ddp - ddw * e - 2.0 * dw * dp - w * ddp


def attitude_loop_for(fb: Any, enabled: bool, track: Any, at_command: bool) -> AttitudeLoop:
    """The attitude loop of a flight on ``track`` (None: straight), with the time
    constants of :func:`axis_beats` and, where ``at_command`` (``freeflight.JAC_AT_COMMAND``)
    and :func:`fourth_stage_pitch` say so, the fourth-stage pitch loop
    (``AttitudeLoop.straight``); a turn's allocation has the reserve of
    :mod:`birdsim.flight.attitude_reserve` (``AttitudeLoop.reserve``)."""
    att = AttitudeLoop(fb, enabled=enabled, **axis_beats(track))
    att.straight = at_command and fourth_stage_pitch(track, fb)
    if track is not None:  # wider lateral bounds where the loop's own leave it short
        att.reserve = TURN_RESERVE
        att.per_inertia = not track.slow_turn  # roll and yaw weighed per unit inertia
    return att


def axis_beats(track: Any) -> dict[str, Any]:
    """The attitude loop's time constants for a flight on ``track`` (None: straight
    flight, the loop's own), as keyword arguments of ``AttitudeLoop``; a turn keeps the
    roll and yaw integrals' full bound (its bank and yaw rate leave a bias to trim;
    straight flight bounds them by ``attitude.LATERAL_INTEGRAL_RAD``)."""
    if track is None:
        return {}
    beats = SLOW_TURN_AXIS_BEATS if track.slow_turn else TURN_AXIS_BEATS
    return {"beats": beats, "lateral_integral_rad": None}


def integral_band(track: Any, att: AttitudeLoop) -> float:
    """The path integral's band (semispans, ``path_integral.within_band``) of a flight on
    ``track`` (None: straight) with the attitude loop ``att``: :data:`TURN_INTEGRAL_BAND`
    in a cruise turn on the second-stage pitch loop (``att.straight`` False: a bird that
    does not rock, the seed bird), else straight flight's :data:`INTEGRAL_BAND`.

    Why not every turn: the pigeon's cruise turns (the fourth-stage loop) fly 0.2 semispan
    RMS off their path, and its integral trims the table's mismatch there: its s-turn
    flew 0.298 m with 64 saturated samples with the band 0.03 (0.0668 m, none, with 0.1;
    0.2: 0.135 m, 72); the slow turns (turn-90, u-turn) keep theirs (docs/turning.md,
    "Gust stage, tenth pass")."""
    if track is None or track.slow_turn or att.straight:
        return INTEGRAL_BAND
    return TURN_INTEGRAL_BAND


#: A track's plan is straight at t when its bank and bank rate are below this (rad, rad
#: per time unit) now and FF_LEAD ahead (:func:`lateral_integral_bound`).
STRAIGHT_BANK_TOL = 1e-6


def lateral_integral_bound(track: Any, t: float) -> float | None:
    """The roll and yaw integrals' bound (``AttitudeLoop.lateral_integral_rad``) on
    ``track`` at ``t``: straight flight's :data:`attitude.LATERAL_INTEGRAL_RAD` where the
    plan is straight now and :data:`FF_LEAD` ahead (no bank to trim), else None (a turn
    keeps the full bound: its bank and yaw rate leave a bias to trim).

    Why: after a turn the pigeon flew straight on with the turn's unbounded lateral
    integrals and a roll-yaw oscillation of about 5.5 wingbeats grew from the roll-out
    until the differential inputs saturated (90 degrees on R = 50 then 40 wingbeats
    straight: diverged at wingbeat 47.8; bounded from the roll-out: path RMS 0.0118, none
    saturated).  The same loop on a straight track at heading 0 with a 10 % side gust
    diverged too (no turn, no heading change) and flew back with the bound
    (docs/turning.md, "Straight flight after a turn")."""
    for tt in (t, t + FF_LEAD * TWO_PI):
        bank = track.bank_plan(tt)[1]
        if abs(bank[0]) > STRAIGHT_BANK_TOL or abs(bank[1]) > STRAIGHT_BANK_TOL:
            return None
    return LATERAL_INTEGRAL_RAD


#: On a track's straight parts a bird on the fourth-stage pitch loop (``att.straight``:
#: one that rocks, the pigeon) takes straight flight's time constants
#: (``attitude.AXIS_BEATS``: roll 1 wingbeat against the turn's 1.25).  Measured (pigeon,
#: 90 degrees at 0.5 omega s on R 55 started 1.91 / 2.86 wingbeats after wingbeat 20,
#: then straight to 81; the flock's centreline birds): with the integrals' bound only,
#: diverged (4.1 / 5.3 m RMS); with these too 0.0122 / 0.0233 m, none saturated.  The
#: seed bird keeps the turn's (its presets with them: turn-90 0.0917 against 0.0684).
STRAIGHT_PART_BEATS = True
#: ... and in its turns (not slow ones) :data:`FOURTH_STAGE_TURN_BEATS`.  Measured
#: (pigeon, m3, free; 360 degrees at 0.5 omega s, 6-wingbeat ramps; path RMS after two
#: wingbeats): with the turn's (1.25, 3, 2) R 50 diverged inside the turn (the
#: wingbeat-mean pitch swinging about its command with a period of about 4 wingbeats,
#: growing from 5 to 30 degrees, the roll error following it, the differential inputs at
#: their bounds from wingbeat 30): 12.0 m; (1, 3, 2) 9.9 m; (1.25, 2, 2) 31 m; (1.25,
#: 2.5, 2) 45 m; (1, 2, 2) 0.0092 m but the flock preset's bird 3 (inner, second row)
#: diverged (1.2 semispans); (1, 2.5, 2) R 50 0.0095 m, R 35 6.5 m; (1, 2.25, 2) R 40 /
#: 45 / 50 / 70 0.0122 / 0.0107 / 0.0094 / 0.0064 m, none saturated, the flock preset's
#: worst 0.0256 semispan (docs/turning.md, "The pigeon's long turns").
FOURTH_STAGE_TURN_BEATS = True
#: The fourth-stage bird's time constants in a turn (roll, pitch, yaw; wingbeats).  The
#: pitch's 2.25 was chosen before the flown-lateral gate (:data:`FOURTH_STAGE_FLOWN_LATERAL`)
#: made the pigeon's circle fly; with the gate, pitch 2.25 / 2.4 / 2.5 / 2.6 / 3 gave the
#: ``circle`` 0.0636 (8 saturated samples) / 0.0332 / 0.0351 / 0.0373 / 0.088 m, the
#: ``s-turn`` 0.0723 / 0.0749 / 0.0664 / 0.0707 / 0.0945 m, R -25 / 30 / 35 0.047 / 0.061
#: (32) -> 0.039 / 0.060 / 0.032 m (2.25 -> 2.5; docs/turning.md, "The pigeon's cruise
#: turns: the pitch loop's time constant").
FOURTH_STAGE_TURN_AXIS_BEATS = (1.0, 2.5, 2.0)


def straight_parts(att: AttitudeLoop, track: Any, t: float) -> None:
    """Set ``att`` for ``track`` at ``t``: the roll and yaw integrals' bound of
    :func:`lateral_integral_bound`, and, for a bird on the fourth-stage pitch loop,
    straight flight's time constants on the straight parts (:data:`STRAIGHT_PART_BEATS`)
    and :data:`FOURTH_STAGE_TURN_AXIS_BEATS` in the turns (:data:`FOURTH_STAGE_TURN_BEATS`)."""
    bound = lateral_integral_bound(track, t)
    att.lateral_integral_rad = bound
    if STRAIGHT_PART_BEATS and att.straight and not track.slow_turn:
        turn = FOURTH_STAGE_TURN_AXIS_BEATS if FOURTH_STAGE_TURN_BEATS else TURN_AXIS_BEATS
        beats = AXIS_BEATS if bound is not None else turn
        if getattr(att, "axis_beats", TURN_AXIS_BEATS) != beats:
            att.axis_beats, att.gains = beats, attitude_gains(att.fb.red.omega, beats)


#: The fourth-stage bird (``att.straight`` in a turn: the pigeon) hands its lateral inputs
#: to :mod:`birdsim.flight.flown_lateral`'s prediction in its cruise turns too, with the
#: loop's roll and yaw integral held while it does (straight flight's anti-windup).
#: Measured (pigeon, m3, free; 360 degrees at 0.5 omega s, 6-wingbeat ramps, path RMS
#: after two wingbeats in m, saturated samples): without it R 25 (the ``circle``) / R -25
#: / 30 / 35 diverged (38.6 / 38.7 / 39.6 / 7.0: the differential inputs on their bounds
#: from the roll-in's end, the held-body loop asking on, the roll running away at wingbeat
#: 12-13); with it 0.064 (8) / 0.047 / 0.061 (32) / 0.024; the s-turn 0.0668 -> 0.0723
#: (docs/turning.md, "The pigeon's cruise turns on the flown prediction").
FOURTH_STAGE_FLOWN_LATERAL = True


def flown_lateral_loop(att: AttitudeLoop, turn: bool) -> bool:
    """Whether :mod:`birdsim.flight.flown_lateral`'s gate may engage on the attitude loop
    ``att`` of a straight (``turn`` False) or turning flight: straight flight's loop (the
    fourth stage, ``att.straight``); in a turn the second-stage loop (the seed bird, the
    slow turns) and, with :data:`FOURTH_STAGE_FLOWN_LATERAL`, the fourth-stage one (the
    pigeon's cruise turns)."""
    if not turn:
        return bool(att.straight)
    return not att.straight or FOURTH_STAGE_FLOWN_LATERAL


def turn_command(
    track: Any,
    t: float,
    lat_window: list,
    per_beat: int,
    gravity: float,
    filter_state: tuple[float, float],
    dt: float,
    pitch: tuple[float, float, float],
    lat_integral: list[float],
    inertia: np.ndarray | None = None,
) -> tuple[TurnAttitude, float, tuple[float, float]]:
    """The turning attitude command at reduced time ``t``: ``lat_window`` the last
    wingbeat's (side offset, its rate) samples (to the left of the path), ``pitch`` the
    body's pitch command (value, rate, acceleration), ``filter_state`` the bank
    correction's filter (value, rate) and ``lat_integral`` (one number, updated here)
    the integral of the side offset; ``inertia`` the body's principal moments (seed body
    axes) for the gyroscopic feed-forward (:data:`GYRO_FEEDFORWARD`).  Returns the command, the commanded sideways
    acceleration (to the left; the force in the banked plane carries it) and the
    filter's new state."""
    heading, bank_ff = track.bank_plan(t)
    st = track.state(t)
    y, vy = lateral_fit(lat_window, per_beat)
    lat_integral[0] += dt * y
    a_left = st.a_lat + lateral_acceleration(y, vy, lat_integral[0])
    up = gravity + st.az_up
    target = math.atan2(-a_left, up) - math.atan2(-st.a_lat, up)
    if abs(target) > BANK_CORRECTION_MAX:  # a bank the roll loop can reach (anti-windup)
        target = math.copysign(BANK_CORRECTION_MAX, target)
        lat_integral[0] -= dt * y
    value, rate, _ = command_filter(*filter_state, target, BANK_BEATS * TWO_PI, dt)
    cmd = turn_attitude(heading, (bank_ff[0] + value, bank_ff[1] + rate, bank_ff[2]), pitch)
    if FF_LEAD > 0.0:
        h2, b2 = track.bank_plan(t + FF_LEAD * TWO_PI)
        ahead = turn_attitude(h2, (b2[0] + value, b2[1] + rate, b2[2]), pitch)
        cmd = replace(cmd, rate=np.asarray(ahead.rate), acc=np.asarray(ahead.acc))
    if GYRO_FEEDFORWARD and inertia is not None:
        cmd = replace(cmd, acc=cmd.acc + gyroscopic_acceleration(cmd.rate, inertia))
    return cmd, a_left, (value, rate)


def ahead(
    track: Any, t: float, bank: tuple[float, float], pitch: tuple[float, float]
) -> Callable[[np.ndarray], np.ndarray]:
    """The turning attitude command ahead of reduced time ``t``, for
    :mod:`birdsim.flight.flown_lateral`'s prediction: a function of the times ahead
    (wingbeats, (n,)) to the Z-Y-X (pitch, roll, yaw) commands (rad, (n, 3)) of
    :func:`turn_command`, the path's heading and planned bank followed, the bank
    correction ``bank`` and the body's pitch ``pitch`` (value, rate) extrapolated."""

    def at(beats: np.ndarray) -> np.ndarray:
        rows = []
        for tau in np.asarray(beats, dtype=float) * TWO_PI:
            heading, bank_ff = track.bank_plan(t + tau)
            phi = (bank_ff[0] + bank[0] + bank[1] * tau, 0.0, 0.0)
            c = turn_attitude(heading, phi, (pitch[0] + pitch[1] * tau, 0.0, 0.0))
            rows.append((c.pitch, c.roll, c.yaw))
        return np.array(rows)

    return at


def gyroscopic_acceleration(rate: np.ndarray, inertia: np.ndarray) -> np.ndarray:
    """The rigid body's gyroscopic term ``(w x (I w)) / I`` (per axis, per unit
    inertia; body rates ``w`` and principal moments ``I`` in the same body axes): Euler's
    equations ``I dw/dt + w x (I w) = M``, so the moment that turns the body at ``w(t)``
    is ``I (dw/dt + this)``; the attitude loop multiplies its acceleration command by
    ``I``."""
    i = np.asarray(inertia, dtype=float)
    w = np.asarray(rate, dtype=float)
    return np.cross(w, i * w) / i


__all__ = [
    "BANK_BEATS",
    "BANK_CORRECTION_MAX",
    "FF_LEAD",
    "FOURTH_STAGE_FLOWN_LATERAL",
    "FOURTH_STAGE_TURN_AXIS_BEATS",
    "FOURTH_STAGE_TURN_BEATS",
    "GYRO_FEEDFORWARD",
    "ROCKING_LIMIT",
    "TURN_AXIS_BEATS",
    "SLOW_TURN_AXIS_BEATS",
    "SLOW_TURN_PITCH",
    "STRAIGHT_BANK_TOL",
    "STRAIGHT_PART_BEATS",
    "TURN_PITCH_PLAN",
    "ahead",
    "attitude_loop_for",
    "flown_lateral_loop",
    "axis_beats",
    "fourth_stage_pitch",
    "gyroscopic_acceleration",
    "integral_band",
    "lateral_integral_bound",
    "straight_parts",
    "turn_command",
    "turn_pitch",
]
