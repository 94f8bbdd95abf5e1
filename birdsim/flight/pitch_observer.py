"""A model-driven observer of the free body's wingbeat-mean pitch, for the stroke plane's
compensation in slow flight on a straight path (docs/free-body.md, "The pigeon's
attitude, sixth stage").

The attitude loop's estimate (:func:`birdsim.flight.flight_arrays.attitude_estimate`)
fits the last wingbeat's samples by a trend plus three harmonics; a rocking whose
amplitude changes from one wingbeat to the next leaks into that trend by about half its
amplitude, and the stroke plane's compensation (the table's pitch minus the body's)
hands the leak on to the wings' force.  This observer predicts the wingbeat-mean pitch
from the loop's own model of the mean moment,

    I q' = M_0 + J u - k (theta - theta_J) + D_qq q + I beta,

the inputs flown through their smoothing, ``beta`` an estimated moment bias per unit
inertia (the rocking's rectified moment and what the held body's measurement misses),
and corrects the prediction slowly by the same one-wingbeat fit applied to the
measurement minus the prediction: a leak then reaches the estimate through a filter of
:data:`OBSERVER_BEATS` wingbeats, while the loop's own inputs move the estimate at once.
Where the prediction leaves the fit by more than :data:`RESET_RAD` (the model lost, as
in a landing's flare) the observer starts again at the fit.  The attitude loop itself
keeps the fit's estimate (the observer there was measured worse).  Reduced units (time
in 1 / omega), seed body axes (pitch nose up), radians.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from birdsim.flight import fast_observer
from birdsim.flight.attitude_jacobians import INPUTS
from birdsim.flight.body_attitude import FIT_BEATS, wingbeat_fit_matrix
from birdsim.flight.flight_arrays import error_rotvec
from birdsim.flight.wingbeat import INPUT_SMOOTHING_BEATS

TWO_PI = 2.0 * math.pi  # one wingbeat in reduced time units

#: Use the observer for the stroke plane's compensation in slow flight (else the fit).
PITCH_OBSERVER = True
#: Slow flight: the airspeed (semispan omega) below which, with no pitch stiffness from
#: the tail, the compensation takes the observer's pitch: half the presets' cruise speed
#: (0.5).  Measured with the pigeon (take-off pitch RMS / landing path RMS): 0.1: 12.2
#: deg / 0.040 m, 0.15: 10.3 / 0.054, 0.2: 9.6 / 0.042, 0.25: 10.0 / 0.039 (the landing
#: is chaotic: a spread, not a trend; docs/free-body.md, "sixth stage").
SLOW_SPEED = 0.25
#: Wingbeats per time constant of the observer's corrections of pitch and rate ...
OBSERVER_BEATS = 1.0
#: ... and of its bias (per unit inertia): the rate and the bias a critically damped
#: pair at 1 / (BIAS_BEATS wingbeats) when BIAS_BEATS = 2 OBSERVER_BEATS.
BIAS_BEATS = 2.0
#: Start again at the fit when the observer's pitch leaves it by more than this (rad).
RESET_RAD = 0.2


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
    """See the module docstring.  ``period`` the wingbeat (time units), ``per_beat`` log
    samples per wingbeat, ``smooth_tau`` the time constant (time units) of the inputs'
    two cascaded filters and ``smoothed`` a mask of the inputs it applies to (the
    shoulders; the tail acts at once)."""

    def __init__(
        self,
        period: float,
        per_beat: int,
        smooth_tau: float,
        smoothed: np.ndarray,
        beats: float = OBSERVER_BEATS,
        bias_beats: float = BIAS_BEATS,
    ):
        self.dt = period / per_beat
        self.n = per_beat
        self.fit = wingbeat_fit_matrix(per_beat, period, beats=FIT_BEATS)
        self.smooth_tau = smooth_tau
        self.smoothed = np.asarray(smoothed, dtype=bool)
        self.rate_gain = 1.0 / (beats * period)
        self.bias_gain = 1.0 / (bias_beats * period) ** 2
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

    def correct(self, theta: np.ndarray, q: np.ndarray, dt_ctl: float) -> tuple[float, float]:
        """Correct by the last wingbeat's measured pitch ``theta`` and rate ``q`` (per log
        sample, the newest last, at least as many as the prediction's history): the
        one-wingbeat fit's value now of the measurement minus the prediction, a fraction
        ``dt_ctl`` / (:data:`OBSERVER_BEATS` wingbeats) of it per control step, the bias
        from the rate's.  The stored prediction is moved by the correction (the same
        residual is not counted twice).  Returns (theta, q)."""
        k = len(self.hist)
        res = np.stack([theta[-k:], q[-k:]], axis=1) - self.hist
        if k < self.n:  # before a whole wingbeat: the earliest residual repeated
            res = np.vstack([np.repeat(res[:1], self.n - k, axis=0), res])
        r_th, r_q = self.fit[0] @ res
        g = min(1.0, dt_ctl * self.rate_gain)
        d_th, d_q = g * r_th, g * r_q
        self.state += (d_th, d_q, dt_ctl * self.bias_gain * r_q)
        tau = -self.dt * np.arange(k - 1, -1, -1)
        self.hist[:, 0] += d_th + d_q * tau
        self.hist[:, 1] += d_q
        return float(self.state[0]), float(self.state[1])


def pitch_source(att: Any, per_beat: int, dt_ctl: float, straight: bool) -> Callable[..., float]:
    """The body's wingbeat-mean pitch (rad) for the stroke plane's compensation, as a
    function of (``window``, ``pitch_ref``, ``err``, ``rates``, ``airspeed``) called
    every control step: the fit's (``pitch_ref - err[1]``, ``err`` / ``rates`` the fit's
    attitude error and body rates, seed body axes), and on a ``straight`` path with the
    fourth-stage pitch loop (``att.straight``) and :data:`PITCH_OBSERVER`, in slow flight
    (``airspeed`` below :data:`SLOW_SPEED` and no pitch stiffness from the tail) the
    observer's.  The observer then runs every control step: its prediction over the step
    just flown (the inputs ``att.u`` in force, the model of ``att``'s last measurement)
    corrected by ``window`` (the last wingbeat's quaternions and seed body rates)."""
    if not (straight and PITCH_OBSERVER and att.enabled and att.straight):
        return lambda window, pitch_ref, err, rates, airspeed: pitch_ref - float(err[1])
    smoothed = np.array([kind == "shoulder" for _, kind, _ in INPUTS])
    obs = PitchObserver(TWO_PI, per_beat, INPUT_SMOOTHING_BEATS * TWO_PI, smoothed)

    def pitch(window: tuple, pitch_ref: float, err: Any, rates: Any, airspeed: float) -> float:
        fit_pitch = pitch_ref - float(err[1])
        if obs.state is None:
            obs.start(fit_pitch, float(rates[1]), 0.0, att.u)
            return fit_pitch
        _, m0, jac, theta_j = att._jac
        stiffness, d_qq = float(att.stiffness[1]), float(att.rate_jac[1, 1])
        inertia = float(att.inertia[1])
        samples = int(round(dt_ctl / obs.dt))
        values = np.array([float(m0[1]), stiffness, float(theta_j), d_qq, inertia])
        a = math.exp(-obs.dt / obs.smooth_tau)
        th = fast_observer.step(obs, values, jac[1], att.u, samples, window, pitch_ref, dt_ctl, a)
        if th is None:  # the numpy reference
            jac_row = np.asarray(jac[1], dtype=float)
            model = PitchModel(float(m0[1]), jac_row, stiffness, float(theta_j), d_qq, inertia)
            obs.predict(model, att.u, samples)
            quat, omega = window
            theta = pitch_ref - error_rotvec(quat, pitch_ref)[:, 1]
            th, _ = obs.correct(theta, omega[:, 1], dt_ctl)
        if abs(th - fit_pitch) > RESET_RAD:  # the model lost: start again at the fit
            obs.start(fit_pitch, float(rates[1]), float(obs.state[2]), obs.u2)
            th = fit_pitch
        slow = airspeed < SLOW_SPEED and att.stiffness[1] <= 1e-9  # (round-off: no air)
        return th if slow else fit_pitch

    return pitch


__all__ = [
    "BIAS_BEATS",
    "OBSERVER_BEATS",
    "PITCH_OBSERVER",
    "RESET_RAD",
    "SLOW_SPEED",
    "PitchModel",
    "PitchObserver",
    "pitch_source",
]
