"""A massive m1 wing flapping Phi sin(wt) in (nearly) no air, shared by the shaft-power
tests: its mass a point at half span, so I = m (s/2)^2, the kinetic energy
1/2 I (Phi w cos wt)^2 and dK/dt = -1/2 I Phi^2 w^3 sin 2wt (the air's share ~1e-10)."""

from __future__ import annotations

from birdsim.physics.bird import Bird

PHI, OMEGA, SPAN = 0.7, 3.0, 2.0
MASS, WING_FRACTION = 2.0e4, 0.25


def vacuum_bird() -> Bird:
    """The bird of the vacuum flap, on the positive power cost."""
    return Bird(
        rho=1e-6,
        mass=MASS,
        wing_mass_fraction=WING_FRACTION,
        omega=OMEGA,
        semispan=SPAN,
        power_cost="positive",
    )


def wing_inertia() -> float:
    """The flapping inertia of one wing about the shoulder, I = m_wing (s/2)^2."""
    return WING_FRACTION * MASS * (SPAN / 2.0) ** 2
