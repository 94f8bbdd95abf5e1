"""The air path's angle in the attitude loop's held-body measurements (docs/free-body.md,
"The pigeon's attitude, twelfth stage").

The path loop reads its level-flight table along the air path: flying along an air path
inclined by ``gamma`` is level flight turned by ``gamma``, and the table's pitch plus
``gamma`` is the body's commanded pitch (:meth:`birdsim.flight.controller.Controller.lookup`).
The attitude loop measures its model (``M_0``, the Jacobians, the rate derivatives, the
pitch stiffness, the rocking's rectified moment) on the body held at the command, and it
held it in horizontal air: in a climb, the table's body turned nose up by ``gamma``
against its air.  While the slow straight flight's loop (:mod:`birdsim.flight.pitch_section`)
is on, the body is held turned back by the air path's angle, so that the wings and the
tail meet the air at the angle they meet it in flight (the wingbeat's parameters are the
body's and stay; the airspeed stays the loop's forward one); the other loops keep
horizontal air (in every loop the pigeon's landing diverged).  The pigeon's take-off
climbs at up to 10.8 degrees in wingbeats 11-16, where the model measured in horizontal
air missed 0.0016-0.0033 table units of nose-down moment a wingbeat (at wingbeat 14.5 the
held body's moment with the rocking's is 0.0017 more nose-down at the 10.3 degree path).

The slow loop's gate (on while the tail has no pitch stiffness) keeps reading the
stiffness at the command in horizontal air, as before (:func:`gate_stiffness`): at the
air angle the tail restores from wingbeat 15 of the take-off, mid-climb (flap amplitude
1.24 rad), and the fourth-stage loop then swung the climb's rocking body by -5.8, +6.8
and -10.5 degrees (wingbeats 17, 21, 24).  Reduced units, radians, pitch nose up,
``gamma`` > 0 climbing.
"""

from __future__ import annotations

from typing import Any

from birdsim.flight.attitude_stiffness import measured_pitch_stiffness
from birdsim.flight.demand import air_path_angle

#: Measure the attitude loop's model at the air path's angle (else in horizontal air).
AIR_ANGLE = True


def straight_air_angle(ref: Any, est: Any, wind: tuple[float, float]) -> float:
    """The angle (rad) of the air path along which the path loop's lookup reads its level
    table in straight flight (:meth:`birdsim.flight.controller.Controller.command` and
    ``lookup``): the reference state ``ref``'s velocity (``vx``, ``vz``) corrected by the
    error estimate ``est`` (:meth:`birdsim.flight.controller.ErrorWindow.estimate`; None:
    the reference's own) less the wind ``(wx, wz)``; 0 without :data:`AIR_ANGLE`."""
    if not AIR_ANGLE:
        return 0.0
    if est is None:
        vx, vz = float(ref.vx), float(ref.vz)
    else:
        vx, vz = float(est[2]), float(ref.vz) - float(est[1][1])
    return float(air_path_angle(vx - wind[0], vz - wind[1]))


def held(att: Any, pitch: float) -> float:
    """The pitch (rad) of the body held for the attitude loop ``att`` at the commanded
    ``pitch``: turned back by its ``air_angle``."""
    return pitch - float(att.air_angle)


def held_air(att: Any, params: Any, pitch: float, speed: float) -> float:
    """:func:`held` for a measurement of ``att``'s model, kept with the airspeed ``speed``
    as ``att.held_at``.  With a nonzero angle in straight flight the pitch stiffness at
    the command in horizontal air (``params`` the wingbeat) goes to ``att.gate_stiffness``
    for :func:`gate_stiffness` (None otherwise)."""
    att.gate_stiffness = None
    if att.air_angle != 0.0 and att.straight:
        att.gate_stiffness = max(-measured_pitch_stiffness(att.fb, params, pitch, speed), 0.0)
    att.held_at = (held(att, pitch), speed)
    return att.held_at[0]


def gate_stiffness(att: Any) -> float:
    """The pitch stiffness (table units per rad, >= 0) the slow loop's gate reads: the
    horizontal air's of the last measurement (:func:`held_pitch`), else the loop's own."""
    gate = getattr(att, "gate_stiffness", None)
    return float(att.stiffness[1]) if gate is None else float(gate)


__all__ = ["AIR_ANGLE", "gate_stiffness", "held", "held_air", "straight_air_angle"]
