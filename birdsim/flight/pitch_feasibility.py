"""Can the free body follow a pitch command at all?  The bound the wingbeat-mean
authority of the pitch inputs puts on pitch tracking (reduced units: time in 1 / omega,
moments in weight x semispan, "table units"; seed body axes, pitch nose up; rad).

Per instant of a command ``theta_c(t)`` the wingbeat-mean pitch dynamics of the free body
are ``I theta'' = M_0 + D q + K (theta - theta_c) + M_u``: ``M_0`` the held body's moment
at the commanded state with every input at zero (the table's wingbeat, its stroke plane
compensated for the command), ``D`` the pitch damping (dM/dq), ``K`` the stiffness
(dM/dtheta, the stroke plane held in the world), ``M_u`` what the pitch inputs (the
shoulders' sweep and dihedral offsets, the tail's elevation) deliver, within
``[down, up]`` (:func:`pitch_authority`: the stored Jacobian's row times the inputs'
bounds, the extreme corner of the box).  Following the command exactly needs
``M_u = I theta_c'' - M_0 - D theta_c'`` (:func:`required_moment`).  Where that lies
outside ``[down, up]`` the body must fall behind; :func:`least_tracking_error` gives the
smallest RMS error any controller could reach on this model (the inputs chosen over the
whole flight at once, by bounded least squares), i.e. a lower bound of the error from
authority alone.  It is a bound of the wingbeat-mean model: the within-wingbeat rocking,
the estimate's lag and what the held body misses come on top (docs/free-body.md, "The
pigeon's landing: is the pitch plan reachable?").  ``scripts/landing_pitch_bound.py``
prints it per wingbeat of a flight.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import lsq_linear


def pitch_authority(row: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> tuple[float, float]:
    """(largest nose-down, largest nose-up) pitching moment (table units; the first <= 0
    <= the second) that inputs within ``[lo, hi]`` deliver on the linear model ``row @
    u`` (``row`` the pitch row of the inputs' Jacobian over the same inputs)."""
    a, b = np.asarray(row, dtype=float) * lo, np.asarray(row, dtype=float) * hi
    return float(np.minimum(a, b).sum()), float(np.maximum(a, b).sum())


def corner_inputs(row: np.ndarray, lo: np.ndarray, hi: np.ndarray, nose_up: bool) -> np.ndarray:
    """The inputs at the corner of ``[lo, hi]`` where ``row @ u`` is largest (``nose_up``)
    or smallest: the inputs :func:`pitch_authority`'s bound assumes (to measure the
    moment there without the linearisation)."""
    row = np.asarray(row, dtype=float)
    up = np.where(row >= 0.0, hi, lo)
    return np.asarray(up if nose_up else np.where(row >= 0.0, lo, hi), dtype=float)


def required_moment(
    inertia: float, acc: np.ndarray, rate: np.ndarray, m0: np.ndarray, damping: np.ndarray
) -> np.ndarray:
    """The inputs' pitching moment that makes the body follow a command of angular
    acceleration ``acc`` and rate ``rate`` (per time unit^2, per time unit) exactly:
    ``inertia acc - M_0 - D rate`` (``m0`` the moment at the commanded state with the
    inputs at zero, ``damping`` dM/dq there; each a number or one per instant)."""
    return inertia * np.asarray(acc, dtype=float) - np.asarray(m0) - np.asarray(damping) * rate


def error_response(
    inertia: float, dt: float, damping: np.ndarray, stiffness: np.ndarray
) -> np.ndarray:
    """(n, n): the pitch error (rad) at the end of each of ``n`` steps of ``dt`` per unit
    moment held over each step (a zero-order hold), on ``I e'' = D e' + K e + m`` (the
    error's dynamics about the command; ``damping`` and ``stiffness`` per step, table
    units), from zero error and rate; integrated exactly per step (the step's matrix
    exponential)."""
    from scipy.linalg import expm

    n = len(damping)
    phis, gams = [], []
    for d, k in zip(np.asarray(damping, dtype=float), np.asarray(stiffness, dtype=float)):
        a = np.array([[0.0, 1.0, 0.0], [k / inertia, d / inertia, 1.0 / inertia], [0.0, 0.0, 0.0]])
        e = expm(a * dt)
        phis.append(e[:2, :2])
        gams.append(e[:2, 2])
    g = np.zeros((n, n))
    for j in range(n):  # a unit moment over step j, then free
        x = gams[j].copy()
        g[j, j] = x[0]
        for i in range(j + 1, n):
            x = phis[i] @ x
            g[i, j] = x[0]
    return g


def least_tracking_error(
    required: np.ndarray,
    down: np.ndarray,
    up: np.ndarray,
    inertia: float,
    dt: float,
    damping: np.ndarray | float = 0.0,
    stiffness: np.ndarray | float = 0.0,
) -> tuple[float, np.ndarray, np.ndarray]:
    """(the smallest RMS pitch error (rad) over the steps, that error per step, the inputs'
    moment per step) of a body that starts on the command and has per step of ``dt`` the
    authority ``[down, up]`` against the moment ``required`` (:func:`required_moment`):
    the moment shortfall ``m - required`` drives the error through
    :func:`error_response`; the inputs' moments ``m`` chosen over all steps at once by
    bounded least squares (:func:`scipy.optimize.lsq_linear`).  Zero where ``required``
    is within the authority at every step."""
    req = np.asarray(required, dtype=float)
    n = len(req)
    lo, hi = np.asarray(down, dtype=float), np.asarray(up, dtype=float)
    if np.all((req >= lo) & (req <= hi)):
        return 0.0, np.zeros(n), req.copy()
    d = np.broadcast_to(np.asarray(damping, dtype=float), (n,))
    k = np.broadcast_to(np.asarray(stiffness, dtype=float), (n,))
    g = error_response(inertia, dt, d, k)
    # e = g (m - req): minimise |g m - g req| within [lo, hi]
    res = lsq_linear(g, g @ req, bounds=(lo, np.maximum(hi, lo + 1e-15)), lsmr_tol="auto")
    err = g @ (res.x - req)
    return float(math.sqrt(np.mean(err**2))), err, res.x


def beat_differences(means: np.ndarray, period: float) -> tuple[np.ndarray, np.ndarray]:
    """(rate per time unit, acceleration per time unit^2) of per-wingbeat means
    ``means`` (one a wingbeat of ``period`` time units): central first and second
    differences (one-sided at the ends; zero acceleration there)."""
    v = np.asarray(means, dtype=float)
    rate = np.gradient(v, period) if v.size > 1 else np.zeros_like(v)
    acc = np.zeros_like(v)
    acc[1:-1] = (v[2:] - 2.0 * v[1:-1] + v[:-2]) / period**2
    return rate, acc


__all__ = [
    "beat_differences",
    "corner_inputs",
    "error_response",
    "least_tracking_error",
    "pitch_authority",
    "required_moment",
]
