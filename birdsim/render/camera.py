"""Cameras that follow the bird smoothly: ``track``, ``chase``, ``side``, ``top`` and
the fixed ``overview`` (:data:`birdsim.render.options.CAMERAS`).

The moving cameras look at the bird's position smoothed by a critically damped
filter (two cascaded first-order lags of time constant ``tau``: a double real pole)
run forward and then backward over the whole clip.  Run both ways it has no lag (a
bird at constant velocity stays in the middle of the frame) and it attenuates the
wingbeat's bobbing by ``(1 + (2 pi tau)^2)^-2`` per beat-frequency component (about
1/120 at tau = 0.5 beat, the default): no jitter at the wingbeat frequency.  The ends are padded
with the trend of the first/last beat so the filter starts and ends on the path.

Distances scale with the wingspan and the narrower field of view of the frame, so the
bird fills about the same part of the frame at every size and aspect ratio.  The
``overview`` camera is fixed: it frames the box around every position of the bird
(plus a wingspan) and the perch.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.signal import lfilter

#: Smoothing time constant of the moving cameras, in wingbeats.
TAU_BEATS = 0.5
#: Part of the narrower frame side the wingspan should cover (track/chase/side/top).
SPAN_FRACTION = 0.45


def smooth_critically_damped(x: np.ndarray, t: np.ndarray, tau: float) -> np.ndarray:
    """Zero-phase critically damped smoothing of ``x`` (N, ...) sampled at times ``t``
    (N,): two first-order lags of time constant ``tau``, forward then backward, on the
    series padded at both ends by linear extrapolation over ``10 tau``."""
    x = np.asarray(x, dtype=float)
    t = np.asarray(t, dtype=float)
    n = len(t)
    if n < 2 or tau <= 0:
        return x.copy()
    dt = float(np.median(np.diff(t)))
    if dt <= 0:
        return x.copy()
    pad = int(math.ceil(10.0 * tau / dt))  # the start-up transients decay to ~1e-4
    w = max(1, int(round(1.0 / dt)))  # samples per wingbeat
    k = np.arange(1, pad + 1)[:, None]

    def trend(seg: np.ndarray, tt: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
        """Line through ``seg``: slope, value at time ``centre``, centre.  From the means
        of two whole wingbeats when there are two (a periodic bob cancels exactly),
        else a least-squares line."""
        flat = seg.reshape(len(seg), -1)
        if len(seg) >= 2 * w:
            ca, cb = float(tt[:w].mean()), float(tt[w : 2 * w].mean())
            ma, mb = flat[:w].mean(axis=0), flat[w : 2 * w].mean(axis=0)
            return (mb - ma) / (cb - ca), ma, ca
        centre = float(tt.mean())
        slope, mean = np.polyfit(tt - centre, flat, 1)
        return slope, mean, centre

    s0, m0, c0 = trend(x[: 2 * w], t[: 2 * w])
    s1, m1, c1 = trend(x[::-1][: 2 * w], t[::-1][: 2 * w])
    head = (m0 + s0 * ((t[0] - k * dt) - c0)).reshape((pad,) + x.shape[1:])[::-1]
    tail = (m1 + s1 * ((t[-1] + k * dt) - c1)).reshape((pad,) + x.shape[1:])
    y = np.concatenate([head, x, tail])
    a = math.exp(-dt / tau)

    def lag(
        z: np.ndarray,
    ) -> np.ndarray:  # y[i] = a y[i-1] + (1 - a) z[i], starting at rest on z[0]
        return lfilter([1.0 - a], [1.0, -a], z, axis=0, zi=(a * z[:1]))[0]

    y = lag(lag(y))
    y = lag(lag(y[::-1]))[::-1]
    return y[pad : pad + n]


def fit_distance(size: float, fovy_deg: float, aspect: float, fraction: float) -> float:
    """Distance at which an object of ``size`` spans ``fraction`` of the narrower side
    of a frame of vertical field of view ``fovy_deg`` and width/height ``aspect``."""
    half_y = math.radians(fovy_deg) / 2
    half = min(half_y, math.atan(aspect * math.tan(half_y)))
    return size / fraction / (2.0 * math.tan(half))


@dataclass(frozen=True)
class CameraPose:
    """Where a camera looks from: ``lookat`` (3,) world, ``distance``, and MuJoCo's
    ``azimuth``/``elevation`` in degrees (elevation < 0 looks down)."""

    lookat: np.ndarray
    distance: float
    azimuth: float
    elevation: float

    @staticmethod
    def from_offset(lookat: np.ndarray, offset: np.ndarray) -> "CameraPose":
        """The camera at ``lookat + offset`` looking at ``lookat``."""
        d = float(np.linalg.norm(offset))
        f = -np.asarray(offset, dtype=float) / d
        el = math.degrees(math.asin(max(-0.9999, min(0.9999, f[2]))))
        az = math.degrees(math.atan2(f[1], f[0]))
        return CameraPose(np.asarray(lookat, dtype=float), d, az, el)

    def position(self) -> np.ndarray:
        az, el = math.radians(self.azimuth), math.radians(self.elevation)
        f = np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
        return self.lookat - self.distance * f


#: Fraction of the frame's height the overview leaves above the flight for the overlay
#: text (six lines cover the top 27 % of a 640x480 frame).
OVERVIEW_TEXT_BAND = 0.3


def camera_path(
    name: str,
    position: np.ndarray,
    heading: np.ndarray,
    t_beats: np.ndarray,
    span: float,
    fovy_deg: float,
    aspect: float,
    extra_points: np.ndarray | None = None,
) -> list[CameraPose]:
    """One :class:`CameraPose` per instant for camera ``name``.

    Args:
        name: track, chase, side, top or overview.
        position: (N, 3) the bird's position (world, x forward, z up).
        heading: (N, 3) the bird's forward direction (world; only its horizontal part
            is used, by ``chase``).
        t_beats: (N,) times in wingbeats.
        span: the bird's wingspan (2 semispans), length units.
        fovy_deg, aspect: the camera's vertical field of view and width/height.
        extra_points: (K, 3) points the overview must also show (e.g. the perch).

    Returns:
        The poses, one per instant.
    """
    n = len(t_beats)
    if name == "overview":
        pts = position if extra_points is None else np.vstack([position, extra_points])
        lo, hi = pts.min(axis=0) - span, pts.max(axis=0) + span
        # the overlay text covers the top of the frame: keep the bird in the rest
        hi[2] = lo[2] + (hi[2] - lo[2]) / (1.0 - OVERVIEW_TEXT_BAND)
        centre = 0.5 * (lo + hi)
        half_x, half_z = 0.5 * (hi[0] - lo[0]), 0.5 * (hi[2] - lo[2])
        half_y_fov = math.radians(fovy_deg) / 2
        half_x_fov = math.atan(aspect * math.tan(half_y_fov))
        # seen from the side (-y) and a little above: both extents inside the frame
        dist = max(half_x / math.tan(half_x_fov), half_z / math.tan(half_y_fov)) * 1.15 + 0.5 * (
            hi[1] - lo[1]
        )
        pose = CameraPose.from_offset(
            centre, np.array([0.0, -1.0, 0.25]) / math.hypot(1.0, 0.25) * dist
        )
        return [pose] * n
    p = smooth_critically_damped(position, t_beats, TAU_BEATS)
    dist = fit_distance(span, fovy_deg, aspect, SPAN_FRACTION)
    if name == "track":
        offset = np.array([-0.6, -0.65, 0.3])
    elif name == "side":  # seen from the side the bird is shorter than its span: closer
        dist *= 0.85
        offset = np.array([0.0, -1.0, 0.0])
    elif name == "top":
        offset = np.array([0.0, -0.02, 1.0])
    elif name == "chase":
        h = smooth_critically_damped(heading * np.array([1.0, 1.0, 0.0]), t_beats, TAU_BEATS)
        out = []
        for k in range(n):
            fwd = (
                h[k] / max(np.linalg.norm(h[k]), 1e-12)
                if np.linalg.norm(h[k]) > 1e-6
                else np.array([1.0, 0.0, 0.0])
            )
            off = -fwd + np.array([0.0, 0.0, 0.3])
            out.append(CameraPose.from_offset(p[k], off / np.linalg.norm(off) * dist * 1.1))
        return out
    else:
        raise ValueError(name)
    offset = offset / np.linalg.norm(offset) * dist
    return [CameraPose.from_offset(p[k], offset) for k in range(n)]


def project(points: np.ndarray, pose: CameraPose, fovy_deg: float, aspect: float) -> np.ndarray:
    """Normalised image coordinates (N, 2) in [-1, 1] (x right, y up) of world
    ``points`` (N, 3) seen by ``pose``; points behind the camera get inf."""
    az, el = math.radians(pose.azimuth), math.radians(pose.elevation)
    f = np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
    right = np.cross(f, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, f)
    rel = np.atleast_2d(points) - pose.position()
    z = rel @ f
    ty = math.tan(math.radians(fovy_deg) / 2)
    x = (rel @ right) / (z * ty * aspect)
    y = (rel @ up) / (z * ty)
    out = np.column_stack([x, y])
    out[z <= 0] = np.inf
    return out


__all__ = [
    "CameraPose",
    "SPAN_FRACTION",
    "TAU_BEATS",
    "camera_path",
    "fit_distance",
    "project",
    "smooth_critically_damped",
]
