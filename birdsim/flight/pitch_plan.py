"""The free body's pitch command planned along a known path (reduced units, rad).

The table's pitch jumps where neighbouring demands fall on different branches of the
optimum (landing's flare: 8 -> 36 -> 8 -> 89 degrees within a few wingbeats); a free body
cannot follow such jumps, so the attitude loop's command is smoothed.  Smoothed causally
(a critically damped filter of time constant ``tau``), the command lags the table by
``2 tau`` on a ramp: in landing's braking the body stays near level while the table's
wingbeat counts on the drag of a body pitched up by 30-80 degrees, and the path loop asks
the wings for more braking than the table has.  The path is known in advance, so the
command is planned instead: the table's pitch along the path's feed-forward (no error,
the start's integral) on the control grid, smoothed without lag by the same filter run
forward and then backward in time (each pass ``tau / sqrt(2)``: the same variance as the
causal filter), plus the causal filter of what the flight's table pitch differs from the
plan by (the closed loop's corrections; it also starts the command at the start's pitch).
Its rate and acceleration (central differences of the smooth plan plus the filter's) are
fed forward to the attitude loop.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from birdsim.flight import fast_smooth
from birdsim.flight.attitude_commands import command_filter


def _smooth(values: np.ndarray, tau: float, dt: float) -> np.ndarray:
    """The critically damped filter of time constant ``tau`` run over ``values`` (a grid
    ``dt`` apart) forward from the first value, then backward from the last: no lag
    (compiled where :func:`birdsim.flight.fast_smooth.smooth` applies: the same numbers)."""
    out = fast_smooth.smooth(values, tau, dt)
    if out is not None:
        return out
    out = np.empty_like(values)
    for order in (1, -1):
        seq = values if order == 1 else out[::-1].copy()
        v, r = float(seq[0]), 0.0
        res = np.empty_like(seq)
        for i, target in enumerate(seq):
            res[i] = v
            v, r, _ = command_filter(v, r, float(target), tau, dt)
        out = res if order == 1 else res[::-1]
    return out


class PitchPlan:
    """The pitch command (value, rate, acceleration) at the control steps of a flight
    along a known path (see the module)."""

    def __init__(
        self,
        table_pitch: Callable[[float], float],
        n_steps: int,
        dt: float,
        tau: float,
        start_pitch: float,
        stride: int = 1,
    ):
        """``table_pitch(t)``: the table's pitch of the path's feed-forward at reduced time
        ``t`` (with the air-path angle, as the flight's schedule holds it), asked in
        increasing ``t`` every ``stride`` control steps and interpolated linearly between
        (the smoothing's time constant is many strides); ``n_steps`` control steps ``dt``
        apart; ``tau`` the command's time constant; ``start_pitch`` the pitch the flight
        starts at."""
        self.dt = dt
        self.tau = tau
        margin = int(math.ceil(3.0 * tau / dt)) if tau > 0 else 0
        n = n_steps + margin + 1
        coarse = stride * np.arange(-(-n // stride) + 1)
        values = np.array([table_pitch(float(dt * k)) for k in coarse])
        self.raw = np.interp(np.arange(n), coarse, values)
        s = tau / math.sqrt(2.0)
        self.plan = _smooth(self.raw, s, dt) if tau > 0 else self.raw.copy()
        self.rate = np.gradient(self.plan, dt)
        self.acc = np.gradient(self.rate, dt)
        # the causal filter of the flight's table pitch minus the plan's
        self.res, self.res_rate = start_pitch - float(self.plan[0]), 0.0

    def step(self, k: int, table_pitch_now: float) -> tuple[float, float, float]:
        """Control step ``k`` (time ``k dt``): the command after this step's filter update
        (value, rate, acceleration), ``table_pitch_now`` the flight's table pitch."""
        k = min(k, len(self.plan) - 2)
        target = table_pitch_now - float(self.raw[k])
        self.res, self.res_rate, res_acc = command_filter(
            self.res, self.res_rate, target, self.tau, self.dt
        )
        j = k + 1  # the filter's output holds at the end of this step, as command_filter's
        return (
            float(self.plan[j]) + self.res,
            float(self.rate[j]) + self.res_rate,
            float(self.acc[j]) + res_acc,
        )


def feedforward_pitch(ctl: Any, path: Any, names: tuple) -> Callable[[float], float]:
    """``f(t)`` for :class:`PitchPlan`: the table's pitch (with the air-path angle) of
    ``path``'s feed-forward through the controller ``ctl`` (a
    :class:`birdsim.flight.controller.Controller`; no error, no wind), asked in
    increasing ``t``: the body drag at that pitch by fixed-point steps (three from 0 at
    the first ``t``, then one from the last pitch).  The feed-forward's command reads
    only the state's accelerations and velocities and the pitch: a step whose five
    numbers have the bits of an earlier step's takes that step's answer (a path flown
    at constant velocity asks the table once, not twice per wingbeat; the same bits)."""
    zero, i = np.zeros(2), names.index("pitch")
    last: list[float] = []
    known: dict[bytes, float] = {}

    def f(t: float) -> float:
        p = last[0] if last else 0.0
        s = path.state(t)
        for _ in range(1 if last else 3):
            key = np.array([s.ax, s.az, s.vx, s.vz, p], dtype=float).tobytes()
            hit = known.get(key)
            p = float(ctl.command(s, None, zero, p).params[i]) if hit is None else hit
            known[key] = p
        last[:] = [p]
        return p

    return f


__all__ = ["PitchPlan", "feedforward_pitch"]
