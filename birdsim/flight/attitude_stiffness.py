"""The free body's static pitch stiffness, measured in MuJoCo (reduced units, seed body
axes, about the centre of mass): how the wingbeat-mean pitching moment changes when the
body pitches with the wings' stroke plane held in the world (the stroke plane's
compensation of :mod:`birdsim.flight.freeflight` keeps it there).  Mostly the tail's
(its angle of attack follows the body): -0.020 weight x semispan per rad in the pigeon's
and the seed bird's cruise, about nothing at hover.  Per unit inertia it is four times
larger for the pigeon (pitch inertia 0.78 reduced, the seed bird's 3.3) than for the
seed bird, and larger than the attitude loop's own proportional gain: the pitch loop's
gains count it as part of the plant (:func:`birdsim.flight.attitude.damped_gains`)."""

from __future__ import annotations

import mujoco
import numpy as np

from birdsim.flight.attitude_jacobians import INPUTS, JAC_SAMPLES, JAC_STEP, _hold, split_inputs
from birdsim.mujoco.model import pitch_quat


def _mean_moment(fb, params: np.ndarray, pitch: float, speed: float) -> np.ndarray:
    """The wingbeat-mean moment (3,) of the held body (pitch ``pitch``, airspeed
    ``speed``, not rotating) beating ``params`` with every input at zero, over
    :data:`JAC_SAMPLES` phases, as :func:`birdsim.flight.attitude_jacobians.measured_jacobian`
    measures its ``M_0``."""
    m, cb, sched = fb.m, fb.cb, fb.schedule
    d = getattr(fb, "_jac_data", None)
    if d is None:
        d = fb._jac_data = mujoco.MjData(m)
    n = JAC_SAMPLES
    times = np.arange(n) * (fb.red.period / n)
    names = sched.names
    right, left, sh, tail = split_inputs(names, params, np.zeros(len(INPUTS)))
    z = np.zeros((n, len(names)))
    sw = np.repeat([np.concatenate([sh, sh])], n, axis=0)
    pres = sched.prescribe(
        times,
        np.repeat([right], n, axis=0),
        z,
        z,
        left=(np.repeat([left], n, axis=0), z, z),
        shoulder=(sw, np.zeros_like(sw), np.zeros_like(sw)),
    )
    c = np.array([1.0, -1.0, -1.0])  # seed <-> MuJoCo axes
    wind = m.opt.wind.copy()
    saved = cb.tail_controls
    m.opt.wind[:] = 0.0
    cb.tail_controls = tail
    quat = pitch_quat(pitch)
    acc = np.zeros(3)
    try:
        for k in range(n):
            _hold(m, d, pres.qpos[k], pres.qvel[k], quat, speed, np.zeros(3))
            acc += d.qfrc_passive[3:6]
    finally:
        m.opt.wind[:] = wind
        cb.tail_controls = saved
    return acc / n * c


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
