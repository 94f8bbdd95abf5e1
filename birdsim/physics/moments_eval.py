"""Evaluation behind :mod:`birdsim.physics.moments`: whole-bird means and Jacobians for
a flat batch of wingbeats, by the compiled kernel (exact forward-mode derivatives,
:mod:`birdsim.physics.kernel_moments`) or by the numpy reference (means from
:func:`birdsim.physics.cycle.element_forces`, derivatives by central differences).

Each wing is evaluated as a right wing: the left one with its own parameters, the
mirrored body rate ``(-p, q, -r)``, and its results mirrored back (force
``(Fx, -Fy, Fz)``, moment ``(-Mx, My, -Mz)``); see :mod:`birdsim.physics.moments`.
"""

from __future__ import annotations

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.control_inputs import input_signs
from birdsim.physics.cycle import element_forces
from birdsim.physics.frames import earth_to_body
from birdsim.physics.inputs import cross
from birdsim.physics.kinematics import KinematicModel, joint_states, strip_positions
from birdsim.physics.wing_sides import MIRROR_F, MIRROR_M, drag_body, sides

#: Central-difference step of the numpy reference Jacobians [rad, rad per unit time]:
#: truncation ~h^2 ~1e-10, round-off ~1e-16/h ~1e-11 relative to the moments.
FD_STEP = 1e-5
BACKENDS = ("kernel", "numpy")


def right_wing_numpy(
    mx: KinematicModel,
    p: dict[str, np.ndarray],
    speed: np.ndarray,
    climb: np.ndarray,
    rate: np.ndarray,
    bird: Bird,
    phases: np.ndarray,
) -> tuple[np.ndarray, np.ndarray]:
    """Mean force and moment (B x 3 each, body axes, about the shoulder) of a right wing
    for flat (B,) parameters, (B,) speed and climb, B x 3 body rate: the numpy reference."""
    states = joint_states(mx, p, bird, phases, trailing=1)
    col = lambda a: np.asarray(a, dtype=float)[:, None, None]  # noqa: E731
    air = earth_to_body(col(p["pitch"]), (col(speed), 0.0, -col(climb)))
    w = tuple(col(rate[:, i]) for i in range(3))
    B = len(speed)
    force, moment = np.zeros((B, 3)), np.zeros((B, 3))
    for k, (chain, span, chord) in enumerate(mx.chain_with_geometry(bird)):
        r, width = strip_positions(span, bird.cp_span_fraction, bird.strips)
        area = chord * mx.area_scale(k, states, bird)  # 1.0 but for m5's folding hand
        el = element_forces(chain, states, r, width, area, air, bird, w)
        shape = (B, len(phases), len(r))
        mom = cross(el.position_body, el.force_body)
        for i in range(3):
            force[:, i] += np.broadcast_to(el.force_body[i], shape).mean(axis=1).sum(axis=-1)
            moment[:, i] += np.broadcast_to(mom[i], shape).mean(axis=1).sum(axis=-1)
    return force, moment


def _means_numpy(mx, sym, speed, climb, rate, u, bird, phases, signs):
    right, left = sides(mx, sym, u, signs)
    B = len(speed)
    both = {k: np.concatenate([right[k], left[k]]) for k in mx.param_names}
    rates = np.concatenate([rate, MIRROR_M * rate])  # the left wing sees (-p, q, -r)
    v2, c2 = np.concatenate([speed, speed]), np.concatenate([climb, climb])
    f, m = right_wing_numpy(mx, both, v2, c2, rates, bird, phases)
    force = f[:B] + MIRROR_F * f[B:] + drag_body(sym, speed, climb, bird)
    return force, m[:B] + MIRROR_M * m[B:]


def whole_bird(
    mx: KinematicModel,
    sym: dict[str, np.ndarray],
    speed: np.ndarray,
    climb: np.ndarray,
    rate: np.ndarray,
    u: np.ndarray,
    bird: Bird,
    phases: np.ndarray,
    *,
    jacobians: bool = False,
    backend: str = "kernel",
) -> dict[str, np.ndarray]:
    """Whole-bird means (and Jacobians) for a flat batch.

    Args:
        mx: the input model (:func:`birdsim.physics.moments.input_model`).
        sym: its parameters, each (B,) (the symmetric wingbeat).
        speed, climb: (B,); rate: B x 3 body rate; u: B x k control inputs.

    Returns:
        ``force_body``, ``moment_body`` (B x 3) and with ``jacobians`` ``force_du``,
        ``moment_du`` (B x 3 x k), ``force_drate``, ``moment_drate`` (B x 3 x 3).
    """
    if backend not in BACKENDS:
        raise BirdsimError(f"backend={backend!r} is unknown; allowed: {', '.join(BACKENDS)}")
    signs = input_signs(mx)
    if backend == "kernel":
        from birdsim.physics import kernel_moments

        out = kernel_moments.whole_bird(mx, sym, speed, climb, rate, u, bird, phases, signs)
        if out is not None:
            if not jacobians:
                out = {k: out[k] for k in ("force_body", "moment_body")}
            return out
    f, m = _means_numpy(mx, sym, speed, climb, rate, u, bird, phases, signs)
    out = {"force_body": f, "moment_body": m}
    if not jacobians:
        return out
    h = FD_STEP
    k = u.shape[1]
    for name, arr, n in (("du", u, k), ("drate", rate, 3)):
        df, dm = np.zeros(f.shape + (n,)), np.zeros(m.shape + (n,))
        for i in range(n):
            step = np.zeros(n)
            step[i] = h
            res = []
            for sgn in (1.0, -1.0):
                moved = {"du": u, "drate": rate, name: arr + sgn * step}
                res.append(
                    _means_numpy(
                        mx, sym, speed, climb, moved["drate"], moved["du"], bird, phases, signs
                    )
                )
            (fp, mp), (fm, mm) = res
            df[..., i], dm[..., i] = (fp - fm) / (2 * h), (mp - mm) / (2 * h)
        out["force_" + name], out["moment_" + name] = df, dm
    return out
