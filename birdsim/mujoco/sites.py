"""The control points the aerodynamic callback acts on (both wings): their sites,
areas and strip layout, from the bird (:mod:`birdsim.mujoco.model` builds the sites)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model

SIDES = ("r", "l")


def span_sign(side: str) -> float:
    """MuJoCo y of the outward span direction at rest: -1 right wing, +1 left wing."""
    return -1.0 if side == "r" else 1.0


def pitch_quat(pitch: float) -> np.ndarray:
    """MuJoCo quaternion (w, x, y, z) of the torso at body pitch ``pitch`` (nose up):
    a rotation by ``pitch`` about MuJoCo -y."""
    return np.array([math.cos(pitch / 2), 0.0, -math.sin(pitch / 2), 0.0])


@dataclass(frozen=True)
class AeroSite:
    """One control point the callback acts on: its site, panel area and strip layout."""

    site: str
    side: str
    panel: str
    area: float
    chord: float
    #: span positions of the strip elements relative to the site, along the panel's
    #: outward span (one element at 0 for the default single control point)
    strip_offsets: tuple[float, ...]
    strip_widths: tuple[float, ...]


def aero_sites(model_name: str, bird: Bird) -> tuple[AeroSite, ...]:
    """The CP sites a kinematic model uses (both wings), with areas from the bird.

    With ``bird.strips > 1`` each panel's elements are the core's strips; their offsets
    from the site follow ``kinematics.strip_positions``.
    """
    from birdsim.physics.kinematics import strip_positions

    get_model(model_name)
    out = []
    for side in SIDES:
        for panel in bird.panels(model_name):
            r, w = strip_positions(panel.span, bird.cp_span_fraction, bird.strips)
            r_cp = bird.cp_span_fraction * panel.span
            out.append(
                AeroSite(
                    f"{side}_cp_{panel.name}",
                    side,
                    panel.name,
                    panel.area,
                    panel.chord,
                    tuple(float(x) for x in r - r_cp),
                    tuple(float(x) for x in w),
                )
            )
    return tuple(out)


__all__ = ["SIDES", "AeroSite", "aero_sites", "pitch_quat", "span_sign"]
