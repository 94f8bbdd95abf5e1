"""A flock in one picture: the leader drawn as :class:`birdsim.render.scene.Scene` draws a
bird (overlay, reference path, trails, forces, shadows), every other bird of the flock
added to the same MuJoCo scene each frame (``mjv_addGeoms`` of the same model posed at
that bird's state: only the dynamic geoms, so the floor and the perch are drawn once),
and the cameras framing the whole flock (its centre, and a span that holds every bird).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from birdsim.render.camera import SPAN_FRACTION, camera_path
from birdsim.render.options import RenderOptions
from birdsim.render.scene import Scene
from birdsim.render.states import StateSequence

#: The fraction of the frame's narrower side the flock's diameter takes.
FLOCK_FRACTION = 0.8


class FlockScene(Scene):
    """``FlockScene(leader, options, others)``: ``others`` the other birds' state
    sequences (the same model and bird, the same instants as the leader's)."""

    def __init__(self, states: StateSequence, options: RenderOptions, others: list):
        self.others = list(others)
        for o in self.others:
            if o.qpos.shape != states.qpos.shape:
                raise ValueError(
                    f"a bird's states {o.qpos.shape} differ from the leader's {states.qpos.shape}"
                )
        super().__init__(states, options)
        mj = self._mj
        self._od = mj.MjData(self.m)
        self._perturb = mj.MjvPerturb()
        old = self.renderer  # room for every bird's geoms
        self.renderer = mj.Renderer(
            self.m, options.height, options.width, max_geom=4000 + self.m.ngeom * len(others)
        )
        self.renderer.scene.flags[:] = old.scene.flags[:]
        old.close()
        # the sun's shadow box around the whole flock, centred on it (pose_instant)
        pos = self.positions()
        self._centre = pos.mean(axis=0)
        reach = float(np.max(np.linalg.norm(pos - self._centre[None], axis=-1)))
        self.m.vis.map.shadowclip = (reach + 3.0 * self._s) / float(self.m.stat.extent)
        self._reach = reach

    def pose_instant(self, k: int) -> None:
        """As Scene's, with the sun's shadow box centred on the flock's centre."""
        super().pose_instant(k)
        centre = getattr(self, "_centre", None)
        if centre is not None and self._sun >= 0:
            self.d.light_xpos[self._sun] = centre[k] - self.d.light_xdir[self._sun] * (
                4.0 * self._s + self._reach
            )

    def positions(self) -> np.ndarray:
        """Every bird's torso origin at every instant (birds, instants, 3)."""
        return np.stack([self.torso_path] + [o.qpos[:, :3] for o in self.others])

    def _camera_poses(self, name: str) -> list:
        """The one-bird cameras, aimed at the flock's centre with a span holding it."""
        pos = self.positions()
        centre = pos.mean(axis=0)
        reach = float(np.max(np.linalg.norm(pos - centre[None], axis=-1)))
        # the one-bird cameras fit a span into SPAN_FRACTION (0.45) of the frame: the
        # flock's diameter (and a wingspan) into FLOCK_FRACTION of it
        span = (2.0 * reach + 2.0 * self.states.bird.semispan) * SPAN_FRACTION / FLOCK_FRACTION
        extra = pos.reshape(-1, 3)[:: max(1, pos.shape[1] // 50)]
        if self.states.reference_path is not None:
            extra = np.vstack([extra, self.states.reference_path])
        poses = camera_path(
            name,
            centre,
            self.heading,
            self.states.t_beats,
            span,
            float(self.m.vis.global_.fovy),
            self.options.width / self.options.height,
            extra,
        )
        return [poses[self.instant(i)] for i in range(self.frames)]

    def update(self, i: int) -> None:
        """The leader's frame (Scene.update), then every other bird's geoms."""
        super().update(i)
        mj, k, scn = self._mj, self.instant(i), self.renderer.scene
        for o in self.others:
            self._od.qpos[:] = o.qpos[k]
            if self._tail_poser is not None and o.tail is not None:
                self._tail_poser.pose(float(o.tail[k, 0]), float(o.tail[k, 2]))
            if self._fan is not None:
                self._fan.pose(self._od.qpos)
            mj.mj_kinematics(self.m, self._od)
            mj.mjv_addGeoms(
                self.m, self._od, self.option, self._perturb, mj.mjtCatBit.mjCAT_DYNAMIC, scn
            )


def flock_states(birds: list[dict], options: Any, title: str = "") -> list[StateSequence]:
    """Each bird's StateSequence (:func:`birdsim.flight.flightstates.flight_states`)."""
    from birdsim.flight.flightstates import flight_states

    return [flight_states(b, options, title=title) for b in birds]


def scene_factory(others: list) -> Any:
    """A ``Scene``-like factory for :func:`birdsim.render.renderer.render_states`."""
    return lambda states, options: FlockScene(states, options, others)


__all__ = ["FlockScene", "flock_states", "scene_factory"]
