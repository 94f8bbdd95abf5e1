"""The partition of the MuJoCo bird's DOF into free and prescribed ones, found by
joint names (:mod:`birdsim.flight.simulate` documents what each mode frees)."""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from birdsim.errors import BirdsimError


@dataclass(frozen=True)
class Partition:
    """Free and prescribed DOF of the bird, found by joint names.

    ``free_dofs``: the root's DOF the physics integrates (6 free, 3 posed);
    ``pres_dofs`` / ``pres_qpos``: the prescribed DOF and their qpos addresses;
    ``wing_dofs``: the wings' joints (their power is the wings' mechanical power)."""

    free_dofs: np.ndarray
    pres_dofs: np.ndarray
    pres_qpos: np.ndarray
    wing_dofs: np.ndarray
    free_rotation: bool


def partition(m: mujoco.MjModel, attitude: str) -> Partition:
    """The partition of ``m``'s DOF for ``attitude`` ("free" or "posed")."""
    root = m.joint("root")
    if int(root.type[0]) != int(mujoco.mjtJoint.mjJNT_FREE):
        raise BirdsimError(
            "joint 'root' is not free; allowed: a model built by birdsim.mujoco.model"
        )
    r_dof, r_q = int(m.jnt_dofadr[root.id]), int(m.jnt_qposadr[root.id])
    wing_dofs, wing_q = [], []
    for j in range(m.njnt):
        if j == root.id:
            continue
        name = m.joint(j).name
        if not name.startswith(("r_", "l_")):
            raise BirdsimError(f"joint {name!r} is neither the root nor a wing joint")
        nv = {0: 6, 1: 3, 2: 1, 3: 1}[int(m.jnt_type[j])]
        nq = {0: 7, 1: 4, 2: 1, 3: 1}[int(m.jnt_type[j])]
        wing_dofs += range(int(m.jnt_dofadr[j]), int(m.jnt_dofadr[j]) + nv)
        wing_q += range(int(m.jnt_qposadr[j]), int(m.jnt_qposadr[j]) + nq)
    free = attitude == "free"
    n_free = 6 if free else 3
    free_dofs = np.arange(r_dof, r_dof + n_free)
    pres_dofs = list(range(r_dof + n_free, r_dof + 6)) + wing_dofs
    pres_q = ([] if free else list(range(r_q + 3, r_q + 7))) + wing_q
    return Partition(free_dofs, np.array(pres_dofs), np.array(pres_q), np.array(wing_dofs), free)


def _as_slice(idx: np.ndarray) -> slice | np.ndarray:
    """A contiguous index array as a slice (numpy views instead of copies)."""
    if len(idx) and np.array_equal(idx, np.arange(idx[0], idx[0] + len(idx))):
        return slice(int(idx[0]), int(idx[0]) + len(idx))
    return idx


__all__ = ["Partition", "partition"]
