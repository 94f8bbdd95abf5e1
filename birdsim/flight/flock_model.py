"""A flock's birds in one MuJoCo model: every bird's body tree under its own free joint,
its names prefixed ``birdNN_`` (:func:`build_flock_model`), and the copies of one bird's
block of the shared ``MjData`` to and from the bird's own one-bird ``MjData``.

The model is built with ``MjSpec`` attach: each bird's one-bird spec
(:func:`birdsim.mujoco.model.build_spec`, no arena) attached under the world in order,
so bird ``b``'s coordinates, DOF, bodies, joints, geoms, sites and mass-matrix entries
are one contiguous block at an offset (:class:`Block`) and its numbers are its one-bird
model's (checked: masses, inertias, joint and site frames, armature, damping, ``qpos0``).
The trees do not touch (no contacts in free flight, no constraints), so MuJoCo's
per-tree computations (kinematics, the composite inertia, the bias forces, the sparse
factorisation of M, the integration) are those of the one-bird model on every bird.

Each bird keeps its own one-bird model and ``MjData`` for its controller (the attitude
loop's Jacobians are measured on its own model): :func:`copy_in` puts the bird's state
into the shared data before an interval, :func:`copy_out` every per-entity array of its
block back after it (the one-bird data is then what stepping it alone would leave).
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from birdsim.errors import BirdsimError
from birdsim.mujoco.model import build_spec

#: the one-bird model's arrays that must equal the shared model's block (a check)
_SAME = (
    "body_mass", "body_inertia", "body_pos", "body_quat", "body_ipos", "body_iquat",
    "jnt_pos", "jnt_axis", "dof_armature", "dof_damping", "site_pos", "site_quat", "qpos0",
)  # fmt: skip
#: option fields copied from the first bird's (flight-ready) model
_OPTIONS = (
    "timestep", "gravity", "wind", "magnetic", "density", "viscosity", "integrator",
    "disableflags", "enableflags", "jacobian",
)  # fmt: skip


@dataclass(frozen=True)
class Block:
    """Bird ``index``'s offsets in the shared model (a one-bird model's id ``i`` >= 1 of a
    body is ``i + body`` there; every other entity's id ``i`` is ``i + <its offset>``)."""

    index: int
    qpos: int
    dof: int
    body: int
    site: int
    joint: int
    geom: int


def build_flock_model(models: list[tuple[str, object, mujoco.MjModel]]) -> tuple:
    """The shared model of ``models`` = [(kinematic model name, reduced bird, the bird's
    flight-ready one-bird MjModel), ...] and each bird's :class:`Block`.

    Raises:
        BirdsimError: the birds' models differ in layout or options, or a block differs
            from its one-bird model.
    """
    first = models[0][2]
    parent = mujoco.MjSpec()
    parent.modelname = "birdsim_flock"
    parent.option.timestep = first.opt.timestep
    for i, (kin, red, m) in enumerate(models):
        if (m.nq, m.nv, m.nbody, m.nsite) != (first.nq, first.nv, first.nbody, first.nsite):
            raise BirdsimError(
                f"bird {i}: its model's layout differs from bird 0's; allowed: one kinematic model"
            )
        for name in ("timestep", "gravity", "wind", "disableflags"):
            if not np.array_equal(getattr(m.opt, name), getattr(first.opt, name)):
                raise BirdsimError(f"bird {i}: option {name} differs from bird 0's")
        child = build_spec(kin, red, scene=False)
        child.option.timestep = first.opt.timestep
        frame = parent.worldbody.add_frame()
        frame.attach_body(child.body("torso"), f"bird{i:02d}_", "")
    shared = parent.compile()
    for name in _OPTIONS:
        value = getattr(first.opt, name)
        if isinstance(value, np.ndarray):
            getattr(shared.opt, name)[:] = value
        else:
            setattr(shared.opt, name, value)
    blocks = []
    for i, (_, _, m) in enumerate(models):
        b = Block(i, i * m.nq, i * m.nv, i * (m.nbody - 1), i * m.nsite, i * m.njnt, i * m.ngeom)
        _check_block(shared, m, b)
        blocks.append(b)
    return shared, blocks


def _rows(m: mujoco.MjModel, name: str, b: Block) -> slice:
    n = getattr(m, name).shape[0]
    if name.startswith("body_"):
        return slice(1 + b.body, b.body + n)
    off = {"jnt": b.joint, "dof": b.dof, "sit": b.site, "qpo": b.qpos}[name[:3]]
    return slice(off, off + n)


def _check_block(shared: mujoco.MjModel, m: mujoco.MjModel, b: Block) -> None:
    for name in _SAME:
        mine = getattr(m, name)
        if name.startswith("body_"):
            mine = mine[1:]
        if not np.array_equal(getattr(shared, name)[_rows(m, name, b)], mine):
            raise BirdsimError(f"bird {b.index}: the shared model's {name} differs from its own")


class DataMap:
    """Which float arrays of ``MjData`` are per-entity blocks, found once by their sizes:
    (name, per_bird_rows, kind) with kind "body" (a world row first) or "flat"."""

    def __init__(self, shared: mujoco.MjModel, one: mujoco.MjModel, n_birds: int):
        D, d = mujoco.MjData(shared), mujoco.MjData(one)
        self.fields: list[tuple[str, int, str]] = []
        for name in dir(d):
            if name.startswith("_") or name.startswith("efc") or name == "M":
                continue
            a, A = getattr(d, name, None), getattr(D, name, None)
            if not isinstance(a, np.ndarray) or a.dtype != np.float64 or a.ndim == 0:
                continue
            rows, rows_all = a.shape[0], A.shape[0]
            if rows == one.nbody and rows_all == 1 + n_birds * (rows - 1):
                self.fields.append((name, rows, "body"))
            elif rows > 0 and rows_all == n_birds * rows and A.shape[1:] == a.shape[1:]:
                self.fields.append((name, rows, "flat"))
        if ("qpos", one.nq, "flat") not in self.fields:
            raise BirdsimError("the shared model's qpos is not one block per bird")

    def copy_out(self, D: mujoco.MjData, d: mujoco.MjData, b: Block) -> None:
        """Bird ``b``'s block of the shared data into its one-bird data."""
        for name, rows, kind in self.fields:
            src = getattr(D, name)
            if kind == "body":
                getattr(d, name)[1:] = src[
                    1 + b.index * (rows - 1) : 1 + (b.index + 1) * (rows - 1)
                ]
            else:
                getattr(d, name)[:] = src[b.index * rows : (b.index + 1) * rows]


def copy_in(D: mujoco.MjData, d: mujoco.MjData, b: Block) -> None:
    """The bird's state (positions, velocities, applied forces) into the shared data."""
    nq, nv = d.qpos.shape[0], d.qvel.shape[0]
    D.qpos[b.qpos : b.qpos + nq] = d.qpos
    D.qvel[b.dof : b.dof + nv] = d.qvel
    D.qacc_warmstart[b.dof : b.dof + nv] = d.qacc_warmstart
    D.qfrc_applied[b.dof : b.dof + nv] = d.qfrc_applied


__all__ = ["Block", "DataMap", "build_flock_model", "copy_in"]
