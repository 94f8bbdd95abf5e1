"""A three-dimensional path seen from its own heading: the frame of turning flight's
path loop (reduced units; MuJoCo world axes: x forward at the start, y to the left,
z up).

Birds turn by banking (Ros et al. 2011, PNAS 108:19990: the wingbeat-mean force stays
nearly fixed in the body and the body rolls to point it).  So the path loop stays the
two-dimensional one of straight flight, in the vertical plane through the path's
heading: along the track (the horizontal component of the path's velocity sets the
heading ``psi``, counter-clockwise from x about z up) and up.  The sideways part is the
bank's: the path's centripetal acceleration ``a_lat`` (to the left) plus a correction
of the bird's side offset (``attitude_commands.bank_command``) is delivered by rolling
the wings' force, whose magnitude the symmetric table gives: the track state's ``az``
is the vertical acceleration the force in the banked plane must carry,
``sqrt((az + g)^2 + a_lat^2) - g``.  A path without a side component (every straight
preset) is not seen through this frame at all (:func:`is_three_d`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

TWO_PI = 2.0 * math.pi
#: Below this horizontal path speed (semispan omega) the heading is held (hover, a perch).
HOLD_SPEED = 0.02
#: Samples per wingbeat of the heading's grid.
GRID_PER_BEAT = 64


def is_three_d(reference: Any, t_end: float) -> bool:
    """Whether ``reference`` (a path with ``sample``) leaves the x-z plane before ``t_end``."""
    fn = getattr(reference, "sample", None)
    if fn is None:
        return False
    s = fn(np.linspace(0.0, t_end, 513))
    return "y" in s and bool(np.any(np.asarray(s["y"]) != 0) or np.any(np.asarray(s["vy"]) != 0))


#: A turn is *slow* below this horizontal path speed (semispan omega): there the table's
#: body pitch is steep (50-60 degrees at 0.2) and the turn is flown in the lowered
#: posture of :func:`birdsim.flight.turning.turn_pitch`.
SLOW_TURN_SPEED = 0.3
#: Wingbeats over which the slow turn's posture is taken before the turn and left after.
POSTURE_BEATS = 2.0
#: Wingbeats the posture is held after the last slow turn before it is left (the
#: u-turn's lateral loop settles the keyhole's exit in it before braking).
POSTURE_HOLD_BEATS = 6.0


def _posture_weight(
    t: np.ndarray, speed: np.ndarray, turn_rate: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The weight (0..1) of the slow-turn posture on the grid ``t`` with its rate and
    acceleration: 1 where the path turns (``turn_rate`` not 0) below
    :data:`SLOW_TURN_SPEED` and for :data:`POSTURE_HOLD_BEATS` after the last such
    sample, falling to 0 over :data:`POSTURE_BEATS` (the quintic smootherstep of the
    time, so taken before the turn, left after it, with continuous rate and
    acceleration)."""
    slow_turn = (np.abs(turn_rate) > 1e-9) & (speed < SLOW_TURN_SPEED)
    if not slow_turn.any():
        zero = np.zeros_like(t)
        return zero, zero, zero
    ts = t[slow_turn]
    i = np.searchsorted(ts, t)
    before, after = ts[np.clip(i - 1, 0, len(ts) - 1)], ts[np.clip(i, 0, len(ts) - 1)]
    gap = np.minimum(np.abs(t - before), np.abs(t - after))  # time to the nearest
    gap = np.where(slow_turn, 0.0, gap)
    gap = np.where(t > ts[-1], np.maximum(gap - POSTURE_HOLD_BEATS * TWO_PI, 0.0), gap)
    u = np.clip(1.0 - gap / (POSTURE_BEATS * TWO_PI), 0.0, 1.0)
    w = u**3 * (10.0 - 15.0 * u + 6.0 * u * u)
    dw = np.gradient(w, t)
    return w, dw, np.gradient(dw, t)


@dataclass(frozen=True)
class TrackState:
    """The path at one time in its track frame: ``x`` the distance along the track,
    ``vx``/``ax`` along the heading, ``z``/``vz`` up, ``az`` the vertical acceleration the
    banked force carries (see the module), ``a_lat`` the centripetal acceleration (to the
    left), ``heading``/``heading_rate`` psi and its rate (rad, counter-clockwise about z),
    ``az_up`` the path's own vertical acceleration."""

    x: float
    z: float
    vx: float
    vz: float
    ax: float
    az: float
    a_lat: float
    heading: float
    heading_rate: float
    az_up: float = 0.0


class TrackFrame:
    """``reference`` (x, y, z and their rates from ``sample``) in its own track frame,
    tabulated over ``[0, t_end]`` and a wingbeat beyond; ``gravity`` the reduced bird's."""

    def __init__(self, reference: Any, t_end: float, gravity: float):
        self.reference = reference
        self.gravity = float(gravity)
        t = np.arange(0.0, t_end + 2.0 * TWO_PI, TWO_PI / GRID_PER_BEAT)
        s = reference.sample(t)
        vx, vy = np.asarray(s["vx"], dtype=float), np.asarray(s["vy"], dtype=float)
        moving = np.hypot(vx, vy) > HOLD_SPEED
        psi = np.arctan2(vy, vx)
        if not moving.any():
            psi[:] = 0.0
        else:
            # the last heading flown while moving, held (and the first, before it)
            idx = np.where(moving, np.arange(len(t)), 0)
            idx = np.maximum.accumulate(idx)
            idx[: int(np.argmax(moving))] = int(np.argmax(moving))
            psi = np.unwrap(psi[idx])
        self._t = t
        self._psi = psi
        self._psi_rate = np.gradient(psi, t)
        along = np.cos(psi) * vx + np.sin(psi) * vy
        arc = np.concatenate([[0.0], np.cumsum(0.5 * (along[1:] + along[:-1]) * np.diff(t))])
        self._arc = float(np.asarray(s["x"])[0]) + arc
        self._posture = _posture_weight(t, np.hypot(vx, vy), self._psi_rate)
        #: whether the path has a slow turn (the posture and the attitude loop's settings
        #: of :mod:`birdsim.flight.turning` for it)
        self.slow_turn = bool(np.any(self._posture[0] > 0.0))

    def posture(self, t: float) -> tuple[float, float, float]:
        """The slow turn's posture weight at ``t`` (0 straight, 1 in a slow turn; see
        :func:`_posture_weight`) with its rate and acceleration (per time unit)."""
        return tuple(float(np.interp(t, self._t, w)) for w in self._posture)  # type: ignore[return-value]

    def heading(self, t: Any) -> np.ndarray:
        """psi(t) (rad, counter-clockwise from x about z up)."""
        return np.interp(t, self._t, self._psi)

    def wind_along(self, t: float, wind: np.ndarray) -> float:
        """The world wind ``wind`` (x, y, z) along the heading at ``t``: what the airspeed
        along the track loses (the path loop's and the attitude loop's alike)."""
        psi = float(self.heading(float(t)))
        return math.cos(psi) * float(wind[0]) + math.sin(psi) * float(wind[1])

    def sample(self, t: Any) -> dict[str, np.ndarray]:
        """The path at reduced times ``t`` in its track frame (see :class:`TrackState`)."""
        t = np.asarray(t, dtype=float)
        s = self.reference.sample(t)
        psi = np.interp(t, self._t, self._psi)
        c, sn = np.cos(psi), np.sin(psi)
        ax, ay, az = (np.asarray(s[k], dtype=float) for k in ("ax", "ay", "az"))
        a_lat = -sn * ax + c * ay
        g = self.gravity
        return {
            "x": np.interp(t, self._t, self._arc),
            "z": np.asarray(s["z"], dtype=float),
            "vx": c * np.asarray(s["vx"]) + sn * np.asarray(s["vy"]),
            "vz": np.asarray(s["vz"], dtype=float),
            "ax": c * ax + sn * ay,
            "az": np.sqrt((az + g) ** 2 + a_lat**2) - g,
            "a_lat": a_lat,
            "heading": psi,
            "heading_rate": np.interp(t, self._t, self._psi_rate),
            "az_up": az,
        }

    def bank_plan(self, t: float, dt: float = TWO_PI / GRID_PER_BEAT) -> tuple[tuple, tuple]:
        """The planned heading and bank at ``t``, each (value, rate, acceleration) by
        central differences over ``dt``: the heading psi (world, counter-clockwise) and
        the bank (seed: right wing down > 0) that tilts the force carrying the path's
        vertical acceleration and weight by the path's centripetal acceleration,
        ``atan2(-a_lat, az_up + g)`` (``az_up`` the path's own, not the banked force's)."""
        ts = np.array([t - dt, t, t + dt])
        s = self.reference.sample(ts)
        psi = np.interp(ts, self._t, self._psi)
        vx, vy = np.asarray(s["vx"], dtype=float), np.asarray(s["vy"], dtype=float)
        if np.all(np.hypot(vx, vy) > HOLD_SPEED):  # the path's own heading, not the grid's
            direct = np.arctan2(vy, vx)
            psi = direct + TWO_PI * np.round((psi - direct) / TWO_PI)
        c, sn = np.cos(psi), np.sin(psi)
        a_lat = -sn * np.asarray(s["ax"], dtype=float) + c * np.asarray(s["ay"], dtype=float)
        phi = np.arctan2(-a_lat, np.asarray(s["az"], dtype=float) + self.gravity)

        def diff(v: np.ndarray) -> tuple[float, float, float]:
            return (
                float(v[1]),
                float((v[2] - v[0]) / (2 * dt)),
                float((v[2] - 2 * v[1] + v[0]) / dt**2),
            )

        return diff(psi), diff(phi)

    def state(self, t: float) -> TrackState:
        s = self.sample(np.array([float(t)]))
        return TrackState(*(float(s[k][0]) for k in TrackState.__dataclass_fields__))

    def errors(
        self, t: np.ndarray, pos: np.ndarray, vel: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict[str, np.ndarray]]:
        """For the bird at world positions ``pos`` and velocities ``vel`` (n, 3) at times
        ``t``: the path loop's errors (reference minus bird) along the track and up (n, 2),
        their rates (n, 2), the bird's speed along the heading (n,), its side offset
        from the path and that offset's rate, to the left (n, 2), and the world
        reference (x, y, z) for the log."""
        s = self.reference.sample(t)
        psi = np.interp(t, self._t, self._psi)
        c, sn = np.cos(psi), np.sin(psi)
        ep = np.stack([s["x"], s["y"], s["z"]], axis=1) - pos
        ev = np.stack([s["vx"], s["vy"], s["vz"]], axis=1) - vel
        fwd = lambda e: c * e[:, 0] + sn * e[:, 1]  # noqa: E731
        left = lambda e: -sn * e[:, 0] + c * e[:, 1]  # noqa: E731
        e_pos = np.stack([fwd(ep), ep[:, 2]], axis=1)
        e_vel = np.stack([fwd(ev), ev[:, 2]], axis=1)
        v_along = c * vel[:, 0] + sn * vel[:, 1]
        lateral = np.stack([-left(ep), -left(ev)], axis=1)
        world = {k: np.asarray(s[k], dtype=float) for k in ("x", "y", "z")}
        return e_pos, e_vel, v_along, lateral, world


__all__ = [
    "HOLD_SPEED",
    "POSTURE_BEATS",
    "POSTURE_HOLD_BEATS",
    "SLOW_TURN_SPEED",
    "TrackFrame",
    "TrackState",
    "is_three_d",
]
