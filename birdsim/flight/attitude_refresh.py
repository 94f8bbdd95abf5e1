"""When the attitude loop's Jacobians under-predict the moment of the wingbeat flown, and
their re-measurement (reduced units, seed body axes, about the centre of mass).

:class:`birdsim.flight.attitude.AttitudeLoop` measures its Jacobians ``J`` (the
wingbeat-mean moment's derivatives with respect to the attitude inputs) at one wingbeat,
the command's, and re-measures them when the airspeed or the pitch command moves.  ``J``
is a local derivative of that wingbeat: the wings' pitch authority (the shoulders'
sweep and dihedral offsets move the force line) changes with the wingbeat's amplitude
and stroke plane.  A set measured while the path loop's wingbeat is far from where it
settles (a gust's transient) is then kept by a cruise whose airspeed and pitch command
no longer move: after the seed bird's -x gust the stored sweep authority was -0.092
where the wingbeat flown has -0.148, the allocation asked for 1.6 times the sweep, and
the pitch loop limit-cycled at a period of two wingbeats (docs/free-body.md, "Gusts and
the Jacobians' staleness check").

The check (:func:`prediction_residual`): once per :data:`CHECK_BEATS` wingbeats, unless
the wingbeat is within the measurement's own step (``JAC_STEP``, 0.02 rad) of the one
the set was measured at (then it is that wingbeat, to the measurement's resolution; a
steady cruise, where a check would cost an eighth of the flight), the held
body beats the wingbeat the loop measures at now with the inputs ``u`` it allocated, and
without them; the difference is the moment those inputs deliver at this wingbeat, ``J u``
the moment the stored set predicts.  The set is stale when the delivered moment exceeds
the predicted one along the prediction by more than :data:`RESIDUAL_TOL` of the moment
the inputs move (``|sum_j |J_ij u_j||``): the allocation's own tolerance (a demand missed
by more than 10 % is "attitude saturated"); the new ``J`` replaces the stored one only if
it predicts the checked moment better (:func:`predicts_better`; else the miss is the
inputs' own nonlinearity at their size, which no tangent at zero removes).  One-sided, because the two errors are not
alike: a set that under-predicts raises the loop's gain above its design by the ratio,
and the pitch loop's gain margin with the about half a wingbeat its estimate and the
inputs' smoothing delay it is about 2 (the measured limit cycle: 1.6); one that
over-predicts lowers it, which only slows the loop (its triple pole keeps stable down to
a ninth of the gain, Routh).  Re-measuring at every residual, both signs, made the
pigeon's and the seed bird's landings worse (docs/free-body.md).  Only ``J`` is
re-measured: a difference in ``M_0`` is a bias, the integral's to trim, and a new ``M_0``
would step the demand."""

from __future__ import annotations

import numpy as np

from birdsim.flight.attitude_jacobians import JAC_STEP, held_mean_moments, measured_jacobian

#: Wingbeats between two checks, and after a measurement (the loop's estimate is a
#: one-wingbeat fit: a wingbeat is the shortest time over which the inputs act).
CHECK_BEATS = 1.0
#: Relative excess of the delivered moment over the predicted one that makes the set
#: stale: the allocation's tolerance for "attitude saturated" (AttitudeLoop.update).
RESIDUAL_TOL = 0.1


def prediction_residual(
    fb,
    params: np.ndarray,
    pitch: float,
    speed: float,
    jac: np.ndarray,
    u: np.ndarray,
    omega_body: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """(residual (3,), moved (3,)): the moment the inputs ``u`` deliver on the held body
    beating ``params`` at ``pitch`` and ``speed`` (turning at ``omega_body``, seed body
    axes) minus ``jac @ u``, and per axis ``sum_j |jac_ij u_j|`` (table units)."""
    omega = [np.zeros(3) if omega_body is None else np.asarray(omega_body, dtype=float)]
    base = held_mean_moments(fb, params, pitch, speed, omega)[0]
    moved = held_mean_moments(fb, params, pitch, speed, omega, inputs=u)[0]
    u = np.asarray(u, dtype=float)
    return moved - base - jac @ u, np.abs(jac * u).sum(axis=1)


def under_predicts(residual: np.ndarray, jac: np.ndarray, u: np.ndarray, tol: float) -> bool:
    """Whether ``residual`` (:func:`prediction_residual`) exceeds, along the predicted
    moment ``jac @ u``, ``tol`` times the norm of ``sum_j |jac_ij u_j|``."""
    pred = jac @ np.asarray(u, dtype=float)
    norm = float(np.linalg.norm(pred))
    if norm == 0.0:
        return False
    moved = float(np.linalg.norm(np.abs(jac * u).sum(axis=1)))
    return float(residual @ pred) / norm > tol * moved


def predicts_better(residual: np.ndarray, old: np.ndarray, new: np.ndarray, u: np.ndarray) -> bool:
    """Whether ``new`` predicts the moment of the inputs ``u`` that left ``residual``
    (:func:`prediction_residual`) with ``old`` more closely than ``old`` does (its
    residual is ``residual + (old - new) @ u``)."""
    u = np.asarray(u, dtype=float)
    return bool(np.linalg.norm(residual + (old - new) @ u) < np.linalg.norm(residual))


class StalenessCheck:
    """Per flight: when a check is due, its verdict, and the re-measurement (see the
    module); ``checks`` and ``refreshes`` count them."""

    def __init__(self, period: float, beats: float = CHECK_BEATS, tol: float = RESIDUAL_TOL):
        self.every = beats * period
        self.tol = tol
        self.last: float | None = None  # time of the last check or measurement
        self.at: np.ndarray | None = None  # the wingbeat the stored J was measured at
        self.checks = 0
        self.refreshes = 0

    def measured(self, t: float, params: np.ndarray) -> None:
        """A set was measured at time ``t`` at the wingbeat ``params``: the next check a
        full interval later."""
        self.last = t
        self.at = np.array(params, dtype=float)

    def refreshed(
        self,
        fb,
        stored: tuple,
        params: np.ndarray,
        pitch: float,
        speed: float,
        u: np.ndarray,
        turn: np.ndarray | None = None,
    ) -> tuple:
        """``stored`` (the loop's (speed, M_0, J, pitch)) with ``J`` re-measured at the
        wingbeat ``params``, body pitch ``pitch`` and airspeed ``speed`` when a check is
        due and finds the stored ``J`` under-predicting the moment of the inputs ``u``;
        else ``stored`` itself.  ``turn``: the body rates the loop measures at."""
        t = fb.time
        if self.last is not None and t - self.last < self.every - 1e-9:
            return stored
        self.last = t
        if not np.any(u):
            return stored
        # within the measurement's own step of the wingbeat measured at: that wingbeat
        if self.at is not None and np.max(np.abs(np.asarray(params) - self.at)) < JAC_STEP:
            return stored
        self.checks += 1
        omega = None if turn is None or not np.any(turn) else np.asarray(turn, dtype=float)
        jac, v = stored[2], max(speed, 0.0)
        res, _ = prediction_residual(fb, params, pitch, v, jac, u, omega)
        if not under_predicts(res, jac, u, self.tol):
            return stored
        _, new = measured_jacobian(fb, params, pitch, v, omega)
        # kept unless the new J predicts the checked moment better (else the miss is the
        # inputs' own nonlinearity at this size, which no tangent at zero removes)
        if not predicts_better(res, jac, new, u):
            return stored
        self.refreshes += 1
        self.at = np.array(params, dtype=float)
        return (stored[0], stored[1], new, stored[3])


__all__ = [
    "CHECK_BEATS",
    "RESIDUAL_TOL",
    "StalenessCheck",
    "prediction_residual",
    "predicts_better",
    "under_predicts",
]
