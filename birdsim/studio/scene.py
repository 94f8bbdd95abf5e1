"""A flight log as the 3-D viewer's scene: the dressed bird's geoms and their bodies'
poses per frame, the world, the reference path, the plotted series.

The bird is not modelled again for the browser: the log's MuJoCo states (``qpos`` of
the REDUCED model) are replayed through the same MJCF the renderer draws
(:func:`birdsim.mujoco.model.build_model`, visuals of :mod:`birdsim.mujoco.visual`),
``mj_kinematics`` gives every body's pose, and the page draws each visual geom (group
2, and the arena's group 0) at its body's pose. Scene units: MuJoCo world, semispans,
x forward, y left, z up (three.js is told z is up). Times: the log's (the bird's time
unit: seconds for an SI bird).

The torso's own track comes from the log's position and attitude: ``quat`` (w, x, y, z,
MuJoCo world) when the log has it, else today's ``pitch`` (nose up) with ``y = 0``; it
is drawn as the flown trail and must agree with the replayed torso (tested).
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird, scales

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

TWO_PI = 2.0 * math.pi
#: Format marker and version of the scene JSON (docs/studio.md).
SCENE_FORMAT = "birdsim-view"
SCENE_VERSION = 1
#: Geom groups drawn: the arena (0) and the bird for the eye (2); not the physical 1.
DRAWN_GROUPS = (0, 2)
#: The most frames a scene holds (the page's size; 10 s at 60 fps is 600).
MAX_FRAMES = 4000
#: Least frames per wingbeat, so that slow motion still shows the wingbeat.
MIN_FRAMES_PER_BEAT = 24
#: Wingbeats of playback per second of the page at "1x" for a bird without SI units.
NONDIM_BEATS_PER_SECOND = 2.0
#: Decimals kept in the JSON (scene units of semispans: 1e-4 s is well below a pixel).
DECIMALS = 4

_GEOM_TYPES = {0: "plane", 2: "sphere", 3: "capsule", 4: "ellipsoid", 5: "cylinder", 6: "box"}


@dataclass(frozen=True)
class ViewOptions:
    """How a log becomes a scene: ``fps`` frames per second of playback at 1x (the
    time base of :func:`time_base`), raised to :data:`MIN_FRAMES_PER_BEAT` per wingbeat."""

    fps: float = 60.0

    def __post_init__(self) -> None:
        if not (isinstance(self.fps, (int, float)) and math.isfinite(self.fps)):
            raise BirdsimError(f"--fps {self.fps!r} is not a number; allowed: 1 to 240")
        if not 1.0 <= float(self.fps) <= 240.0:
            raise BirdsimError(f"--fps {self.fps:g} is out of range; allowed: 1 to 240")


def is_si(bird: Bird) -> bool:
    """An SI bird (its time unit is the second) rather than the non-dimensional seed."""
    sc = scales(bird)
    return not (sc.length == 1.0 and sc.time == 1.0)


def time_base(bird: Bird) -> dict[str, Any]:
    """What "1x" means in the page: real time for an SI bird; for a non-dimensional bird
    :data:`NONDIM_BEATS_PER_SECOND` wingbeats per second (``birdsim render``'s default)."""
    period = TWO_PI / bird.omega  # in the bird's time unit
    if is_si(bird):
        return {"log_time_per_second": 1.0, "label": "real time", "period": period}
    return {
        "log_time_per_second": NONDIM_BEATS_PER_SECOND * period,
        "label": f"{NONDIM_BEATS_PER_SECOND:g} wingbeats per second",
        "period": period,
    }


def log_bird(log: dict[str, Any]) -> Bird:
    return log.get("bird_obj") or Bird.from_dict(tomllib.loads(str(log["bird"])))


def frame_times(log: dict[str, Any], options: ViewOptions) -> np.ndarray:
    """The scene's instants [the log's time unit], from the first to the last sample."""
    bird = log_bird(log)
    t_log = np.asarray(log["t"], dtype=float)
    if t_log.size < 2:
        raise BirdsimError("the flight log has fewer than two samples; allowed: a longer flight")
    tb = time_base(bird)
    per_time = max(options.fps / tb["log_time_per_second"], MIN_FRAMES_PER_BEAT / tb["period"])
    span = float(t_log[-1] - t_log[0])
    n = int(math.floor(span * per_time)) + 1
    if n > MAX_FRAMES:
        n = MAX_FRAMES
    return np.linspace(float(t_log[0]), float(t_log[-1]), max(n, 2))


def body_track(log: dict[str, Any]) -> tuple[np.ndarray, np.ndarray]:
    """The torso's position (T, 3) [semispans, MuJoCo world] and quaternion (T, 4)
    (w, x, y, z) at the log's samples: ``quat`` when logged, else from ``pitch``."""
    sc = scales(log_bird(log))
    x = np.asarray(log["x"], dtype=float) / sc.length
    z = np.asarray(log["z"], dtype=float) / sc.length
    y = np.asarray(log["y"], dtype=float) / sc.length if "y" in log else np.zeros_like(x)
    if "quat" in log:
        q = np.asarray(log["quat"], dtype=float).reshape(-1, 4)
    else:
        half = 0.5 * np.asarray(log["pitch"], dtype=float)  # nose up: about MuJoCo -y
        q = np.column_stack([np.cos(half), 0 * half, -np.sin(half), 0 * half])
    q = q / np.linalg.norm(q, axis=1, keepdims=True)
    return np.column_stack([x, y, z]), q


def _quaternion_slices(m: Any) -> list[slice]:
    import mujoco

    out = []
    for j in range(m.njnt):
        adr = int(m.jnt_qposadr[j])
        if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE:
            out.append(slice(adr + 3, adr + 7))
        elif m.jnt_type[j] == mujoco.mjtJoint.mjJNT_BALL:
            out.append(slice(adr, adr + 4))
    return out


def _interp(t_log: np.ndarray, values: np.ndarray, t: np.ndarray) -> np.ndarray:
    values = np.asarray(values, dtype=float)
    if values.ndim == 1:
        return np.interp(t, t_log, values)
    return np.column_stack([np.interp(t, t_log, values[:, k]) for k in range(values.shape[1])])


def _round(a: Any) -> list:
    return np.round(np.asarray(a, dtype=float), DECIMALS).ravel().tolist()


def _material_rgba(m: Any, mat: int) -> np.ndarray:
    """A material's colour; a textured one's times its texture's mean colour (the
    page draws no textures)."""
    rgba = np.array(m.mat_rgba[mat], dtype=float)
    texids = np.atleast_1d(m.mat_texid[mat])
    tex = next((int(t) for t in texids if t >= 0), -1)
    if tex >= 0:
        adr, n = int(m.tex_adr[tex]), int(m.tex_nchannel[tex])
        size = int(m.tex_height[tex]) * int(m.tex_width[tex]) * n
        pixels = np.asarray(m.tex_data[adr : adr + size], dtype=float).reshape(-1, n)
        rgba[:3] *= pixels[:, :3].mean(axis=0) / 255.0
    return rgba


def geoms_and_poses(log: dict[str, Any], t: np.ndarray) -> dict[str, Any]:
    """The drawn geoms (static description), meshes, and per-frame poses of the bodies
    that carry them (the log's qpos at ``t`` replayed through the MJCF)."""
    import mujoco

    from birdsim.mujoco.model import build_model

    m = build_model(str(log["model"]), reduced_bird(log_bird(log)))
    d = mujoco.MjData(m)
    qpos = _interp(np.asarray(log["t"], dtype=float), log["qpos"], t)
    for sl in _quaternion_slices(m):
        qpos[:, sl] /= np.linalg.norm(qpos[:, sl], axis=1, keepdims=True)
    geoms, meshes, used = [], {}, []
    for g in range(m.ngeom):
        if int(m.geom_group[g]) not in DRAWN_GROUPS:
            continue
        gtype = int(m.geom_type[g])
        body = int(m.geom_bodyid[g])
        mat = int(m.geom_matid[g])
        rgba = _material_rgba(m, mat) if mat >= 0 else m.geom_rgba[g]
        entry = {
            "name": m.geom(g).name,
            "body": body,
            "size": _round(m.geom_size[g]),
            "pos": _round(m.geom_pos[g]),
            "quat": _round(m.geom_quat[g]),
            "rgba": _round(rgba),
        }
        if gtype == int(mujoco.mjtGeom.mjGEOM_MESH):
            mid = int(m.geom_dataid[g])
            if mid not in meshes:
                v0, nv = int(m.mesh_vertadr[mid]), int(m.mesh_vertnum[mid])
                f0, nf = int(m.mesh_faceadr[mid]), int(m.mesh_facenum[mid])
                meshes[mid] = {
                    "vert": _round(m.mesh_vert[v0 : v0 + nv]),
                    "face": m.mesh_face[f0 : f0 + nf].ravel().astype(int).tolist(),
                }
            entry.update(type="mesh", mesh=mid)
        elif gtype in _GEOM_TYPES:
            entry["type"] = _GEOM_TYPES[gtype]
        else:
            continue
        geoms.append(entry)
        used.append(body)
    bodies = sorted(set(used))
    pos = np.zeros((t.size, len(bodies), 3))
    quat = np.zeros((t.size, len(bodies), 4))
    for k in range(t.size):
        d.qpos[:] = qpos[k]
        mujoco.mj_kinematics(m, d)
        pos[k] = d.xpos[bodies]
        quat[k] = d.xquat[bodies]
    poses = {}
    for i, b in enumerate(bodies):
        moving = np.ptp(pos[:, i], axis=0).max() > 1e-9 or np.ptp(quat[:, i], axis=0).max() > 1e-9
        sel = slice(None) if moving else slice(0, 1)
        poses[str(b)] = {
            "name": m.body(b).name,
            "pos": _round(pos[sel, i]),
            "quat": _round(quat[sel, i]),
            "frames": t.size if moving else 1,
        }
    return {"geoms": geoms, "meshes": {str(k): v for k, v in meshes.items()}, "bodies": poses}


def _series(log: dict[str, Any], t: np.ndarray) -> dict[str, list]:
    """The plotted series at the frames (the bird's units; forces as logged)."""
    t_log = np.asarray(log["t"], dtype=float)
    out: dict[str, list] = {}
    ex = np.asarray(log["x"], float) - np.asarray(log["x_ref"], float)
    ez = np.asarray(log["z"], float) - np.asarray(log["z_ref"], float)
    out["error_x"], out["error_z"] = _round(_interp(t_log, ex, t)), _round(_interp(t_log, ez, t))
    keys = ["Fx_demand", "Fz_demand", "force_x", "force_z", "power", "V_air", "pitch"]
    keys += [k for k in ("roll", "yaw") if k in log]
    names = [str(n) for n in np.asarray(log["param_names"]).tolist()]
    for k in keys + [n for n in names if n in log]:
        if k in log:
            out[k] = _round(_interp(t_log, log[k], t))
    sat = np.asarray(log["saturated"], dtype=bool)
    idx = np.clip(np.searchsorted(t_log, t, side="right") - 1, 0, t_log.size - 1)
    out["saturated"] = sat[idx].astype(int).tolist()
    return out


def flight_scene(
    log: dict[str, Any], options: ViewOptions | None = None, *, title: str = ""
) -> dict:
    """The viewer's scene of a flight log (:func:`birdsim.flight.flightlog.load_log` or
    ``log_arrays``): JSON-ready dict, format :data:`SCENE_FORMAT` (docs/studio.md).

    Raises:
        BirdsimError: a log of fewer than two samples.
    """
    options = options or ViewOptions()
    bird = log_bird(log)
    sc = scales(bird)
    t = frame_times(log, options)
    t_log = np.asarray(log["t"], dtype=float)
    track_pos, track_quat = body_track(log)
    ref = np.column_stack(
        [
            np.asarray(log["x_ref"], float) / sc.length,
            np.zeros(t_log.size),
            np.asarray(log["z_ref"], float) / sc.length,
        ]
    )
    step = max(1, t_log.size // 2000)  # the path as a line of at most ~2000 points
    names = [str(n) for n in np.asarray(log["param_names"]).tolist()]
    si = is_si(bird)
    return {
        "format": SCENE_FORMAT,
        "version": SCENE_VERSION,
        "title": title or str(log.get("manoeuvre", "")) or "flight",
        "bird": bird.name,
        "model": str(log["model"]),
        "open_loop": bool(log.get("open_loop", False)),
        "attitude": "quat" if "quat" in log else "pitch",
        "units": {
            "length": "m" if si else "semispans",
            "time": "s" if si else "time units",
            "length_per_scene_unit": sc.length,
        },
        "time_base": time_base(bird),
        "duration": float(t[-1] - t[0]),
        "t": _round(t - t[0]),
        **geoms_and_poses(log, t),
        "track": {
            "pos": _round(_interp(t_log, track_pos, t)),
            "quat": _round(_interp(t_log, track_quat, t)),
        },
        "reference": _round(ref[::step]),
        "reference_t": _round(t_log[::step] - t[0]),
        "param_names": names,
        "series": _series(log, t),
    }


__all__ = [
    "SCENE_FORMAT",
    "SCENE_VERSION",
    "ViewOptions",
    "body_track",
    "flight_scene",
    "frame_times",
    "time_base",
]
