"""The posed MuJoCo bird and its offscreen renderer: :class:`Scene` draws any
:class:`~birdsim.render.states.StateSequence` (a Playback is adapted on the way in).

Set-up: the MJCF of the states' model and bird (the visual bird drawn, the physical
group 1 hidden), the effects of ``options.quality`` (shadows, sky, haze,
multisampling), one pass over every instant (CP sites, torso, forces), the camera
path (:mod:`birdsim.render.camera`).  Per frame: state ``qpos``/``qvel`` ->
kinematics -> ``mujoco.Renderer.update_scene`` with the frame's free camera ->
decorations (reference path, CP pathlines, force arrows) -> render -> sky, overlay and
plot strip in the pixels.

:mod:`birdsim.render.gl` rules: the GL back-end is chosen before :mod:`mujoco` is
imported, so this module imports mujoco lazily.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from birdsim.flight.playback import Playback
from birdsim.render.camera import CameraPose, camera_path, project
from birdsim.render.decor import add_arrow, add_polyline, add_trails, trail_window
from birdsim.render.forces import (
    ARM_RGBA,
    DRAG_RGBA,
    HAND_RGBA,
    dissertation_force,
    site_forces,
    weight,
    wingbeat_mean,
)
from birdsim.render.options import CAMERAS, RenderError, RenderOptions
from birdsim.render.overlay import (
    PlotStrip,
    draw_overlay,
    fill_sky,
    font_for_height,
    force_lines,
    legend_line,
)
from birdsim.render.states import StateSequence, states_from_playback


class Scene:
    """A posed MuJoCo bird with an offscreen renderer; use as a context manager.

    ``Scene(states, options)``: ``states`` a :class:`StateSequence` (or a
    :class:`Playback` from :func:`~birdsim.render.states.play_for_video`, adapted with
    ``options.trail_substeps`` instants per frame).  It builds the MJCF of the states'
    model and bird, enlarges the offscreen buffer when needed, sets the quality's
    effects and precomputes pathlines, forces and the camera path.  ``rgb(i)`` renders video frame ``i``
    (overlay included), ``segmentation(i)`` the (object id, object type) image of the
    same view.
    """

    def __init__(self, states: StateSequence | Playback, options: RenderOptions):
        import mujoco

        from birdsim.mujoco.fan import PrimaryFan
        from birdsim.mujoco.legged import build_model_for
        from birdsim.mujoco.model import aero_sites
        from birdsim.render.tail_pose import TailPoser

        self._mj = mujoco
        self.playback = states if isinstance(states, Playback) else None
        self.options = options
        self.m = build_model_for(  # with legs when the states carry them
            states.model.name if isinstance(states, Playback) else states.model,
            states.bird,
            -1 if isinstance(states, Playback) else int(states.qpos.shape[1]),
            perches=getattr(states, "perches", None),
        )
        if isinstance(states, Playback):
            states = states_from_playback(states, max(1, int(options.trail_substeps)), m=self.m)
        if states.qpos.shape[1] != self.m.nq or states.qvel.shape[1] != self.m.nv:
            raise RenderError(
                f"states have nq={states.qpos.shape[1]}, nv={states.qvel.shape[1]}; the model {states.model!r} has nq={self.m.nq}, nv={self.m.nv}"
            )
        self.states = states
        self.sub = states.instants_per_frame
        self.frames = states.frames
        self.m.vis.global_.offwidth = max(int(self.m.vis.global_.offwidth), options.width)
        self.m.vis.global_.offheight = max(int(self.m.vis.global_.offheight), options.height)
        look = options.look
        self.m.vis.quality.offsamples = look.samples
        self.m.vis.quality.shadowsize = look.shadowsize
        if not look.textures:
            self.m.geom_matid[:] = np.where(
                self.m.geom_group == 0, -1, self.m.geom_matid
            )  # arena plain
            self.m.geom_rgba[self.m.geom_group == 0] = (0.45, 0.56, 0.38, 1.0)
        floor = mujoco.mj_name2id(self.m, mujoco.mjtObj.mjOBJ_GEOM, "floor")
        if floor >= 0 and self.m.geom_type[floor] == mujoco.mjtGeom.mjGEOM_PLANE:
            self.m.geom_size[floor][:2] = 0.0  # drawn without edges (this copy only renders)
        # shadow box of +-3 semispans around the bird (the scene's extent would blur it)
        self._s = float(states.bird.semispan)
        self.m.vis.map.shadowclip = 3.0 * self._s / float(self.m.stat.extent)
        self._sun = mujoco.mj_name2id(self.m, mujoco.mjtObj.mjOBJ_LIGHT, "sun")
        self._torso = mujoco.mj_name2id(self.m, mujoco.mjtObj.mjOBJ_BODY, "torso")
        self._tail = getattr(states, "tail", None)  # (F, 3) elevation, spread, roll
        self._tail_poser = TailPoser(self.m, self._s) if self._tail is not None else None
        self._fan = PrimaryFan.for_model(self.m, states.bird)  # m5: the primaries fan
        self.d = mujoco.MjData(self.m)
        self.renderer = mujoco.Renderer(self.m, options.height, options.width, max_geom=4000)
        flags = self.renderer.scene.flags
        rnd = mujoco.mjtRndFlag
        flags[rnd.mjRND_SHADOW] = int(look.shadowsize > 0)
        flags[rnd.mjRND_SKYBOX] = int(look.skybox)
        flags[rnd.mjRND_HAZE] = int(look.haze)
        flags[rnd.mjRND_REFLECTION] = 0
        flags[rnd.mjRND_FOG] = 0
        self.camera = mujoco.MjvCamera()
        self.camera.type = mujoco.mjtCamera.mjCAMERA_FREE
        self.option = mujoco.MjvOption()
        self.option.geomgroup[1] = (
            0  # the physical bird (panels as boxes): the visual bird (group 2) is drawn
        )
        self.aero = aero_sites(states.model, states.bird)
        self.sites = [s.site for s in self.aero]
        self.site_ids = [mujoco.mj_name2id(self.m, mujoco.mjtObj.mjOBJ_SITE, s) for s in self.sites]
        self.paths, self.torso_path, self.heading = self._precompute()
        self.trails = self.paths if options.trails else None
        self.poses = self._camera_poses(options.camera)
        self.shadows = self._shadow_frames(look.shadowsize > 0)
        self._font = None
        self._strip: PlotStrip | None = None

    # ---- set-up ----------------------------------------------------------------------

    def _camera_poses(self, name: str) -> list[CameraPose]:
        """One camera pose per video frame (see :mod:`birdsim.render.camera`)."""
        mj = self._mj
        if name not in CAMERAS:
            raise RenderError(f"--camera {name!r} is unknown; allowed: {', '.join(CAMERAS)}")
        extra = []
        for k in range(1, 100):  # every perch's top: perch_top, perch2_top, ...
            sid = mj.mj_name2id(self.m, mj.mjtObj.mjOBJ_SITE, f"perch{k if k > 1 else ''}_top")
            if sid < 0:
                break
            top = self.d.site_xpos[sid].copy()
            extra += [top, top * np.array([1.0, 1.0, 0.0])]
        if self.states.reference_path is not None:
            extra += list(self.states.reference_path)
        aspect = self.options.width / self.options.height
        poses = camera_path(
            name,
            self.torso_path,
            self.heading,
            self.states.t_beats,
            2.0 * self.states.bird.semispan,
            float(self.m.vis.global_.fovy),
            aspect,
            np.array(extra) if extra else None,
        )
        return [poses[self.instant(i)] for i in range(self.frames)]

    def _shadow_frames(self, wanted: bool) -> np.ndarray:
        """Per frame: draw shadows?  Only where the bird's shadow can be seen: the point
        where the sun's ray through the bird meets the ground projects into the frame
        (a shadow off-screen costs a second render pass for nothing)."""
        if not wanted or self._sun < 0:
            return np.zeros(self.frames, dtype=bool)
        d = self.m.light_dir[self._sun] / np.linalg.norm(self.m.light_dir[self._sun])
        if d[2] >= -1e-6:  # the sun does not shine down: no ground shadow
            return np.zeros(self.frames, dtype=bool)
        fovy, aspect = float(self.m.vis.global_.fovy), self.options.width / self.options.height
        out = np.zeros(self.frames, dtype=bool)
        for i in range(self.frames):
            p = self.torso_path[self.instant(i)]
            ground = p + d * (p[2] / -d[2])  # where the sun's ray through the bird meets z = 0
            margin = 2.0 * self._s  # the wings' shadow reaches a semispan or two beyond
            pts = ground + np.array(
                [[0, 0, 0], [margin, 0, 0], [-margin, 0, 0], [0, margin, 0], [0, -margin, 0]]
            )
            out[i] = bool(
                np.any(np.all(np.abs(project(pts, self.poses[i], fovy, aspect)) <= 1.0, axis=1))
            )
        return out

    def pose_instant(self, k: int) -> None:
        """Pose the bird at instant ``k``: qpos/qvel, then only what drawing needs
        (kinematics, centre of mass for the tracking cameras, cameras/lights)."""
        mj = self._mj
        self.d.qpos[:] = self.states.qpos[k]
        self.d.qvel[:] = self.states.qvel[k]
        if self._tail_poser is not None:  # the dressed tail follows the controls
            self._tail_poser.pose(float(self._tail[k, 0]), float(self._tail[k, 2]))
        if self._fan is not None:  # m5's primaries fan closed with the wrist's flexion
            self._fan.pose(self.d.qpos)
        mj.mj_kinematics(self.m, self.d)
        mj.mj_comPos(self.m, self.d)
        mj.mj_camlight(self.m, self.d)
        if self._sun >= 0:  # the sun's shadow box (directional light) centred on the bird
            self.d.light_xpos[self._sun] = (
                self.d.xpos[self._torso] - self.d.light_xdir[self._sun] * 4.0 * self._s
            )

    def _precompute(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """One pass over every instant: CP site positions (instants, sites, 3), torso
        position (instants, 3) and forward direction (instants, 3), world; and the
        aerodynamic forces (:attr:`cp_forces`, :attr:`drag`, :attr:`achieved`)."""
        n = self.states.instants
        sites = np.empty((n, len(self.site_ids), 3))
        torso = np.empty((n, 3))
        heading = np.empty((n, 3))
        self.cp_forces = np.empty((n, len(self.site_ids), 3))
        self.drag = np.empty((n, 3))
        self.drag_at = np.empty((n, 3))
        mj, bird = self._mj, self.states.bird
        tsite = mj.mj_name2id(self.m, mj.mjtObj.mjOBJ_SITE, "torso_cp")
        for k in range(n):
            self.pose_instant(k)
            sites[k] = self.d.site_xpos[self.site_ids]
            torso[k] = self.d.xpos[self._torso]
            heading[k] = self.d.xmat[self._torso].reshape(3, 3)[:, 0]
            self.cp_forces[k], self.drag[k] = site_forces(
                mj, self.m, self.d, self.aero, self.site_ids, tsite, bird
            )
            self.drag_at[k] = self.d.site_xpos[tsite]
        #: the dissertation's force (right wing + body drag), seed axes, table units, wingbeat mean
        self.achieved = wingbeat_mean(
            dissertation_force(self.cp_forces, self.drag, [a.side for a in self.aero], bird),
            self.states.t_beats,
        )
        w = weight(bird)
        self.force_unit = (
            w
            if w > 0
            else max(
                float(np.linalg.norm(self.cp_forces, axis=-1).max()),
                float(np.linalg.norm(self.drag, axis=-1).max()),
                1e-300,
            )
        )
        self.force_unit_name = "the weight" if w > 0 else "the largest force"
        return sites, torso, heading

    def _add_forces(self, k: int) -> None:
        """Arrows of the CP forces and the body drag at instant ``k``: one ``force_unit``
        is ``options.forces`` semispans long."""
        per = self.options.forces * self._s / self.force_unit
        scn, mj = self.renderer.scene, self._mj
        width = 0.025 * self._s
        for site, pos, f in zip(self.sites, self.paths[k], self.cp_forces[k]):
            add_arrow(mj, scn, pos, pos + per * f, HAND_RGBA if "hand" in site else ARM_RGBA, width)
        add_arrow(mj, scn, self.drag_at[k], self.drag_at[k] + per * self.drag[k], DRAG_RGBA, width)

    # ---- per frame -------------------------------------------------------------------

    def instant(self, i: int) -> int:
        """The state instant video frame ``i`` shows."""
        return i * self.sub

    def update(self, i: int) -> None:
        """Pose frame ``i`` and build its scene (bird, camera, decorations)."""
        self.pose_instant(self.instant(i))
        pose = self.poses[i]
        self.camera.lookat[:] = pose.lookat
        self.camera.distance = pose.distance
        self.camera.azimuth = pose.azimuth
        self.camera.elevation = pose.elevation
        self.renderer.update_scene(self.d, camera=self.camera, scene_option=self.option)
        scn = self.renderer.scene
        scn.flags[self._mj.mjtRndFlag.mjRND_SHADOW] = int(self.shadows[i])
        if self.states.reference_path is not None and self.options.reference:
            add_polyline(self._mj, scn, self.states.reference_path)
        if self.trails is not None:
            self._add_trails(i)
        if self.options.forces is not None:
            self._add_forces(self.instant(i))

    def _add_trails(self, i: int) -> None:
        dt_beats = (
            float(np.median(np.diff(self.states.t_beats))) if self.states.instants > 1 else 1.0
        )
        keep = max(2, int(round(self.options.trail_beats / max(dt_beats, 1e-12))))
        add_trails(
            self._mj, self.renderer.scene, self.trails[trail_window(i, self.sub, keep)], self.sites
        )

    def overlay_lines(self, k: int) -> list:
        """The overlay of instant ``k``. Short (the default): the states' brief lines (at
        most three; the arrows' legend takes the third when they are drawn). Full: the
        states' own lines, the demanded and achieved force, and the arrows' legend."""
        legend = []
        if self.options.forces is not None:
            legend.append(
                legend_line(
                    "1 weight" if self.force_unit_name == "the weight" else "largest force",
                    self.options.forces,
                )
            )
        if self.options.overlay_detail == "short":
            lines = self.states.brief_at(k)
            return (lines[:2] + legend) if legend else lines
        dem = self.states.demanded_force
        lines = list(self.states.overlay_at(k))
        lines[1:1] = force_lines(None if dem is None else dem[k], self.achieved[k])
        return lines + legend

    def finish(self, img: np.ndarray, i: int) -> np.ndarray:
        """Sky, overlay and plot strip of frame ``i`` drawn into the rendered pixels
        (in place)."""
        fill_sky(img)
        if self.options.overlay:
            k = self.instant(i)
            draw_overlay(img, self.overlay_lines(k), self._get_font())
            self._get_strip().draw(img, float(self.states.t_beats[k]))
        return img

    def _get_strip(self) -> PlotStrip:
        if self._strip is None:
            t, dem = self.states.t_beats, self.states.demanded_force
            series = []
            if dem is not None:
                series += [
                    ("Fz demanded", dem[:, 2], (120, 170, 255)),
                    ("Fx demanded", dem[:, 0], (120, 220, 120)),
                ]
            series += [
                ("Fz achieved", self.achieved[:, 2], (255, 200, 60)),
                ("Fx achieved", self.achieved[:, 0], (255, 110, 110)),
                ("(wingbeat mean)", self.achieved[:1, 0][:0], (200, 200, 200)),
            ]
            from birdsim.render.overlay import font_for_height

            self._strip = PlotStrip(
                self.options.width,
                self.options.height,
                t,
                series,
                font_for_height(int(self.options.height * 0.8)),
            )
        return self._strip

    def rgb(self, i: int) -> np.ndarray:
        """Frame ``i`` as (H, W, 3) uint8, overlay included."""
        self.update(i)
        return self.finish(self.renderer.render(), i)

    def segmentation(self, i: int) -> np.ndarray:
        """(H, W, 2): object id and object type per pixel (-1 where nothing)."""
        self.update(i)
        self.renderer.enable_segmentation_rendering()
        try:
            return self.renderer.render().copy()
        finally:
            self.renderer.disable_segmentation_rendering()

    def bird_geoms(self) -> np.ndarray:
        """Geom ids of the bird (every body below the torso)."""
        mj = self._mj
        torso = mj.mj_name2id(self.m, mj.mjtObj.mjOBJ_BODY, "torso")
        return np.flatnonzero(self.m.body_rootid[self.m.geom_bodyid] == torso)

    def wing_geoms(self) -> np.ndarray:
        """Geom ids of the wings (bird geoms not on the torso)."""
        mj = self._mj
        torso = mj.mj_name2id(self.m, mj.mjtObj.mjOBJ_BODY, "torso")
        g = self.bird_geoms()
        return g[self.m.geom_bodyid[g] != torso]

    def _get_font(self) -> Any:
        if self._font is None:
            self._font = font_for_height(self.options.height)
        return self._font

    def close(self) -> None:
        self.renderer.close()

    def __enter__(self) -> "Scene":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


__all__ = ["Scene"]
