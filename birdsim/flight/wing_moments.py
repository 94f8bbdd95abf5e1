"""Wingbeat-mean forces and moments of both wings and their Jacobians with respect to
the wings' control inputs -- the local stand-in for ``birdsim.physics.moments``.

The analytic core's numpy path gives one (right) wing's force and control-point history
over a wingbeat (:func:`birdsim.physics.cycle.evaluate_cycle`); the moment about the
torso origin (the centre of mass; the shoulders sit there) is ``r x F`` per sample, its
mean the wingbeat-mean moment.  The left wing is the mirror image of a right wing
flying the left parameters: force (x, -y, z), moment (-x, y, -z) (a pseudovector).

Control inputs (:data:`CONTROL_INPUTS`, as ``birdsim.physics.moments`` defines them):
``("name", "diff")`` puts +u/2 on the right wing's parameter and -u/2 on the left's
(roll and yaw); ``("name", "sym")`` adds u to both (pitch: the stroke plane or the sweep
move the wings' force line fore and aft of the centre of mass).  Jacobians are central
differences (step :data:`FD_STEP`) of the batched core: one call for every input.

Axes: seed body axes (x forward, y right, z down), moments about the torso origin;
the body moves at ``V`` along the body pitch's air path (level flight of the table).
The body's rotation rate is not an input here (zero): its damping enters the loop
through the feedback.  Swap for ``birdsim.physics.moments`` when it exists: the names
and shapes are the same.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.frames import earth_to_body
from birdsim.physics.kinematics import get_model

#: Per model: the wings' control inputs (parameter, kind).  Differential flap amplitude
#: (roll: the wing that beats wider lifts more, as pigeons and bats do), differential
#: twist (yaw/roll through the thrust difference), symmetric stroke plane or sweep
#: (pitch, the force line moves fore and aft; Ros et al. 2015 J. Exp. Biol. 218:480
#: found pigeons turn by reorienting the wing trajectory), symmetric twist where a
#: model has neither.
CONTROL_INPUTS: dict[str, tuple[tuple[str, str], ...]] = {
    "base": (("flap_amp", "diff"), ("twist_amp", "diff"), ("twist_amp", "sym")),
    "m1": (("flap_amp", "diff"), ("twist_amp", "diff"), ("twist_amp", "sym")),
    "m2": (("flap_amp", "diff"), ("twist_amp", "diff"), ("sweep", "sym")),
    "m3": (("flap_amp", "diff"), ("twist_amp", "diff"), ("stroke_plane", "sym")),
    "m4": (("flap_amp", "diff"), ("twist_amp", "diff"), ("stroke_plane", "sym")),
}
#: Largest magnitude of a control input (rad): a correction, not a new wingbeat.
INPUT_MAX = 0.15
#: Central-difference step of the Jacobians (rad).
FD_STEP = 1e-4
#: Samples per wingbeat of the moments (the mean moment converges like the force).
MOMENT_SAMPLES = 64

_MIRROR_F = np.array([1.0, -1.0, 1.0])
_MIRROR_M = np.array([-1.0, 1.0, -1.0])


@dataclass(frozen=True)
class WingbeatMoments:
    """Whole-bird wing forces and moments (seed body axes, about the torso origin)."""

    force_body: np.ndarray  # (3,)
    moment_body: np.ndarray  # (3,)
    force_du: np.ndarray | None = None  # (3, k)
    moment_du: np.ndarray | None = None  # (3, k)


def wing_params(model: str, params: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(right, left) wing parameters for control inputs ``u`` (k,) of ``model``."""
    names = get_model(model).param_names
    right = np.array(params, dtype=float)
    left = right.copy()
    for (name, kind), ui in zip(CONTROL_INPUTS[model], np.asarray(u, dtype=float)):
        j = names.index(name)
        if kind == "diff":
            right[j] += 0.5 * ui
            left[j] -= 0.5 * ui
        else:
            right[j] += ui
            left[j] += ui
    return right, left


def input_bounds(model: str, params: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Bounds of the inputs that keep both wings' parameters within the model's bounds
    (and each input within :data:`INPUT_MAX`)."""
    kin = get_model(model)
    spec = {p.name: p for p in kin.params}
    lo, hi = [], []
    for name, kind in CONTROL_INPUTS[model]:
        p = float(params[kin.param_names.index(name)])
        room_lo, room_hi = p - spec[name].lower, spec[name].upper - p
        if kind == "diff":
            r = max(0.0, 2.0 * min(room_lo, room_hi))
            lo.append(-min(INPUT_MAX, r))
            hi.append(min(INPUT_MAX, r))
        else:
            lo.append(-min(INPUT_MAX, max(0.0, room_lo)))
            hi.append(min(INPUT_MAX, max(0.0, room_hi)))
    return np.array(lo), np.array(hi)


def _right_wing(model: str, rows: np.ndarray, speed: float, bird: Bird, n: int):
    """Mean force and moment (seed body axes) of the right wing for parameter rows (B, nP)."""
    names = get_model(model).param_names
    cyc = evaluate_cycle(
        model,
        {k: rows[:, i] for i, k in enumerate(names)},
        speed,
        bird=bird,
        n=n,
        backend="numpy",
        check_bounds=False,
    )
    hist = cyc._hist
    pitch = rows[:, names.index("pitch")][:, None, None]
    fe = hist.force_earth  # B, K, N, 3
    fb = np.stack(earth_to_body(pitch, (fe[..., 0], fe[..., 1], fe[..., 2])), axis=-1)
    r = hist.cp_position
    mom = np.cross(r, fb)
    return fb.sum(axis=1).mean(axis=1), mom.sum(axis=1).mean(axis=1)


def wingbeat_moments(
    model: str,
    params: np.ndarray,
    V: float,
    bird: Bird,
    *,
    u: np.ndarray | None = None,
    n: int = MOMENT_SAMPLES,
    jacobians: bool = False,
) -> WingbeatMoments:
    """Both wings' wingbeat-mean force and moment for ``params`` (the table's, right =
    left) plus inputs ``u`` (default 0), and with ``jacobians`` their derivatives with
    respect to the inputs.  ``bird``: the reduced bird."""
    inputs = CONTROL_INPUTS[model]
    k = len(inputs)
    u0 = np.zeros(k) if u is None else np.asarray(u, dtype=float)
    sets = [u0]
    if jacobians:
        for i in range(k):
            for s in (1.0, -1.0):
                du = u0.copy()
                du[i] += s * FD_STEP
                sets.append(du)
    rows = []
    for ui in sets:
        r, left = wing_params(model, params, ui)
        rows += [r, left]
    f, m = _right_wing(model, np.array(rows), max(float(V), 0.0), bird, n)
    whole_f = f[0::2] + f[1::2] * _MIRROR_F
    whole_m = m[0::2] + m[1::2] * _MIRROR_M
    if not jacobians:
        return WingbeatMoments(whole_f[0], whole_m[0])
    df = (whole_f[1::2] - whole_f[2::2]).T / (2 * FD_STEP)
    dm = (whole_m[1::2] - whole_m[2::2]).T / (2 * FD_STEP)
    return WingbeatMoments(whole_f[0], whole_m[0], df, dm)


__all__ = [
    "CONTROL_INPUTS",
    "INPUT_MAX",
    "WingbeatMoments",
    "input_bounds",
    "wing_params",
    "wingbeat_moments",
]
