"""The wingbeat-mean pitching moment of the body's rocking within the wingbeat (the
rocking's rectified moment), for the slow straight flight's pitch loop
(:mod:`birdsim.flight.pitch_section`; docs/free-body.md, "The pigeon's attitude, tenth
stage").

A free body pitches to and fro within every wingbeat under the wings' periodic moment
and their reaction (the held body's moment about its mean and the wings' relative
angular momentum ``h``).  The moment depends on the body's pitch and pitch rate, and
both derivatives change with the phase, so the rocking times them has a mean that no
measurement on the held body sees: at the pigeon's take-off speeds (airspeed 0.35-0.47)
-0.003 to -0.010 table units, nose down, about the moment the section loop's model
missed in flight; it scales as the rocking, i.e. as 1 / inertia.  Here the rocking is
the periodic solution of ``I th'' - D th' - K th = (M(t) - mean M) - h'(t)`` (pitch
axis; ``D`` and ``K`` the mean rate and angle derivatives; solved per wingbeat
harmonic) and the moment is ``mean_t (dM/dq(t) th'(t) + dM/dth(t) th(t))``, each phase
measured on the held body as :func:`birdsim.flight.attitude_jacobians.held_mean_moments`
holds it (the stroke plane turning with the body: the compensation acts on the
wingbeat mean only).  Reduced units (time in 1 / omega), seed body axes (pitch nose up).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from birdsim.flight.attitude_jacobians import (
    JAC_SAMPLES,
    JAC_STEP,
    RATE_STEP,
    SEED_AXES,
    _hold,
    held_body,
)
from birdsim.mujoco.model import pitch_quat


def rocking_pitch_moment(
    fb, params: np.ndarray, pitch: float, speed: float, inertia: float
) -> tuple[float, float]:
    """(the rocking's rectified pitching moment (table units; > 0 nose up), the
    rocking's peak to peak (rad)) of the held body at ``pitch`` (rad) and airspeed
    ``speed`` beating ``params`` with every input at zero, ``inertia`` its pitch inertia
    (reduced); :data:`JAC_SAMPLES` phases, steps :data:`RATE_STEP` and :data:`JAC_STEP`."""
    d_q, d_th, theta_r, rate_r = periodic_rocking(fb, params, pitch, speed, inertia)
    return float(np.mean(d_q * rate_r + d_th * theta_r)), float(np.ptp(theta_r))


def periodic_rocking(
    fb, params: np.ndarray, pitch: float, speed: float, inertia: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(dM/dq, dM/dth, the rocking's pitch (rad), its pitch rate (rad per reduced time)),
    each at the :data:`JAC_SAMPLES` phases of the wingbeat ``params`` (phase 0 the
    wingbeat's start): the periodic solution of the module's equation for the held body
    as :func:`rocking_pitch_moment` measures it."""
    n, c = JAC_SAMPLES, SEED_AXES
    held = ((pitch, 0.0), (pitch, RATE_STEP), (pitch + JAC_STEP, 0.0))
    mom, h = np.zeros((3, n)), np.zeros(n)
    with held_body(fb, params, None) as (m, d, pres):
        vec, res = np.zeros(m.nv), np.zeros(m.nv)
        for i, (theta, q) in enumerate(held):
            quat, omega = pitch_quat(theta), np.array([0.0, q, 0.0]) * c
            for k in range(n):
                _hold(m, d, pres.qpos[k], pres.qvel[k], quat, speed, omega)
                mom[i, k] = d.qfrc_passive[4] * c[1]
                if i == 0:  # the wings' angular momentum relative to the torso
                    vec[:] = d.qvel
                    vec[:6] = 0.0
                    mujoco.mj_mulM(m, d, res, vec)
                    h[k] = res[4] * c[1]
    d_q = (mom[1] - mom[0]) / RATE_STEP
    d_th = (mom[2] - mom[0]) / JAC_STEP
    damping, stiffness = float(d_q.mean()), float(d_th.mean())
    w = 2.0 * math.pi / fb.red.period * np.arange(n // 2 + 1)  # the harmonics' frequencies
    spec_m, spec_h = np.fft.rfft(mom[0]), np.fft.rfft(h)
    spec = np.zeros_like(spec_m)
    jw = 1j * w[1 : n // 2]  # harmonics 1 .. n/2 - 1 (the Nyquist term left out)
    spec[1 : n // 2] = (spec_m[1 : n // 2] - jw * spec_h[1 : n // 2]) / (
        inertia * jw * jw - damping * jw - stiffness
    )
    theta_r = np.fft.irfft(spec, n=n)
    rate_r = np.fft.irfft(1j * w * spec, n=n)
    return d_q, d_th, theta_r, rate_r


__all__ = ["periodic_rocking", "rocking_pitch_moment"]
