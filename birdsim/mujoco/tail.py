"""The tail: a slender lifting surface behind the body, applied in the aero callback.

Slender-wing theory (Jones 1946, applied to bird tails by Thomas 1993, Phil. Trans. R.
Soc. B 340:361-380): a triangular fan of spread span ``b`` at a small angle of attack
``alpha`` lifts ``L = (pi/4) rho V^2 alpha b^2``, whatever its length, acting about two
thirds along the tail from its root; its induced drag, elliptic loading over the span
b, is ``D_i = L^2 / ((pi/2) rho V^2 b^2) = L alpha / 2``; a profile drag
``1/2 rho V^2 S C_D0`` (S = b l / 2, the fan's area) is added.

Validity (stated, and enforced by capping): the theory holds for small alpha, about
15-20 degrees (:data:`ALPHA_MAX` = 20 degrees: beyond it the lift is held at its value
there, the tail is taken as stalled-but-not-lost), and for fans spread below about
60 degrees either side of the axis; the bird file's ``tail_span`` is the widest spread
the model allows, ``spread`` in [:data:`SPREAD_MIN`, 1] scales it.  Evans (2003, J.
Exp. Biol. 206:4501) found the theory's predictions poorly supported in swallows: the
tail here is a first model, not a validated one.

Local flow: the velocity of the tail's centre of pressure through the air (MuJoCo's site
velocity: body velocity, the body's rotation (omega x r, the pitch rate's q x_t term)
and the wind); the wings' downwash at the tail is NOT included.  Flow from behind (the
tail moving backwards through the air) gives drag only.

Controls (:class:`TailControls`): ``elevation`` (rad, positive = trailing edge up, a
nose-up moment), ``spread`` (fraction of the widest span), ``roll`` (rad, the tail
banked about the body's x axis, positive = right side down: its lift leans right and
swings the tail to the right, a nose-left yaw moment).

Axes: MuJoCo body axes (x forward, y left, z up).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: Largest angle of attack of the slender-wing lift (rad); beyond it the lift is capped.
ALPHA_MAX = math.radians(20.0)
#: Smallest spread (fraction of the bird's tail_span): a furled tail still has a width.
SPREAD_MIN = 0.25
#: Profile drag coefficient of the spread tail on its area (ESTIMATE: a thin feathered plate).
TAIL_CD0 = 0.02
#: Bounds of the elevation and roll controls (rad).
ELEVATION_MAX = math.radians(30.0)
ROLL_MAX = math.radians(30.0)


@dataclass(frozen=True)
class TailControls:
    """The tail's controls (a new object every control step: the callback keeps the
    tail's frame for the object it last saw)."""

    elevation: float = 0.0
    spread: float = 1.0
    roll: float = 0.0

    def clipped(self) -> "TailControls":
        return TailControls(*self.clipped_values())

    def clipped_values(self) -> tuple[float, float, float]:
        """(elevation, spread, roll) of :meth:`clipped` as floats (no new object)."""
        return (
            min(max(float(self.elevation), -ELEVATION_MAX), ELEVATION_MAX),
            min(max(float(self.spread), SPREAD_MIN), 1.0),
            min(max(float(self.roll), -ROLL_MAX), ROLL_MAX),
        )


def tail_frame(controls: TailControls) -> np.ndarray:
    """Columns: the tail's chord (forward), span (left) and normal (up) in body axes."""
    out = np.empty((3, 3))
    frame_into(controls.elevation, controls.roll, out)
    return out


def frame_into(e: float, r: float, out: np.ndarray) -> None:
    """:func:`tail_frame` of the elevation ``e`` and roll ``r`` (rad) into ``out`` (3, 3)
    (plain Python; :mod:`birdsim.mujoco.aero_kernel` compiles it: the C library's ``cos``
    and ``sin`` there as in ``math``, the same bits)."""
    ce, se, cr, sr = math.cos(e), math.sin(e), math.cos(r), math.sin(r)
    # rot_x @ rot_y, rot_y = [[ce, 0, se], [0, 1, 0], [-se, 0, ce]] (trailing edge up),
    # rot_x = [[1, 0, 0], [0, cr, -sr], [0, sr, cr]] (right side down): each entry has one
    # product that is not an exact zero, so the matrix product's numbers in any order of
    # summation (cos > 0 within the clipped angles: a +0 term makes a zero +0)
    out[0, 0], out[0, 1], out[0, 2] = ce, 0.0, se + 0.0
    out[1, 0], out[1, 1], out[1, 2] = sr * se + 0.0, cr, -sr * ce + 0.0
    out[2, 0], out[2, 1], out[2, 2] = cr * -se + 0.0, sr + 0.0, cr * ce


def tail_cp_offset(tail_root: float, tail_length: float) -> np.ndarray:
    """Body-axes position of the tail's centre of pressure (2/3 along from the root)."""
    return np.array([-(tail_root + 2.0 / 3.0 * tail_length), 0.0, 0.0])


def tail_force(
    vel_body: np.ndarray,
    controls: TailControls,
    *,
    span: float,
    length: float,
    rho: float,
    frame: np.ndarray | list | None = None,
) -> tuple[np.ndarray, float]:
    """Force on the tail (body axes) for the tail's velocity through the air
    ``vel_body`` (body axes), and the angle of attack used (rad, capped).  ``frame``:
    :func:`tail_frame` of the clipped controls (or its rows as lists), when the caller
    has it already."""
    spread = min(max(float(controls.spread), SPREAD_MIN), 1.0)
    if frame is None:
        frame = tail_frame(controls.clipped())
    fr = frame.tolist() if isinstance(frame, np.ndarray) else frame  # rows, as floats
    v0, v1, v2_ = float(vel_body[0]), float(vel_body[1]), float(vel_body[2])
    # tail axes: chord, span, normal (frame^T v)
    ux = fr[0][0] * v0 + fr[1][0] * v1 + fr[2][0] * v2_
    uz = fr[0][2] * v0 + fr[1][2] * v1 + fr[2][2] * v2_
    v2 = ux * ux + uz * uz
    if v2 == 0.0:
        return np.zeros(3), 0.0
    fx, fz, a = plane_force(ux, uz, v2, span * spread, length, rho)
    return np.array([fr[i][0] * fx + fr[i][2] * fz for i in range(3)]), a


def plane_force(
    ux: float, uz: float, v2: float, b: float, length: float, rho: float
) -> tuple[float, float, float]:
    """The tail's force in its own chord (x) and normal (z) axes for the air's velocity
    ``(ux, uz)`` in them (``v2 = ux^2 + uz^2 > 0``), spread span ``b``: slender-wing
    lift, induced and profile drag; and the angle of attack (rad, capped).  Plain floats:
    the compiled callback (:mod:`birdsim.mujoco.aero_kernel`) compiles this same
    function."""
    v = math.sqrt(v2)
    profile = 0.5 * rho * v2 * 0.5 * b * length * TAIL_CD0
    if ux <= 0.0:  # flow from behind: no slender-wing lift
        return -profile * ux / v, -profile * uz / v, 0.0
    alpha = math.atan2(-uz, ux)
    a = max(-ALPHA_MAX, min(ALPHA_MAX, alpha))
    lift = 0.25 * math.pi * rho * v2 * a * b * b
    drag = 0.5 * lift * a + profile
    return (lift * -uz - drag * ux) / v, (lift * ux - drag * uz) / v, a


__all__ = [
    "ALPHA_MAX",
    "ELEVATION_MAX",
    "ROLL_MAX",
    "SPREAD_MIN",
    "TAIL_CD0",
    "TailControls",
    "plane_force",
    "tail_cp_offset",
    "tail_force",
    "frame_into",
    "tail_frame",
]
