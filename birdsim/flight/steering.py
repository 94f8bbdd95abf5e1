"""Steering rules of a flock (Reynolds 1987) acting on each bird's path reference.

Reynolds, C. W. 1987, "Flocks, herds and schools: a distributed behavioral model",
SIGGRAPH '87, Computer Graphics 21(4) 25-34: each boid steers by three rules computed
from its neighbours (separation: away from those too close; alignment: towards their
mean velocity; cohesion: towards their centre), plus a goal ("migratory urge").  Here
the goal is the leader's path with the bird's place in the formation (its offset,
turned with the leader's heading), and alignment and cohesion act on the neighbours'
*formation errors* (a bird's position and velocity minus its goal's: matching the
neighbours' drift keeps the formation's shape instead of collapsing it onto its centre).

Everything is in REDUCED units (semispans, 1 / omega; world axes x forward at the
start, y left, z up).  Every bird of a flock shares its semispan and period, so the
birds' reduced units are one frame.

The rules never push a body: they give each bird a steering displacement ``delta`` of
its path reference (:class:`FlockPath`), a critically damped second-order state driven
by the rules' acceleration; the bird's own controller (:func:`birdsim.flight.freeflight.fly`)
then flies the moved reference with its own wings.  ``delta``'s acceleration is held over
a control interval (the reference stays continuous in position and velocity) and bounded
by :attr:`SteeringConfig.max_accel` times gravity (the table's margins carry it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

TWO_PI = 2.0 * math.pi
#: Samples per wingbeat of a turned place's heading-acceleration table, and how far past
#: the path (wingbeats) it reaches.
GRID_PER_BEAT = 256
RATE_MARGIN_BEATS = 4.0
#: goals kept by :meth:`FlockPath.goal` (times asked again within a control update)
GOAL_CACHE = 256


@dataclass(frozen=True)
class SteeringConfig:
    """The rules' radii (semispans), weights and time constant (wingbeats).

    The goal's spring and the damping of ``delta`` have the natural frequency
    ``1 / (tau_beats 2 pi)`` (critically damped); the rules' accelerations are written in
    that frequency squared times a length: separation ``separation`` semispans at
    contact (falling linearly to 0 at ``separation_radius``), cohesion ``cohesion`` times
    the neighbours' mean formation error minus the bird's own, alignment ``alignment``
    times the same for velocities (times the frequency)."""

    separation_radius: float = 2.5
    neighbour_radius: float = 8.0
    separation: float = 2.0
    cohesion: float = 0.5
    alignment: float = 0.5
    tau_beats: float = 2.0
    #: the rules fade in over this many wingbeats from the start (linearly): the bird
    #: settles on its trimmed start before its reference moves
    start_beats: float = 2.0
    #: the steering acceleration's bound, a fraction of gravity
    max_accel: float = 0.05


STEERING_KEYS = tuple(SteeringConfig.__dataclass_fields__)


def rule_accelerations(
    pos: np.ndarray,
    vel: np.ndarray,
    goal: np.ndarray,
    goal_vel: np.ndarray,
    delta: np.ndarray,
    delta_vel: np.ndarray,
    cfg: SteeringConfig,
    gravity: float,
    t: float = math.inf,
) -> np.ndarray:
    """At reduced time ``t``, each bird's steering acceleration (N, 3) from every bird's position and velocity
    (torso origin, world, (N, 3)), its goal (the leader's path plus its turned offset) and
    goal velocity, and its steering state ``delta``/``delta_vel``."""
    n = pos.shape[0]
    w = 1.0 / (cfg.tau_beats * TWO_PI)
    diff = pos[:, None, :] - pos[None, :, :]  # (i, j): from j to i
    dist = np.linalg.norm(diff, axis=-1)
    np.fill_diagonal(dist, np.inf)
    # separation: away from every bird inside the radius, linearly stronger to contact
    push = np.clip(1.0 - dist / cfg.separation_radius, 0.0, None)
    unit = diff / np.maximum(np.where(np.isfinite(dist), dist, 1.0), 1e-12)[..., None]
    sep = np.einsum("ij,ijk->ik", push, unit)
    # alignment and cohesion: the neighbours' mean formation error minus the bird's own
    nbr = dist < cfg.neighbour_radius
    count = nbr.sum(axis=1)
    err, err_v = pos - goal, vel - goal_vel
    has = count > 0
    mean_e = np.where(has[:, None], nbr @ err / np.maximum(count, 1)[:, None], err)
    mean_v = np.where(has[:, None], nbr @ err_v / np.maximum(count, 1)[:, None], err_v)
    acc = w * w * (cfg.separation * sep + cfg.cohesion * (mean_e - err) - delta)
    acc += w * (cfg.alignment * (mean_v - err_v) - 2.0 * delta_vel)
    limit = cfg.max_accel * gravity
    mag = np.linalg.norm(acc, axis=1)
    scale = np.where(mag > limit, limit / np.maximum(mag, 1e-300), 1.0)
    scale *= min(1.0, t / (cfg.start_beats * TWO_PI)) if cfg.start_beats > 0 else 1.0
    return acc * scale[:, None] if n else acc


class FlockPath:
    """One bird's reference: its place by the leader's path (a FlightPath, reduced
    units; the offset in semispans, x forward, y left, z up: along the leader's track
    and its left normal when ``turn_offset``, else in world axes; :meth:`goal`) plus the
    steering displacement ``delta``
    (quadratic in time from the last control update).  Other attributes are the leader
    path's (``duration_beats``, ``regime``, ...).

    The free-flight loop starts a bird at y = 0 (its paths start there): the bird flies
    the reference moved sideways by ``-shift_y`` (its goal's y at t = 0) and its flown
    state is moved back by ``shift_y`` (nothing in free flight depends on y: uniform
    gravity and wind, no contacts), so :meth:`sample` is the flown frame's and
    :meth:`goal` the world's.  ``lateral`` False (a planar leader path: the bird is
    flown by the straight loop, which holds y): the steering acts in x and z only."""

    def __init__(self, base: Any, offset: np.ndarray, turn_offset: bool):
        self._base = base
        self._goals: dict[tuple, dict[str, np.ndarray]] = {}
        self.offset = np.asarray(offset, dtype=float)
        self.turn_offset = bool(turn_offset)
        if self.turn_offset:  # the along-track offset as a time lag at the start's speed
            s0 = base.sample(np.array([0.0]))
            v0 = float(np.hypot(s0["vx"][0], s0["vy"][0]))
            if not v0 > 1e-6:
                raise ValueError("a turning leader path that starts at rest: no heading")
            self.lag = float(self.offset[0]) / v0
            # the heading's acceleration tabulated (central differences of the exact
            # rate, GRID_PER_BEAT a wingbeat) over the path and RATE_MARGIN_BEATS beyond
            span = float(base.duration_beats) + abs(self.lag) / TWO_PI + RATE_MARGIN_BEATS
            tg = np.arange(-span, span + 1e-9, 1.0 / GRID_PER_BEAT) * TWO_PI
            self._grid = (tg, np.gradient(self._rate(tg), tg))
        else:
            self.lag = 0.0
        self.lateral = bool(getattr(base, "is_3d", True))
        self.shift_y = 0.0
        self.shift_y = float(self.goal(np.array([0.0]))["y"][0])
        self.t0 = 0.0
        self.delta = np.zeros(3)
        self.delta_vel = np.zeros(3)
        self.delta_acc = np.zeros(3)
        #: (t, delta, delta_vel, delta_acc) of every control update
        self.history: list[tuple[float, np.ndarray, np.ndarray, np.ndarray]] = []

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__") or name == "_base":
            raise AttributeError(name)
        return getattr(self._base, name)

    def set_steering(self, t: float, delta: Any, delta_vel: Any, delta_acc: Any) -> None:
        """From reduced time ``t`` on, delta = delta + delta_vel tau + delta_acc tau^2 / 2."""
        self.t0 = float(t)
        self.delta = np.array(delta, dtype=float)
        self.delta_vel = np.array(delta_vel, dtype=float)
        self.delta_acc = np.array(delta_acc, dtype=float)
        self.history.append((self.t0, self.delta, self.delta_vel, self.delta_acc))

    def goal(self, t: Any) -> dict[str, np.ndarray]:
        """The bird's place: x, y, z and their rates and accelerations at reduced times
        ``t``.  Turned (``turn_offset``): the leader's path ``x / V0`` later (``V0`` its
        speed at the start: an arc ``x`` along it for a path at constant speed) moved
        ``y`` along its left normal and ``z`` up: parallel paths, the inner bird slower
        by ``1 - y kappa`` (a rigid formation turned about the leader would swing the
        birds behind it outwards at the turn's start).  Else: the leader's path plus
        the offset (world axes).

        The goal is a function of ``t`` alone (the steering is added by :meth:`sample`):
        the last :data:`GOAL_CACHE` are kept and handed out as copies (a control update
        asks for the same times several times: the track's state, the lockstep's rules)."""
        t = np.asarray(t, dtype=float)
        key = (t.shape, t.tobytes())
        out = self._goals.get(key)
        if out is None:
            out = self._goal(t)
            if len(self._goals) >= GOAL_CACHE:
                self._goals.clear()
            self._goals[key] = out
        return {k: v.copy() for k, v in out.items()}

    def _goal(self, t: np.ndarray) -> dict[str, np.ndarray]:
        ox, oy, oz = self.offset
        if not self.turn_offset:
            s = self._base.sample(t)
            out = {k: np.array(s[k], dtype=float) for k in s}
            out["x"], out["y"] = out["x"] + ox, out["y"] + oy
            out["z"] = out["z"] + oz
            return out
        q = t + self.lag
        s = self._base.sample(q)
        out = {k: np.array(s[k], dtype=float) for k in s}
        # heading psi, its rate and acceleration; T = (c, s), n = (-s, c) the left normal
        vx, vy = s["vx"], s["vy"]
        psi = np.arctan2(vy, vx)
        rate = (vx * s["ay"] - vy * s["ax"]) / np.maximum(vx * vx + vy * vy, 1e-12)
        tg, rate_dots = self._grid
        rate_dot = np.interp(q, tg, rate_dots)
        outside = (q < tg[0]) | (q > tg[-1])
        if np.any(outside):  # beyond the table: central differences of the exact rate
            dt = 1e-3 * TWO_PI
            fd = (self._rate(q + dt) - self._rate(q - dt)) / (2.0 * dt)
            rate_dot = np.where(outside, fd, rate_dot)
        c, sn = np.cos(psi), np.sin(psi)
        # p = L + oy n; p' = v - oy psi' T; p'' = a - oy (psi'' T + psi'^2 n)
        out["x"], out["y"] = out["x"] - oy * sn, out["y"] + oy * c
        out["vx"], out["vy"] = out["vx"] - oy * rate * c, out["vy"] - oy * rate * sn
        out["ax"] = out["ax"] - oy * (rate_dot * c - rate * rate * sn)
        out["ay"] = out["ay"] - oy * (rate_dot * sn + rate * rate * c)
        out["z"] = out["z"] + oz
        return out

    def _rate(self, t: np.ndarray) -> np.ndarray:
        """The leader path's heading rate (vx ay - vy ax) / v_h^2 at reduced times ``t``."""
        s = self._base.sample(t)
        v2 = np.maximum(s["vx"] ** 2 + s["vy"] ** 2, 1e-12)
        return (s["vx"] * s["ay"] - s["vy"] * s["ax"]) / v2

    def sample(self, t: Any) -> dict[str, np.ndarray]:
        """The reference at reduced times ``t``: the goal plus the steering displacement."""
        t = np.asarray(t, dtype=float)
        out = self.goal(t)
        out["y"] = out["y"] - self.shift_y
        tau = t - self.t0
        for i, k in enumerate("xyz"):
            d, v, a = self.delta[i], self.delta_vel[i], self.delta_acc[i]
            if d == 0.0 and v == 0.0 and a == 0.0:
                continue
            out[k] = out[k] + d + v * tau + 0.5 * a * tau * tau
            out["v" + k] = out["v" + k] + v + a * tau
            out["a" + k] = out["a" + k] + a
        return out

    def state(self, t: float) -> Any:
        from birdsim.flight.path import PathState

        s = self.sample(float(t))
        keys = ("x", "z", "vx", "vz", "ax", "az", "y", "vy", "ay")
        return PathState(*(float(s[k]) for k in keys))

    def steering_at(self, t: np.ndarray) -> np.ndarray:
        """delta at reduced times ``t`` (n, 3) from the recorded control updates."""
        t = np.asarray(t, dtype=float)
        out = np.zeros((len(t), 3))
        if not self.history:
            return out
        starts = np.array([h[0] for h in self.history])
        idx = np.clip(np.searchsorted(starts, t + 1e-12, side="right") - 1, 0, None)
        for j, (t0, d, v, a) in enumerate(self.history):
            m = idx == j
            if m.any():
                tau = (t[m] - t0)[:, None]
                out[m] = d + v * tau + 0.5 * a * tau * tau
        return out


__all__ = ["STEERING_KEYS", "FlockPath", "SteeringConfig", "rule_accelerations"]
