"""The wing's shaft power: aerodynamic plus inertial, and its positive part (issue 24).

The power the shoulder (and elbow, wrist) must deliver to drive one wing through a
wingbeat, in body axes (the body flies straight at constant speed, so they are inertial):

``p(t) = p_aero(t) + dK/dt``,   ``p_aero = -F_aero . v_flap`` (the cycle's power history),
``K(t) = 1/2 sum_k m_k |v_k(t)|^2``

where ``v_k`` is the flapping velocity of panel k's control point (body axes) and ``m_k``
one wing's mass ``wing_mass_fraction x mass`` shared among the panels by their extended
area and lumped at their control points (a point mass at half span: 3/4 of a uniform
panel's moment of inertia about its root; the panels' own rotational inertia and the
wing's weight are left out).  Over a wingbeat ``dK/dt`` averages to zero, so the mean of
``p`` is the mean aerodynamic power whatever the mass.  Muscles cannot store the work
the air or the wing's momentum does on them; the **positive power** is

``P+ = mean over the wingbeat of max(p(t), 0)``

(negative work neither credited nor recovered elastically).  ``dK/dt`` is the spectral
derivative of the sampled ``K`` (exact for a band-limited ``K``; the samples are the
periodic grid without its end point).
"""

from __future__ import annotations

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.cycle_result import Cycle


def panel_masses(model: str, bird: Bird) -> np.ndarray:
    """One wing's mass shared among ``model``'s panels by extended area [mass units], K."""
    areas = np.array([p.area for p in bird.panels(model)])
    return bird.wing_mass_fraction * bird.mass * areas / areas.sum()


def periodic_derivative(y: np.ndarray, omega: float) -> np.ndarray:
    """d/dt of samples ``y`` (last axis) on ``t = 2 pi j / (n omega)``, j = 0..n-1, one
    period without its end point: the spectral derivative (the Nyquist term dropped)."""
    n = y.shape[-1]
    k = np.fft.rfftfreq(n, 1.0 / n)
    if n % 2 == 0:
        k[-1] = 0.0
    return np.fft.irfft(1j * k * omega * np.fft.rfft(y, axis=-1), n=n, axis=-1)


def inertial_power(cycle: Cycle, bird: Bird) -> np.ndarray:
    """``dK/dt`` of one (right) wing, shape ``B + (N,)`` [power units]."""
    _check_grid(cycle, bird)
    m = panel_masses(cycle.model, bird)
    v2 = np.square(cycle.cp_velocity_body).sum(axis=-1)  # B x K x N
    kinetic = 0.5 * np.einsum("k,...kn->...n", m, v2)
    return periodic_derivative(kinetic, bird.omega)


def shaft_power(cycle: Cycle, bird: Bird) -> np.ndarray:
    """Aerodynamic plus inertial power of one wing, ``B + (N,)`` (zero mass: the
    aerodynamic power history itself)."""
    if bird.wing_mass_fraction == 0.0:
        return cycle.power
    return cycle.power + inertial_power(cycle, bird)


def positive_power(cycle: Cycle, bird: Bird) -> np.ndarray:
    """``P+``: the wingbeat mean of ``max(shaft power, 0)`` of one wing, shape ``B``."""
    _check_grid(cycle, bird)
    return np.maximum(shaft_power(cycle, bird), 0.0).mean(axis=-1)


def _check_grid(cycle: Cycle, bird: Bird) -> None:
    if cycle.endpoint:
        raise BirdsimError(
            "endpoint=True is invalid for the positive power; allowed: the periodic grid "
            "(endpoint=False)"
        )
    check_wing_mass(bird)


def check_wing_mass(bird: Bird) -> None:
    """A massive wing needs one element per panel (its mass at the control point)."""
    if bird.strips != 1 and bird.wing_mass_fraction > 0.0:
        raise BirdsimError(
            f"bird.strips={bird.strips!r} is invalid with wing_mass_fraction > 0; allowed: 1 "
            "(the wing's mass sits at the panels' control points)"
        )


__all__ = [
    "check_wing_mass",
    "inertial_power",
    "panel_masses",
    "periodic_derivative",
    "positive_power",
    "shaft_power",
]
