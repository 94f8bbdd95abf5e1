"""The attitude loop's gains per unit inertia: the design's triple pole and the gains for a
body that already has its own damping and stiffness (used by :mod:`birdsim.flight.attitude`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class AttitudeGains:
    """Per axis (roll, pitch, yaw) arrays, per unit inertia."""

    omega_a: np.ndarray
    kp: np.ndarray
    kd: np.ndarray
    ki: np.ndarray


def damped_gains(
    omega_a: np.ndarray, damping: np.ndarray, stiffness: object = 0.0
) -> AttitudeGains:
    """Per axis gains (per unit inertia) for a body whose wingbeat-mean rotation already
    has the damping ``c`` and the restoring stiffness ``k`` (per unit inertia, >= 0; the
    flapping's and the tail's, measured): closed-loop poles at ``-p``, ``p = max(c,
    omega_a)`` (the natural pole kept where it is faster than the design), and the roots
    of ``s^2 + 2 omega_a s + q``, ``q = max(omega_a^2, k)`` (a double pole at
    ``-omega_a``, or, where the stiffness alone is stiffer than the design, the natural
    frequency kept): ``Kd = p + 2 omega_a - c``, ``Kp = 2 p omega_a + q - k``, ``Ki = p
    q``; at ``c = k = 0`` the triple pole of :func:`attitude_gains`."""
    wa = np.asarray(omega_a, dtype=float)
    c = np.asarray(damping, dtype=float)
    k = np.asarray(stiffness, dtype=float)
    p = np.maximum(c, wa)
    stiff = k > wa * wa
    q = np.where(stiff, k, wa * wa)
    ki = np.where(stiff, p * k, p * wa * wa)
    return AttitudeGains(wa, 2.0 * p * wa + q - k, p + 2.0 * wa - c, ki)
