"""Ball joints of the kinematic driver (:mod:`birdsim.mujoco.driver`): the quaternion,
child-frame angular velocity and acceleration of an intrinsic composition of rotations
about fixed axes (see the driver's module docstring for the formulas)."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

_KK: dict[bytes, tuple[np.ndarray, np.ndarray]] = {}


def _skew(axis: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(k, k @ k) of the cross-product matrix of ``axis`` (cached: the axes are few)."""
    key = np.asarray(axis, dtype=float).tobytes()
    hit = _KK.get(key)
    if hit is None:
        k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
        hit = _KK[key] = (k, k @ k)
    return hit


def _rotation_matrices(axis: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """Active rotations by ``angle`` (T,) about unit ``axis`` (3,): (T, 3, 3) (Rodrigues)."""
    k, kk = _skew(axis)
    s, c = np.sin(angle)[:, None, None], np.cos(angle)[:, None, None]
    return _EYE3 + s * k + (1.0 - c) * kk


_EYE3 = np.eye(3)


def _quat_mul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    w1, x1, y1, z1 = np.moveaxis(a, -1, 0)
    w2, x2, y2, z2 = np.moveaxis(b, -1, 0)
    return np.stack(
        [
            w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
            w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
        ],
        axis=-1,
    )


def ball_state(
    axes: Sequence[np.ndarray],
    q: Sequence[np.ndarray],
    qd: Sequence[np.ndarray],
    qdd: Sequence[np.ndarray],
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Quaternion (T, 4), child-frame angular velocity and acceleration (T, 3) of the
    intrinsic composition of rotations by ``q[k]`` about ``axes[k]`` (outermost first).

    (The products of :func:`_quat_mul` written out on columns, the first factor taken
    as it is instead of multiplied by the identity: the same numbers up to the sign of
    a zero, without the per-call array shuffling.)"""
    n = len(axes)
    t = np.shape(q[0])[0]
    w = x = y = z = None  # the identity: its product with the first factor is that factor
    for a, ang in zip(axes, q):
        half = 0.5 * np.asarray(ang)
        w2 = np.cos(half)
        sn = np.sin(half)
        x2, y2, z2 = sn * a[0], sn * a[1], sn * a[2]
        if w is None:
            w, x, y, z = w2, x2, y2, z2
            continue
        w, x, y, z = (
            w * w2 - x * x2 - y * y2 - z * z2,
            w * x2 + x * w2 + y * z2 - z * y2,
            w * y2 - x * z2 + y * w2 + z * x2,
            w * z2 + x * y2 - y * x2 + z * w2,
        )
    quat = np.empty((t, 4))
    quat[:, 0], quat[:, 1], quat[:, 2], quat[:, 3] = w, x, y, z
    v = [None] * n
    b = None  # A_{k+1} .. A_n, built from the inside out (None: the identity)
    for k in range(n - 1, -1, -1):
        a = np.asarray(axes[k], dtype=float)
        # B^T a_k (at B = I: a_k exactly, as the einsum gives it)
        v[k] = np.broadcast_to(a, (t, 3)) if b is None else np.einsum("tji,j->ti", b, a)
        rot = _rotation_matrices(a, np.asarray(q[k]))
        b = rot if b is None else rot @ b
    alpha = np.zeros((t, 3))
    outer = np.zeros((t, 3))  # W_k = sum_{j>k} v_j qd_j
    for k in range(n - 1, -1, -1):
        rate = np.asarray(qd[k])[:, None]
        vk = v[k]
        o0, o1, o2 = outer[:, 0], outer[:, 1], outer[:, 2]
        v0, v1, v2 = vk[:, 0], vk[:, 1], vk[:, 2]
        cross = np.empty((t, 3))  # np.cross(outer, v_k), its products in its order
        cross[:, 0] = o1 * v2 - o2 * v1
        cross[:, 1] = o2 * v0 - o0 * v2
        cross[:, 2] = o0 * v1 - o1 * v0
        alpha += vk * np.asarray(qdd[k])[:, None] - rate * cross
        outer = outer + vk * rate
    omega = outer
    return quat, omega, alpha


__all__ = ["ball_state"]
