"""The inner loop: the body's attitude held by aerodynamic moments of wings and tail.

Every control step (``control_per_beat`` per wingbeat, like the path loop):

1. estimate: the body's Euler angles (:func:`euler_zyx`) and body rates over the last
   wingbeat fitted by a trend plus the wingbeat's first three harmonics
   (:func:`wingbeat_fit_matrix`): the trend's value now is the wingbeat-mean state
   without a moving average's half-wingbeat lag (the within-beat rocking is the physics,
   not an error);
2. demand: ``M = I (Kp e + Kd de/dt + Ki integral e) - M_0`` per body axis (seed body
   axes x fwd / y right / z down, about the centre of mass), e = commanded minus
   estimated (roll 0, pitch = the table's pitch, yaw 0), ``I`` the whole bird's
   principal moments about the centre of mass at the start, ``M_0`` the measured
   wingbeat-mean moment of the table's wingbeat with every input at zero;
3. allocation: ``min || J u - M ||^2 + lambda || u / u_max ||^2`` within the inputs'
   bounds (:func:`scipy.optimize.lsq_linear`), the inputs :data:`INPUTS`: the wings'
   differential flap and twist amplitudes, sweep and dihedral offsets, the tail's
   elevation and roll (pitch: :mod:`birdsim.flight.attitude_pitch`).  ``attitude_saturated``
   when a bound binds and the moment delivered misses the demand by more than 10 %.

Gains (:func:`attitude_gains`): a triple pole at ``-omega_a``, ``omega_a = omega / (2 pi
N_a)`` with :data:`ATTITUDE_BEATS` wingbeats per time constant (the design asked for
a few times faster than the path loop's 2 wingbeats; faster loops limit-cycled, see
the constant), slower than the wingbeat so that the wingbeat-mean is a meaningful
state; multiplied by the inertia, the same closed loop for every bird.

Jacobians (:func:`measured_jacobian`): the wingbeat-mean moment of the bird in MuJoCo
(the same callback, a second MjData, the body held at the commanded pitch and the
airspeed) over :data:`JAC_SAMPLES` phases, per input by a one-sided step; cached and
re-measured when the airspeed moves by :data:`JAC_DV`.  This measures what the wings
and the tail really do in the simulation (the analytic core's Jacobians, when
``birdsim.physics.moments`` exists, are an independent path for the same numbers).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from birdsim.flight import fast_attitude
from birdsim.flight.air_angle import held, held_air
from birdsim.flight.attitude_gains import AttitudeGains, damped_gains
from birdsim.flight.attitude_input_bounds import bounds_plan, plan_bounds
from birdsim.flight.attitude_jacobians import (
    INPUTS,
    JAC_SAMPLES,
    JAC_STEP,
    SHOULDER_BOUND,
    measured_jacobian,
    measured_rate_derivatives,
    measured_with_rocking,
    split_inputs,
)
from birdsim.flight.attitude_pitch import WING_PITCH_BEATS, pitch_allocation
from birdsim.flight.attitude_refresh import StalenessCheck
from birdsim.flight.attitude_reserve import RESERVE_MISS, per_inertia, turn_reserve_bounds, weighs
from birdsim.flight.attitude_stiffness import measured_pitch_stiffness
from birdsim.flight.body_attitude import FIT_BEATS, euler_zyx, wingbeat_fit_matrix
from birdsim.flight.bounded_lsq import bounded_lsq, vector_norm
from birdsim.flight.rocking_share import RockingShare
from birdsim.flight.wing_momentum import WingMomentumRate, with_momentum_rate
from birdsim.mujoco.tail import TailControls

#: Wingbeats per time constant of the attitude loop.  Measured (seed bird): without the
#: stroke plane's compensation 0.5, 1 and 1.5 wingbeats limit-cycled at a period of two
#: wingbeats (the one-wingbeat estimate and the inputs' smoothing delay the loop by about
#: a wingbeat); with it, over the four presets, 1 and 1.5 are worse than 2, and 3 is the
#: best (cruise, hover within 3 degrees of pitch; take-off and landing the least
#: saturated); 4 loses cruise's pitch again (docs/free-body.md).
ATTITUDE_BEATS = 2.0
#: Wingbeats per time constant of the roll loop in straight flight: at 2 the yaw a side
#: gust leaves rang through the flapping's roll-yaw coupling for 10 wingbeats (roll and
#: yaw 5 degrees 8 wingbeats after the gust); 1.5, 1.25, 1 measured in docs/free-body.md.
ROLL_BEATS = 1.0
#: ... per axis (roll, pitch, yaw); yaw keeps 2 wingbeats (1.5 was worse, second stage).
AXIS_BEATS = (ROLL_BEATS, ATTITUDE_BEATS, 2.0)
#: The moment rows and the inputs of the two allocations: pitch by the symmetric inputs
#: (sweep, tail elevation), roll and yaw by the differential ones.
SYM_ROWS, SYM_INPUTS = [1], [2, 3, 6]
LAT_ROWS, LAT_INPUTS = [0, 2], [0, 1, 4, 5]
#: Airspeed (semispan omega) and pitch command (rad) changes that trigger a new Jacobian.
JAC_DV = 0.05
JAC_DPITCH = 0.1
#: ... and the change of a turn's body rates (rad per time unit) that does.
JAC_DRATE = 0.002
#: Cancel the flapping's rate derivatives in the demand (:func:`measured_rate_derivatives`).
RATE_CANCEL = True
#: Measure the Jacobians with the body's rocking within the wingbeat
#: (:func:`birdsim.flight.attitude_jacobians.measured_with_rocking`).  Off: with it the
#: loop's yaw authority is the one measured in flight (a quarter of the held body's for
#: the differential flap amplitude), but the loop then asks for four times the input and
#: roll and yaw limit-cycle at a period of two wingbeats (+-2 degrees of roll in a yaw
#: step); the side gust's peak error rose from 0.155 to 0.187 (docs/free-body.md).
ROCKING = False
#: Straight path: also re-measure J when the stored set under-predicts the moment the
#: inputs in use deliver at the wingbeat measured at now (:mod:`birdsim.flight.attitude_refresh`).
REFRESH = True
#: Regularisation of the allocation (relative to the inputs' bounds).
LAMBDA = 1e-4
#: The integral's share of the moment (per unit inertia) is bounded by this many radians
#: times omega_a^2 (anti-windup) ...
INTEGRAL_LIMIT_RAD = 0.5
#: ... or, on the axes INTEGRAL_AUTHORITY marks (roll, pitch, yaw), by the moment the
#: axis's inputs deliver at their bounds where that is larger (:func:`integral_bound`):
#: the bias it holds is a moment (the pigeon's cruise: 0.002-0.008 table units, above the
#: radians' 0.0025, at which its integral sat in every control step).  Pitch only: on
#: roll and yaw the seed bird's side gust came back more slowly (docs/free-body.md).
INTEGRAL_AUTHORITY = (False, True, False)
#: Straight flight: the roll and yaw integrals' share is bounded by this many radians
#: times omega_a^2 (no lateral bias to trim; at 0.5 a side gust's yaw wound it up into a
#: lateral swing; docs/free-body.md, "Gusts").  Turns keep INTEGRAL_LIMIT_RAD.
LATERAL_INTEGRAL_RAD = 0.1
#: Allocate pitch by :func:`birdsim.flight.attitude_pitch.pitch_allocation` (else the
#: symmetric inputs together, by least squares, as roll and yaw).
PITCH_SPLIT = True
#: the groups as index arrays (integral_bound: the same entries as the lists pick)
_AUTHORITY = ((SYM_ROWS, np.array(SYM_INPUTS)), (LAT_ROWS, np.array(LAT_INPUTS)))
#: integral_limit's axes by authority, straight flight and turns (fast_attitude's argument)
_AXES = {True: np.array(INTEGRAL_AUTHORITY, dtype=bool), False: np.zeros(3, dtype=bool)}


def attitude_gains(omega: float = 1.0, beats: object = AXIS_BEATS) -> AttitudeGains:
    """Triple pole at ``-omega / (2 pi beats)`` per axis (per unit inertia); ``beats`` a
    number (every axis) or three (roll, pitch, yaw)."""
    wa = omega / (2.0 * math.pi * np.broadcast_to(np.asarray(beats, dtype=float), (3,)))
    return AttitudeGains(wa, 3.0 * wa * wa, 3.0 * wa, wa**3)


def integral_bound(
    omega_a: np.ndarray,
    jac: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    inertia: np.ndarray,
    authority: object = INTEGRAL_AUTHORITY,
) -> np.ndarray:
    """Per axis (roll, pitch, yaw) bound of the attitude integral's share of the demand,
    per unit inertia (1 / time unit^2): :data:`INTEGRAL_LIMIT_RAD` ``omega_a^2``; on the
    axes ``authority`` marks (a bool for all three, or three bools) the moment the axis's
    own inputs (:data:`SYM_INPUTS` for pitch, :data:`LAT_INPUTS` for roll and yaw)
    deliver at their bounds, ``sum_j |J_ij| (hi_j - lo_j) / 2``, divided by ``inertia``,
    where that is larger."""
    lim = INTEGRAL_LIMIT_RAD * np.asarray(omega_a, dtype=float) ** 2
    axes = np.broadcast_to(np.asarray(authority, dtype=bool), (3,))
    if not axes.any():
        return lim
    half = (np.asarray(hi, dtype=float) - np.asarray(lo, dtype=float)) / 2
    auth = np.zeros(3)
    jac = np.asarray(jac)
    for rows, cols in _AUTHORITY:
        h = half[cols]
        for r in rows:
            auth[r] = float(np.abs(jac[r, cols]) @ h)
    return np.where(axes, np.maximum(lim, auth / np.asarray(inertia, dtype=float)), lim)


class AttitudeLoop:
    """The inner loop for one flight (see the module docstring)."""

    def __init__(
        self,
        fb,
        *,
        enabled: bool = True,
        beats: object = AXIS_BEATS,
        lateral_integral_rad: float | None = LATERAL_INTEGRAL_RAD,
    ):
        self.fb = fb
        self.wing_momentum = WingMomentumRate()  # the wings' mean angular momentum's rate
        self.lateral_integral_rad = lateral_integral_rad
        self.enabled = enabled
        self.gains = attitude_gains(fb.red.omega, beats)
        mujoco.mj_fwdPosition(fb.m, fb.d)
        full = np.zeros((fb.m.nv, fb.m.nv))
        mujoco.mj_fullM(fb.m, fb.d, full)
        #: whole-bird principal moments about the torso origin (MuJoCo x, y, z = seed)
        self.inertia = np.diag(full[3:6, 3:6]).copy()
        self.integral = np.zeros(3)
        self.u = np.zeros(len(INPUTS))
        self.saturated = False
        self._jac: tuple[float, np.ndarray, np.ndarray, float] | None = None
        self.rate_jac = np.zeros((3, 3))  # the moment's rate derivatives, measured with J
        self._turn = np.zeros(3)  # the turning rates the Jacobians were measured at
        self.kinds = INPUTS
        #: straight path: docs/free-body.md's fourth-stage pitch loop (the tail's stiffness
        #: in the gains, M_0 measured at the command; pitch integral by authority; pitch
        #: slow to fast); turns keep the second stage's (with it: circle 0.083 -> 0.096)
        self.straight = False
        self.stiffness = np.zeros(3)  # restoring stiffness per axis (>= 0, table units)
        self.check = StalenessCheck(fb.red.period)  # straight: J re-measured (attitude_refresh)
        self.reserve = 1.0  # a turn's reserve (:mod:`birdsim.flight.attitude_reserve`; 1: none)
        self.per_inertia = False  # a cruise turn's: roll and yaw per unit inertia (same module)
        self.rocking: RockingShare | None = None  # the rocking's moment in M_0 (rocking_share)
        self.air_angle, self.held_at = 0.0, (0.0, 0.0)  # the held body's air (air_angle)
        self.gate_stiffness: float | None = None  # the slow loop's gate (air_angle)

    def preset_integral(
        self, moment: np.ndarray, params: np.ndarray, pitch: float, speed: float
    ) -> None:
        """Start the integral where it cancels the difference between ``moment`` (the
        wingbeat-mean moment the trim's probe wingbeat measured in flight, every input at
        zero, seed body axes) and the Jacobian measurement's ``M_0`` at the start (the
        path loop's integral starts the same way)."""
        if not self.enabled:
            return
        m0, jac = self._measure(params, pitch, speed, None)
        self._jac = (speed, m0, jac, pitch)
        self.check.measured(self.fb.time, params)
        lim = self.integral_limit(self.gains.omega_a, jac, params)
        self.integral = np.clip((m0 - np.asarray(moment)) / self.inertia, -lim, lim)

    def integral_limit(
        self, omega_a: np.ndarray, jac: np.ndarray, params: np.ndarray, bounds: tuple | None = None
    ) -> np.ndarray:
        """Per axis bound of the integral's share (per unit inertia): :func:`integral_bound`
        with this loop's inertia and the inputs' bounds at ``params`` (or ``bounds``)."""
        lo, hi = self.bounds(params) if bounds is None else bounds
        auth = INTEGRAL_AUTHORITY if self.straight else False
        lim = integral_bound(omega_a, jac, lo, hi, self.inertia, auth)
        if self.lateral_integral_rad is not None:  # straight flight: no lateral bias
            cap = self.lateral_integral_rad * np.asarray(omega_a, dtype=float) ** 2
            lim = np.where([True, False, True], np.minimum(lim, cap), lim)
        return lim

    def _measure(
        self, params: np.ndarray, pitch: float, speed: float, turn: np.ndarray | None
    ) -> tuple[np.ndarray, np.ndarray]:
        """(M_0, J) for the loop, and the rate derivatives into ``rate_jac``: with
        :data:`ROCKING`, what the body's rocking within the wingbeat does to them included
        (:func:`measured_with_rocking`)."""
        v = max(speed, 0.0)
        pitch = held_air(self, params, pitch, v)  # the slow loop's: turned by the air path
        if ROCKING:
            m0, jac, rate = measured_with_rocking(self.fb, params, pitch, v, self.inertia, turn)
        else:
            m0, jac = measured_jacobian(self.fb, params, pitch, v, turn)
            rate = measured_rate_derivatives(self.fb, params, pitch, v, turn)
        self.rate_jac = rate if RATE_CANCEL else np.zeros((3, 3))
        if self.rocking is not None:
            self.rocking.measure(
                self.fb, params, pitch, v, float(self.inertia[1]), self._flap(params)
            )
        if self.straight:
            k = measured_pitch_stiffness(self.fb, params, pitch, v, m0)
            self.stiffness = np.array([0.0, max(-k, 0.0), 0.0])
        return m0, jac

    def _plant(self) -> tuple[np.ndarray, np.ndarray, AttitudeGains, np.ndarray]:
        """(rate derivatives used, damping per axis (>= 0), the gains placed for it, the
        residual), made again when a measurement replaced the rate derivatives or stiffness."""
        key = (self.rate_jac, self.stiffness, self.inertia, self.gains, RATE_CANCEL)
        hit = self.__dict__.get("_plant_for")
        if hit is not None and all(a is b for a, b in zip(hit[0], key)):
            return hit[1]
        d_used = self.rate_jac if RATE_CANCEL else np.zeros((3, 3))
        damping = np.maximum(-np.diag(d_used), 0.0)
        g = damped_gains(self.gains.omega_a, damping / self.inertia, self.stiffness / self.inertia)
        out = (d_used, damping, g, d_used + np.diag(damping))
        self._plant_for = (key, out)
        return out

    def _flap(self, params: np.ndarray) -> float | None:
        """The flap amplitude of the wingbeat ``params`` (None: the bird has none)."""
        names = self.fb.kin.param_names
        return float(params[names.index("flap_amp")]) if "flap_amp" in names else None

    def bounds(self, params: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(lo, hi) of :data:`INPUTS` at ``params`` (per input: parameter index, bounds)."""
        plan = self.__dict__.get("_bounds_plan")
        if plan is None:  # fast_attitude reads it too
            plan = self._bounds_plan = bounds_plan(self.fb.kin, INPUTS)
        return plan_bounds(plan, params)

    def update(
        self,
        params: np.ndarray,
        pitch_cmd: float,
        speed: float,
        err: np.ndarray,
        rates: np.ndarray,
        dt: float,
        *,
        jac_params: np.ndarray | None = None,
        jac_pitch: float | None = None,
        rate_cmd: np.ndarray | None = None,
        acc_cmd: np.ndarray | None = None,
        turn_rates: np.ndarray | None = None,
        pitch_demand: float | None = None,
    ) -> tuple[np.ndarray, np.ndarray, float, TailControls]:
        """The wings' and tail's commands for this control step.  ``err`` / ``rates``:
        the wingbeat-mean attitude error (rotation vector onto the command) and body
        rates (p, q, r), seed body axes.  ``jac_params`` / ``jac_pitch``: the wingbeat
        and body pitch the Jacobians are measured at (default: ``params``, the command).
        ``pitch_demand``: the pitch moment of :mod:`birdsim.flight.pitch_section`'s loop."""
        names = self.fb.schedule.names
        if not self.enabled:
            self.u = np.zeros(len(INPUTS))
            self.saturated = False
            return split_inputs(names, params, self.u)
        # the wings' mean angular momentum's change, supplied by the air (wing_momentum)
        acc_cmd, pitch_demand = with_momentum_rate(self, params, dt, acc_cmd, pitch_demand)
        jp = pitch_cmd if jac_pitch is None else jac_pitch
        turn = np.zeros(3) if turn_rates is None else np.asarray(turn_rates, dtype=float)
        at = params if jac_params is None else jac_params
        if (
            self._jac is None
            or abs(self._jac[0] - speed) > JAC_DV
            or abs(self._jac[3] - jp) > JAC_DPITCH
            or any(abs(a - b) > JAC_DRATE for a, b in zip(self._turn.tolist(), turn.tolist()))
            or (self.rocking is not None and self.rocking.stale(self._flap(at)))
        ):
            m0, jac = self._measure(at, jp, speed, turn if turn.any() else None)
            self._jac = (speed, m0, jac, jp)
            self._turn = turn
            self.check.measured(self.fb.time, at)
        elif REFRESH and self.straight:  # a new J only (attitude_refresh: M_0 stays)
            self._jac = self.check.refreshed(
                self.fb, self._jac, at, held(self, jp), speed, self.u, turn
            )
        _, m0, jac, _ = self._jac
        if self.rocking is not None:  # the rocking's moment, lagged (rocking_share)
            m0 = m0 + self.rocking.step(dt, self.fb.red.period)
        # the flapping's own damping (each axis, >= 0) is part of the plant the gains are
        # placed for; what is left of the rate derivatives (cross terms, any negative
        # damping) is cancelled with the estimated rates
        d_used, damping, g, residual = self._plant()
        split = PITCH_SPLIT and self.straight
        a_lp = 1.0 - math.exp(-dt / (WING_PITCH_BEATS * self.fb.red.period)) if split else 0.0
        if pitch_demand is None and not weighs(self) and fast_attitude.allocate(  # compiled
            self, ((SYM_ROWS, SYM_INPUTS), (LAT_ROWS, LAT_INPUTS)), params, g, m0, jac,
            residual, damping, err, rates, dt, rate_cmd, acc_cmd, turn, INTEGRAL_LIMIT_RAD,
            _AXES[self.straight], split, a_lp, LAMBDA,
        ):  # fmt: skip
            return split_inputs(names, params, self.u)
        lo, hi = self.bounds(params)
        lim = self.integral_limit(g.omega_a, jac, params, (lo, hi))
        if not self.saturated:  # anti-windup: frozen while the inputs are at their bounds
            self.integral = np.clip(self.integral + dt * g.ki * err, -lim, lim)
        rate_err = (0.0 if rate_cmd is None else rate_cmd) - rates
        acc = 0.0 if acc_cmd is None else acc_cmd
        demand = self.inertia * (acc + g.kp * err + g.kd * rate_err + self.integral) - m0
        demand -= residual @ (np.asarray(rates, dtype=float) - turn)
        # the damping opposes the commanded rotation too: fed forward (the damping then
        # acts on the rate error only, as the gains assume)
        demand += damping * (rate_err + np.asarray(rates, dtype=float) - turn)
        if pitch_demand is not None:  # the section's loop (pitch_section), wings unfiltered
            demand[1] = self._slow = pitch_demand
        u = np.zeros(len(INPUTS))
        miss, active, groups = 0.0, False, [(SYM_ROWS, SYM_INPUTS), (LAT_ROWS, LAT_INPUTS)]
        if split:  # pitch: slow moment by the wings, fast by the tail
            slow = getattr(self, "_slow", None)
            self._slow = demand[1] if slow is None else slow + a_lp * (demand[1] - slow)
            up, miss, active = pitch_allocation(jac[1], demand[1], self._slow, lo, hi, LAMBDA)
            u[SYM_INPUTS], groups = up[SYM_INPUTS], groups[1:]
        # a symmetric bird: the symmetric inputs pitch it, the differential ones roll and
        # yaw it (the measured cross terms are round-off and are not used)
        for rows, cols in groups:
            cols = [c for c in cols if hi[c] > lo[c]]
            if not cols:
                miss += vector_norm(demand[rows])
                continue
            scale = (hi[cols] - lo[cols]) / 2
            a = jac[rows][:, cols] * scale  # jac[np.ix_(rows, cols)]
            reg = math.sqrt(LAMBDA) * max(float(np.abs(a).max()), 1e-12)
            a_aug = np.vstack([a, reg * np.eye(len(cols))])
            b_aug = np.concatenate([demand[rows], np.zeros(len(cols))])
            if rows is LAT_ROWS and weighs(self):  # a cruise turn's: per unit inertia
                a_aug, b_aug = per_inertia(a_aug, b_aug, self.inertia[rows])
            x, mask = bounded_lsq(a_aug, b_aug, lo[cols] / scale, hi[cols] / scale)
            short = vector_norm(a @ x - demand[rows]) > RESERVE_MISS * vector_norm(demand[rows])
            if rows is LAT_ROWS and self.reserve > 1.0 and np.any(mask != 0) and short:
                b2 = turn_reserve_bounds(self, INPUTS, params, lo, hi)  # wider where short
                x, mask = bounded_lsq(a_aug, b_aug, b2[0][cols] / scale, b2[1][cols] / scale)
            u[cols] = x * scale
            active = active or bool(np.any(mask != 0))
            miss += vector_norm(a @ x - demand[rows])
        self.u = u
        self.saturated = bool(active and miss > 0.1 * vector_norm(demand) + 1e-12)
        return split_inputs(names, params, u)


__all__ = [
    "ATTITUDE_BEATS", "AXIS_BEATS", "LATERAL_INTEGRAL_RAD", "ROLL_BEATS", "INPUTS",
    "AttitudeLoop", "attitude_gains", "euler_zyx", "FIT_BEATS", "wingbeat_fit_matrix",
    "integral_bound", "JAC_SAMPLES", "JAC_STEP", "SHOULDER_BOUND", "damped_gains",
    "measured_jacobian", "measured_rate_derivatives", "measured_with_rocking", "split_inputs",
]  # fmt: skip
