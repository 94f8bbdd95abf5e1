"""Wingbeat-mean forces and moments of the whole bird, left and right wings apart, and
their derivatives with respect to the control inputs and the body's angular velocity.

Axes and origin: seed body axes (x forward, y along the right wing, z down); moments
about the torso origin, which is the centre of mass and the shoulder position of the
MuJoCo bird (:mod:`birdsim.mujoco.model`).  Whole bird: both wings plus the body drag
(which acts at the torso origin: no moment).  ``body_rate`` = (p, q, r), the body's
angular velocity in body axes [rad per unit time]: roll, pitch, yaw rate.  Means are
the plain means over ``n`` uniform samples of the wingbeat, as ``Cycle.mean``.

Left and right wings are evaluated exactly, each with its own parameters: the left wing
is the mirror image (y -> -y) of a right wing with the left wing's parameters, seeing
the mirrored body rate ``(-p, q, -r)``; its force is mirrored back as ``(Fx, -Fy, Fz)``
and its moment (a pseudovector) as ``(-Mx, My, -Mz)``.  A left-wing parameter therefore
means what the right wing's does for the mirror image (positive sweep: the left tip
back too).

Control inputs (:data:`CONTROL_INPUTS`): each a (parameter, kind); kind ``"diff"``
gives the right wing ``+u/2`` and the left ``-u/2`` of that wingbeat parameter,
``"sym"`` gives both ``+u``.  An input may name a parameter the model does not optimise
(``sweep`` for base, m1, m3, m4; ``stroke_plane`` for base, m1, m2; default 0): the
core then evaluates the model's chain with that constant joint added where MuJoCo's
shoulder (a ball joint composing sweep, stroke, flap, twist) has it; at 0 it is the
model's own wingbeat.  Why these inputs: docs/moments.md.

The moments ignore the optional induced velocity (``Bird.induced_velocity``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.control_inputs import (  # noqa: F401 (re-exported)
    CONTROL_INPUTS,
    KINDS,
    _check_u,
    control_inputs,
    input_model,
    input_signs,
    wing_params,
)
from birdsim.physics.cycle import DEFAULT_SAMPLES, sample_phases
from birdsim.physics.inputs import _check_climb, check_body_rate
from birdsim.physics.kinematics import KinematicModel
from birdsim.physics.moments_eval import whole_bird


@dataclass(frozen=True)
class WingbeatMoments:
    """Wingbeat-mean force and moment of the whole bird (seed body axes, about the torso
    origin) and, when asked, their derivatives.

    Shapes: ``force_body``, ``moment_body`` (3,); ``force_du``, ``moment_du`` (3, k)
    for the k control inputs of :data:`CONTROL_INPUTS` (columns in that order);
    ``force_drate``, ``moment_drate`` (3, 3): d/d(p, q, r), the columns of
    ``moment_drate`` the roll, pitch and yaw damping (diagonal) and their couplings.
    Units: the bird's force, force x length, per unit rate [per rad per unit time].
    """

    force_body: np.ndarray
    moment_body: np.ndarray
    inputs: tuple[tuple[str, str], ...]
    force_du: np.ndarray | None = None
    moment_du: np.ndarray | None = None
    force_drate: np.ndarray | None = None
    moment_drate: np.ndarray | None = None


def wingbeat_moments(
    model: str | KinematicModel,
    params: Mapping[str, object],
    V: float,
    bird: Bird | None = None,
    *,
    u: object = None,
    body_rate: object = (0.0, 0.0, 0.0),
    climb: float = 0.0,
    n: int = DEFAULT_SAMPLES,
    jacobians: bool = False,
    backend: str = "kernel",
) -> WingbeatMoments:
    """Wingbeat-mean force and moment of the whole bird and, with ``jacobians=True``,
    their derivatives with respect to the control inputs and the body rate.

    Args:
        model: a model name or :class:`KinematicModel`.
        params: the symmetric wingbeat (every parameter of the model, floats, plus
            optionally an input parameter it does not optimise, default 0) [rad].
        V: flight speed relative to the air (>= 0), bird units.
        bird: the bird (default: the seed bird).
        u: the control inputs (k,) of :data:`CONTROL_INPUTS` (None: zeros).
        body_rate: (p, q, r), body axes [rad per unit time].
        climb: vertical speed relative to the air, positive up.
        n: samples per wingbeat.
        jacobians: also compute ``force_du``, ``moment_du`` (3 x k) and
            ``force_drate``, ``moment_drate`` (3 x 3).
        backend: ``"kernel"`` (compiled, exact forward-mode derivatives; numpy where
            the kernel cannot run) or ``"numpy"`` (the reference: means from
            ``cycle.element_forces``, derivatives by central differences).

    Returns:
        A :class:`WingbeatMoments` (body axes, moments about the torso origin).

    Raises:
        BirdsimError: bad model, parameters, speed, rate, inputs or n (one line).
    """

    bird = Bird() if bird is None else bird
    mx = input_model(model)
    right, left = wing_params(mx, params, u)
    rate = check_body_rate(body_rate)
    if rate.shape != (3,):
        raise BirdsimError(f"body_rate has shape {rate.shape}; allowed: (3,) (p, q, r)")
    try:
        speed = float(np.asarray(V, dtype=float))
    except (TypeError, ValueError):
        raise BirdsimError(f"V={V!r} is not a number; allowed: a finite number >= 0") from None
    if not np.isfinite(speed) or speed < 0:
        raise BirdsimError(f"V={V!r} is invalid; allowed: a finite number >= 0")
    vc = float(_check_climb(climb))
    phases = sample_phases(n, False)
    one = lambda x: np.array([x], dtype=float)  # noqa: E731
    sym = {k: one(v) for k, v in wing_params(mx, params, None)[0].items()}
    out = whole_bird(
        mx,
        sym,
        one(speed),
        one(vc),
        rate[None, :],
        _check_u(u, len(CONTROL_INPUTS[mx.name]))[None, :],
        bird,
        phases,
        jacobians=jacobians,
        backend=backend,
    )
    first = {k: v[0] for k, v in out.items()}
    return WingbeatMoments(inputs=CONTROL_INPUTS[mx.name], **first)
