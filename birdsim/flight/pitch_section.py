"""The free body's pitch loop in slow straight flight, from stroboscopic samples of the
body's periodic rocking (docs/free-body.md, "The pigeon's attitude, seventh stage").

A flapping body is a periodic system: its pitch rocks within every wingbeat about the
wingbeat-mean.  The attitude loop's estimate fits the last wingbeat by a trend and three
harmonics, and a rocking whose amplitude changes from one wingbeat to the next leaks into
that trend by about half its amplitude.  Here the pitch and the pitch rate are sampled
at four phases a quarter wingbeat apart (the newest :data:`QUAD_OFFSET_BEATS` before
now): the mean of the four cancels the rocking's first three harmonics whatever their
amplitude and phase, and is the wingbeat-mean state at the samples' centre, 7/16 of a
wingbeat ago.  The wingbeat-mean model of the attitude loop's last measurement
(:func:`birdsim.flight.pitch_observer.loop_model`: ``I q' = M_0 + J u - k (theta -
theta_J) + D q``, the inputs flown through their smoothing;
:class:`birdsim.flight.pitch_observer.PitchObserver`'s prediction) carries that state on
to now: every control step the prediction is moved by the free motion that makes it
match the measured means then.

The control is discrete, per control step ``h``, on the error from the planned pitch,
``x = (e, r, f1, f2, z)``: ``e`` and ``r`` the wingbeat-mean pitch and rate error, ``f1``
and ``f2`` the shoulders' two cascaded smoothing filters (time constant
:data:`birdsim.flight.wingbeat.INPUT_SMOOTHING_BEATS`) of the commanded acceleration
``v``, ``z`` the error's integral (a bias: the rocking's rectified moment, what the held
body misses); the exact zero-order-hold map ``x+ = Phi x + Gamma v`` of that model
(:func:`section_map`), and ``v = -K x`` with three poles of the closed loop at
``exp(-h / (SECTION_BEATS wingbeats))`` and the filters' two where they are (Ackermann's
formula, :func:`placed_gain`).  The moment demanded, ``I (theta_ref'' + v) - M_0 + k
(theta_ref - theta_J) - D q_ref``, goes to the shoulders unfiltered
(:meth:`birdsim.flight.attitude.AttitudeLoop.update`'s ``pitch_demand``).  Reduced units
(time in 1 / omega), seed body axes (pitch nose up), radians.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any

import numpy as np
from scipy.linalg import expm

from birdsim.flight.air_angle import gate_stiffness
from birdsim.flight.attitude_jacobians import INPUTS
from birdsim.flight.flight_arrays import error_rotvec
from birdsim.flight.pitch_observer import SLOW_SPEED, PitchObserver, loop_model
from birdsim.flight.pitch_rocking import rocking_pitch_moment
from birdsim.flight.rocking_share import RockingShare
from birdsim.flight.wingbeat import INPUT_SMOOTHING_BEATS

TWO_PI = 2.0 * math.pi  # one wingbeat in reduced time units

#: Close the slow straight flight's pitch loop on the stroboscopic samples (else the
#: fit's estimate and the attitude loop's own pitch demand).  Slow flight: entered at an
#: airspeed below SLOW_SPEED, kept while the tail has no pitch stiffness (the eighth
#: stage: a take-off's climb-out, up to where the tail starts to restore; entered at any
#: speed, a landing's flare switched over mid-swing and looped; over the whole flight the
#: pigeon's landing diverged and its cruise lost 4 degrees; docs/free-body.md).
SECTION_LOOP = True
#: The newest of the four samples, a fraction of the wingbeat before now: where the
#: rate's fourth harmonic (which the four samples do not cancel) crossed zero in the
#: pigeon's slow flights (measured: the quads' rate error 0.002-0.008 rad per time unit
#: at 1/16 and 3/16, 0.013-0.015 at 0 and 1/8).
QUAD_OFFSET_BEATS = 1.0 / 16.0
#: Wingbeats per time constant of the closed loop's three slow poles.
SECTION_BEATS = 1.0
#: The loop's model counts the body's rocking's rectified moment in ``M_0``
#: (:func:`birdsim.flight.pitch_rocking.rocking_pitch_moment`, measured once per
#: measurement of the attitude loop's Jacobians while the loop is on), and the attitude
#: loop's pitch integral takes it over when the loop is left (tenth stage: the pigeon's
#: take-off pitch 7.79 -> 6.09 degrees RMS; docs/free-body.md).
ROCKING_MOMENT = True
#: While the loop is on, the attitude loop's Jacobians, ``M_0`` and the rocking's moment
#: are measured again when the command has moved by this much since (rad; elsewhere
#: :data:`birdsim.flight.attitude.JAC_DPITCH`, 0.1): the model is piecewise constant,
#: and at 0.1 rad its ``M_0`` with the rocking's moment stepped by up to 0.003 table
#: units in the take-off's climb-out (the pigeon's take-off pitch 6.09 degrees RMS; at
#: 0.04 and 0.02 rad 4.43 and 4.52: converged; tenth stage).
SECTION_JAC_DPITCH = 0.04
#: At the hand-back the rocking's moment stays a measured, lagged part of the attitude
#: loop's ``M_0`` (:mod:`birdsim.flight.rocking_share`); else the attitude loop's pitch
#: integral takes it over (the tenth stage: it stayed there while the take-off's wingbeat
#: turned into the cruise's; the pigeon's take-off pitch 4.43 -> 3.81 degrees RMS, eleventh
#: stage, docs/free-body.md).
ROCKING_HANDBACK = True


def section_map(
    inertia: float, stiffness: float, damping: float, h: float, tau: float
) -> tuple[np.ndarray, np.ndarray]:
    """(Phi (5, 5), Gamma (5,)): the map over ``h`` time units of ``x = (e, r, f1, f2,
    z)`` with ``v`` held: ``e' = r``, ``r' = f2 - (k / I) e + (D / I) r`` (``stiffness``
    k >= 0 and ``damping`` D in table units per rad and per rad per time unit, ``inertia``
    I), ``f1' = (v - f1) / tau``, ``f2' = (f1 - f2) / tau``; ``z+ = z + h e``."""
    a = np.zeros((5, 5))
    a[0, 1] = 1.0
    a[1, 0], a[1, 1], a[1, 3] = -stiffness / inertia, damping / inertia, 1.0
    a[2, 2], a[2, 4] = -1.0 / tau, 1.0 / tau
    a[3, 2], a[3, 3] = 1.0 / tau, -1.0 / tau
    e = expm(a * h)  # the input as a fifth state, constant
    phi = np.zeros((5, 5))
    phi[:4, :4] = e[:4, :4]
    phi[4, 0], phi[4, 4] = h, 1.0
    return phi, np.concatenate([e[:4, 4], [0.0]])


def placed_gain(phi: np.ndarray, gamma: np.ndarray, poles: list[float]) -> np.ndarray:
    """``K`` with the eigenvalues of ``Phi - Gamma K`` at ``poles`` (Ackermann's formula)."""
    n = len(gamma)
    ctrb = np.stack([np.linalg.matrix_power(phi, j) @ gamma for j in range(n)], axis=1)
    poly = np.eye(n)
    for p in poles:
        poly = poly @ (phi - p * np.eye(n))
    return np.linalg.solve(ctrb.T, np.eye(n)[-1]) @ poly


class SectionPitch:
    """The estimate and the discrete loop of one flight (see the module).  ``att`` the
    attitude loop (its last measurement's model, the inputs it commanded), ``per_beat``
    log samples per wingbeat (a multiple of 16), ``dt_ctl`` the control step (time units);
    ``rocking``: the model counts the rocking's rectified moment (``att`` a flight's
    :class:`birdsim.flight.attitude.AttitudeLoop`: its bird and the wingbeat it measured at)."""

    def __init__(self, att: Any, per_beat: int, dt_ctl: float, rocking: bool = False):
        self.att = att
        self.with_rocking = rocking
        self.dt = dt_ctl
        self.tau = INPUT_SMOOTHING_BEATS * TWO_PI
        self.quarter = per_beat // 4
        self.offset = int(round(QUAD_OFFSET_BEATS * per_beat))
        self.lag = self.offset + 3 * self.quarter // 2  # the samples' centre (samples ago)
        smoothed = np.array([kind == "shoulder" for _, kind, _ in INPUTS])
        self.obs = PitchObserver(TWO_PI, per_beat, self.tau, smoothed)
        self.on = False
        self.f = np.zeros(3)  # the loop's (f1, f2, z)
        self.v = 0.0  # the commanded acceleration (per unit inertia)
        self._design: dict = {}
        self._rock_for: object = None  # the attitude loop's M_0 the moment below is for
        self._rock = 0.0  # the rocking's rectified moment (table units)

    def _gain(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(Phi, Gamma, K) for the last measurement's inertia, stiffness and damping."""
        att = self.att
        key = (float(att.inertia[1]), float(att.stiffness[1]), float(att.rate_jac[1, 1]))
        if key not in self._design:
            phi, gam = section_map(*key, self.dt, self.tau)
            p, p_f = math.exp(-self.dt / (SECTION_BEATS * TWO_PI)), math.exp(-self.dt / self.tau)
            self._design[key] = (phi, gam, placed_gain(phi, gam, [p, p, p, p_f, p_f]))
        return self._design[key]

    def rocking(self) -> float:
        """The rocking's rectified pitching moment at the attitude loop's last measurement
        (its pitch, airspeed and wingbeat; table units); 0 without ``rocking``."""
        att = self.att
        if not self.with_rocking:
            return 0.0
        m0 = att._jac[1]
        if self._rock_for is not m0:  # once per measurement of M_0
            inertia = float(att.inertia[1])
            theta, v = att.held_at  # the measurement's held body (air_angle), as M_0's
            self._rock = rocking_pitch_moment(att.fb, att.check.at, theta, max(v, 0.0), inertia)[0]
            self._rock_for = m0
        return self._rock

    def step(
        self,
        window: tuple,
        ref: tuple[float, float, float],
        airspeed: float,
        air: float = 0.0,
    ) -> tuple[float, float, float] | None:
        """Every control step: ``window`` the last wingbeat's (quaternions, seed body
        rates) per log sample, the newest now; ``ref`` the planned pitch, rate and
        acceleration now; ``air`` the air path's angle (rad), at which this loop's model
        is measured (:mod:`birdsim.flight.air_angle`; the other loops' in horizontal
        air).  Returns (wingbeat-mean pitch, its rate, the pitch moment
        demanded, table units), or None outside slow straight flight (entered below
        ``SLOW_SPEED``, left when the tail's pitch stiffness appears) or before a wingbeat
        of samples: the fit's estimate and the loop's own demand then."""
        att, obs = self.att, self.obs
        quat, omega = window
        # entered below SLOW_SPEED, kept on while the tail has no pitch stiffness
        slow = (airspeed < SLOW_SPEED or self.on) and gate_stiffness(att) <= 1e-9  # (round-off)
        if not (slow and att.enabled and att.straight and att._jac is not None):
            if (
                self.on and ROCKING_HANDBACK and self.with_rocking
            ):  # the loop's M_0 counts the moment from now on
                att.rocking = RockingShare(self._rock, att._flap(att.check.at))
            elif self.on:  # the attitude loop's pitch integral holds the rocking's moment
                att.integral[1] -= self._rock / float(att.inertia[1])
            self.on, att.air_angle = False, 0.0
            return None
        att.air_angle = air
        if len(quat) <= self.offset + 3 * self.quarter:
            return None
        idx = -1 - self.offset - self.quarter * np.arange(4)
        theta = float(np.mean(ref[0] - error_rotvec(quat[idx], ref[0])[:, 1]))
        q = float(np.mean(omega[idx, 1]))
        phi, gam, k = self._gain()
        model = loop_model(att)  # the last measurement's (unchanged within the step)
        rock = self.rocking()
        model = replace(model, m0=model.m0 + rock) if rock else model
        lag_t = self.lag * obs.dt
        if not self.on:  # start at the samples' means, carried on as a free motion; the
            # integral where it holds the attitude loop's integral's acceleration (which
            # held the rocking's moment too)
            obs.start(theta + q * lag_t, q, 0.0, att.u)
            kept = getattr(att, "rocking", None)  # a share in the loop's M_0 (rocking_share)
            held, att.rocking = (0.0 if kept is None else kept.used), None
            share = float(att.integral[1]) + (rock - held) / model.inertia
            self.f = np.array([0.0, 0.0, -share / k[4]])
            self.on = True
        else:  # predict over the step just flown, then move onto the measured means
            obs.predict(model, att.u, int(round(self.dt / obs.dt)))
            x = np.array([float(obs.state[0]) - ref[0], 0.0, *self.f])
            self.f = (phi @ x + gam * self.v)[2:]
            if att.saturated:  # anti-windup
                self.f[2] = x[4]
            if len(obs.hist) > self.lag:
                d_q = q - obs.hist[-1 - self.lag, 1]
                obs.shift(theta - obs.hist[-1 - self.lag, 0] + d_q * lag_t, d_q)
        x = np.array([obs.state[0] - ref[0], obs.state[1] - ref[1], *self.f])
        self.v = -float(k @ x)
        demand = model.inertia * (ref[2] + self.v) - model.m0
        demand += model.stiffness * (ref[0] - model.theta_j) - model.d_qq * ref[1]
        if abs(att._jac[3] - ref[0]) > SECTION_JAC_DPITCH:  # measured again this step
            att._jac = None
        return float(obs.state[0]), float(obs.state[1]), demand


def section_source(att: Any, per_beat: int, dt_ctl: float, straight: bool) -> Callable[..., tuple]:
    """The wingbeat-mean pitch, the attitude error and rates, and the pitch moment demanded
    as a function of (``window``, ``ref`` (planned pitch, rate, acceleration), ``err``,
    ``rates``, ``airspeed``, the air path's angle) called every control step: in slow straight flight
    (:data:`SECTION_LOOP`, ``straight``) the section's (:class:`SectionPitch`; ``err`` and
    ``rates`` copied with their pitch entries replaced), else the fit's pitch (``ref[0]
    - err[1]``), ``err``, ``rates`` and None."""
    on = SECTION_LOOP and straight
    sec = SectionPitch(att, per_beat, dt_ctl, rocking=ROCKING_MOMENT) if on else None

    def source(
        window: tuple, ref: tuple, err: Any, rates: Any, airspeed: float, air: float = 0.0
    ) -> tuple:
        out = None if sec is None else sec.step(window, ref, airspeed, air)
        if out is None:
            return ref[0] - float(err[1]), err, rates, None
        err, rates = np.array(err, dtype=float), np.array(rates, dtype=float)
        err[1], rates[1] = ref[0] - out[0], out[1]
        return out[0], err, rates, out[2]

    return source


__all__ = [
    "QUAD_OFFSET_BEATS",
    "ROCKING_HANDBACK",
    "ROCKING_MOMENT",
    "SECTION_BEATS",
    "SECTION_JAC_DPITCH",
    "SECTION_LOOP",
    "SectionPitch",
    "placed_gain",
    "section_map",
    "section_source",
]
