"""Quasi-steady blade-element aerodynamics: polars, the element force, body drag and
the actuator-disc induced velocity (appendix 1A).

Everything works on panel-axes velocity components ``(vx, vz)`` of the element's
motion *relative to the air* (x chordwise towards the leading edge, z down; the
spanwise component has no influence, sec. 3.2.3).  The angle of attack is
``alpha = atan2(vz, vx)``, the dynamic pressure ``q = rho/2 (vx^2 + vz^2)`` and the
force in wind axes ``(-Cd, 0, -Cl) q S`` (docs/design.md section 2).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from birdsim.errors import BirdConfigError


@dataclass(frozen=True)
class Polar:
    """Lift and drag coefficients against angle of attack (radians).

    Subclasses implement :meth:`coefficients`; :meth:`force_panel` turns them into the
    panel-axes force.  A subclass may override ``force_panel`` with an algebraic
    shortcut as long as it returns the same numbers.
    """

    kind: ClassVar[str] = "abstract"

    def coefficients(self, alpha: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        raise NotImplementedError

    def force_panel(
        self, vx: np.ndarray, vz: np.ndarray, area: float | np.ndarray, rho: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """Panel-axes force ``(fx, fz)`` on an element of area ``area`` moving at (vx, vz)."""
        alpha = np.arctan2(vz, vx)
        cl, cd = self.coefficients(alpha)
        q_area = 0.5 * rho * (vx * vx + vz * vz) * area
        ca, sa = np.cos(alpha), np.sin(alpha)
        # wind x = (cos a, sin a), wind z = (-sin a, cos a) in panel axes
        return q_area * (-cd * ca + cl * sa), q_area * (-cd * sa - cl * ca)

    def to_dict(self) -> dict:
        from dataclasses import asdict

        return {"kind": self.kind, **asdict(self)}


@dataclass(frozen=True)
class SeedPolar(Polar):
    """The dissertation's polar (eqs 4-6): ``Cl = Clmax sin 2a``, ``Cd = Cd0 + Cdmax sin^2 a``."""

    kind: ClassVar[str] = "seed"
    cl_max: float = 2.0
    cd0: float = 0.05
    cd_max: float = 1.0

    def __post_init__(self) -> None:
        for name in ("cl_max", "cd0", "cd_max"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not np.isfinite(v):
                raise BirdConfigError(f"polar.{name}={v!r} is invalid; allowed: a finite number")

    def coefficients(self, alpha: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        s = np.sin(alpha)
        return self.cl_max * np.sin(2.0 * alpha), self.cd0 + self.cd_max * s * s

    def force_panel(
        self, vx: np.ndarray, vz: np.ndarray, area: float | np.ndarray, rho: float
    ) -> tuple[np.ndarray, np.ndarray]:
        # With cos a = vx/U and sin a = vz/U the trigonometry cancels:
        #   Cl q = rho Clmax vx vz,  Cd q = rho/2 (Cd0 U^2 + Cdmax vz^2).
        # One square root per element instead of atan2, sin and cos.
        vx2, vz2 = vx * vx, vz * vz
        u2 = vx2 + vz2
        u = np.sqrt(u2)
        num = 0.5 * rho * np.asarray(area, dtype=float)
        # the strips of a heaving (base) wing share one velocity: broadcast against the areas
        inv_u = np.divide(
            num, u, out=np.zeros(np.broadcast_shapes(num.shape, u.shape)), where=u > 0.0
        )
        drag_u2 = self.cd0 * u2 + self.cd_max * vz2
        lift2 = 2.0 * self.cl_max
        fx = inv_u * vx * (lift2 * vz2 - drag_u2)
        fz = -inv_u * vz * (lift2 * vx2 + drag_u2)
        return fx, fz

    def force_scalar(self, vx: float, vz: float, area: float, rho: float) -> tuple[float, float]:
        """:meth:`force_panel` for one element, on Python floats (the same operations in
        the same order: the same numbers, without numpy's per-call cost; the MuJoCo
        callback's per-step path)."""
        vx2, vz2 = vx * vx, vz * vz
        u2 = vx2 + vz2
        u = math.sqrt(u2)
        num = 0.5 * rho * area
        inv_u = num / u if u > 0.0 else 0.0
        drag_u2 = self.cd0 * u2 + self.cd_max * vz2
        lift2 = 2.0 * self.cl_max
        return inv_u * vx * (lift2 * vz2 - drag_u2), -inv_u * vz * (lift2 * vx2 + drag_u2)


@dataclass(frozen=True)
class RoboflyPolar(Polar):
    """Dickinson, Lehmann & Sane (1999) robofly fit, with its angles in degrees:
    ``CL = 0.225 + 1.58 sin(2.13 a - 7.20 deg)``, ``CD = 1.92 - 1.55 cos(2.04 a - 9.82 deg)``
    for ``a`` in degrees on [0, 90].  A flat plate is symmetric, so the fit is folded:
    period pi in alpha, ``CL`` odd and ``CD`` even in alpha.
    """

    kind: ClassVar[str] = "robofly"

    def coefficients(self, alpha: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        a = np.mod(np.asarray(alpha) + 0.5 * np.pi, np.pi) - 0.5 * np.pi  # [-pi/2, pi/2)
        deg = np.degrees(np.abs(a))
        cl = 0.225 + 1.58 * np.sin(np.radians(2.13 * deg - 7.20))
        cd = 1.92 - 1.55 * np.cos(np.radians(2.04 * deg - 9.82))
        return np.sign(a) * cl, cd


POLARS: dict[str, type[Polar]] = {"seed": SeedPolar, "robofly": RoboflyPolar}


def polar_from_dict(d: dict) -> Polar:
    """Build a polar from ``{"kind": ..., **coefficients}`` (as written by ``to_dict``)."""
    d = dict(d)
    kind = d.pop("kind", "seed")
    if kind not in POLARS:
        raise BirdConfigError(f"polar.kind={kind!r} is unknown; allowed: {', '.join(POLARS)}")
    try:
        return POLARS[kind](**d)
    except TypeError as exc:
        raise BirdConfigError(f"polar={d!r} does not fit polar kind {kind!r}: {exc}") from None


def body_drag_x(speed: np.ndarray, pitch: np.ndarray, rho: float, area: float) -> np.ndarray:
    """Body drag along earth X (eq. 7, appendix 1B): ``-rho/2 V^2 sin(theta) * area``."""
    return -0.5 * rho * np.square(speed) * np.sin(pitch) * area


def body_drag_magnitude(
    speed_total: np.ndarray | float, attack: np.ndarray | float, rho: float, area: float
):
    """``rho/2 Vt^2 |sin(attack)| area``: the body drag's magnitude for a body meeting
    the air at speed ``Vt`` and angle of attack ``attack = theta - gamma`` (the angle
    from the body's x axis to its velocity relative to the air, in the pitch plane)."""
    if isinstance(speed_total, float) and isinstance(attack, float):  # MuJoCo's per-step call
        return 0.5 * rho * (speed_total * speed_total) * abs(math.sin(attack)) * area
    return 0.5 * rho * np.square(speed_total) * np.abs(np.sin(attack)) * area


def body_drag(
    speed: np.ndarray, climb: np.ndarray, pitch: np.ndarray, rho: float, area: float
) -> tuple[np.ndarray, np.ndarray]:
    """Body drag (Dx, Dz) in seed earth axes for a body moving at ``(V, 0, -climb)``
    relative to the air (climb positive up).

    ``|D| = rho/2 Vt^2 |sin(theta - gamma)| area`` with ``Vt = sqrt(V^2 + climb^2)`` and
    the flight-path angle ``gamma = atan2(climb, V)``, opposite the velocity:
    ``D = -|D| (V, -climb) / Vt``.  Where ``climb == 0`` it is exactly eq. 7
    (:func:`body_drag_x`, the same floating-point operations) and Dz = 0.

    Args:
        speed: flight speed V >= 0 (bird units), any shape.
        climb: vertical speed relative to the air, positive up, broadcast with ``speed``.
        pitch: body pitch theta [rad].
        rho: air density; area: the body's drag area.

    Returns:
        ``(Dx, Dz)``, seed earth axes (Dz > 0 is down: a climbing body is pushed down).
    """
    speed, climb, pitch = np.broadcast_arrays(
        *(np.asarray(a, dtype=float) for a in (speed, climb, pitch))
    )
    level = -0.5 * rho * np.square(speed) * np.sin(pitch) * area
    if not np.any(climb != 0.0):
        return level, np.zeros_like(level)
    vt = np.hypot(speed, climb)
    gamma = np.arctan2(climb, speed)
    mag = body_drag_magnitude(vt, pitch - gamma, rho, area)
    unit = np.divide(1.0, vt, out=np.zeros_like(vt), where=vt > 0.0)
    dx = np.where(climb == 0.0, level, -mag * unit * speed)
    dz = np.where(climb == 0.0, 0.0, mag * unit * climb)
    return dx, dz


def induced_velocity(
    force_earth: np.ndarray,
    speed: np.ndarray,
    rho: float,
    disc_area: float,
    iterations: int = 60,
    climb: np.ndarray | None = None,
) -> np.ndarray:
    """Actuator-disc (Glauert) induced velocity magnitude for a mean aerodynamic force.

    The disc pushes the air opposite to ``force_earth`` (..., 3, seed axes) with speed
    ``v``; the bird moves at ``speed`` along +X through still air.  ``v`` solves
    ``|F| = 2 rho A v |U + v F_hat|`` with ``U = (speed, 0, 0)`` -- in axial flow this
    is appendix 1A's ``v = -V/2 + sqrt(V^2/4 + F/(2 rho A))``.  Solved by bisection,
    vectorised over the leading axes.  With ``climb`` (positive up) the bird moves at
    ``U = (speed, 0, -climb)``.
    """
    f = np.asarray(force_earth, dtype=float)
    thrust = np.linalg.norm(f, axis=-1)
    f_hat = np.divide(f, thrust[..., None], out=np.zeros_like(f), where=thrust[..., None] > 0)
    u_along = np.asarray(speed, dtype=float) * f_hat[..., 0]
    u2 = np.square(speed)
    if climb is not None and np.any(np.asarray(climb) != 0.0):
        u_along = u_along - np.asarray(climb, dtype=float) * f_hat[..., 2]
        u2 = u2 + np.square(climb)

    def residual(v: np.ndarray) -> np.ndarray:
        return 2.0 * rho * disc_area * v * np.sqrt(u2 + 2.0 * v * u_along + v * v) - thrust

    lo = np.zeros_like(thrust)
    hi = np.sqrt(thrust / (2.0 * rho * disc_area)) + np.abs(speed) + 1.0
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        pos = residual(mid) > 0.0
        hi = np.where(pos, mid, hi)
        lo = np.where(pos, lo, mid)
    return 0.5 * (lo + hi)
