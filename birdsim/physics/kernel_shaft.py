"""The positive shaft power in the fused kernels (issue 24): the arrays the kernels need
and their compiled end-of-row step.

The numpy reference is :mod:`birdsim.physics.shaft_power`: ``P+ = mean over the samples
of max(p_t, 0)`` with ``p_t = p_aero(t) + dK/dt(t)``.  The kernels
(:mod:`birdsim.physics.kernel_means`, :mod:`birdsim.physics.kernel_dual`) accumulate, per
sample, the right wing's aerodynamic power ``hp[t]`` and its kinetic energy ``hk[t] =
1/2 sum_k m_k |v_flap,k(t)|^2`` (dual numbers in the gradient kernel: column 0 the
value, column 1 + i the derivative by parameter i); :func:`_positive_part` then takes
``dK/dt = Dm hk`` with ``Dm`` the spectral differentiation matrix of the periodic grid
(:func:`shaft_arrays`: :func:`birdsim.physics.shaft_power.periodic_derivative` applied to
the unit vectors, so the same operator as the reference's FFT, to round-off) and sums
the positive part.

**The gradient of the positive part** is the exact derivative of the sampled sum, not
of a smoothed one: ``d P+ / dx = 1/N sum_{t: p_t > 0} d p_t / dx``.  ``P+`` is a sum of
N terms each differentiable except where its ``p_t`` is exactly zero, so this is the
derivative wherever one exists (almost everywhere) and a one-sided one on the kinks.
A smooth rectifier (softplus of width eps) would change the cost itself (by up to
``eps log 2`` per sample) and so not equal the numpy reference; with N samples each kink
moves the gradient by ``|d p_t / dx| / N`` only, the same kind of kink the cost's
``|Fx - Fx_d|`` terms already have (SLSQP's slack form handles those; the power term
enters the cost through ``|P+|`` with ``P+ >= 0``).  A zero ``p_t`` counts as not
positive (max(0, 0)'s derivative taken as 0); NaN stays NaN.

The gradient of the inertial part is formed without N x d matrix products: with
``s_t = [p_t > 0]``, ``sum_t s_t (Dm dK)_t = sum_u (Dm^T s)_u dK_u``, so one weight
vector ``w = Dm^T s`` (N^2 operations) serves every parameter.
"""

from __future__ import annotations

import functools

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.jit import jit as _jit
from birdsim.physics.kinematics import KinematicModel
from birdsim.physics.shaft_power import check_wing_mass, panel_masses, periodic_derivative

#: The kernels' placeholders where no positive power is asked for.
NO_MASS = np.zeros(0)
NO_MATRIX = np.zeros((0, 0))


@functools.lru_cache(maxsize=64)
def shaft_arrays(m: KinematicModel, bird: Bird, n: int) -> tuple[np.ndarray, np.ndarray]:
    """``(masses K, Dm N x N)`` for ``n`` samples of the periodic grid: the panels' point
    masses and the spectral d/dt (``Dm[t, u]``: the derivative at sample t of the unit
    sample u); a 0 x 0 matrix for a massless wing (no inertial power at all)."""
    check_wing_mass(bird)
    masses = np.ascontiguousarray(panel_masses(m.name, bird), dtype=float)
    if bird.wing_mass_fraction == 0.0:
        return masses, NO_MATRIX
    dmat = periodic_derivative(np.eye(n), float(bird.omega)).T
    return masses, np.ascontiguousarray(dmat)


@_jit
def _positive_part(hp, hk, dmat, res):
    """``res[i]`` = column i of ``1/N sum_t max(hp[t] + (dmat hk)[t], 0)`` (hp, hk: N x D
    dual histories; dmat N x N, or 0 x 0 for no inertial power); see the module text."""
    N, D = hp.shape
    massive = dmat.shape[0] > 0
    w = np.zeros(N if massive else 0)
    for i in range(D):
        res[i] = 0.0
    for t in range(N):
        p = hp[t, 0]
        if massive:
            kd = 0.0
            for u in range(N):
                kd += dmat[t, u] * hk[u, 0]
            p += kd
        if not p <= 0.0:  # positive, or NaN (a NaN row stays NaN, as np.maximum)
            res[0] += p
            for i in range(1, D):
                res[i] += hp[t, i]
            if massive:
                for u in range(N):
                    w[u] += dmat[t, u]
    if massive:
        for u in range(N):
            for i in range(1, D):
                res[i] += w[u] * hk[u, i]
    for i in range(D):
        res[i] /= N
