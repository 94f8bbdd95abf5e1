"""m5's extra MuJoCo joints: the elbow on the arm, and the wrist's flexion and the
hand's supination around m4's wrist hinges (issue 24).  Other models keep their layout.

The core chain ``shoulder -> Offset(e) -> elbow -> Offset(-e) -> arm panel`` becomes the
bodies ``X_arm`` (shoulder) -> ``X_forearm`` at the elbow (hinge ``X_elbow`` about the
panel's z axis) -> ``X_arm_plate`` back at the shoulder's place (no joint), which
carries the arm panel, its CP site and the hand exactly as ``X_arm`` does for m4; the
hand body gets ``X_wrist_sweep`` (z) before m4's hinges, in the core's chain order.  The
supination follows the wrist twist about the same axis: MuJoCo turns the hand by their
sum with ``X_wrist_twist`` (mujoco/driver.py; two collinear hinges in one body would make
the mass matrix singular).
"""

from __future__ import annotations

import mujoco
import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import JOINTS, get_model

#: The hand's hinges per model, outward order (the core's chain order).
M4_HAND = ("wrist_flap", "wrist_twist")
M5_HAND = ("wrist_sweep", "wrist_flap", "wrist_twist")  # + supination, in X_wrist_twist
#: Mass of the massless links (the shoulder-to-elbow and forearm bodies), as a fraction
#: of a panel's: MuJoCo needs a moving body to have some mass; the panels carry the rest.
LINK_MASS_FRACTION = 1e-6


def hand_joints(model_name: str) -> tuple[str, ...]:
    """The hand's hinge joints of ``model_name`` (every model but m5 has m4's two)."""
    return M5_HAND if get_model(model_name).name == "m5" else M4_HAND


def add_elbow(
    arm: mujoco.MjsBody, side: str, bird: Bird, arm_span: float, sign: float, axis, wing_mass: float
) -> mujoco.MjsBody:
    """Give ``arm`` (the shoulder's body) an elbow; returns the body that carries the arm
    panel (at the shoulder's place, turned by the elbow)."""
    elbow = bird.elbow_span_fraction * arm_span
    tiny = LINK_MASS_FRACTION * wing_mass
    for body in (arm,):
        _tiny_inertia(body, tiny)
    fore = arm.add_body(name=f"{side}_forearm", pos=[0.0, sign * elbow, 0.0])
    _tiny_inertia(fore, tiny)
    fore.add_joint(name=f"{side}_elbow", type=mujoco.mjtJoint.mjJNT_HINGE, axis=axis(side, "z"))
    return fore.add_body(name=f"{side}_arm_plate", pos=[0.0, -sign * elbow, 0.0])


def add_hand_joints(hand: mujoco.MjsBody, side: str, model_name: str, axis) -> None:
    """The hand's hinges, in the core's chain order."""
    for name in hand_joints(model_name):
        hand.add_joint(
            name=f"{side}_{name}",
            type=mujoco.mjtJoint.mjJNT_HINGE,
            axis=axis(side, JOINTS[name].axis),
        )


def _tiny_inertia(body: mujoco.MjsBody, mass: float) -> None:
    body.explicitinertial = True
    body.mass = mass
    body.ipos = [0.0, 0.0, 0.0]
    body.inertia = np.full(3, mass)


def fold_area_joints(m: mujoco.MjModel, model_name: str, sites) -> np.ndarray | None:
    """Per aero site: the qpos address of the joint that sets its panel's area (-1 for
    none), or None when no panel's area folds (every model but m5)."""
    km = get_model(model_name)
    if not any(km.area_folds):
        return None
    panels = [p.name for p in Bird().panels(km.name)]
    out = []
    for s in sites:
        name = km.area_folds[panels.index(s.panel)]
        out.append(-1 if name is None else int(m.jnt_qposadr[m.joint(f"{s.side}_{name}").id]))
    return np.array(out)


def fold_area_scale(qpos: np.ndarray, addresses: np.ndarray, bird: Bird) -> np.ndarray:
    """The area factor of each site (1 where ``addresses`` is -1): the core's
    :func:`birdsim.physics.m5.area_factor` of the joint angle (cos is even: the left
    wing's mirrored angle gives the same factor)."""
    from birdsim.physics.m5 import area_factor

    q = np.where(addresses >= 0, qpos[np.maximum(addresses, 0)], 0.0)
    return np.asarray(area_factor(np.cos(q), bird))
