"""The two wings of a whole-bird evaluation: the right and left wings' parameters from the
symmetric wingbeat and the control inputs, the mirror of the left wing's results back to
the bird (force ``(Fx, -Fy, Fz)``, moment ``(-Mx, My, -Mz)``) and the body drag in body
axes; shared by the numpy reference (:mod:`birdsim.physics.moments_eval`) and the kernel
(:mod:`birdsim.physics.kernel_moments`)."""

from __future__ import annotations

import numpy as np

from birdsim.physics.aero import body_drag
from birdsim.physics.control_inputs import CONTROL_INPUTS
from birdsim.physics.frames import earth_to_body

MIRROR_F = np.array([1.0, -1.0, 1.0])
MIRROR_M = np.array([-1.0, 1.0, -1.0])


def sides(mx, sym, u, signs):
    """Right and left parameters (dicts of B arrays) from the symmetric ones and u (B x k)."""
    right = {k: np.array(v, dtype=float) for k, v in sym.items()}
    left = {k: np.array(v, dtype=float) for k, v in sym.items()}
    for i, (name, _) in enumerate(CONTROL_INPUTS[mx.name]):
        right[name] = right[name] + signs[0][i] * u[:, i]
        left[name] = left[name] + signs[1][i] * u[:, i]
    return right, left


def drag_body(sym, speed, climb, bird) -> np.ndarray:
    dx, dz = body_drag(speed, climb, sym["pitch"], bird.rho, bird.body_drag_area)
    out = earth_to_body(sym["pitch"], (dx, 0.0, dz))
    return np.stack([np.broadcast_to(c, speed.shape) for c in out], axis=-1)
