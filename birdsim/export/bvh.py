"""BVH export: the bird as a skeleton with per-frame channels, written through pybvh.

Skeleton (bones named after the MJCF joints, docs/mujoco.md)::

    root            torso: Xposition Yposition Zposition + three rotations (the free joint)
    ├── r_shoulder  ball: three rotations, at the shoulder (the torso origin)
    │   └── r_wrist_flap   hinge (wrist flap), at the wrist, one arm span out
    │       └── r_wrist_twist  hinge (wrist twist), same place; End Site at the hand tip
    └── l_shoulder ... the mirror image

BVH has no one-channel joint: each hinge is written with the usual three rotation
channels, the hinge angle on its axis and the other two zero (to write precision).
Axes: BVH is Y-up; the file uses X forward, Y up, Z right, i.e. (X, Y, Z)_BVH =
(x, z, -y)_MuJoCo, so that Blender's default BVH import (forward -Z, up Y) puts the bird
exactly where the USD export puts it (Blender: x forward, y left, z up). Lengths in the
bird's length units times ``metres_per_unit``. Angles in degrees (the format's).

Writer: ``pybvh`` (MIT, maintained in 2026, numpy only; ``bvh`` 0.3 on PyPI is a parser
only; ``bvhio`` pins exact versions of its two dependencies; ``bvhtools`` pulls raylib and
matplotlib for a viewer).  The base model's heave slide has no BVH channel (BVH moves only
the root): BVH of the base model is refused with one line.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from birdsim.export.frames import ExportError, FrameSequence
from birdsim.mujoco.model import SIDES

#: BVH axes from MuJoCo axes: (X, Y, Z)_BVH = (x, z, -y)_MuJoCo (a proper rotation).
TO_BVH = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
#: Euler channel orders: the root pitches about BVH Z; the shoulder composes sweep (Y),
#: stroke (Z) and flap (X); the wrist flap hinge is about X, the twist hinge about Z.
ORDERS = {"root": "ZXY", "shoulder": "YZX", "wrist_flap": "XYZ", "wrist_twist": "ZXY"}


def quat_to_matrix(q: np.ndarray) -> np.ndarray:
    """(..., 4) unit quaternions (w, x, y, z) -> (..., 3, 3) rotation matrices."""
    q = np.asarray(q, dtype=float)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = np.moveaxis(q, -1, 0)
    return np.stack(
        [
            np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
            np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
            np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
        ],
        -2,
    )


def axis_angle_matrix(axis: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """Rotations by ``angle`` (F,) about the unit ``axis`` (3,): (F, 3, 3)."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    k = np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])
    s, c = np.sin(angle)[:, None, None], np.cos(angle)[:, None, None]
    return np.eye(3) + s * k + (1.0 - c) * (k @ k)


def local_transforms(
    frames: FrameSequence,
) -> tuple[list[str], dict[str, np.ndarray], dict[str, np.ndarray], np.ndarray]:
    """Bone names, rest offsets (MuJoCo axes, bird units), per-frame local rotations
    (F, 3, 3) in MuJoCo axes, and the root position (F, 3), all from the MJCF and qpos."""
    from birdsim.mujoco.legged import build_model_for

    m = build_model_for(frames.model, frames.bird, frames.qpos.shape[1])  # legs if any
    qpos = frames.qpos
    n = frames.frames
    names = ["root"]
    offsets = {"root": np.zeros(3)}
    rots = {"root": quat_to_matrix(qpos[:, 3:7])}
    for side in SIDES:
        arm, hand = m.body(f"{side}_arm"), m.body(f"{side}_hand")
        ball = m.joint(f"{side}_shoulder")
        adr = m.jnt_qposadr[ball.id]
        names += [f"{side}_shoulder", f"{side}_wrist_flap", f"{side}_wrist_twist"]
        offsets[f"{side}_shoulder"] = np.array(arm.pos, dtype=float)
        rots[f"{side}_shoulder"] = quat_to_matrix(np.array(arm.quat)) @ quat_to_matrix(
            qpos[:, adr : adr + 4]
        )
        offsets[f"{side}_wrist_flap"] = np.array(hand.pos, dtype=float)
        offsets[f"{side}_wrist_twist"] = np.zeros(3)
        for j in ("wrist_flap", "wrist_twist"):
            jnt = m.joint(f"{side}_{j}")
            r = axis_angle_matrix(np.array(m.jnt_axis[jnt.id]), qpos[:, m.jnt_qposadr[jnt.id]])
            rots[f"{side}_{j}"] = (
                (quat_to_matrix(np.array(hand.quat)) @ r) if j == "wrist_flap" else r
            )
        hand_span = frames.bird.semispan * frames.bird.hand_span_fraction
        offsets[f"{side}_tip"] = np.array([0.0, (-1.0 if side == "r" else 1.0) * hand_span, 0.0])
    assert all(r.shape == (n, 3, 3) for r in rots.values())
    return names, offsets, rots, qpos[:, 0:3].copy()


def require_bvh() -> None:
    """One line naming the extra when pybvh is missing."""
    import importlib

    try:
        importlib.import_module("pybvh")
    except ImportError:
        raise ExportError(
            "--format bvh needs pybvh, which is not installed; allowed: pip install 'birdsim[bvh]' (or --format usd/csv)"
        ) from None


def check_bvh_model(model: str | None) -> None:
    """Refuse the base model (its heave slide has no BVH channel) in one line; ``birdsim
    export`` asks before it flies."""
    if model == "base":
        raise ExportError(
            "--format bvh cannot carry the base model's heave slide (BVH moves only the root); allowed: --model m1..m4, or --format usd/csv"
        )


def build_bvh(frames: FrameSequence):  # -> pybvh.Bvh
    """The :class:`pybvh.Bvh` of ``frames`` (skeleton and motion; see the module docstring).

    Raises:
        ExportError: the base model (its heave slide has no BVH channel).
    """
    require_bvh()
    from pybvh import Bvh
    from pybvh.bvhnode import BvhEndSite, BvhJoint, BvhRoot

    check_bvh_model(frames.model)
    names, offsets, rots, root_pos = local_transforms(frames)
    scale = frames.metres_per_unit
    root = BvhRoot("root", offset=[0.0, 0.0, 0.0], pos_channels="XYZ", rot_channels=ORDERS["root"])
    nodes = [root]
    for side in SIDES:
        parent = root
        for kind in ("shoulder", "wrist_flap", "wrist_twist"):
            name = f"{side}_{kind}"
            j = BvhJoint(
                name,
                offset=TO_BVH @ offsets[name] * scale,
                rot_channels=ORDERS[kind],
                parent=parent,
            )
            parent.children.append(j)
            nodes.append(j)
            parent = j
        tip = BvhEndSite(
            f"{side}_tip", offset=TO_BVH @ offsets[f"{side}_tip"] * scale, parent=parent
        )
        parent.children.append(tip)
        nodes.append(tip)
    joint_names = [n.name for n in nodes if not n.is_end_site()]
    mats = np.stack(
        [TO_BVH @ rots[name] @ TO_BVH.T for name in joint_names], axis=1
    )  # (F, J, 3, 3)
    skeleton = Bvh(nodes=nodes, frame_time=1.0 / frames.fps, world_up="+y")
    return skeleton.from_rotmat(root_pos @ TO_BVH.T * scale, mats)


def write_bvh(frames: FrameSequence, out: str | Path) -> Path:
    """Write ``frames`` as BVH to ``out`` (atomically; the path must end in .bvh).

    Args:
        frames: the frame source.
        out: the output path.

    Returns:
        The path written.

    Raises:
        ExportError: the base model (see :func:`build_bvh`).
    """
    import os

    from birdsim.io import temporary_sibling

    motion = build_bvh(frames)
    out = Path(out)
    tmp = temporary_sibling(out)
    try:
        motion.write(tmp)
        os.replace(tmp, out)
    finally:
        if tmp.exists():
            tmp.unlink()
    return out


__all__ = ["ORDERS", "TO_BVH", "build_bvh", "local_transforms", "require_bvh", "write_bvh"]
