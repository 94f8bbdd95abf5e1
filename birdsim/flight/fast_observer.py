"""The pitch observer's control step in one compiled call (issue 27: the control update's
Python).

:class:`birdsim.flight.pitch_observer.PitchObserver` runs at every control update of a
straight free flight (its pitch is used in slow flight only, but its state runs on): the
prediction over the step's log samples (two filters and the model's acceleration per
sample), the last wingbeat's pitch from the quaternions
(:func:`birdsim.flight.flight_arrays.error_rotvec`) and the correction by the
one-wingbeat fit, some sixty numpy calls.  :func:`step` does the same in one numba call,
every operation the reference's in its order: the filters and the model elementwise, the
model's ``jac_row @ u`` and the fit's ``fit[0] @ res`` through numba's ``np.dot`` (the
BLAS ``ddot`` and ``dgemv`` numpy's ``@`` calls: bitwise on 20 000 random problems of
each shape), the rotation vectors by :data:`birdsim.flight.fast_estimate.rotvec_kernel`
with numpy's ``einsum`` sums of squares (``pairwise``) and the C library's ``atan2`` /
``sin`` / ``cos`` (numpy's own on this machine, bitwise; where numpy's SIMD functions
differ, round-off).  :data:`ENABLED` False gives the numpy reference
(``tests/test_fast_observer.py``).  Reduced units, seed body axes, radians.
"""

from __future__ import annotations

import numpy as np

from birdsim.flight import fast_estimate
from birdsim.physics.jit import numba

#: the observer's step compiled (False: the numpy reference)
ENABLED = True


def _predict(state, u1, u2, smoothed, u, a, b, dt, samples, model, jac_row, hist, n):
    """PitchObserver.predict on arrays: ``b`` = 1 - a; ``model`` (m0, stiffness, theta_j,
    d_qq, inertia); returns the new history (the last ``n`` rows)."""
    m0, stiffness, theta_j, d_qq, inertia = model[0], model[1], model[2], model[3], model[4]
    th, q, beta = state[0], state[1], state[2]
    k = hist.shape[0]
    rows = np.empty((k + samples, 2))
    rows[:k] = hist
    for i in range(samples):
        for j in range(u.shape[0]):
            u1[j] = a * u1[j] + b * u[j] if smoothed[j] else u[j]
        for j in range(u.shape[0]):
            u2[j] = a * u2[j] + b * u1[j] if smoothed[j] else u[j]
        m = m0 + np.dot(jac_row, u2) - stiffness * (th - theta_j)
        acc = (m + d_qq * q) / inertia + beta
        th += dt * (q + 0.5 * dt * acc)
        q += dt * acc
        rows[k + i, 0] = th
        rows[k + i, 1] = q
    state[0] = th
    state[1] = q
    start = max(0, k + samples - n)
    return rows[start:].copy()


def _correct(state, hist, theta, q, fit0, n, dt, dt_ctl, rate_gain, bias_gain):
    """PitchObserver.correct on arrays (``hist`` moved in place)."""
    k = hist.shape[0]
    m = theta.shape[0]
    res = np.empty((n, 2))
    pad = n - k
    for i in range(k):
        res[pad + i, 0] = theta[m - k + i] - hist[i, 0]
        res[pad + i, 1] = q[m - k + i] - hist[i, 1]
    for i in range(pad):  # before a whole wingbeat: the earliest residual repeated
        res[i, 0] = res[pad, 0]
        res[i, 1] = res[pad, 1]
    r = np.dot(fit0, res)
    r_th, r_q = r[0], r[1]
    x = dt_ctl * rate_gain
    g = x if x < 1.0 else 1.0  # min(1.0, x)
    d_th, d_q = g * r_th, g * r_q
    state[0] += d_th
    state[1] += d_q
    state[2] += dt_ctl * bias_gain * r_q
    for i in range(k):
        tau = -dt * (k - 1 - i)
        hist[i, 0] += d_th + d_q * tau
        hist[i, 1] += d_q


def _step(state, u1, u2, smoothed, u, a, b, dt, samples, model, jac_row, hist, n,
          quat, omega_q, pitch_ref, fit0, dt_ctl, rate_gain, bias_gain):  # fmt: skip
    hist = _predict(state, u1, u2, smoothed, u, a, b, dt, samples, model, jac_row, hist, n)
    rot = np.empty((quat.shape[0], 3))
    fast_estimate.rotvec_kernel(quat, pitch_ref, 0.0, 0.0, rot, True)
    theta = pitch_ref - rot[:, 1]
    _correct(state, hist, theta, omega_q, fit0, n, dt, dt_ctl, rate_gain, bias_gain)
    return hist


kernel = None
if numba is not None and fast_estimate.rotvec_kernel is not None:
    _predict = numba.njit(cache=True)(_predict)
    _correct = numba.njit(cache=True)(_correct)
    kernel = numba.njit(cache=True)(_step)


def step(obs, model: np.ndarray, jac_row: np.ndarray, u: np.ndarray, samples: int,
         window: tuple, pitch_ref: float, dt_ctl: float, a: float) -> float | None:  # fmt: skip
    """The observer ``obs``'s predict over ``samples`` log samples (inputs ``u``; ``model``
    the (m0, stiffness, theta_j, d_qq, inertia) of its PitchModel, ``jac_row`` its
    Jacobian row; ``a`` the filters' factor) and its correction by ``window`` (the last
    wingbeat's quaternions and seed body rates), compiled: the corrected pitch (rad), the
    observer's state, filters and history moved as the reference moves them; None where
    it does not apply (switched off, numba missing)."""
    if not (ENABLED and fast_estimate.ENABLED) or kernel is None:
        return None
    quat, omega = window
    if min(len(obs.hist) + samples, obs.n) > len(quat):
        return None  # fewer samples than the prediction's history: the reference's error
    f = np.ascontiguousarray
    obs.u1 = np.array(obs.u1, dtype=float)  # the reference replaces them (no aliasing)
    obs.u2 = np.array(obs.u2, dtype=float)
    obs.hist = kernel(
        obs.state, obs.u1, obs.u2, obs.smoothed, f(u, dtype=float), a, 1 - a, obs.dt,
        samples, model, f(jac_row, dtype=float), f(obs.hist, dtype=float), obs.n,
        f(quat, dtype=float), f(omega[:, 1], dtype=float), float(pitch_ref), obs.fit[0],
        float(dt_ctl), obs.rate_gain, obs.bias_gain,
    )  # fmt: skip
    return float(obs.state[0])


__all__ = ["ENABLED", "kernel", "step"]
