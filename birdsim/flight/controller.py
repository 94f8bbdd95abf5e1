"""Flight control: path error -> force demand -> table wingbeat (reduced units).

The wingbeat is the actuator: its mean force is what the tables promise, so the loop
acts on wingbeat-averaged quantities.  Per update (``control_per_beat`` times a wingbeat):

1. state estimate: the position and velocity errors ``e = ref - actual`` averaged over
   the last wingbeat (a moving average over exactly one period, which removes the
   within-wingbeat bobbing), moved forward by what the average lags, (T - dt)/2 for
   samples dt apart (``e_p + (T - dt)/2 e_v`` and ``e_v + (T - dt)/2 e_a``, ``e_a`` the wingbeat-mean acceleration error
   ``(e_v(t) - e_v(t - T)) / T``); before the first wingbeat is complete the missing
   samples are the start's (zero error);
2. acceleration command ``a_cmd = a_ref + Kp e_p + Kd e_v + Ki integral(e_p)``;
3. the whole bird's aerodynamic force ``m (a_cmd - g)`` becomes the table force (one
   wing + body drag, seed axes) through ``demand_from_acceleration``;
4. clipped to the table's grid; ``saturated`` when clipped or when the table's
   achieved force (interpolated like the parameters) misses the demand by more than
   the tables' own tolerance 0.01 (the table then gives its best wingbeat: the bird
   does its best);
5. lookup at the estimated airspeed -> target wingbeat parameters (the schedule smooths
   them and keeps the phase continuous).

Climbing flight: a table with a climb axis (``table.has_climb``) is read at the bird's
estimated climb rate (the wingbeat-mean vertical speed relative to the air) directly;
a level table is read along the air path, turned by the flight-path angle (see
:meth:`Controller.lookup`).

Gains (:func:`gains_for`): one natural frequency ``omega_n = omega / (2 pi N)`` for a
time constant of N wingbeats, a triple pole at ``-omega_n``.  ``open_loop`` keeps the
feed-forward (a_ref, v_ref) only.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.flight import fast_command, fast_window
from birdsim.flight.demand import (
    air_path_angle,
)  # one air-path rule (CLIMB_SPEED re-exported)
from birdsim.physics.bird import Bird

#: Wingbeats per closed-loop time constant 1 / omega_n (see gains_for and docs/flight.md).
TIME_CONSTANT_BEATS = 2.0
#: A demand counts as reachable when the table's interpolated achieved force is within
#: this of it (table force units; the tables' own "ok" tolerance).
REACH_TOLERANCE = 0.01
#: A lookup airspeed (or climb rate) clipped by more than this (semispan omega) counts
#: as saturated.
V_CLIP_TOLERANCE = 0.05
_TOLERANCES = (V_CLIP_TOLERANCE, REACH_TOLERANCE)  # the compiled lookup's


class Reference(Protocol):
    """A path in reduced units (birdsim.flight.path.FlightPath)."""

    def state(self, t: float) -> Any: ...


@dataclass(frozen=True)
class Gains:
    """Feedback gains (reduced units: time 1 / omega)."""

    omega_n: float
    kp: float
    kd: float
    ki: float


def gains_for(
    bird: Bird, time_constant_beats: float = TIME_CONSTANT_BEATS, *, integral: bool = True
) -> Gains:
    """Gains from the wingbeat: ``omega_n = omega / (2 pi N)``.

    With integral action the closed loop ``s^3 + Kd s^2 + Kp s + Ki`` has a triple pole
    at ``-omega_n``: ``Kd = 3 omega_n``, ``Kp = 3 omega_n^2``, ``Ki = omega_n^3``;
    without, a critically damped pair: ``Kd = 2 omega_n``, ``Kp = omega_n^2``.

    Args:
        bird: the (reduced) bird; only its omega is used.
        time_constant_beats: N, wingbeats per 1 / omega_n.
    Returns:
        Gains in the bird's time units.
    """
    if not (math.isfinite(time_constant_beats) and time_constant_beats > 0):
        raise BirdsimError(f"time_constant_beats={time_constant_beats!r}; allowed: a number > 0")
    wn = bird.omega / (2.0 * math.pi * time_constant_beats)
    if integral:
        return Gains(wn, 3.0 * wn * wn, 3.0 * wn, wn**3)
    return Gains(wn, wn * wn, 2.0 * wn, 0.0)


@dataclass(frozen=True)
class Command:
    """One controller output (reduced units; table force = one wing + body drag, seed axes)."""

    Fx: float
    Fz: float
    V: float
    params: np.ndarray
    saturated: bool
    a_cmd: tuple[float, float]
    climb: float = 0.0  # the table's climb (0 for a level table)


ToTable = Callable[..., tuple[float, float]]


class ErrorWindow:
    """Samples of the tracking error over the last wingbeat (``per_beat`` samples)."""

    def __init__(self, per_beat: int, period: float):
        self.n = per_beat
        self.period = period
        self.ep: list[np.ndarray] = []
        self.ev: list[np.ndarray] = []
        self.vx: list[float] = []
        self.integral = np.zeros(2)
        self.dt = period / per_beat
        #: the samples also as rows of growing arrays (ep, ev, vx): a full window is a
        #: copy of their last rows, the array ``np.asarray`` makes of the lists' tails
        self._rows = [np.empty((64, 2)), np.empty((64, 2)), np.empty(64)]

    def add(self, e_pos: np.ndarray, e_vel: np.ndarray, vx_air: float) -> None:
        ep, ev, vx = np.asarray(e_pos, dtype=float), np.asarray(e_vel, dtype=float), float(vx_air)
        k = len(self.vx)
        if k == self._rows[2].shape[0]:
            self._rows = [np.concatenate([r, np.empty_like(r)]) for r in self._rows]
        self._rows[0][k], self._rows[1][k], self._rows[2][k] = ep, ev, vx
        self.ep.append(ep)
        self.ev.append(ev)
        self.vx.append(vx)

    def add_many(self, e_pos: np.ndarray, e_vel: np.ndarray, vx_air: np.ndarray) -> None:
        """:meth:`add` of every row of ``e_pos``, ``e_vel`` (n, 2) and ``vx_air`` (n,)."""
        e_pos, e_vel = np.asarray(e_pos, dtype=float), np.asarray(e_vel, dtype=float)
        vx = np.asarray(vx_air, dtype=float).tolist()
        k, n = len(self.vx), len(vx)
        while k + n > self._rows[2].shape[0]:
            self._rows = [np.concatenate([r, np.empty_like(r)]) for r in self._rows]
        self._rows[0][k : k + n], self._rows[1][k : k + n], self._rows[2][k : k + n] = (
            e_pos,
            e_vel,
            vx,
        )
        self.ep.extend(e_pos)
        self.ev.extend(e_vel)
        self.vx.extend(vx)

    def _window(self, xs: list, k: int) -> np.ndarray:
        n = len(xs)
        if n >= k:  # the arrays' rows: the same numbers, no list
            for rows, samples in zip(self._rows, (self.ep, self.ev, self.vx)):
                if samples is xs and n == len(self.vx):
                    return rows[n - k : n].copy()
        tail = xs[-k:]
        if len(tail) < k:  # before the first full wingbeat: the start's value
            tail = [xs[0]] * (k - len(tail)) + tail
        return np.asarray(tail)

    def estimate(self) -> tuple[np.ndarray, np.ndarray, float]:
        """Predicted wingbeat-mean position and velocity errors and airspeed (x)."""
        if not self.ep:
            return np.zeros(2), np.zeros(2), 0.0
        # the mean of n samples lags the newest by (n - 1) / 2 sample intervals
        n, half = self.n, 0.5 * (self.period - self.dt)
        count = len(self.vx)
        if count == len(self.ep) == len(self.ev):  # a full window: compiled, bitwise
            fast = fast_window.estimate(self._rows, count, n, half, self.period)
            if fast is not None:
                return fast
        ev_win = self._window(self.ev, n + 1)
        ep = self._window(self.ep, n).mean(axis=0)
        ev = ev_win[1:].mean(axis=0)
        ea = (ev_win[-1] - ev_win[0]) / self.period  # the window spans n + 1 samples
        vx_win = self._window(self.vx, n + 1)
        vx = float(vx_win[1:].mean() + half * (vx_win[-1] - vx_win[0]) / self.period)
        return ep + half * ev, ev + half * ea, vx

    def integrate(self, e_pos: np.ndarray, dt: float) -> None:
        self.integral = self.integral + dt * np.asarray(e_pos)


class Controller:
    """Path following with table wingbeats; see the module docstring.

    Args:
        table: a LookupTable (lookup_many, status_at, axes, param_names).
        bird: the REDUCED bird (mass ratio, gravity in semispan omega^2).
        gains: feedback gains; ignored when ``open_loop``.
        to_table: ``(ax_up, az_up, vx, vz, bird, pitch) -> (Fx_table, Fz_table)``
            (default birdsim.flight.demand.demand_from_acceleration). With a climb
            table it is called with ``table_climb=True`` as well when it is the default.
    """

    def __init__(
        self,
        table: Any,
        bird: Bird,
        gains: Gains,
        *,
        open_loop: bool = False,
        to_table: ToTable | None = None,
    ):
        if to_table is None:
            from birdsim.flight.demand import demand_from_acceleration as to_table
        self.table = table
        self.bird = bird
        self.gains = gains
        self.open_loop = open_loop
        self.to_table = to_table
        self.names = tuple(table.param_names)
        axes = table.axes
        #: the table has a climb axis: the feed-forward reads it at the bird's climb rate
        self.has_climb = bool(getattr(table, "has_climb", False))
        keys = ("Fx", "Fz", "V", "climb") if self.has_climb else ("Fx", "Fz", "V")
        self.lo = {k: float(np.min(axes[k])) for k in keys}
        self.hi = {k: float(np.max(axes[k])) for k in keys}

    def command(
        self,
        ref: Any,
        est: tuple[np.ndarray, np.ndarray, float] | None,
        integral: np.ndarray,
        pitch: float,
        wind: tuple[float, float] = (0.0, 0.0),
    ) -> Command:
        """The wingbeat for reference state ``ref`` (PathState), the error estimate
        ``est`` (ErrorWindow.estimate(); None = feed-forward only) and the wind
        ``(wx, wz)`` (reduced, world x forward, z up)."""
        ax, az = float(ref.ax), float(ref.az)
        if est is not None and not self.open_loop:
            ep, ev, vx = est
            g = self.gains
            ax += g.kp * ep[0] + g.kd * ev[0] + g.ki * integral[0]
            az += g.kp * ep[1] + g.kd * ev[1] + g.ki * integral[1]
            vz = float(ref.vz) - float(ev[1])
        else:
            vx, vz = float(ref.vx), float(ref.vz)
        return self.lookup(ax, az, vx - wind[0], vz - wind[1], pitch)

    def command_at(
        self,
        path: Any,
        t: float,
        est: tuple[np.ndarray, np.ndarray, float] | None,
        integral: np.ndarray,
        pitch: float,
        wind: tuple[float, float] = (0.0, 0.0),
    ) -> Command:
        """:meth:`command` at ``path.state(t)``: the path's curves, the feedback and the
        lookup in one compiled call where it applies (:func:`fast_command.path_command`,
        within round-off of these lines)."""
        if not self.has_climb:
            fast = fast_command.path_command(self, path, t, est, integral, pitch, wind, _TOLERANCES)
            if fast is not None:
                return Command(*fast[:4], fast[4], fast[5], 0.0)
        return self.command(path.state(t), est, integral, pitch, wind)

    def lookup(self, ax: float, az: float, vx_air: float, vz_air: float, pitch: float) -> Command:
        """The wingbeat that gives the whole bird the acceleration (ax, az) (world, z up)
        while it moves through the air at (vx_air, vz_air).

        Tables are built for level flight.  Flying along an air path inclined by
        ``gamma = atan2(vz_air, vx_air)`` is level flight turned by gamma: the wings see
        the same flow when the body pitch is the table's plus gamma.  So the needed
        aerodynamic force ``m (a - g)`` is turned into the air-path frame, looked up at
        the airspeed, and gamma is added to the table's pitch.  Below a forward airspeed
        of :data:`CLIMB_SPEED` the turn fades out quadratically (none at hover, none when
        flying backwards through the air).

        A table with a climb axis was built for climbing flight: it is read at the
        horizontal airspeed ``vx_air`` and the climb rate ``vz_air`` directly, with the
        climbing body drag on both sides (:func:`demand_from_acceleration`,
        ``table_climb=True``) and no turn.
        """
        if self.has_climb:
            return self._lookup_climbing(ax, az, vx_air, vz_air, pitch)
        fast = fast_command.lookup(self, ax, az, vx_air, vz_air, pitch, _TOLERANCES)
        if fast is not None:  # compiled (within round-off of the lines below)
            return Command(*fast[:4], fast[4], (ax, az), 0.0)
        m, grav = self.bird.mass, self.bird.gravity
        gamma = float(air_path_angle(vx_air, vz_air))  # faded below CLIMB_SPEED of forward airspeed
        f_x, f_z = m * ax, m * (az + grav)  # aerodynamic force needed, world
        c, s = math.cos(gamma), math.sin(gamma)
        w_x, w_z = c * f_x + s * f_z, -s * f_x + c * f_z  # in the air-path frame
        v_table = math.hypot(vx_air, vz_air) if gamma != 0.0 else vx_air
        fx, fz = self.to_table(w_x / m, w_z / m - grav, v_table, 0.0, self.bird, pitch - gamma)
        cmd = self.lookup_table_force(float(fx), float(fz), v_table, (ax, az))
        if gamma != 0.0 and "pitch" in self.names:
            cmd.params[self.names.index("pitch")] += gamma
        return cmd

    def _lookup_climbing(
        self, ax: float, az: float, vx_air: float, vz_air: float, pitch: float
    ) -> Command:
        """:meth:`lookup` for a table with a climb axis: read at (vx_air, climb = vz_air)."""
        to_table = self.to_table
        from birdsim.flight.demand import demand_from_acceleration

        if to_table is demand_from_acceleration:
            fx, fz = to_table(ax, az, vx_air, vz_air, self.bird, pitch, table_climb=True)
        else:
            fx, fz = to_table(ax, az, vx_air, vz_air, self.bird, pitch)
        return self.lookup_table_force(float(fx), float(fz), vx_air, (ax, az), climb=vz_air)

    def lookup_table_force(
        self,
        fx: float,
        fz: float,
        v_air: float,
        a_cmd: tuple[float, float] = (0.0, 0.0),
        *,
        climb: float = 0.0,
    ) -> Command:
        """The table's wingbeat for a table-force demand (clipped; saturated flag).

        ``climb`` (vertical airspeed, up) is used only by a table with a climb axis; it
        is clipped to the axis and counts as saturated when clipped by more than
        :data:`V_CLIP_TOLERANCE`, like V. The saturation test interpolates the achieved
        force at the same (Fx, Fz, V[, climb]) as the parameters.
        """
        if not all(math.isfinite(v) for v in (fx, fz, v_air, climb)):
            raise BirdsimError(
                f"non-finite demand Fx={fx}, Fz={fz}, V={v_air}, climb={climb}; "
                "allowed: finite path states"
            )
        used = {"Fx": fx, "Fz": fz, "V": v_air}
        if self.has_climb:
            used["climb"] = climb
        clipped = {k: min(max(v, self.lo[k]), self.hi[k]) for k, v in used.items()}
        saturated = (
            abs(clipped["Fx"] - fx) > 1e-9
            or abs(clipped["Fz"] - fz) > 1e-9
            or abs(clipped["V"] - v_air) > V_CLIP_TOLERANCE
            or abs(clipped.get("climb", 0.0) - used.get("climb", 0.0)) > V_CLIP_TOLERANCE
        )
        extra = {"climb": clipped["climb"]} if self.has_climb else {}
        row_of = None if self.has_climb else getattr(self.table, "lookup_row", None)
        row = row_of(clipped["Fx"], clipped["Fz"], clipped["V"]) if row_of else None
        if row is not None:  # lookup_many's numbers, one row (birdsim.tables.lookup)
            d = len(self.names)
            miss = max(abs(float(row[d]) - clipped["Fx"]), abs(float(row[d + 1]) - clipped["Fz"]))
            saturated = saturated or miss > REACH_TOLERANCE
            return Command(fx, fz, v_air, row[:d].copy(), bool(saturated), a_cmd, 0.0)
        raw = self.table.lookup_many(clipped["Fx"], clipped["Fz"], clipped["V"], clip=True, **extra)
        params = np.array([float(raw[n]) for n in self.names])
        if "achieved_Fx" in raw:  # the cells' achieved forces, interpolated like the parameters
            miss = max(
                abs(float(raw["achieved_Fx"]) - clipped["Fx"]),
                abs(float(raw["achieved_Fz"]) - clipped["Fz"]),
            )
            saturated = saturated or miss > REACH_TOLERANCE
        return Command(fx, fz, v_air, params, bool(saturated), a_cmd, clipped.get("climb", 0.0))


__all__ = ["Command", "Controller", "ErrorWindow", "Gains", "TIME_CONSTANT_BEATS", "gains_for"]
