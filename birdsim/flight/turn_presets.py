"""The turning presets as paths (issue 23 item 3), flown by ``birdsim fly`` (attitude free).

Speed-and-heading paths (:class:`birdsim.flight.path.FlightPath`, speed form) in reduced
units, like the straight presets of :mod:`birdsim.flight.presets` and kept apart from them
(the straight presets' lists and figures are untouched); ``birdsim fly`` finds them by
name and flies them with the attitude free (:mod:`birdsim.flight.turning`).

Every turn is a *coordinated-turn template*: the heading ramps from a turn rate of 0 to
``omega_t = V / R`` over :data:`RAMP_BEATS` wingbeats (a smoothstep turn rate: the
heading's quintic with slopes 0 and ``omega_t`` and a heading change ``omega_t h / 2``,
so the turn rate is ``omega_t s^2 (3 - 2 s)``), turns at the constant rate, and ramps
back, all at constant speed; a turn is therefore an arc of radius R with two short
spiral transitions, and its centripetal acceleration ``V omega_t = V^2 / R`` asks for a
bank ``atan(V^2 / (R g))``.

* ``turn-90``: a level 90-degree turn to the left at slow speed, after the corridor turns
  of Ros et al. 2011 (PNAS 108:19990; pigeons at about 3-4 m/s, radius about 1 m):
  :data:`SLOW_SPEED` 0.2 omega s (3.3 m/s for the pigeon), :data:`SLOW_RADIUS` 5 s
  (1.65 m; the issue's 3 s, about 1 m, does not fly yet: docs/turning.md); centripetal
  acceleration 0.008 omega^2 s = 0.67 g of the seed bird and the pigeon (bank about 34
  degrees).
* ``circle``: a level 360-degree circle to the left at cruise speed (0.5 omega s) and
  radius :data:`CIRCLE_RADIUS` 25 s (8.3 m for the pigeon; 0.83 g, bank about 40
  degrees); by the symmetry of the ramps the track leaves the loop on the line and
  heading it entered on.
* ``s-turn``: at cruise speed, 45 degrees to the left then 45 to the right (radius 25 s),
  ending on the first heading, offset to the left.
* ``u-turn``: from rest on the perch, out at slow speed, a keyhole turn (right by
  :data:`U_TURN_THETA`, left by 180 + 2 theta degrees, right by theta; radius
  :data:`SLOW_RADIUS`) and back to rest on the perch it left, facing the other way.
  theta (about 60 degrees) and the outbound straight are solved so that the path ends on
  the perch to round-off.
"""

from __future__ import annotations

import math

from scipy.optimize import brentq

from birdsim.flight.path import PERCH_X, PERCH_Z, FlightPath, PathKeyframe
from birdsim.flight.presets import CRUISE_HEIGHT, CRUISE_SPEED

TWO_PI = 2.0 * math.pi
#: Slow turning speed (omega s) and radius (semispans): Ros et al. 2011's pigeon turns.
SLOW_SPEED = 0.2
SLOW_RADIUS = 5.0
#: Radius of the cruise-speed circle and s-turn (semispans).
CIRCLE_RADIUS = 25.0
#: Wingbeats of each turn-rate ramp (slow turns, cruise turns): long enough for the free
#: body's roll (1.5 and 2 asked more roll rate than its inputs give; docs/turning.md).
#: Cruise turns 6: with the attitude loop's gains placed for the flapping's roll damping
#: (0.45 per unit inertia, 3.6 times the turn's roll pole) the moment that damping asks
#: at a 4-wingbeat ramp's roll rate (1.4e-2 x inertia) saturates the differential inputs
#: and the s-turn's reversal diverged (path RMS 1.12, 4 saturated wingbeats); ramps of
#: 5 and 6 wingbeats: 0.38 and 0.18, none saturated (docs/turning.md).
RAMP_BEATS = 5.0
CRUISE_RAMP_BEATS = 6.0
#: Straight flight before the first and after the last turn (wingbeats).
STRAIGHT_BEATS = 2.0

_K = PathKeyframe


def turn_keyframes(
    t0: float, psi0: float, delta: float, speed: float, radius: float, ramp_beats: float, z: float
) -> list[PathKeyframe]:
    """The keyframes of one turn by ``delta`` rad (positive to the left) from heading
    ``psi0`` at time ``t0`` [wingbeats], at constant ``speed`` [omega s], radius
    ``radius`` [s] and height ``z`` [s]: start, end of the ramp in, start of the ramp
    out, end (turn rates 0, w, w, 0 with w = +-speed / radius).

    Raises:
        ValueError: the turn is shorter than its two ramps.
    """
    rate = speed / radius
    h = ramp_beats * TWO_PI
    ramp = 0.5 * rate * h  # heading change of one smoothstep ramp
    if abs(delta) < 2.0 * ramp:
        raise ValueError(f"turn of {delta:g} rad is shorter than its ramps (2 x {ramp:g} rad)")
    sign = math.copysign(1.0, delta)
    steady_beats = (abs(delta) - 2.0 * ramp) / rate / TWO_PI
    t1 = t0 + ramp_beats
    t2 = t1 + steady_beats
    return [
        _K(t0, z, V=speed, heading=psi0, turn_rate=0.0),
        _K(t1, z, V=speed, heading=psi0 + sign * ramp, turn_rate=sign * rate),
        _K(t2, z, V=speed, heading=psi0 + delta - sign * ramp, turn_rate=sign * rate),
        _K(t2 + ramp_beats, z, V=speed, heading=psi0 + delta, turn_rate=0.0),
    ]


def turns_keyframes(
    t0: float, deltas: list[float], speed: float, radius: float, ramp_beats: float, z: float
) -> list[PathKeyframe]:
    """Turns one after the other from heading 0 at ``t0`` (each starts where the last ends)."""
    out: list[PathKeyframe] = []
    psi = 0.0
    for delta in deltas:
        ks = turn_keyframes(t0, psi, delta, speed, radius, ramp_beats, z)
        out.extend(ks if not out else ks[1:])
        t0, psi = ks[-1].t, psi + delta
    return out


def level_turns(
    name: str, deltas: list[float], speed: float, radius: float, ramp: float, text: str
) -> FlightPath:
    """A level path of turns by ``deltas`` (rad, positive to the left) at ``speed``
    [omega s] on ``radius`` [semispans] with ``ramp``-wingbeat turn-rate ramps, at the
    cruise height, with :data:`STRAIGHT_BEATS` of straight flight before and after (the
    first turn starts at x = 0); the shape of ``turn-90``, ``circle`` and ``s-turn``."""
    ks = turns_keyframes(STRAIGHT_BEATS, deltas, speed, radius, ramp, CRUISE_HEIGHT)
    first = _K(0.0, CRUISE_HEIGHT, V=speed, heading=0.0, turn_rate=0.0, regime="straight")
    ks[0] = _K(ks[0].t, ks[0].z, V=speed, heading=0.0, turn_rate=0.0, regime="turn")
    last = ks[-1]
    ks[-1] = _K(last.t, last.z, V=speed, heading=last.heading, turn_rate=0.0, regime="straight")
    x0 = -speed * STRAIGHT_BEATS * TWO_PI  # the first turn starts at x = 0
    return FlightPath(name, ks[-1].t + STRAIGHT_BEATS, False, False, (first, *ks), text, x0=x0)


#: The u-turn's take-off (0 -> SLOW_SPEED) and braking (the landing preset's last 17
#: wingbeats, scaled to start at SLOW_SPEED): (wingbeats from the start of the phase, V, z).
U_TAKE_OFF = ((0.0, 0.0, PERCH_Z), (9.0, SLOW_SPEED, 2.0))
U_BRAKING = ((0.0, SLOW_SPEED, 2.0), (5.0, 0.12, 1.8), (10.0, 0.04, 1.7), (16.0, 0.0, PERCH_Z))
#: Straight flight at slow speed before the keyhole and after it (wingbeats, before the
#: outbound one is lengthened to bring the bird back to its perch).
U_STRAIGHT = 1.0
#: Straight flight at slow speed between the keyhole and the braking (wingbeats): the
#: lateral loop settles the keyhole's exit in the slow-turn posture (held
#: ``track.POSTURE_HOLD_BEATS`` after the turn) before the braking pitches the body up to
#: 80 degrees, where a bank is mostly a rotation about the body's z axis again
#: (measured: 1 wingbeat -> path RMS 1.17, drifting 5 semispans sideways in the braking;
#: 5 with the posture held 4 -> 0.44; 7 and 6 -> 0.18; docs/turning.md).
U_BACK = 7.0
U_RAMP_BEATS = RAMP_BEATS


def _u_turn(theta: float, out_beats: float, perch: bool) -> FlightPath:
    v, r, zt = SLOW_SPEED, SLOW_RADIUS, U_TAKE_OFF[-1][2]
    ks = [_K(t, z, V=s, heading=0.0, regime="take-off" if t == 0 else "") for t, s, z in U_TAKE_OFF]
    t0 = U_TAKE_OFF[-1][0] + out_beats
    # the side turns at the keyhole's rate, their ramps as long as the angle lets them
    # (a steady part of 5 % of it), the middle one with the slow turns' ramps
    # the side turns with the slow turns' ramps: on a wider radius, their steady part 5 %
    # of the angle (on the keyhole's radius their ramps would be 2.5 wingbeats: path RMS
    # 0.18 against 0.067)
    side, r_side = U_RAMP_BEATS, v * 1.05 * U_RAMP_BEATS * TWO_PI / theta
    turn = turn_keyframes(t0, 0.0, -theta, v, r_side, side, zt)
    turn += turn_keyframes(turn[-1].t, -theta, math.pi + 2 * theta, v, r, U_RAMP_BEATS, zt)[1:]
    turn += turn_keyframes(turn[-1].t, math.pi + theta, -theta, v, r_side, side, zt)[1:]
    turn[0] = _K(turn[0].t, zt, V=v, heading=0.0, turn_rate=0.0, regime="keyhole turn")
    ks += turn
    tb = turn[-1].t + U_BACK
    for i, (dt, s, z) in enumerate(U_BRAKING):
        label = ("braking", "", "approach", "perched")[i]
        ks.append(_K(tb + dt, z, V=s, heading=math.pi, regime=label))
    return FlightPath(
        "u-turn",
        ks[-1].t + 1.0,
        perch,
        perch,
        tuple(ks),
        "from rest on the perch: out at slow speed, a keyhole turn, back to rest on the perch",
        x0=PERCH_X,
    )


def _solve_u_turn() -> tuple[float, float]:
    """(theta, outbound straight [wingbeats]) that bring the u-turn back onto its perch:
    theta closes y (the keyhole's sideways offset, 0 at 60 degrees for circular arcs),
    the straight closes x (the path is linear in its length)."""

    def end(theta: float, out: float) -> tuple[float, float]:
        p = _u_turn(theta, out, perch=False)
        s = p.state(p.keyframes[-1].t * TWO_PI)
        return s.x - PERCH_X, s.y

    theta = brentq(lambda th: end(th, U_STRAIGHT)[1], 0.3, 1.3, xtol=1e-15, rtol=1e-15)
    dx = end(theta, U_STRAIGHT)[0]
    out = U_STRAIGHT - dx / (SLOW_SPEED * TWO_PI)
    if out < U_STRAIGHT:  # the take-off covers more ground than the braking: never here
        raise RuntimeError(f"u-turn: outbound straight {out:g} wingbeats; re-lay the braking")
    return theta, out


def _presets() -> dict[str, FlightPath]:
    quarter = 0.5 * math.pi
    turn_90 = level_turns(
        "turn-90",
        [quarter],
        SLOW_SPEED,
        SLOW_RADIUS,
        RAMP_BEATS,
        f"a level 90-degree turn to the left at V = {SLOW_SPEED:g} omega s, radius "
        f"{SLOW_RADIUS:g} semispans (Ros et al. 2011's pigeon turns)",
    )
    circle = level_turns(
        "circle",
        [TWO_PI],
        CRUISE_SPEED,
        CIRCLE_RADIUS,
        CRUISE_RAMP_BEATS,
        f"a level 360-degree circle to the left at cruise speed, radius {CIRCLE_RADIUS:g} "
        "semispans",
    )
    s_turn = level_turns(
        "s-turn",
        [0.25 * math.pi, -0.25 * math.pi],
        CRUISE_SPEED,
        CIRCLE_RADIUS,
        CRUISE_RAMP_BEATS,
        "at cruise speed: 45 degrees to the left, then 45 to the right, back on the first heading",
    )
    u_turn = _u_turn(*U_TURN_SOLUTION, perch=True)
    return {p.name: p for p in (turn_90, circle, s_turn, u_turn)}


#: The u-turn's keyhole angle theta [rad] and outbound straight [wingbeats].
U_TURN_SOLUTION: tuple[float, float] = _solve_u_turn()
U_TURN_THETA = U_TURN_SOLUTION[0]
#: The turning presets by name (not in ``PATH_PRESETS``: the straight presets' lists and
#: figures stay as they were; ``path_file.get_flight(name, turning=True)`` finds them).
TURN_PRESETS: dict[str, FlightPath] = _presets()

__all__ = [
    "CIRCLE_RADIUS",
    "SLOW_RADIUS",
    "SLOW_SPEED",
    "TURN_PRESETS",
    "U_TURN_THETA",
    "level_turns",
    "turn_keyframes",
    "turns_keyframes",
]
