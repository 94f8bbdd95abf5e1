"""Joints and the chain kinematics every wing model is made of.

A panel's *chain* runs from the body to the panel frame: hinge joints (Table 2
rotations, applied in chain order to go from body to panel axes), slide joints and
fixed offsets.  Each joint follows a sinusoid ``q = amp sin(omega t + phase) + bias``.
Positions and velocities of points on a panel come from one inward pass along the chain
(the exact derivative of the rotation chain; docs/design.md).  The models themselves
(which joints, which parameters) are in :mod:`birdsim.physics.kinematics`.

Joint groups split the power (``shoulder``; ``wrist``: every joint distal to the
shoulder, i.e. m4's wrist and m5's elbow and wrist).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.frames import Axis, Vec3, _is_zero, cross_axis, rotate


class _Moving(Protocol):
    """What :func:`joint_states` needs of a model (a
    :class:`birdsim.physics.kinematics.KinematicModel`; a protocol, so that this module
    does not import kinematics, which imports it)."""

    def joint_motion(self, params: Mapping[str, np.ndarray], bird: Bird) -> Mapping: ...


@dataclass(frozen=True)
class ParamSpec:
    """One free wingbeat parameter: public name, symbol, bounds (rad) and two guesses."""

    name: str
    symbol: str
    lower: float
    upper: float
    hover_guess: float
    cruise_guess: float
    doc: str


@dataclass(frozen=True)
class Joint:
    """A joint of a panel chain.  ``group`` says which muscle drives it (power split)."""

    name: str
    kind: str  # "hinge" or "slide"
    axis: Axis
    group: str = "shoulder"


@dataclass(frozen=True)
class Offset:
    """A fixed translation along the current frame's span (y) axis, e.g. arm -> wrist.

    ``role`` names the length the bird gives it (:meth:`KinematicModel.chain_with_geometry`):
    ``wrist`` the arm span (m4, m5), ``elbow`` shoulder -> elbow, ``elbow_back`` its
    negative, ``forearm`` elbow -> wrist (m5)."""

    span: float
    role: str = "wrist"


ChainElement = Joint | Offset


@dataclass(frozen=True)
class Sinusoid:
    """``q(t) = amp sin(omega t + phase) + bias`` (arrays broadcast over parameter sets)."""

    amp: np.ndarray | float
    phase: np.ndarray | float
    bias: np.ndarray | float

    def at(self, omega_t: np.ndarray, omega: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Angle, rate and acceleration at phase ``omega_t``."""
        q, qd = self.angle_rate(omega_t, omega)
        if _is_zero(qd):
            return q, 0.0, 0.0
        return q, qd, -omega * omega * (q - self.bias)

    def angle_rate(
        self, omega_t: np.ndarray, omega: float
    ) -> tuple[np.ndarray, np.ndarray | float]:
        """Angle and rate at phase ``omega_t`` (the hot path: no acceleration, no zero bias)."""
        if isinstance(self.amp, float) and self.amp == 0.0:  # a constant joint: no time axis
            return np.asarray(self.bias, dtype=float), 0.0
        arg = omega_t + self.phase
        q = self.amp * np.sin(arg)
        qd = (self.amp * omega) * np.cos(arg)
        return (q if _is_zero(self.bias) else q + self.bias), qd


JOINTS: dict[str, Joint] = {
    j.name: j
    for j in (
        Joint("heave", "slide", "z"),
        Joint("sweep", "hinge", "z"),
        Joint("stroke", "hinge", "y"),
        Joint("flap", "hinge", "x"),
        Joint("twist", "hinge", "y"),
        Joint("wrist_flap", "hinge", "x", "wrist"),
        Joint("wrist_twist", "hinge", "y", "wrist"),
        Joint("elbow", "hinge", "z", "wrist"),
        Joint("wrist_sweep", "hinge", "z", "wrist"),
        Joint("supination", "hinge", "y", "wrist"),
    )
}


# ---- chain kinematics -------------------------------------------------------------------


@dataclass(frozen=True)
class JointState:
    """cos, sin, angle and rate of one joint, arrays broadcast over (batch..., time, strip)."""

    cos: np.ndarray
    sin: np.ndarray
    angle: np.ndarray
    rate: np.ndarray | float  # the scalar 0.0 for a constant joint


def joint_states(
    model: _Moving,
    params: Mapping[str, np.ndarray],
    bird: Bird,
    omega_t: np.ndarray,
    trailing: int = 1,
) -> dict[str, JointState]:
    """Evaluate every joint at phases ``omega_t`` (N,).  Parameter arrays of shape B get
    shape (*B, N, 1...) with ``trailing`` extra unit axes (strips)."""
    shaped = {k: np.reshape(v, np.shape(v) + (1,) * (1 + trailing)) for k, v in params.items()}
    wt = np.reshape(omega_t, (-1,) + (1,) * trailing)
    states = {}
    for name, motion in model.joint_motion(shaped, bird).items():
        q, qd = motion.angle_rate(wt, bird.omega)
        states[name] = JointState(np.cos(q), np.sin(q), q, qd)
    return states


def points_in_body(
    chain: tuple[ChainElement, ...], states: Mapping[str, JointState], span_positions: np.ndarray
) -> tuple[Vec3, dict[str, Vec3]]:
    """Position and velocity (body axes, relative to the shoulder) of points at
    ``span_positions`` along the panel's y axis, by one inward pass along the chain.

    The velocity is returned split by joint group (``shoulder``, ``wrist``): each
    joint's rate contributes ``rate * (axis x p)`` in its own frame, so the total is
    the exact time derivative of the position and the split gives joint powers.
    """
    p: Vec3 = (0.0, np.asarray(span_positions, dtype=float), 0.0)
    vel: dict[str, Vec3] = {}
    for el in reversed(chain):
        if isinstance(el, Offset):
            p = (p[0], p[1] + el.span, p[2])
            continue
        st = states[el.name]
        if el.kind == "slide":
            i = "xyz".index(el.axis)
            p = tuple(_add(c, st.angle) if k == i else c for k, c in enumerate(p))  # type: ignore[assignment]
            dv = tuple(st.rate if k == i else 0.0 for k in range(3))
        else:
            p = rotate(el.axis, st.cos, -st.sin, p)
            vel = {g: rotate(el.axis, st.cos, -st.sin, v) for g, v in vel.items()}
            if _is_zero(st.rate):  # a constant joint adds no velocity
                continue
            dv = tuple(0.0 if _is_zero(c) else st.rate * c for c in cross_axis(el.axis, p))
        old = vel.get(el.group, (0.0, 0.0, 0.0))
        vel[el.group] = tuple(_add(a, b) for a, b in zip(old, dv))  # type: ignore[assignment]
    return p, vel


def _add(a: np.ndarray | float, b: np.ndarray | float) -> np.ndarray | float:
    return b if _is_zero(a) else a if _is_zero(b) else a + b


def body_to_panel(
    chain: tuple[ChainElement, ...], states: Mapping[str, JointState], v: Vec3
) -> Vec3:
    """Rotate a body-axes vector into the panel frame (Table 2 matrices in chain order)."""
    for el in chain:
        if isinstance(el, Joint) and el.kind == "hinge":
            st = states[el.name]
            v = rotate(el.axis, st.cos, st.sin, v)
    return v


def panel_to_body(
    chain: tuple[ChainElement, ...], states: Mapping[str, JointState], v: Vec3
) -> Vec3:
    """The way back: panel frame -> body axes (transposes in reverse order)."""
    for el in reversed(chain):
        if isinstance(el, Joint) and el.kind == "hinge":
            st = states[el.name]
            v = rotate(el.axis, st.cos, -st.sin, v)
    return v


def strip_positions(span: float, cp_fraction: float, strips: int) -> tuple[np.ndarray, np.ndarray]:
    """Span positions and widths of the elements of a panel: one control point at
    ``cp_fraction * span`` (default), or ``strips`` equal strips at their mid-points."""
    if strips == 1:
        return np.array([cp_fraction * span]), np.array([span])
    width = span / strips
    return (np.arange(strips) + 0.5) * width, np.full(strips, width)
