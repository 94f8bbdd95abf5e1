"""The control inputs of the wings (each a wingbeat parameter applied differentially or
symmetrically) and the left and right wings' parameters they give; the model a set of
inputs needs (a missing ``sweep`` or ``stroke_plane`` added as a constant shoulder joint).
Used by :mod:`birdsim.physics.moments` and its evaluation; the conventions are there and
in docs/moments.md."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.kinematics import (
    _PARAMS,
    JOINTS,
    MODELS,
    KinematicModel,
    get_model,
    validate_params,
)

#: Per model: the control inputs, (wingbeat parameter, "diff" or "sym"): roll mainly from
#: the differential stroke plane, yaw from the differential flap and twist amplitudes,
#: pitch from the symmetric sweep.  docs/moments.md gives the measured Jacobians, the
#: reasons and the sources (and why differential sweep and symmetric stroke plane, null
#: inputs of this model at sweep 0 and in hover, are not among them).
CONTROL_INPUTS: dict[str, tuple[tuple[str, str], ...]] = {
    m: (("stroke_plane", "diff"), ("flap_amp", "diff"), ("twist_amp", "diff"), ("sweep", "sym"))
    for m in MODELS
}
KINDS = ("diff", "sym")


def control_inputs(model: str | KinematicModel) -> tuple[tuple[str, str], ...]:
    """The control inputs of ``model`` (:data:`CONTROL_INPUTS`)."""
    m = model if isinstance(model, KinematicModel) else get_model(model)
    return CONTROL_INPUTS[m.name]


def input_model(model: str | KinematicModel) -> KinematicModel:
    """``model`` with every parameter its inputs need: a missing ``sweep`` or
    ``stroke_plane`` becomes a constant joint of the shoulder in MuJoCo's order
    (after the base model's heave slide: sweep, stroke, flap, twist)."""
    m = model if isinstance(model, KinematicModel) else get_model(model)
    missing = tuple(
        n for n in _ADDABLE if n in {p for p, _ in CONTROL_INPUTS[m.name]} - set(m.param_names)
    )
    if not missing:
        return m
    key = (m.name, missing)
    if key not in _EXTENDED:
        chains = []
        for chain in m.chains:
            for n in missing:  # before the first joint that comes later in MuJoCo's order
                rank = _ORDER.index(_ADDABLE[n])
                at = next(i for i, el in enumerate(chain) if _rank(getattr(el, "name", "|")) > rank)
                chain = chain[:at] + (JOINTS[_ADDABLE[n]],) + chain[at:]
            chains.append(chain)
        params = m.params + tuple(_PARAMS[n] for n in missing)
        _EXTENDED[key] = replace(m, params=params, chains=tuple(chains))  # keeps area_folds
    return _EXTENDED[key]


#: Parameters an input may add to a model that lacks them -> their joint (MuJoCo order).
_ADDABLE = {"sweep": "sweep", "stroke_plane": "stroke"}
_EXTENDED: dict[tuple[str, tuple[str, ...]], KinematicModel] = {}
_ORDER = ("heave", "sweep", "stroke", "flap", "twist", "|", "wrist_flap", "wrist_twist")


def _rank(joint: str) -> int:
    """A joint's place in MuJoCo's order (a joint it does not list: after the stroke)."""
    return _ORDER.index(joint) if joint in _ORDER else _ORDER.index("flap")


def _check_u(u: object, k: int) -> np.ndarray:
    if u is None:
        return np.zeros(k)
    try:
        a = np.asarray(u, dtype=float)
    except (TypeError, ValueError):
        raise BirdsimError(f"u={u!r} is not a vector; allowed: {k} finite numbers") from None
    if a.shape != (k,) or not np.all(np.isfinite(a)):
        raise BirdsimError(f"u={u!r} is invalid; allowed: {k} finite numbers (CONTROL_INPUTS)")
    return a


def wing_params(
    model: str | KinematicModel, params: Mapping[str, object], u: object = None
) -> tuple[dict[str, float], dict[str, float]]:
    """The right and left wings' parameters for the symmetric wingbeat ``params`` and the
    control inputs ``u`` (len k, :data:`CONTROL_INPUTS` order; None = zeros).

    ``params``: every parameter of the model; an input parameter the model does not
    optimise (``sweep`` for m3) may be given too (default 0).

    Returns:
        ``(params_right, params_left)``: the model's parameters plus any input parameter
        it does not optimise (e.g. ``sweep`` for m3, 0 without input); ``pitch`` is the
        body's and equal on both sides.  Bounds are not checked (an input may leave them).

    Raises:
        BirdsimError: unknown model, bad parameters, ``u`` of the wrong length or not finite.
    """
    mx = input_model(model)
    base = get_model(mx.name)
    extra = {n: 0.0 for n in mx.param_names if n not in base.param_names}
    p = validate_params(
        mx, {**extra, **params} if isinstance(params, Mapping) else params, check_bounds=False
    )
    if any(a.ndim for a in p.values()):
        raise BirdsimError("params must be floats here; allowed: one wingbeat (floats)")
    inputs = CONTROL_INPUTS[mx.name]
    uu = _check_u(u, len(inputs))
    right = {k: float(v) for k, v in p.items()}
    left = dict(right)
    for (name, kind), ui in zip(inputs, uu):
        if kind == "diff":
            right[name] += 0.5 * ui
            left[name] -= 0.5 * ui
        else:
            right[name] += ui
            left[name] += ui
    return right, left


def input_signs(model: str | KinematicModel) -> tuple[np.ndarray, np.ndarray, list[int]]:
    """(d p_right / du, d p_left / du) as (k,) arrays and, per input, the index of its
    parameter in :func:`input_model`'s ``param_names``."""
    mx = input_model(model)
    inputs = CONTROL_INPUTS[mx.name]
    sr = np.array([0.5 if kind == "diff" else 1.0 for _, kind in inputs])
    sl = np.array([-0.5 if kind == "diff" else 1.0 for _, kind in inputs])
    return sr, sl, [mx.param_names.index(name) for name, _ in inputs]
