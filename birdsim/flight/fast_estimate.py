"""The attitude estimate's rotation vectors in compiled code (issue 27: the control
update's Python).

:func:`birdsim.flight.flight_arrays.error_rotvec` turns every sample of the last
wingbeats (a quaternion each) into the rotation vector of ``S^T S_cmd`` with some thirty
numpy calls on (n, 4) arrays at every control update; :func:`error_rotvec` does the same
per-sample formulas in one numba loop: the same operations in the same order, but the
quaternion's norm and the vector's length summed left to right (numpy's ``einsum``
may pair them) and ``cos``, ``sin``, ``arctan2`` from the C library (numpy may use its
own SIMD versions): round-off, measured below 1e-16 (``tests/test_fast_estimate.py``).
Used only with the attitude free (the posed presets never reach it); :data:`ENABLED`
False gives the numpy reference.
"""

from __future__ import annotations

import math

import numpy as np

from birdsim.physics.jit import numba

#: the compiled estimate is used where numba is present (False: numpy, the reference)
ENABLED = True


def _rotvec(quat, pitch_cmd, roll_cmd, yaw_cmd, out, pairwise=False):
    # pairwise: the sums of squares as numpy's einsum makes them on this machine's SIMD
    # lanes ((0 + 2) + (1 + 3), (0 + 2) + 1: bitwise here, round-off elsewhere)
    c, s = math.cos(0.5 * pitch_cmd), math.sin(0.5 * pitch_cmd)
    level = roll_cmd == 0.0 and yaw_cmd == 0.0
    a2 = b2 = c2 = d2 = 0.0
    if not level:  # q_cmd = (cy, 0, 0, sy) * (c, 0, s, 0) * (cr, sr, 0, 0)
        cr, sr = math.cos(0.5 * roll_cmd), math.sin(0.5 * roll_cmd)
        cy, sy = math.cos(0.5 * yaw_cmd), math.sin(0.5 * yaw_cmd)
        p1, p2, p3, p4 = cy * c, -sy * s, cy * s, sy * c
        # flight_arrays._qmul((p1, p2, p3, p4), (cr, sr, 0, 0))
        a2 = p1 * cr - p2 * sr - p3 * 0.0 - p4 * 0.0
        b2 = p1 * sr + p2 * cr + p3 * 0.0 - p4 * 0.0
        c2 = p1 * 0.0 - p2 * 0.0 + p3 * cr + p4 * sr
        d2 = p1 * 0.0 + p2 * 0.0 - p3 * sr + p4 * cr
    for i in range(quat.shape[0]):
        q0, q1, q2, q3 = quat[i, 0], quat[i, 1], quat[i, 2], quat[i, 3]
        if pairwise:
            norm = math.sqrt((q0 * q0 + q2 * q2) + (q1 * q1 + q3 * q3))
        else:
            norm = math.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
        w, x, y, z = q0 / norm, q1 / norm, q2 / norm, q3 / norm
        if level:  # conj(q_S) * q_cmd, q_cmd = (c, 0, s, 0)
            rw = w * c - y * s
            v0 = -x * c - z * s
            v1 = w * s + y * c
            v2 = z * c - x * s
        else:
            a1, b1, c1, d1 = w, -x, y, z  # conj(q_S)
            rw = a1 * a2 - b1 * b2 - c1 * c2 - d1 * d2
            v0 = a1 * b2 + b1 * a2 + c1 * d2 - d1 * c2
            v1 = a1 * c2 - b1 * d2 + c1 * a2 + d1 * b2
            v2 = a1 * d2 + b1 * c2 - c1 * b2 + d1 * a2
        if rw < 0.0:  # the rotation of angle in [0, pi]
            rw = -rw
            v0, v1, v2 = -v0, -v1, -v2
        if pairwise:
            nv = math.sqrt((v0 * v0 + v2 * v2) + v1 * v1)
        else:
            nv = math.sqrt(v0 * v0 + v1 * v1 + v2 * v2)
        angle = 2.0 * math.atan2(nv, rw)
        if angle <= 1e-3:
            sq = angle * angle
            scale = 2.0 + sq / 12.0 + 7.0 * sq * sq / 2880.0
        else:
            scale = angle / math.sin(0.5 * angle)
        out[i, 0] = scale * v0
        out[i, 1] = scale * v1
        out[i, 2] = scale * v2


rotvec_kernel = numba.njit(cache=True)(_rotvec) if numba is not None else None


def error_rotvec(
    quat: np.ndarray, pitch_cmd: float, roll_cmd: float = 0.0, yaw_cmd: float = 0.0
) -> np.ndarray | None:
    """:func:`birdsim.flight.flight_arrays.error_rotvec` compiled: (n, 3), or None where
    it does not apply (switched off, numba missing)."""
    if not ENABLED or rotvec_kernel is None:
        return None
    out = np.empty((quat.shape[0], 3))
    rotvec_kernel(
        np.ascontiguousarray(quat, dtype=float),
        float(pitch_cmd),
        float(roll_cmd),
        float(yaw_cmd),
        out,
    )
    return out


__all__ = ["ENABLED", "error_rotvec", "rotvec_kernel"]
