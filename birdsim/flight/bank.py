"""Bank to turn: the turning attitude command (reduced units, seed axes: x forward, y
right, z down; earth axes x, y right, z down, so the seed yaw is minus the world heading).

A bird turns by rolling its wingbeat-mean force, which stays nearly fixed in the body
(Ros et al. 2011, PNAS 108:19990).  The symmetric table gives that force for a body at
the table's pitch in air coming along the body's symmetry plane.  Banked about the *air
velocity* (horizontal, along the heading, in a level turn) the whole bird turns rigidly
about the air's direction: the air seen by the body, so the table's wingbeat and its
force in the body, are unchanged, and the force is tilted sideways by the bank.  The
commanded attitude is therefore ``S = Rz(yaw) Rx(bank) Ry(pitch)``: yaw to the heading,
bank about the (horizontal) heading, then pitch about the banked body's y axis.

Rolling instead about the body's own x axis (the Z-Y-X roll) does something else when
the body is steep: at the slow turn's body pitch of 57 degrees the force's sideways
part is only ``cos(pitch) sin(roll)`` of it and the air meets the body from the side
(``asin(sin(pitch) sin(roll))`` = 39 degrees out of the symmetry plane at a 48-degree
roll, a sideslip of ``atan(tan(pitch) sin(roll))`` = 49 degrees): the
table's wingbeat no longer gives the table's force, and the first bank-to-turn
controller (a Z-Y-X roll command) drifted outside every turn (docs/turning.md).

The attitude loop keeps its Z-Y-X error (``flight_arrays.error_rotvec``): the command is
handed to it as the Z-Y-X angles of the same rotation (:func:`zyx_of`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


def rot_x(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rot_y(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def rot_z(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def banked_attitude(heading: float, bank: float, pitch: float) -> np.ndarray:
    """The seed body frame (3, 3; columns the body axes in seed earth axes) of a bird
    heading ``heading`` (world, rad, counter-clockwise about z up), banked by ``bank``
    (rad, right wing down > 0) about the horizontal heading, pitched ``pitch`` (nose up
    > 0) about its banked y axis."""
    return rot_z(-heading) @ rot_x(bank) @ rot_y(pitch)


def zyx_of(s: np.ndarray) -> tuple[float, float, float]:
    """(roll, pitch, yaw), the Z-Y-X Euler angles of the seed attitude matrix ``s``
    (the convention of ``attitude.euler_zyx``)."""
    pitch = math.asin(float(np.clip(-s[2, 0], -1.0, 1.0)))
    return math.atan2(s[2, 1], s[2, 2]), pitch, math.atan2(s[1, 0], s[0, 0])


def bank_of(quat: np.ndarray, heading: np.ndarray | None = None) -> np.ndarray:
    """The bank (rad, right wing down > 0) of MuJoCo quaternions (n, 4): the angle about
    the horizontal heading between the body's y axis and the horizontal, i.e. the roll
    of the Z-X-Y decomposition ``Rz(yaw) Rx(bank) Ry(pitch)``: ``asin`` of the body's y
    axis' downward (seed z) component."""
    w, x, y, z = np.moveaxis(np.asarray(quat, dtype=float), -1, 0)
    # MuJoCo's body y axis in world axes is column 1 of R; its world z component r21
    r21 = 2 * (y * z + w * x)
    # seed body y = -MuJoCo y; seed down = -world z: down component of seed y is r21
    return np.arcsin(np.clip(r21, -1.0, 1.0))


def sideslip_of(quat: np.ndarray, v_air: np.ndarray) -> np.ndarray:
    """The sideslip (rad, air from the right > 0) of MuJoCo quaternions (n, 4) in air
    velocities ``v_air`` (n, 3, world, the bird's velocity minus the wind): the angle
    between the body's x axis and the air velocity's projection on the body's x-y
    plane (the body's horizontal plane)."""
    q = np.asarray(quat, dtype=float)
    w, x, y, z = np.moveaxis(q, -1, 0)
    r = np.stack(
        [
            np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
            np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
            np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
        ],
        axis=-2,
    )
    vb = np.einsum("nji,nj->ni", r, np.asarray(v_air, dtype=float))  # body (MuJoCo) axes
    # the bird moves forward through the air (+x); air from the right (MuJoCo -y side)
    # means the bird's velocity has a component to its right: seed +y = MuJoCo -y
    return np.arctan2(-vb[:, 1], vb[:, 0])


@dataclass(frozen=True)
class TurnAttitude:
    """One control step's turning command: the Z-Y-X angles of the banked attitude for
    the attitude loop (``roll``, ``pitch``, ``yaw``), the body-rate command and its
    derivative (seed body axes, p, q, r), and the body rates of the turn alone (for the
    Jacobians' measurement)."""

    roll: float
    pitch: float
    yaw: float
    rate: np.ndarray
    acc: np.ndarray
    turn_rates: np.ndarray
    bank: float = 0.0
    heading: float = 0.0


def turn_attitude(
    heading: tuple[float, float, float],
    bank: tuple[float, float, float],
    pitch: tuple[float, float, float],
) -> TurnAttitude:
    """The attitude command from the heading (world, counter-clockwise), the bank and
    the pitch, each ``(value, rate, acceleration)``: the angular velocity of ``S(t) =
    Rz(-psi) Rx(phi) Ry(theta)`` in body axes, ``Ry^T Rx^T (0, 0, -psi') + Ry^T (phi', 0,
    0) + (0, theta', 0)``, and its time derivative (the product rule, every term)."""
    psi, dpsi, ddpsi = heading
    phi, dphi, ddphi = bank
    th, dth, ddth = pitch
    s = banked_attitude(psi, phi, th)
    roll, p, yaw = zyx_of(s)
    ry, rx = rot_y(th), rot_x(phi)
    ez, ex = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0])
    yaw_vec = ry.T @ rx.T @ ez  # the earth's vertical (down) in body axes
    bank_vec = ry.T @ ex  # the heading axis in body axes
    turn = -dpsi * yaw_vec
    rate = turn + dphi * bank_vec + np.array([0.0, dth, 0.0])
    # d/dt of R^T v for a rotation R(t) = exp(a [e]): -[e] R^T v a'
    hat_x = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
    hat_y = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]])
    d_yaw_vec = -hat_y @ yaw_vec * dth - ry.T @ hat_x @ rx.T @ ez * dphi
    d_bank_vec = -hat_y @ bank_vec * dth
    acc = (
        -ddpsi * yaw_vec
        - dpsi * d_yaw_vec
        + ddphi * bank_vec
        + dphi * d_bank_vec
        + np.array([0.0, ddth, 0.0])
    )
    return TurnAttitude(roll, p, yaw, rate, acc, turn, phi, psi)


__all__ = [
    "TurnAttitude",
    "bank_of",
    "banked_attitude",
    "sideslip_of",
    "turn_attitude",
    "zyx_of",
]


def lateral_fit(window: list, per_beat: int) -> tuple[float, float]:
    """The wingbeat-mean side offset from the path and its rate (to the left), the
    trend's value now, from the last wingbeat of samples ``(y, vy)`` (the attitude
    estimate's fit; the start's sample repeated before a whole wingbeat)."""
    from birdsim.flight.body_attitude import FIT_BEATS
    from birdsim.flight.flight_arrays import fit_matrix

    n = FIT_BEATS * per_beat
    if not window:
        return 0.0, 0.0
    yv = np.array(window, dtype=float)
    if len(yv) < n:
        yv = np.vstack([np.repeat(yv[:1], n - len(yv), axis=0), yv])
    y, vy = fit_matrix(n, 2.0 * math.pi)[0] @ yv[-n:]
    return float(y), float(vy)


#: The lateral path loop of a turn: a triple pole of LATERAL_BEATS wingbeats per time
#: constant (the roll loop inside it has 1.25).  Measured on the circle (6-wingbeat ramps,
#: the damping-placed attitude gains, lead 0.75): 14, 10, 7, 6, 5, 4 wingbeats gave path
#: RMS 0.35, 0.17, 0.14, 0.10, 0.095, 0.11 semispan, the steady bank's largest miss of
#: atan(a_c/g) 2.9, 4.0, 3.4, 3.4, 4.6, 6.4 degrees (the faster loop bends the flown path
#: more); with the lead of 0.5: 6 -> circle 0.083 / 2.9 degrees, s-turn 0.107; 5 -> 0.083
#: / 3.5 degrees, s-turn 0.099 (6 kept: the coordination target; the side gust's peak
#: 2.7 against 3.3 semispans).
LATERAL_BEATS = 6.0


def lateral_acceleration(y: float, vy: float, integral: float = 0.0, omega: float = 1.0) -> float:
    """The sideways acceleration (to the left) that brings a side offset ``y``, its rate
    ``vy`` (to the left) and its time integral back to the path: a triple pole at ``-w``,
    ``w = omega / (2 pi LATERAL_BEATS)`` (the path loop's structure: the integral trims
    a steady bias of the bank flown, a few degrees, that a PD loop would leave as an
    offset of ``bias / w^2``)."""
    w = omega / (2.0 * math.pi * LATERAL_BEATS)
    return -(3.0 * w * w * y + 3.0 * w * vy + w**3 * integral)
