"""Rotational damping of flapping (issue 22): birdsim's side of the damping rows.

The derivatives come from :func:`birdsim.physics.moments.wingbeat_moments` (the
blade-element model with ``omega x r`` in every element's air velocity), for the
trimmed wingbeat at the row's speed, in the bird's own units.  They are made
non-dimensional as in airplane flight dynamics, the comparison Hedrick, Usherwood &
Biewener (2007) make ("2-6 times greater than those typical of airplane flight dynamics
(approximately -0.45)"): ``C_lp = dC_l / d(p b / 2V)`` with ``C_l = L / (q S b)``, so
``C_lp = 4 (dL/dp) / (rho V S b^2)``; b the full span (2 semispans), S both wings' area.
That reading of their normalisation is inferred from that comparison, not from their
methods section (not verified).
"""

from __future__ import annotations

import math

from birdsim.physics.bird import Bird
from birdsim.physics.moments import wingbeat_moments


def wing_area(model: str, bird: Bird) -> float:
    """Both wings' planform area S (sum of the panels' span x chord, twice)."""
    return 2.0 * sum(p.span * p.chord for p in bird.panels(model))


def damping_coefficients(
    model: str, bird: Bird, params: dict[str, float], speed: float
) -> tuple[float, float]:
    """(C_lp, C_nr): roll and yaw damping, non-dimensional as above (speed > 0)."""
    r = wingbeat_moments(model, params, speed, bird, jacobians=True)
    b = 2.0 * bird.semispan
    scale = 4.0 / (bird.rho * speed * wing_area(model, bird) * b * b)
    return scale * float(r.moment_drate[0, 0]), scale * float(r.moment_drate[2, 2])


def frequency_scaling(model: str, bird: Bird, params: dict[str, float]) -> float:
    """The ratio of the hover roll damping at twice the wingbeat frequency to that at the
    bird's own (2 when the damping is proportional to the frequency)."""
    from dataclasses import replace

    slow = wingbeat_moments(model, params, 0.0, bird, jacobians=True).moment_drate[0, 0]
    fast = wingbeat_moments(
        model, params, 0.0, replace(bird, omega=2.0 * bird.omega), jacobians=True
    ).moment_drate[0, 0]
    return float(fast / slow) if slow != 0 and math.isfinite(slow) else math.nan
