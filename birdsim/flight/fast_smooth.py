"""The pitch plan's lag-free smoothing (:func:`birdsim.flight.pitch_plan._smooth`)
compiled: the critically damped filter's semi-implicit Euler substeps
(:func:`birdsim.flight.attitude_commands.command_filter`, its operations in its order)
run forward over the plan's grid and then backward, in one numba call instead of some
four hundred Python calls per flight.  ``tau ** 2`` and the substep are computed in
Python as the filter computes them (C ``pow`` is not always ``x * x``), so the numbers
are the reference's bit for bit (``tests/test_fast_smooth.py``)."""

from __future__ import annotations

import numpy as np

from birdsim.physics.jit import numba

#: the compiled smoothing (False: the Python filter, step by step)
ENABLED = True


def _pass(seq, tau, tau2, h, substeps, res):
    """One pass of the filter over ``seq`` from its first value at rest: the value
    before each step into ``res``."""
    v, r = seq[0], 0.0
    for i in range(seq.shape[0]):
        res[i] = v
        target = seq[i]
        for _ in range(substeps):
            r += h * ((target - v) / tau2 - 2.0 * r / tau)
            v += h * r


def _smooth(values, tau, tau2, h, substeps, out):
    n = values.shape[0]
    forward = np.empty(n)
    _pass(values, tau, tau2, h, substeps, forward)
    backward = np.empty(n)
    _pass(forward[::-1].copy(), tau, tau2, h, substeps, backward)
    for i in range(n):
        out[i] = backward[n - 1 - i]


if numba is not None:
    _pass = numba.njit(cache=True)(_pass)
    kernel = numba.njit(cache=True)(_smooth)
else:  # pragma: no cover
    kernel = None


def smooth(values: np.ndarray, tau: float, dt: float, substeps: int = 8) -> np.ndarray | None:
    """``pitch_plan._smooth(values, tau, dt)`` compiled (``tau`` > 0, ``values`` a 1-D
    grid ``dt`` apart, at least one value), or None where it does not apply."""
    if not ENABLED or kernel is None or tau <= 0.0:
        return None
    values = np.ascontiguousarray(values, dtype=float)
    if values.ndim != 1 or not len(values):
        return None
    out = np.empty_like(values)
    kernel(values, float(tau), tau**2, dt / substeps, int(substeps), out)
    return out


__all__ = ["ENABLED", "kernel", "smooth"]
