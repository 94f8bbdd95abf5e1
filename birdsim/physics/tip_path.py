"""The right wingtip's path through a wingbeat, and its stroke-plane angle in side view.

Tobalske & Dial 1996 (J Exp Biol 199:263, Summary) measure "the stroke-plane angles of
the wingtip and wrist relative to the horizontal": the station is the wingtip, the
reference the horizontal.  For a rigid wing (base-m3) the tip moves in the flap's plane,
so its side view is a straight segment at ``90 - (pitch + stroke_plane)`` degrees; a
wrist or a folding wing (m4, m5) moves the tip off that plane, so the angle is taken
from the tip itself: the line through the tip's highest and lowest points of the
wingbeat in side view (seed earth axes: X forward, Z down; the body pitched by
``pitch``), measured from the forward horizontal, positive when the lowest point lies
ahead of the highest (the downstroke runs down and forward), in (-90, 90] degrees.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.frames import body_to_earth
from birdsim.physics.kinematics import (
    KinematicModel,
    get_model,
    joint_states,
    points_in_body,
    validate_params,
)

#: Phases of the coarse scan of the tip path (a multiple of 4 holds the rigid wing's
#: extremes, phases -pi/2 and pi/2, exactly).
COARSE_SAMPLES = 360
#: Phases of the fine scan around each coarse extreme (odd: centred on it).
FINE_SAMPLES = 201


def tip_positions(
    model: str | KinematicModel,
    params: Mapping[str, object],
    phases: np.ndarray,
    *,
    bird: Bird | None = None,
    check_bounds: bool = True,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The right wingtip (the outermost panel's span end, on its twist axis) in body axes
    relative to the shoulder [bird length units] at ``phases`` (omega t, shape N): (x, y, z),
    each of shape (*B, N) with the parameters' batch shape B in front."""
    m = model if isinstance(model, KinematicModel) else get_model(model)
    bird = Bird() if bird is None else bird
    p = validate_params(m, params, check_bounds=check_bounds)
    batch = np.broadcast_shapes(*(a.shape for a in p.values()))
    flat = {k: np.broadcast_to(a, batch).reshape(-1) for k, a in p.items()}
    phases = np.asarray(phases, dtype=float)
    states = joint_states(m, flat, bird, phases, trailing=1)
    chain, span, _ = m.chain_with_geometry(bird)[-1]  # the outermost panel carries the tip
    pos, _ = points_in_body(chain, states, np.array([span]))
    shape = (len(flat["pitch"]), len(phases), 1)
    return tuple(  # type: ignore[return-value]
        np.broadcast_to(c, shape)[..., 0].reshape(batch + (len(phases),)) for c in pos
    )


def _side_view(
    m: KinematicModel, params: Mapping[str, object], bird: Bird, phases: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Earth X (forward) and Z (down) of the tip at ``phases`` for one parameter set."""
    x, y, z = tip_positions(m, params, phases, bird=bird, check_bounds=False)
    pitch = float(np.asarray(params["pitch"], dtype=float))
    ex, _, ez = body_to_earth(pitch, (x, y, z))
    return np.asarray(ex, dtype=float).ravel(), np.asarray(ez, dtype=float).ravel()


def _extreme_phase(
    m: KinematicModel,
    params: Mapping[str, object],
    bird: Bird,
    coarse: np.ndarray,
    k: int,
    sign: float,
) -> float:
    """The phase of the tip's highest (sign -1: least Z) or lowest (+1) point, refined on a
    fine scan one coarse step either side of coarse sample ``k``."""
    step = 2.0 * math.pi / len(coarse)
    fine = coarse[k] + np.linspace(-step, step, FINE_SAMPLES)
    _, z = _side_view(m, params, bird, fine)
    return float(fine[int(np.argmax(sign * z))])


def tip_stroke_plane_deg(
    model: str | KinematicModel,
    params: Mapping[str, object],
    *,
    bird: Bird | None = None,
    check_bounds: bool = True,
) -> float:
    """The wingtip's stroke-plane angle to the horizontal [deg] of one wingbeat (module
    docstring): the side-view line through the tip's highest and lowest points."""
    m = model if isinstance(model, KinematicModel) else get_model(model)
    bird = Bird() if bird is None else bird
    validate_params(m, params, check_bounds=check_bounds)
    coarse = 2.0 * math.pi * np.arange(COARSE_SAMPLES) / COARSE_SAMPLES
    _, z = _side_view(m, params, bird, coarse)
    top = _extreme_phase(m, params, bird, coarse, int(np.argmin(z)), -1.0)
    bottom = _extreme_phase(m, params, bird, coarse, int(np.argmax(z)), 1.0)
    x2, z2 = _side_view(m, params, bird, np.array([top, bottom]))
    angle = math.degrees(math.atan2(z2[1] - z2[0], x2[1] - x2[0]))  # in [0, 180]: Z down
    return angle - 180.0 if angle > 90.0 else angle


__all__ = ["COARSE_SAMPLES", "FINE_SAMPLES", "tip_positions", "tip_stroke_plane_deg"]
