"""What the renderer draws: a :class:`StateSequence`, the bird's MuJoCo state at a
sequence of instants, whatever produced it (a table-driven playback, a free-flight
simulation...).

Stable API (other stages build these; keep it backward compatible):

``StateSequence(model, bird, t_beats, qpos, qvel, overlay=None, reference_path=None,
instants_per_frame=1, title="", clip_note="", demanded_force=None)``

* ``model``: kinematic model name (base, m1..m4); with ``bird`` it names the MJCF
  :func:`birdsim.mujoco.model.build_model` builds, whose ``nq``/``nv`` the states use.
* ``t_beats`` (F,): time of each instant in wingbeats, evenly spaced (the wingbeat
  mean of the achieved force and the cameras' smoothing use the median step).
* ``qpos`` (F, nq), ``qvel`` (F, nv): MuJoCo world (x forward, y left, z up), the bird's
  length units; qvel per unit of the bird's time.
* ``overlay``: text per instant, ``callable(k) -> list of lines`` or a sequence of
  F lists; a line is ``(text, (r, g, b))`` or a plain ``str``.  None = no text.
* ``reference_path`` (K, 3): a polyline in world coordinates (e.g. the manoeuvre's
  demanded path), drawn as a thin line when given.
* ``instants_per_frame``: video frame ``i`` shows instant ``i * instants_per_frame``;
  the instants in between only make the control-point pathlines smoother.
* ``title``: a short name for progress bars; ``clip_note``: one line printed before
  rendering (e.g. what was clipped), "" when nothing.
* ``demanded_force`` (F, 3): the dissertation's force demanded at each instant (right
  wing + body drag, seed earth axes, Fz < 0 up, table force units), shown beside the
  achieved one (which the renderer measures from the states, in still air) and in the
  plot strip.

Added after the first release, with defaults, so older callers keep working:
``demanded_force``.

:func:`states_from_playback` adapts today's :class:`~birdsim.flight.playback.Playback`;
:func:`birdsim.render.renderer.render_states` renders any sequence to MP4.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, Union

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.flight.manoeuvre import Manoeuvre
from birdsim.flight.playback import Playback, TableLike, frame_times, play
from birdsim.physics.bird import Bird
from birdsim.render.options import RenderOptions
from birdsim.render.overlay import OverlayLine, overlay_lines

OverlaySource = Union[Callable[[int], Sequence[OverlayLine]], Sequence[Sequence[OverlayLine]], None]


@dataclass(frozen=True, eq=False)
class StateSequence:
    """The bird's MuJoCo state at F instants, plus what to draw beside it (see the
    module docstring for every field)."""

    model: str
    bird: Bird
    t_beats: np.ndarray
    qpos: np.ndarray
    qvel: np.ndarray
    overlay: OverlaySource = None
    reference_path: np.ndarray | None = None
    instants_per_frame: int = 1
    title: str = ""
    clip_note: str = ""
    demanded_force: np.ndarray | None = None
    brief: OverlaySource = None  # the default overlay: at most three short lines
    #: the tail's controls per instant (F, 3): elevation, spread, roll (free flight)
    tail: np.ndarray | None = None
    #: the scene's perches (birdsim.mujoco.perches.Scene; None: the presets' one perch)
    perches: object = None

    def __post_init__(self) -> None:
        t = np.asarray(self.t_beats, dtype=float)
        qpos = np.asarray(self.qpos, dtype=float)
        qvel = np.asarray(self.qvel, dtype=float)
        if t.ndim != 1 or len(t) == 0:
            raise BirdsimError(f"t_beats has shape {t.shape}; allowed: (F,) with F >= 1")
        if qpos.ndim != 2 or qpos.shape[0] != len(t) or qvel.ndim != 2 or qvel.shape[0] != len(t):
            raise BirdsimError(
                f"qpos {qpos.shape} / qvel {qvel.shape} do not match t_beats ({len(t)},); allowed: (F, nq) and (F, nv)"
            )
        if not (np.all(np.isfinite(qpos)) and np.all(np.isfinite(qvel))):
            raise BirdsimError("qpos/qvel contain NaN or inf; allowed: finite states")
        if not isinstance(self.instants_per_frame, int) or self.instants_per_frame < 1:
            raise BirdsimError(
                f"instants_per_frame={self.instants_per_frame!r}; allowed: an integer >= 1"
            )
        path = self.reference_path
        if path is not None:
            path = np.asarray(path, dtype=float)
            if (
                path.ndim != 2
                or path.shape[1] != 3
                or len(path) < 2
                or not np.all(np.isfinite(path))
            ):
                raise BirdsimError(
                    f"reference_path has shape {path.shape}; allowed: (K, 3) finite points, K >= 2"
                )
        if self.overlay is not None and not callable(self.overlay) and len(self.overlay) != len(t):
            raise BirdsimError(
                f"overlay has {len(self.overlay)} entries for {len(t)} instants; allowed: one per instant or a callable"
            )
        object.__setattr__(self, "t_beats", t)
        object.__setattr__(self, "qpos", qpos)
        object.__setattr__(self, "qvel", qvel)
        object.__setattr__(self, "reference_path", path)
        if self.tail is not None:
            tail = np.asarray(self.tail, dtype=float)
            if tail.shape != (len(t), 3) or not np.all(np.isfinite(tail)):
                raise BirdsimError(
                    f"tail has shape {tail.shape}; allowed: ({len(t)}, 3) finite controls"
                )
            object.__setattr__(self, "tail", tail)
        if self.demanded_force is not None:
            dem = np.asarray(self.demanded_force, dtype=float)
            if dem.shape != (len(t), 3) or not np.all(np.isfinite(dem)):
                raise BirdsimError(
                    f"demanded_force has shape {dem.shape}; allowed: ({len(t)}, 3) finite values"
                )
            object.__setattr__(self, "demanded_force", dem)

    @property
    def instants(self) -> int:
        return len(self.t_beats)

    @property
    def frames(self) -> int:
        """Video frames: ceil(instants / instants_per_frame)."""
        return -(-self.instants // self.instants_per_frame)

    def overlay_at(self, k: int) -> list[OverlayLine]:
        """The overlay lines of instant ``k`` ([] without an overlay)."""
        if self.overlay is None:
            return []
        return list(self.overlay(k) if callable(self.overlay) else self.overlay[k])

    def brief_at(self, k: int) -> list[OverlayLine]:
        """The short overlay of instant ``k`` (``brief``, else the first two lines of the
        full one), at most three lines."""
        if self.brief is not None:
            lines = list(self.brief(k) if callable(self.brief) else self.brief[k])
        else:
            lines = self.overlay_at(k)[:2]
        return lines[:3]


def playback_state(pb: Playback, m: Any | None = None) -> tuple[np.ndarray, np.ndarray]:
    """qpos, qvel of every playback instant at once (the driver's vectorised path;
    ``birdsim.mujoco.driver.set_pose`` does the same for one instant)."""
    from birdsim.mujoco.driver import set_root, wing_arrays
    from birdsim.mujoco.model import build_model

    m = m if m is not None else build_model(pb.model.name, pb.bird, visuals=False)  # joints only
    qpos, qvel, _ = wing_arrays(m, pb.angles, pb.rates, samples=pb.frames)
    set_root(
        m,
        qpos,
        qvel,
        pitch=pb.pitch,
        position_seed=pb.position_seed,
        velocity_seed=pb.velocity_seed,
        pitch_rate=pb.pitch_rate,
    )
    return qpos, qvel


def states_from_playback(
    pb: Playback, instants_per_frame: int = 1, *, m: Any | None = None
) -> StateSequence:
    """The :class:`StateSequence` of a table-driven playback (overlay: time, regime,
    demanded force, parameters; reference path: the body's prescribed path)."""
    qpos, qvel = playback_state(pb, m)
    return StateSequence(
        model=pb.model.name,
        bird=pb.bird,
        t_beats=pb.t_beats,
        qpos=qpos,
        qvel=qvel,
        overlay=lambda k: overlay_lines(pb, k),
        reference_path=None,
        instants_per_frame=instants_per_frame,
        title=pb.manoeuvre.name,
        clip_note=pb.clip_note,
        demanded_force=np.column_stack(
            [pb.demand_used["Fx"], np.zeros(pb.frames), pb.demand_used["Fz"]]
        ),
    )


def play_for_video(
    manoeuvre: Manoeuvre,
    table: TableLike,
    options: RenderOptions,
    *,
    bird: Bird | None = None,
    model: str | None = None,
) -> Playback:
    """The playback at ``trail_substeps`` instants per video frame, the body placed so
    that a perched start or end sits on the scene's perch."""
    sub = max(1, int(options.trail_substeps))
    frames = len(frame_times(options.duration(manoeuvre), options.fps, options.beats_per_second))
    t_beats = np.arange(frames * sub) * (options.beats_per_second / (options.fps * sub))
    bird = bird or getattr(table, "bird", None) or Bird()
    kin = play(
        manoeuvre, table, t_beats[:1], bird=bird, model=model
    ).model  # validates model and table first
    return play(
        manoeuvre,
        table,
        t_beats,
        bird=bird,
        model=model,
        perch_seed=perch_seed_position(kin.name, bird),
    )


def perch_seed_position(model_name: str, bird: Bird) -> tuple[float, float]:
    """(X, Z) in seed axes of the torso when it sits on the MJCF's perch."""
    import mujoco

    from birdsim.mujoco.model import build_model

    m = build_model(model_name, bird, visuals=False)  # sites and the physical torso only
    d = mujoco.MjData(m)
    mujoco.mj_kinematics(m, d)
    sid = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_SITE, "perch_top")
    gid = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, "torso_body")
    if sid < 0:
        return (0.0, -3.0)
    top = d.site_xpos[sid]
    clearance = float(m.geom_size[gid][2]) if gid >= 0 else 0.1 * bird.semispan
    return (float(top[0]), -float(top[2] + clearance))


__all__ = [
    "OverlaySource",
    "StateSequence",
    "perch_seed_position",
    "play_for_video",
    "playback_state",
    "states_from_playback",
]
