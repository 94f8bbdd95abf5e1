"""The attitude loop's commands with the attitude free (reduced units, seed body axes):
the body's pitch command filtered from the table's pitch, with its rate and
acceleration to feed forward, and the lateral path loop's bank (roll) command."""

from __future__ import annotations

import math

import numpy as np

from birdsim.flight.attitude import FIT_BEATS, ROLL_BEATS
from birdsim.flight.flight_arrays import fit_matrix
from birdsim.flight.float_ops import clip_float

TWO_PI = 2.0 * math.pi
#: The lateral path loop (attitude free): a side error and velocity ask for a sideways
#: acceleration ``omega_l^2 e_y + 2 omega_l e_vy`` (critically damped, ``omega_l = omega /
#: (2 pi LATERAL_BEATS)``), delivered by banking: roll = atan(a_y / g), at most
#: LATERAL_ROLL_MAX (rad).  Its time constant is LATERAL_PER_ROLL times the roll loop's
#: (:data:`birdsim.flight.attitude.ROLL_BEATS`), so that the roll loop inside it is the
#: faster.  Measured with the roll loop at 1 wingbeat (30 % side gust from wingbeat 3,
#: wingbeats after it until within 0.05 semispan and 2 degrees): lateral 2.5: 10, 3: 7,
#: 3.5: 8, 4: 9 wingbeats; with the lateral integral bounded
#: (:data:`birdsim.flight.attitude.LATERAL_INTEGRAL_RAD`) and the gust from wingbeat 3,
#: 3.25, 3.5, 3.75: lateral 3: 8, 8, 9, 9; 3.5: 8, 8, 8, 8; 4: -, 7, 8, 8
#: (docs/free-body.md, "Gusts").
LATERAL_PER_ROLL = 3.5
LATERAL_BEATS = LATERAL_PER_ROLL * ROLL_BEATS
LATERAL_ROLL_MAX = math.radians(30.0)


def command_filter(
    value: float, rate: float, target: float, tau: float, dt: float, substeps: int = 8
) -> tuple[float, float, float]:
    """One step ``dt`` of the critically damped second-order filter ``a = (target -
    value) / tau^2 - 2 rate / tau`` (semi-implicit Euler substeps): (value, rate,
    acceleration at the end of the step)."""
    if tau <= 0.0:  # no filter: the target, held
        return target, 0.0, 0.0
    h = dt / substeps
    for _ in range(substeps):
        rate += h * ((target - value) / tau**2 - 2.0 * rate / tau)
        value += h * rate
    return value, rate, (target - value) / tau**2 - 2.0 * rate / tau


#: The largest bank of a turn (rad): the centripetal acceleration fed forward may ask for
#: more than a correction's LATERAL_ROLL_MAX.
TURN_ROLL_MAX = math.radians(60.0)


def bank_command(window: list, per_beat: int, gravity: float, a_left_ref: float = 0.0) -> float:
    """The lateral path loop's roll command (rad, seed axes: right wing down > 0) from the
    last wingbeat's samples ``(y, vy)``: the bird's side offset from the path and its
    rate, to the left (MuJoCo y; a straight path has y = 0): the wingbeat-mean offset
    (the trend's value now), the sideways acceleration it asks for
    (:data:`LATERAL_BEATS`) plus the path's own ``a_left_ref`` (a turn's centripetal
    acceleration, to the left), and the bank that tilts by it the force that carries
    ``gravity`` (the weight's acceleration plus the path's vertical one)."""
    if len(window) == 0 or gravity <= 0.0:  # a list of pairs or an (n, 2) array
        return 0.0
    n = FIT_BEATS * per_beat
    yv = np.asarray(window, dtype=float)  # read only
    if len(yv) < n:
        yv = np.vstack([np.repeat(yv[:1], n - len(yv), axis=0), yv])
    y, vy = (fit_matrix(n, TWO_PI)[0] @ yv).tolist()  # floats: numpy scalars' numbers
    w = 1.0 / LATERAL_BEATS  # omega / (2 pi N), reduced units (omega = 1 per 2 pi)
    w = w / TWO_PI
    a_left = a_left_ref - (w * w * y + 2.0 * w * vy)
    bound = LATERAL_ROLL_MAX if a_left_ref == 0.0 else TURN_ROLL_MAX
    # banking right (roll > 0) leans the support to the right, -y
    return clip_float(math.atan2(-a_left, gravity), -bound, bound)  # np.clip's bits


def body_rates(pitch: float, roll: float, pitch_rate: float, yaw_rate: float) -> np.ndarray:
    """The body rates (p, q, r), seed body axes, of the Z-Y-X attitude (yaw, ``pitch``,
    ``roll``) turning at ``yaw_rate`` (about seed z, down) and ``pitch_rate``, the roll
    held: the rates a steady turn's command moves at (Euler kinematics)."""
    return np.array(_rates(pitch, roll, pitch_rate, yaw_rate))


def _rates(pitch: float, roll: float, pitch_rate: float, yaw_rate: float) -> tuple:
    """:func:`body_rates` as three floats."""
    cp, sp = math.cos(pitch), math.sin(pitch)
    cr, sr = math.cos(roll), math.sin(roll)
    return (
        -yaw_rate * sp,
        pitch_rate * cr + yaw_rate * cp * sr,
        -pitch_rate * sr + yaw_rate * cp * cr,
    )


def straight_commands(
    pitch: float,
    roll: float,
    rates: tuple[float, float],
    accs: tuple[float, float],
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A straight path's (rate command, acceleration command, the command's own turning
    rates) for the attitude loop, seed body axes: ``body_rates(pitch, roll, q, 0) +
    [p, 0, 0]`` for the ``rates`` (p, q) of the roll and pitch commands, ``[*accs, 0]``
    for their accelerations, and ``body_rates(pitch, roll, 0, 0)``: those numpy
    expressions' numbers, made of floats."""
    p0, q0, r0 = _rates(pitch, roll, rates[1], 0.0)
    rate_cmd = np.array([p0 + rates[0], q0 + 0.0, r0 + 0.0])
    return rate_cmd, np.array([accs[0], accs[1], 0.0]), body_rates(pitch, roll, 0.0, 0.0)


__all__ = [
    "LATERAL_BEATS",
    "LATERAL_PER_ROLL",
    "LATERAL_ROLL_MAX",
    "TURN_ROLL_MAX",
    "bank_command",
    "body_rates",
    "command_filter",
    "straight_commands",
]
