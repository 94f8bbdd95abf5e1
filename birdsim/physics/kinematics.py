"""The six kinematic wing models (base, m1, m2, m3, m4, m5): parameters and joints.

A model is a set of named wingbeat parameters (docs/design.md's public names) and, per
wing panel, a *chain* from the body to the panel frame: hinge joints (Table 2
rotations, applied in chain order to go from body to panel axes), slide joints and
fixed offsets (:mod:`birdsim.physics.joints`, which also walks the chains).  Each joint
follows a sinusoid ``q = amp sin(omega t + phase) + bias`` whose amplitude and bias come
from the parameters:

===========  =======  =====  ===============================  =====================
joint        kind     axis   motion                           models
===========  =======  =====  ===============================  =====================
heave        slide    z      r_cp Phi_f sin(wt)               base
sweep        hinge    z      gamma_f (constant)               m2
stroke       hinge    y      theta_sp (constant)              m3, m4, m5
flap         hinge    x      Phi_f sin(wt)                    m1..m5
twist        hinge    y      -Theta_f cos(wt)                 all
elbow        hinge    z      -F (1 - cos(wt - phi_F)) / 2     m5
wrist_sweep  hinge    z      k F (1 - cos(wt - phi_F)) / 2    m5 (hand only)
wrist_flap   hinge    x      Phi_w sin(wt - Delta) + Psi      m4, m5 (hand only)
wrist_twist  hinge    y      -k_t Theta_f cos(wt), k_t = 0.25 m4, m5 (hand only)
supination   hinge    y      S (1 - cos(wt - phi_F)) / 2      m5 (hand only)
===========  =======  =====  ===============================  =====================

m5 is described in :mod:`birdsim.physics.m5`.
Positions and velocities of points on a panel come from one inward pass along the
chain (exact derivative of the rotation chain; docs/design.md).  The same chain gives the
MuJoCo joint layout, so the simulator and this module cannot disagree on geometry.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from birdsim.errors import ParameterError, UnknownModelError
from birdsim.physics import m5 as _m5
from birdsim.physics.bird import Bird
from birdsim.physics.joints import (  # noqa: F401 (re-exported: the chain kinematics)
    JOINTS,
    ChainElement,
    Joint,
    JointState,
    Offset,
    ParamSpec,
    Sinusoid,
    _add,
    body_to_panel,
    joint_states,
    panel_to_body,
    points_in_body,
    strip_positions,
)

PI = math.pi


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
    #: per panel: the joint whose angle sets the panel's area (m5's hand), or None
    area_folds: tuple[str | None, ...] = ()

    @cached_property
    def param_names(self) -> tuple[str, ...]:
        # made once per (frozen) model: the control loops read it many times a step
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
        lengths = _m5.offset_lengths(bird)
        for chain, panel in zip(self.chains, bird.panels(self.name)):
            concrete = tuple(
                Offset(lengths[el.role], el.role) if isinstance(el, Offset) else el for el in chain
            )
            out.append((concrete, panel.span, panel.chord))
        return tuple(out)

    def area_scale(
        self, panel: int, states: Mapping[str, JointState], bird: Bird
    ) -> np.ndarray | float:
        """The area of panel ``panel`` over its extended area at the joint ``states``
        (1.0 except where an area fold is defined: m5's hand, :func:`m5.area_factor`)."""
        name = self.area_folds[panel] if panel < len(self.area_folds) else None
        return 1.0 if name is None else _m5.area_factor(states[name].cos, bird)

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
        if self.name in ("m4", "m5"):
            motion["wrist_flap"] = Sinusoid(
                params["wrist_amp"], -params["wrist_lag"], params["wrist_bias"]
            )
            motion["wrist_twist"] = Sinusoid(
                bird.wrist_twist_ratio * params["twist_amp"], -PI / 2, zero
            )
        if self.name == "m5":
            motion.update(_m5.fold_motion(params, bird))
        return motion


def _chain(*names: str) -> tuple[ChainElement, ...]:
    return tuple(Offset(0.0) if n == "|" else JOINTS[n] for n in names)


_SHOULDER_SP = ("stroke", "flap", "twist")
_M4_PARAMS = tuple(
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
)

#: m5's bounds that differ from m4's (:mod:`birdsim.physics.m5`).
_M5_UPPER = {"stroke_plane": _m5.STROKE_PLANE_UPPER, "flap_amp": _m5.FLAP_UPPER}

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
            _M4_PARAMS,
            (_chain(*_SHOULDER_SP), _chain(*_SHOULDER_SP, "|", "wrist_flap", "wrist_twist")),
            "7 DOF: m3 arm plus a hand panel on a wrist (flap with lag and bias, twist 0.25 x shoulder)",
        ),
        KinematicModel(
            "m5",
            tuple(
                ParamSpec(**{**p.__dict__, "upper": _M5_UPPER[p.name]})
                if p.name in _M5_UPPER
                else p
                for p in _M4_PARAMS
            )
            + _m5.FOLD_PARAMS,
            (_m5.ARM_CHAIN, _m5.HAND_CHAIN),
            "the folding wing: m4 plus an elbow and a wrist flexing together (fold amplitude, "
            "phase, coupling from the bird) and hand supination in the upstroke",
            area_folds=_m5.AREA_FOLDS,
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
