"""The path loop's vertical correction carried in a turn's banked force (reduced units;
accelerations per unit mass, up and to the left of the path's track frame).

In a banked turn the force's magnitude is ``hypot(g + az, a_left)`` at the bank
``atan2(-a_left, g + az)`` (``turning.turn_command``), and the path loop adds its vertical
correction ``dv`` (``Controller.command``) to the magnitude only: a push up of ``dv``
then comes out ``dv cos(bank)`` up and ``dv sin(bank)`` into the turn, against the lateral
loop (docs/turning.md, "The calm circle's swing", p23y).  A share
:data:`VERTICAL_SHARE` of the correction's proportional and rate terms is carried in the
force vector instead: bank ``atan2(-a_left, g + az + s dv)``, magnitude ``hypot(g + az
+ s dv, a_left)`` plus the rest ``(1 - s) dv`` and the integral term.  Where the bank is
zero (``a_left = 0``) the force is the same at every share.
"""

from __future__ import annotations

import math
from typing import Any

#: Share ``s`` of the path loop's vertical proportional and rate correction carried in
#: the banked force vector (0: all of it on the magnitude, main's).
VERTICAL_SHARE = 0.0

#: The lateral loop's integral (p23y's untried idea: kept in units of the planned bank so
#: that a steady turn's trim goes with the bank at the roll-out): "sum" (main's: the sum
#: of ``dt y``), "bank" (its term ``J sin(bank_plan)``, ``J`` summing ``dt y /
#: sin(bank_plan)``, held below :data:`BANK_SIN_MIN`), "fade" (main's sum, scaled down
#: by ``|sin(bank_plan)|``'s ratio to its value a step before wherever that falls).
LATERAL_MODE = "sum"
#: "fade"'s power of the ratio (1: the integral in proportion to the bank's sine).
FADE_POWER = 1.0
#: Below this ``|sin(bank_plan)|`` the integral in bank units is held (straight parts).
BANK_SIN_MIN = 0.1


def lateral_integral_step(
    lat_integral: list[float], dt: float, y: float, bank: float, bank_before: float = 0.0
) -> tuple[float, float]:
    """Add the side offset ``y`` (semispans, to the left) over ``dt`` to the lateral
    integral ``lat_integral`` (one number, updated here) at the plan's bank ``bank`` (rad;
    ``bank_before`` a step before, for "fade"); returns the increment (to undo it,
    anti-windup) and the integral term for ``bank.lateral_acceleration`` (semispan time
    units), as :data:`LATERAL_MODE` says."""
    if LATERAL_MODE == "bank":
        sb = math.sin(bank)
        inc = dt * y / sb if abs(sb) > BANK_SIN_MIN else 0.0
        lat_integral[0] += inc
        return inc, lat_integral[0] * sb
    if LATERAL_MODE == "fade":
        now, before = abs(math.sin(bank)), abs(math.sin(bank_before))
        if now < before:
            lat_integral[0] *= (now / before) ** FADE_POWER
    lat_integral[0] += dt * y
    return dt * y, lat_integral[0]


def banked_az(
    az_up: float, a_left: float, gravity: float, ctl: Any, est: Any
) -> tuple[float, float]:
    """The vertical acceleration (up, reduced) to hand ``ctl.command`` for a turn's force
    at the path's vertical acceleration ``az_up`` and the commanded sideways one
    ``a_left`` (to the left), with the error estimate ``est`` (``ErrorWindow.estimate()``,
    None: none) and ``gravity``; and the shared vertical correction ``s dv`` (reduced
    acceleration, up) that the bank carries (:func:`bank_target`).  ``ctl.command`` adds
    the whole correction ``dv`` back, so the magnitude is ``hypot(g + az_up + s dv,
    a_left) + (1 - s) dv`` plus the integral term."""
    s_dv = 0.0
    if VERTICAL_SHARE != 0.0 and est is not None and not ctl.open_loop:
        ep, ev = est[0], est[1]
        s_dv = VERTICAL_SHARE * (ctl.gains.kp * float(ep[1]) + ctl.gains.kd * float(ev[1]))
    return math.hypot(az_up + gravity + s_dv, a_left) - gravity - s_dv, s_dv


def bank_target(a_left: float, a_lat: float, up: float, s_dv: float = 0.0) -> float:
    """The bank correction (rad) about the path's planned bank ``atan2(-a_lat, up)`` for
    the commanded sideways acceleration ``a_left`` (to the left), ``up`` the force's
    planned vertical part ``g + az`` and ``s_dv`` the shared vertical correction
    (:func:`banked_az`)."""
    return math.atan2(-a_left, up + s_dv) - math.atan2(-a_lat, up)


__all__ = [
    "BANK_SIN_MIN",
    "FADE_POWER",
    "LATERAL_MODE",
    "VERTICAL_SHARE",
    "bank_target",
    "banked_az",
    "lateral_integral_step",
]
