"""The curves of a flight path: minimum-jerk quintic segments, their slopes, and the
ground track of a speed-and-heading path (issue 9 item 3; issue 23 item 1).

Every coordinate of a path (x, y, z, or a speed V and a heading) is a piecewise quintic
with the keyframe values, slopes and a zero second derivative at every keyframe
(:func:`quintic_hermite`): a minimum-jerk blend, C2. The speed form integrates the
horizontal velocity ``V (cos heading, sin heading)`` into x and y
(:class:`HeadingTrack`): no closed form, so by Gauss-Legendre quadrature on short pieces,
exact to round-off for these smooth integrands.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.interpolate import PPoly

#: Gauss-Legendre nodes per piece of the heading track's quadrature.
GL_NODES = 16
#: Longest piece of the quadrature (reduced time: a quarter wingbeat) and largest heading
#: change on one piece (rad): 16 nodes are then exact to round-off.
GL_PIECE = 0.5 * math.pi
GL_TURN = 0.5


def knot_slopes(
    t: np.ndarray, y: np.ndarray, given: list[float | None], ends: str | tuple[str, str] = "level"
) -> np.ndarray:
    """Slopes dy/dt at the knots: ``given`` where not None, else the harmonic mean of the
    neighbouring secants (0 at an extremum or flat data: at most twice the smaller secant,
    which keeps a quintic minimum-jerk segment monotone). End slopes: ``level`` / ``zero``
    = 0, ``secant`` = the adjacent segment's secant. One knot: slope 0 (or given).

    Args:
        t: knot times, increasing (n,).
        y: knot values (n,).
        given: per knot a slope or None (n,).
        ends: rule for the first and last knot (one string for both, or a pair).

    Returns:
        Slopes (n,).
    """
    n = len(t)
    first, last = (ends, ends) if isinstance(ends, str) else ends
    m = np.zeros(n)
    if n > 1:
        d = np.diff(y) / np.diff(t)
        for i in range(1, n - 1):
            a, b = d[i - 1], d[i]
            m[i] = 2.0 * a * b / (a + b) if a * b > 0 else 0.0
        m[0] = d[0] if first == "secant" else 0.0
        m[-1] = d[-1] if last == "secant" else 0.0
    for i, g in enumerate(given):
        if g is not None:
            m[i] = float(g)
    return m


def quintic_hermite(t: np.ndarray, y: np.ndarray, dy: np.ndarray) -> PPoly:
    """Piecewise quintic through ``(t, y)`` with slopes ``dy`` and zero second derivative
    at every knot (C2; a minimum-jerk blend). One knot gives a constant (a segment of
    length 1 is added so that PPoly has an interval). Not extrapolating: callers continue
    linearly outside (see :func:`eval_extrapolated`)."""
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    dy = np.asarray(dy, dtype=float)
    if len(t) == 1:
        t = np.array([t[0], t[0] + 1.0])
        y = np.array([y[0], y[0] + dy[0]])
        dy = np.array([dy[0], dy[0]])
    n = len(t) - 1
    c = np.zeros((6, n))
    for i in range(n):
        h = t[i + 1] - t[i]
        y0, y1, v0, v1 = y[i], y[i + 1], dy[i] * h, dy[i + 1] * h  # in local s = (t - t_i) / h
        # p(s) = y0 + v0 s + a3 s^3 + a4 s^4 + a5 s^5 with p(1) = y1, p'(1) = v1, p''(1) = 0
        rhs = np.array([y1 - y0 - v0, v1 - v0, 0.0])
        a3, a4, a5 = np.linalg.solve(
            np.array([[1.0, 1.0, 1.0], [3.0, 4.0, 5.0], [6.0, 12.0, 20.0]]), rhs
        )
        coef_s = np.array([a5, a4, a3, 0.0, v0, y0])  # highest power first
        c[:, i] = coef_s / h ** np.arange(5, -1, -1)
    return PPoly(c, t, extrapolate=False)


def eval_extrapolated(pp: PPoly, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Value, first and second derivative of ``pp`` at ``t``; outside the knots the
    curve continues on its end tangent (zero second derivative: the knots' own)."""
    t0, t1 = pp.x[0], pp.x[-1]
    tc = np.clip(t, t0, t1)
    y, v, a = pp(tc), pp(tc, 1), pp(tc, 2)
    a = np.where((t < t0) | (t > t1), 0.0, a)
    return y + v * (t - tc), v, a


class HeadingTrack:
    """The ground track of a speed (``V``) and heading (``psi``) pair of quintics:
    ``x' = V cos psi``, ``y' = V sin psi`` from ``(x0, y0)`` at the first knot.

    Outside the knots V and psi hold their end values (level ends: the caller checks that
    the end turn rates are 0), so the track continues straight at constant velocity.
    """

    def __init__(self, v: PPoly, psi: PPoly, x0: float, y0: float) -> None:
        self.v, self.psi = v, psi
        knots = v.x
        edges = [knots[0]]
        for a, b in zip(knots[:-1], knots[1:]):
            sample = np.linspace(a, b, 65)
            turn = float(np.max(np.abs(psi(sample, 1)))) * (b - a)
            n = max(1, math.ceil((b - a) / GL_PIECE), math.ceil(turn / GL_TURN))
            edges.extend(np.linspace(a, b, n + 1)[1:])
        self.edges = np.array(edges)
        self.nodes, self.weights = np.polynomial.legendre.leggauss(GL_NODES)
        dx, dy = self._integrate(self.edges[:-1], self.edges[1:])
        self.cum_x = x0 + np.concatenate([[0.0], np.cumsum(dx)])
        self.cum_y = y0 + np.concatenate([[0.0], np.cumsum(dy)])

    def _integrate(self, a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        half = 0.5 * (b - a)
        tt = (a + half)[..., None] + half[..., None] * self.nodes
        flat = tt.ravel()
        v, psi = self.v(flat).reshape(tt.shape), self.psi(flat).reshape(tt.shape)
        w = half[..., None] * self.weights
        return np.sum(w * v * np.cos(psi), axis=-1), np.sum(w * v * np.sin(psi), axis=-1)

    def position(self, tc: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """x, y at times ``tc`` inside the knots."""
        k = np.clip(np.searchsorted(self.edges, tc, side="right") - 1, 0, len(self.edges) - 2)
        dx, dy = self._integrate(self.edges[k], tc)
        return self.cum_x[k] + dx, self.cum_y[k] + dy

    def sample(self, t: np.ndarray) -> dict[str, np.ndarray]:
        """x, y, vx, vy, ax, ay at reduced times ``t`` (any shape)."""
        t = np.asarray(t, dtype=float)
        t0, t1 = self.edges[0], self.edges[-1]
        tc = np.clip(t, t0, t1)
        x, y = self.position(tc)
        v, dv = self.v(tc), self.v(tc, 1)
        psi, rate = self.psi(tc), self.psi(tc, 1)
        c, s = np.cos(psi), np.sin(psi)
        outside = (t < t0) | (t > t1)
        ax = np.where(outside, 0.0, dv * c - v * rate * s)
        ay = np.where(outside, 0.0, dv * s + v * rate * c)
        vx, vy = v * c, v * s
        return {
            "x": x + vx * (t - tc),
            "y": y + vy * (t - tc),
            "vx": vx,
            "vy": vy,
            "ax": ax,
            "ay": ay,
        }


__all__ = ["HeadingTrack", "eval_extrapolated", "knot_slopes", "quintic_hermite"]
