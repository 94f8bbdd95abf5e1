"""Aerodynamic forces of a posed MuJoCo bird, per control point, for drawing: the
arrows of ``--forces`` and the achieved force of the overlay.

:func:`site_forces` evaluates, from ``qpos``/``qvel`` alone, the force the aero callback
(:mod:`birdsim.mujoco.callback`) applies at each control-point site and the body drag at
the torso: the same core element force (``bird.polar.force_panel``) on the same site
velocities, the air at rest (``opt.wind`` of the rendering model, normally 0).  A test
holds their generalised forces to the callback's ``qfrc_passive`` to 1e-12.

:func:`dissertation_force` sums them into the dissertation's force (ONE wing, the
right, plus body drag) in seed earth axes (x forward, z DOWN) and table force units
(rho omega^2 s^3 c); :func:`wingbeat_mean` averages a series over one wingbeat.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from birdsim.physics.aero import body_drag_x
from birdsim.physics.bird import Bird
from birdsim.physics.units import scales

#: Arrow colours (RGBA): arm / single-panel CP, hand CP, body drag.
ARM_RGBA = (0.95, 0.35, 0.10, 1.0)
HAND_RGBA = (0.15, 0.45, 1.00, 1.0)
DRAG_RGBA = (0.70, 0.20, 0.85, 1.0)
C = np.array([1.0, -1.0, -1.0])  # MuJoCo world <-> seed earth axes (a reflection: its own inverse)


def site_forces(
    mj: Any,
    m: Any,
    d: Any,
    sites: Sequence[Any],
    site_ids: Sequence[int],
    torso_site: int,
    bird: Bird,
) -> tuple[np.ndarray, np.ndarray]:
    """World forces (P, 3) of every CP site (strip forces summed; their moments about
    the site are not returned) and the body drag (3,) on the torso, for the posed
    ``d`` (``mj_kinematics`` + ``mj_comPos`` done; this calls ``mj_comVel``).

    Args:
        mj: the mujoco module; m, d: model and data.
        sites: the :class:`~birdsim.mujoco.model.AeroSite` list; site_ids: their ids.
        torso_site: id of ``torso_cp``; bird: areas, polar and rho.

    Returns:
        (forces (P, 3), drag (3,)), world axes, the bird's force units.
    """
    from birdsim.mujoco.model import span_sign

    mj.mj_comVel(m, d)  # body velocities (cvel) of this qvel: mj_objectVelocity reads them
    vel = np.zeros(6)
    out = np.zeros((len(site_ids), 3))
    wind = np.asarray(m.opt.wind, dtype=float)
    for k, (s, sid) in enumerate(zip(sites, site_ids)):
        mj.mj_objectVelocity(m, d, mj.mjtObj.mjOBJ_SITE, int(sid), vel, 0)
        xmat = d.site_xmat[sid].reshape(3, 3)
        ang, lin = vel[:3].copy(), vel[3:] - wind
        offsets = np.array(s.strip_offsets) * span_sign(s.side)
        areas = np.array(s.strip_widths) * s.chord
        r = xmat[:, 1][None, :] * offsets[:, None]  # site -> element, (S, 3)
        v = lin[None, :] + np.cross(ang[None, :], r)
        local = v @ xmat  # xmat^T v per element
        fx, fz = bird.polar.force_panel(local[:, 0], -local[:, 2], areas, bird.rho)
        out[k] = (np.asarray(fx)[:, None] * xmat[:, 0] - np.asarray(fz)[:, None] * xmat[:, 2]).sum(
            axis=0
        )
    mj.mj_objectVelocity(m, d, mj.mjtObj.mjOBJ_SITE, int(torso_site), vel, 0)
    u = vel[3:] - wind
    speed = float(np.linalg.norm(u))
    drag = np.zeros(3)
    if speed > 0.0:
        loc = d.site_xmat[torso_site].reshape(3, 3).T @ u
        attack = np.arctan2(-loc[2], loc[0])
        drag = float(body_drag_x(speed, abs(attack), bird.rho, bird.body_drag_area)) * u / speed
    return out, drag


def dissertation_force(
    forces_world: np.ndarray, drag_world: np.ndarray, sides: Sequence[str], bird: Bird
) -> np.ndarray:
    """The dissertation's force: right-wing CP forces + body drag, seed earth axes
    (x forward, y right, z down), in table force units (rho omega^2 s^3 c).

    Args:
        forces_world: (..., P, 3) CP forces; drag_world: (..., 3); sides: "r"/"l" per CP.

    Returns:
        (..., 3).
    """
    right = np.array([s == "r" for s in sides])
    total = forces_world[..., right, :].sum(axis=-2) + drag_world
    return total * C / scales(bird).force


def wingbeat_mean(x: np.ndarray, t_beats: np.ndarray) -> np.ndarray:
    """Centred moving average of ``x`` (N, ...) over exactly one wingbeat (within half a
    beat of the clip's ends: the first/last whole wingbeat's mean)."""
    x = np.asarray(x, dtype=float)
    n = len(x)
    if n < 2:
        return x.copy()
    dt = float(np.median(np.diff(t_beats)))
    w = max(1, int(round(1.0 / dt)))  # samples in one wingbeat
    half = w // 2
    weights = np.ones(2 * half + 1)
    if w % 2 == 0:  # w + 1 samples, the two ends at half weight: exactly one beat
        weights[0] = weights[-1] = 0.5
    flat = x.reshape(n, -1)
    if n < 2 * half + 1:  # shorter than a wingbeat: the mean of all
        return np.broadcast_to(flat.mean(axis=0), flat.shape).reshape(x.shape).copy()
    full = (
        np.stack(
            [np.convolve(flat[:, j], weights, mode="valid") for j in range(flat.shape[1])], axis=1
        )
        / weights.sum()
    )
    # near the clip's ends: the nearest whole wingbeat (a partial one would show the wingbeat's ripple)
    out = np.concatenate(
        [np.repeat(full[:1], half, axis=0), full, np.repeat(full[-1:], half, axis=0)]
    )
    return out.reshape(x.shape)


def weight(bird: Bird) -> float:
    """The whole bird's weight m g (the bird's force units); 0 when weightless."""
    return float(bird.mass * bird.gravity)


__all__ = [
    "ARM_RGBA",
    "DRAG_RGBA",
    "HAND_RGBA",
    "dissertation_force",
    "site_forces",
    "weight",
    "wingbeat_mean",
]
