"""The dressed tail follows the tail's controls: per instant, the tail's geoms (the
visual fan ``vis_tail``, ``vis_tail_band`` and the plain ``tail`` box) are turned about
the fan's hub by the elevation and the roll of :func:`birdsim.mujoco.tail.tail_frame`
(on this render's own copy of the model; the geoms are massless, so the dynamics are not
touched).  The spread is not drawn (a mesh has no size to scale)."""

from __future__ import annotations

import mujoco
import numpy as np

from birdsim.mujoco.tail import TailControls, tail_frame

#: The tail's geoms, when the model has them.
TAIL_GEOMS = ("vis_tail", "vis_tail_band", "tail")
#: The visual fan's hub (torso frame, semispans; birdsim.mujoco.visual.tail_fan).
HUB = np.array([-0.42, 0.0, 0.0])


class TailPoser:
    """Remembers the tail geoms' rest poses of ``m`` and turns them per instant."""

    def __init__(self, m: mujoco.MjModel, semispan: float):
        self.m = m
        self.ids = [
            g
            for g in (mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, n) for n in TAIL_GEOMS)
            if g >= 0
        ]
        self.pos0 = {g: m.geom_pos[g].copy() for g in self.ids}
        self.quat0 = {g: m.geom_quat[g].copy() for g in self.ids}
        self.hub = HUB * semispan
        for g in self.ids:  # MuJoCo skips geom_pos/quat of a geom in its body's frame
            m.geom_sameframe[g] = 0

    def pose(self, elevation: float, roll: float) -> None:
        rot = tail_frame(TailControls(elevation, 1.0, roll).clipped())
        q = np.zeros(4)
        mujoco.mju_mat2Quat(q, rot.ravel())
        for g in self.ids:
            self.m.geom_pos[g] = self.hub + rot @ (self.pos0[g] - self.hub)
            out = np.zeros(4)
            mujoco.mju_mulQuat(out, q, self.quat0[g])
            self.m.geom_quat[g] = out


__all__ = ["TailPoser"]
