"""The body's attitude as the attitude loop reads it: Euler angles of MuJoCo's
quaternion (:func:`euler_zyx`) and the least-squares fit that takes the wingbeat-mean
state out of the last wingbeat's samples (:func:`wingbeat_fit_matrix`)."""

from __future__ import annotations

import math

import numpy as np


def euler_zyx(quat: np.ndarray) -> np.ndarray:
    """(roll, pitch, yaw) of MuJoCo quaternions (..., 4) (w, x, y, z): the seed body frame
    relative to seed earth axes, Z-Y-X order (yaw about earth z down, then pitch about
    y right, nose up, then roll about x forward, right wing down)."""
    w, x, y, z = np.moveaxis(np.asarray(quat, dtype=float), -1, 0)
    # MuJoCo rotation matrix entries; the seed frame is C R C, C = diag(1, -1, -1)
    r00 = 1 - 2 * (y * y + z * z)
    r10 = 2 * (x * y + w * z)
    r20 = 2 * (x * z - w * y)
    r21 = 2 * (y * z + w * x)
    r22 = 1 - 2 * (x * x + y * y)
    # seed: S = C R C -> S00 = r00, S10 = -r10, S20 = -r20, S21 = r21, S22 = r22
    pitch = np.arcsin(np.clip(r20, -1.0, 1.0))
    roll = np.arctan2(r21, r22)
    yaw = np.arctan2(-r10, r00)
    return np.stack([roll, pitch, yaw], axis=-1)


#: Harmonics of the wingbeat removed by the attitude estimate's fit.
FIT_HARMONICS = 3
#: Wingbeats of samples the estimate fits.
FIT_BEATS = 1


def wingbeat_fit_matrix(
    n: int, period: float, harmonics: int = FIT_HARMONICS, beats: int = 1
) -> np.ndarray:
    """Rows (2, n): the least-squares weights that give, from ``n`` samples spanning the
    last ``beats`` wingbeats (the newest last), the value now and the slope of the fit
    ``a + b tau + sum_k (c_k cos k w tau + s_k sin k w tau)`` (tau = time before now,
    k = 1..harmonics and, over two or more wingbeats, k = 1/2 too): the wingbeat-mean
    state without the moving average's lag."""
    length = beats * period
    dt = length / n
    tau = -dt * np.arange(n - 1, -1, -1)
    w = 2.0 * math.pi / period
    ks = [k for k in range(1, harmonics + 1)] + ([0.5] if beats >= 2 else [])
    cols = [np.ones(n), tau]
    for k in ks:
        cols += [np.cos(k * w * tau), np.sin(k * w * tau)]
    pinv = np.linalg.pinv(np.stack(cols, axis=1))
    # the trend's value now (a; the periodic part is the within-beat rocking) and slope (b)
    return np.stack([pinv[0], pinv[1]])
