"""A plain transcription of the dissertation's ``flapcost`` (appendix 1B) for the
single-panel models, written independently of birdsim's chain machinery: a loop over
time samples, the 3x3 matrices of Table 2 typed in again, the CP velocities of
eqs 55, 59, 66 (constant sweep) and 73.  OCR typos mended as docs/design.md says: the zero
middle element of the printed 3x3 matrices is 1, ``F1 = R12.*F2`` is the transpose
product, forces go to earth axes with R_e1 transposed, twist is ``-Theta_f cos(wt)``,
power is ``-F1 . V1f``.
"""

from __future__ import annotations

import numpy as np


def _pitch(a: float) -> np.ndarray:
    return np.array([[np.cos(a), 0, -np.sin(a)], [0, 1, 0], [np.sin(a), 0, np.cos(a)]])


def _flap(a: float) -> np.ndarray:
    return np.array([[1, 0, 0], [0, np.cos(a), np.sin(a)], [0, -np.sin(a), np.cos(a)]])


def _sweep(a: float) -> np.ndarray:
    return np.array([[np.cos(a), np.sin(a), 0], [-np.sin(a), np.cos(a), 0], [0, 0, 1]])


def flapcost_histories(
    model: str, params: dict, speed: float, times: np.ndarray, s: float = 1.0, c: float = 1.0
):
    """Earth-axes force (N x 3) and power (N,) of the right wing, no body drag."""
    cl_max, cd0, cd_max, rho, omega = 2.0, 0.05, 1.0, 1.0, 1.0
    theta, phi_amp, theta_amp = params["pitch"], params["flap_amp"], params["twist_amp"]
    gamma = params.get("sweep", 0.0)
    sp = params.get("stroke_plane", 0.0)
    r_e1 = _pitch(theta)
    forces, powers = [], []
    for t in times:
        phi = phi_amp * np.sin(omega * t)
        w = s / 2 * omega * phi_amp * np.cos(omega * t)
        thetaf = theta_amp * np.sin(omega * t - np.pi / 2)
        if model == "base":  # eq 55-56
            v1f = np.array([0.0, 0.0, w])
            r12 = _pitch(thetaf)
        elif model == "m1":  # eq 59-60
            v1f = np.array([0.0, -w * np.sin(phi), w * np.cos(phi)])
            r12 = _pitch(thetaf) @ _flap(phi)
        elif model == "m2":  # eq 66-67 with a constant sweep (Gamma_f = 0)
            v1f = np.array(
                [w * np.sin(phi) * np.sin(gamma), -w * np.sin(phi) * np.cos(gamma), w * np.cos(phi)]
            )
            r12 = _pitch(thetaf) @ _flap(phi) @ _sweep(gamma)
        elif model == "m3":  # eq 73-74, stroke plane as a pitch-type matrix (docs/design.md)
            v1f = np.array(
                [w * np.cos(phi) * np.sin(sp), -w * np.sin(phi), w * np.cos(phi) * np.cos(sp)]
            )
            r12 = _pitch(thetaf) @ _flap(phi) @ _pitch(sp)
        else:
            raise ValueError(model)
        v1 = v1f + r_e1 @ np.array([speed, 0.0, 0.0])
        v2 = r12 @ v1
        alpha = np.arctan2(v2[2], v2[0])
        q = 0.5 * rho * (v2[0] ** 2 + v2[2] ** 2)
        cd = cd0 + cd_max * np.sin(alpha) ** 2
        cl = cl_max * np.sin(2 * alpha)
        f3 = np.array([-cd, 0.0, -cl]) * q * s * c
        f2 = _pitch(alpha) @ f3
        f1 = r12.T @ f2
        powers.append(-f1 @ v1f)
        forces.append(r_e1.T @ f1)
    return np.array(forces), np.array(powers)
