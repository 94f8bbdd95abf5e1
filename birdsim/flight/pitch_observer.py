"""The free body's wingbeat-mean pitch model and its prediction, for the slow straight
flight's pitch loop (:mod:`birdsim.flight.pitch_section`; docs/free-body.md, "The
pigeon's attitude", sixth and seventh stages).

The attitude loop's last measurement gives the wingbeat-mean moment,

    I q' = M_0 + J u - k (theta - theta_J) + D_qq q + I beta,

(``beta`` a moment bias per unit inertia); :class:`PitchObserver` integrates it with the
inputs flown through their smoothing and keeps the prediction of the last wingbeat, so
that a measurement of the wingbeat-mean state some samples ago can move the prediction
(:meth:`PitchObserver.shift`).  (Sixth stage: an observer that corrected this prediction
slowly by the one-wingbeat fit, for the stroke plane's compensation in slow flight; the
seventh stage's stroboscopic estimate replaced it.)  Reduced units (time in 1 / omega),
seed body axes (pitch nose up), radians.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

#: Slow flight: the airspeed (semispan omega) below which, with no pitch stiffness from
#: the tail, the pitch loop of :mod:`birdsim.flight.pitch_section` runs: half the presets'
#: cruise speed (0.5).  Measured with the sixth stage's observer (take-off pitch RMS /
#: landing path RMS): 0.1: 12.2 deg / 0.040 m, 0.15: 10.3 / 0.054, 0.2: 9.6 / 0.042, 0.25:
#: 10.0 / 0.039; with the seventh stage's loop 0.35: take-off 10.9 deg, landing 0.035 m
#: (docs/free-body.md).
SLOW_SPEED = 0.25


@dataclass(frozen=True)
class PitchModel:
    """The wingbeat-mean pitch model (reduced units, seed body axes): ``M_0`` (table
    units), the pitch row of ``J`` (table units per rad of each input), the pitch stiffness
    ``k`` (>= 0, table units per rad) about ``theta_j`` (rad), the pitch damping ``d_qq``
    (table units per rad per time unit) and the pitch inertia."""

    m0: float
    jac_row: np.ndarray
    stiffness: float
    theta_j: float
    d_qq: float
    inertia: float

    def acceleration(self, theta: float, q: float, u: np.ndarray) -> float:
        """The wingbeat-mean pitch acceleration (rad per time unit^2) the model predicts."""
        m = self.m0 + float(self.jac_row @ u) - self.stiffness * (theta - self.theta_j)
        return (m + self.d_qq * q) / self.inertia


class PitchObserver:
    """The prediction of the wingbeat-mean pitch (see the module).  ``period`` the
    wingbeat (time units), ``per_beat`` log samples per wingbeat, ``smooth_tau`` the time
    constant (time units) of the inputs' two cascaded filters and ``smoothed`` a mask of
    the inputs it applies to (the shoulders; the tail acts at once)."""

    def __init__(self, period: float, per_beat: int, smooth_tau: float, smoothed: np.ndarray):
        self.dt = period / per_beat
        self.n = per_beat
        self.smooth_tau = smooth_tau
        self.smoothed = np.asarray(smoothed, dtype=bool)
        self.state: np.ndarray | None = None  # (theta, q, beta)
        self.hist = np.zeros((0, 2))  # predicted (theta, q) per sample, the newest last
        self.u1 = self.u2 = np.zeros(len(smoothed))

    def start(self, theta: float, q: float, beta: float, u: np.ndarray) -> None:
        """Start at (``theta``, ``q``) with the bias ``beta`` (per unit inertia) and the
        inputs ``u`` in force."""
        self.state = np.array([theta, q, beta], dtype=float)
        self.u1 = np.array(u, dtype=float)
        self.u2 = self.u1.copy()
        self.hist = np.zeros((0, 2))

    def predict(self, model: PitchModel, u: np.ndarray, samples: int) -> None:
        """Advance the prediction over ``samples`` log samples with the inputs ``u``
        commanded (the shoulders through their smoothing, the tail at once)."""
        th, q, beta = self.state
        a = math.exp(-self.dt / self.smooth_tau)
        rows = []
        for _ in range(samples):
            self.u1 = np.where(self.smoothed, a * self.u1 + (1 - a) * u, u)
            self.u2 = np.where(self.smoothed, a * self.u2 + (1 - a) * self.u1, u)
            acc = model.acceleration(th, q, self.u2) + beta
            th += self.dt * (q + 0.5 * self.dt * acc)
            q += self.dt * acc
            rows.append((th, q))
        self.state[:2] = th, q
        self.hist = np.concatenate([self.hist, np.array(rows).reshape(-1, 2)])[-self.n :]

    def shift(self, d_th: float, d_q: float) -> None:
        """Move the state and the stored prediction by a free motion: ``d_th`` (rad) now
        and ``d_q`` (rad per time unit)."""
        self.state[:2] += (d_th, d_q)
        tau = -self.dt * np.arange(len(self.hist) - 1, -1, -1)
        self.hist[:, 0] += d_th + d_q * tau
        self.hist[:, 1] += d_q


def loop_model(att: Any) -> PitchModel:
    """The pitch model of the attitude loop ``att``'s last measurement."""
    _, m0, jac, theta_j = att._jac
    return PitchModel(
        float(m0[1]),
        np.asarray(jac[1], dtype=float),
        float(att.stiffness[1]),
        float(theta_j),
        float(att.rate_jac[1, 1]),
        float(att.inertia[1]),
    )


__all__ = ["SLOW_SPEED", "PitchModel", "PitchObserver", "loop_model"]
