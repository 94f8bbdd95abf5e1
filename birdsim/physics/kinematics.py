"""The five kinematic wing models (base, m1, m2, m3, m4): parameters, joints and the
exact control-point kinematics.

A model is a set of named wingbeat parameters (docs/design.md's public names) and, per
wing panel, a *chain* from the body to the panel frame: hinge joints (Table 2
rotations, applied in chain order to go from body to panel axes), slide joints and
fixed offsets.  Each joint follows a sinusoid ``q = amp sin(omega t + phase) + bias``
whose amplitude and bias come from the parameters:

========  =======  =====  ===============================  =====================
joint     kind     axis   motion                           models
========  =======  =====  ===============================  =====================
heave     slide    z      r_cp Phi_f sin(wt)               base
sweep     hinge    z      gamma_f (constant)               m2
stroke    hinge    y      theta_sp (constant)              m3, m4
flap      hinge    x      Phi_f sin(wt)                    m1..m4
twist     hinge    y      -Theta_f cos(wt)                 all
wrist_flap hinge   x      Phi_w sin(wt - Delta) + Psi      m4 (hand only)
wrist_twist hinge  y      -k Theta_f cos(wt), k = 0.25     m4 (hand only)
========  =======  =====  ===============================  =====================

Positions and velocities of points on a panel come from one inward pass along the
chain (exact derivative of the rotation chain; docs/design.md).  The same chain gives the
MuJoCo joint layout, so the simulator and this module cannot disagree on geometry.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from birdsim.errors import ParameterError, UnknownModelError
from birdsim.physics.bird import Bird
from birdsim.physics.frames import Axis, Vec3, _is_zero, cross_axis, rotate

PI = math.pi


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
    """A fixed translation along the current frame's span (y) axis, e.g. arm -> wrist."""

    span: float


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
    )
}

_PARAMS: dict[str, ParamSpec] = {
    p.name: p
    for p in (
        ParamSpec("pitch", "theta", 0.0, PI / 2, 1.4, 0.1, "body pitch, nose up"),
        ParamSpec("flap_amp", "Phi_f", 0.0, PI / 2, PI / 2, 0.7, "shoulder flap amplitude"),
        ParamSpec(
            "twist_amp",
            "Theta_f",
            0.0,
            PI / 4,
            PI / 4,
            0.2,
            "twist amplitude, leading edge down on the downstroke",
        ),
        ParamSpec(
            "sweep",
            "gamma_f",
            -PI / 4,
            PI / 4,
            0.0,
            0.0,
            "constant sweep about body z; positive sweeps the right wing tip back",
        ),
        ParamSpec(
            "stroke_plane",
            "theta_sp",
            0.0,
            0.35,
            0.35,
            0.2,
            "stroke-plane inclination about body y",
        ),
        ParamSpec("wrist_amp", "Phi_w", 0.0, PI / 4, 0.05, 0.3, "wrist flap amplitude"),
        ParamSpec("wrist_bias", "Psi", 0.0, PI / 4, 0.05, 0.3, "wrist flap bias (hand tip down)"),
        ParamSpec("wrist_lag", "Delta", 0.0, PI / 2, PI / 2, PI / 2, "wrist flap phase lag"),
    )
}


@dataclass(frozen=True)
class KinematicModel:
    """A kinematic wing model: its parameters and the chain of each wing panel."""

    name: str
    params: tuple[ParamSpec, ...]
    chains: tuple[tuple[ChainElement, ...], ...]  # per panel, body -> panel root frame
    description: str

    @property
    def param_names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.params)

    @property
    def joints(self) -> tuple[Joint, ...]:
        """Every joint of the model, each once, outward order."""
        seen: dict[str, Joint] = {}
        for chain in self.chains:
            for el in chain:
                if isinstance(el, Joint):
                    seen.setdefault(el.name, el)
        return tuple(seen.values())

    @property
    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        return np.array([p.lower for p in self.params]), np.array([p.upper for p in self.params])

    def spec(self, name: str) -> ParamSpec:
        for p in self.params:
            if p.name == name:
                return p
        raise ParameterError(
            f"parameter {name!r} is unknown for model {self.name}; allowed: {', '.join(self.param_names)}"
        )

    def guess(self, regime: str = "hover") -> dict[str, float]:
        """A physically sensible starting point: ``hover`` (large amplitudes, steep pitch)
        or ``cruise`` (small amplitudes, flat body)."""
        attrs = {"hover": "hover_guess", "cruise": "cruise_guess"}
        if regime not in attrs:
            raise ParameterError(f"regime={regime!r} is unknown; allowed: hover, cruise")
        attr = attrs[regime]
        return {p.name: min(max(getattr(p, attr), p.lower), p.upper) for p in self.params}

    def chain_with_geometry(
        self, bird: Bird
    ) -> tuple[tuple[tuple[ChainElement, ...], float, float], ...]:
        """Per panel: (chain with the wrist offset set from the bird, panel span, chord)."""
        out = []
        for chain, panel in zip(self.chains, bird.panels(self.name)):
            arm_span = bird.semispan - panel.span if panel.name == "hand" else 0.0
            concrete = tuple(Offset(arm_span) if isinstance(el, Offset) else el for el in chain)
            out.append((concrete, panel.span, panel.chord))
        return tuple(out)

    def joint_motion(self, params: Mapping[str, np.ndarray], bird: Bird) -> dict[str, Sinusoid]:
        """The sinusoid of every joint for (already validated) parameter arrays."""
        zero = 0.0
        flap_amp = params["flap_amp"]
        twist = Sinusoid(params["twist_amp"], -PI / 2, zero)  # -Theta_f cos(wt)
        motion: dict[str, Sinusoid] = {"twist": twist}
        if self.name == "base":
            r_cp = bird.cp_span_fraction * bird.semispan
            motion["heave"] = Sinusoid(r_cp * flap_amp, 0.0, zero)
        else:
            motion["flap"] = Sinusoid(flap_amp, 0.0, zero)
        if "sweep" in params:
            motion["sweep"] = Sinusoid(zero, 0.0, params["sweep"])
        if "stroke_plane" in params:
            motion["stroke"] = Sinusoid(zero, 0.0, params["stroke_plane"])
        if self.name == "m4":
            motion["wrist_flap"] = Sinusoid(
                params["wrist_amp"], -params["wrist_lag"], params["wrist_bias"]
            )
            motion["wrist_twist"] = Sinusoid(
                bird.wrist_twist_ratio * params["twist_amp"], -PI / 2, zero
            )
        return motion


def _chain(*names: str) -> tuple[ChainElement, ...]:
    return tuple(Offset(0.0) if n == "|" else JOINTS[n] for n in names)


_SHOULDER_SP = ("stroke", "flap", "twist")

MODELS: dict[str, KinematicModel] = {
    m.name: m
    for m in (
        KinematicModel(
            "base",
            tuple(_PARAMS[n] for n in ("pitch", "flap_amp", "twist_amp")),
            (_chain("heave", "twist"),),
            "3 DOF: wing translates vertically (no flap rotation), twists about its span",
        ),
        KinematicModel(
            "m1",
            tuple(_PARAMS[n] for n in ("pitch", "flap_amp", "twist_amp")),
            (_chain("flap", "twist"),),
            "3 DOF: true flap rotation about body x, then twist",
        ),
        KinematicModel(
            "m2",
            tuple(_PARAMS[n] for n in ("pitch", "flap_amp", "twist_amp", "sweep")),
            (_chain("sweep", "flap", "twist"),),
            "4 DOF: constant sweep about body z, flap, twist",
        ),
        KinematicModel(
            "m3",
            tuple(_PARAMS[n] for n in ("pitch", "flap_amp", "twist_amp", "stroke_plane")),
            (_chain(*_SHOULDER_SP),),
            "4 DOF: constant stroke-plane inclination about body y, flap, twist",
        ),
        KinematicModel(
            "m4",
            tuple(
                ParamSpec(
                    **{
                        **_PARAMS["flap_amp"].__dict__,
                        "upper": PI / 4,
                        "hover_guess": PI / 4,
                        "cruise_guess": 0.5,
                    }
                )
                if n == "flap_amp"
                else _PARAMS[n]
                for n in (
                    "pitch",
                    "flap_amp",
                    "twist_amp",
                    "stroke_plane",
                    "wrist_amp",
                    "wrist_bias",
                    "wrist_lag",
                )
            ),
            (_chain(*_SHOULDER_SP), _chain(*_SHOULDER_SP, "|", "wrist_flap", "wrist_twist")),
            "7 DOF: m3 arm plus a hand panel on a wrist (flap with lag and bias, twist 0.25 x shoulder)",
        ),
    )
}


def get_model(name: str) -> KinematicModel:
    """The model called ``name`` or a one-line :class:`UnknownModelError`."""
    try:
        return MODELS[name]
    except (KeyError, TypeError):
        raise UnknownModelError(
            f"model {name!r} is unknown; allowed: {', '.join(MODELS)}"
        ) from None


def validate_params(
    model: KinematicModel, params: Mapping[str, object], *, check_bounds: bool = True
) -> dict[str, np.ndarray]:
    """Arrays of every parameter of ``model``; one clear error for anything wrong."""
    if not isinstance(params, Mapping):
        raise ParameterError(
            f"params={params!r} is not a mapping; allowed: {{name: value}} for {', '.join(model.param_names)}"
        )
    unknown = [k for k in params if k not in model.param_names]
    if unknown:
        raise ParameterError(
            f"parameter {unknown[0]!r} is unknown for model {model.name}; allowed: {', '.join(model.param_names)}"
        )
    out: dict[str, np.ndarray] = {}
    for spec in model.params:
        if spec.name not in params:
            raise ParameterError(
                f"parameter {spec.name!r} is missing for model {model.name}; required: {', '.join(model.param_names)}"
            )
        try:
            v = np.asarray(params[spec.name], dtype=float)
        except (TypeError, ValueError):
            raise ParameterError(
                f"parameter {spec.name}={params[spec.name]!r} is not a number"
            ) from None
        if not np.all(np.isfinite(v)):
            raise ParameterError(
                f"parameter {spec.name}={_first_bad(v)} is not finite; allowed: [{spec.lower:.6g}, {spec.upper:.6g}]"
            )
        if check_bounds:
            tol = 1e-9
            bad = (v < spec.lower - tol) | (v > spec.upper + tol)
            if np.any(bad):
                raise ParameterError(
                    f"parameter {spec.name}={float(np.asarray(v)[bad].flat[0]):.6g} is out of bounds for model "
                    f"{model.name}; allowed: [{spec.lower:.6g}, {spec.upper:.6g}]"
                )
        out[spec.name] = v
    return out


def _first_bad(v: np.ndarray) -> float:
    return float(v[~np.isfinite(v)].flat[0]) if v.ndim else float(v)


# ---- chain kinematics -------------------------------------------------------------------


@dataclass(frozen=True)
class JointState:
    """cos, sin, angle and rate of one joint, arrays broadcast over (batch..., time, strip)."""

    cos: np.ndarray
    sin: np.ndarray
    angle: np.ndarray
    rate: np.ndarray | float  # the scalar 0.0 for a constant joint


def joint_states(
    model: KinematicModel,
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
