"""The free body's static pitch stiffness, measured in MuJoCo (reduced units, seed body
axes, about the centre of mass): how the wingbeat-mean pitching moment changes when the
body pitches with the wings' stroke plane held in the world (the stroke plane's
compensation of :mod:`birdsim.flight.freeflight` keeps it there).  Mostly the tail's
(its angle of attack follows the body): -0.020 weight x semispan per rad in the pigeon's
and the seed bird's cruise, about nothing at hover.  Per unit inertia it is four times
larger for the pigeon (pitch inertia 0.78 reduced, the seed bird's 3.3) than for the
seed bird, and larger than the attitude loop's own proportional gain: the pitch loop's
gains count it as part of the plant (:func:`birdsim.flight.attitude_gains.damped_gains`)."""

from __future__ import annotations

import numpy as np

from birdsim.flight.attitude_jacobians import JAC_STEP, held_mean_moments


def _mean_moment(fb, params: np.ndarray, pitch: float, speed: float) -> np.ndarray:
    """The wingbeat-mean moment (3,) of the held body, not rotating, as
    :func:`birdsim.flight.attitude_jacobians.measured_jacobian` measures its ``M_0``."""
    return held_mean_moments(fb, params, pitch, speed, [np.zeros(3)])[0]


def measured_pitch_stiffness(
    fb, params: np.ndarray, pitch: float, speed: float, m0: np.ndarray | None = None
) -> float:
    """dM_y / d theta (weight x semispan per rad, table units; < 0 restoring): the
    wingbeat-mean pitching moment's change when the held body pitches up by
    :data:`JAC_STEP` and the stroke plane (if the model has one) turns down by as much,
    one-sided from ``m0`` (the moment at ``pitch``; measured if not given)."""
    base = _mean_moment(fb, params, pitch, speed) if m0 is None else np.asarray(m0)
    moved = np.array(params, dtype=float)
    names = fb.schedule.names
    if "stroke_plane" in names:
        moved[names.index("stroke_plane")] -= JAC_STEP
    up = _mean_moment(fb, moved, pitch + JAC_STEP, speed)
    return float((up[1] - base[1]) / JAC_STEP)


__all__ = ["measured_pitch_stiffness"]
