"""The span ratio of a wingbeat: the wing's span at mid-upstroke over its span at
mid-downstroke (Tobalske & Dial 1996 J Exp Biol 199:263 measure it from the wingtips).

The span is the tip-to-tip distance seen from above, twice the right wingtip's body-axes
y (the wings are mirror images).  Mid-downstroke is phase 0 (the flap angle passes 0
going down, docs/conventions.md), mid-upstroke phase pi.  Every model has it; it differs
from 1 for m4 (the wrist flap) and above all for m5 (the fold).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import KinematicModel
from birdsim.physics.tip_path import tip_positions


def tip_span(
    model: str | KinematicModel,
    params: Mapping[str, object],
    phases: np.ndarray,
    *,
    bird: Bird | None = None,
    check_bounds: bool = True,
) -> np.ndarray:
    """Tip-to-tip span [bird length units] at ``phases`` (omega t, shape N), with the
    parameters' batch shape B in front: shape (*B, N)."""
    _, y, _ = tip_positions(model, params, phases, bird=bird, check_bounds=check_bounds)
    return 2.0 * y


def span_ratio(
    model: str | KinematicModel,
    params: Mapping[str, object],
    *,
    bird: Bird | None = None,
    check_bounds: bool = True,
) -> np.ndarray:
    """Span at mid-upstroke over span at mid-downstroke (shape: the parameters' batch)."""
    s = tip_span(model, params, np.array([0.0, np.pi]), bird=bird, check_bounds=check_bounds)
    return s[..., 1] / s[..., 0]
