"""The MJCF that fits a state: with legs when the state has the legs' coordinates
(issue 25: a flight log of a take-off or landing with legs has four more qpos and qvel
entries, both hips and both leg slides, after the wings')."""

from __future__ import annotations

from typing import Any

import mujoco

from birdsim.mujoco.model import build_model
from birdsim.physics.bird import Bird

#: qpos (and qvel) entries the legs add: a hinge and a slide per side.
LEG_COORDINATES = 4


def build_model_for(model_name: str, bird: Bird, nq: int, **kwargs: Any) -> mujoco.MjModel:
    """``build_model(model_name, bird, **kwargs)``, with legs when ``nq`` (the state's
    qpos length) is the legless model's plus :data:`LEG_COORDINATES`."""
    m = build_model(model_name, bird, **kwargs)
    if nq == m.nq + LEG_COORDINATES:
        return build_model(model_name, bird, legs=True, **kwargs)
    return m


__all__ = ["LEG_COORDINATES", "build_model_for"]
