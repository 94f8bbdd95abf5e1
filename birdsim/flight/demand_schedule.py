"""A force-keyframe manoeuvre as free flight's open-loop reference (reduced units)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.flight.path import PathState

#: The reference state of a force-keyframe manoeuvre: a path state in the vertical plane.
RefState = PathState

TWO_PI = 2.0 * math.pi


class DemandSchedule:
    """A force-keyframe manoeuvre (birdsim.flight.manoeuvre.Manoeuvre) as an open-loop
    reference: demands Fx, Fz, V straight from the keyframes (table units); the
    reference path is x = integral of V, z = the keyframes' height."""

    open_loop_demands = True

    def __init__(self, manoeuvre: Any, x0: float = 0.0):
        self.manoeuvre = manoeuvre
        self.name = manoeuvre.name
        self.duration_beats = float(manoeuvre.duration)
        self.x0 = x0
        self._grid = np.linspace(
            0.0, self.duration_beats * TWO_PI, max(2, int(self.duration_beats * 64) + 1)
        )
        v = manoeuvre.demands(self._grid / TWO_PI)["V"]
        dx = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(self._grid))])
        self._x = dx

    def demands(self, t: float) -> tuple[float, float, float]:
        d = self.manoeuvre.demands(t / TWO_PI)
        return float(d["Fx"]), float(d["Fz"]), float(d["V"])

    def state(self, t: float) -> RefState:
        d = self.manoeuvre.demands(np.array([t, t + 1e-3]) / TWO_PI)
        x = (
            self.x0
            + float(np.interp(t, self._grid, self._x))
            + max(0.0, t - self._grid[-1]) * float(d["V"][0])
        )
        vz = (float(d["z"][1]) - float(d["z"][0])) / 1e-3
        return RefState(x, float(d["z"][0]), float(d["V"][0]), vz, 0.0, 0.0)


__all__ = ["DemandSchedule", "RefState"]
