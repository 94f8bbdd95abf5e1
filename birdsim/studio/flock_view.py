"""A flock's log (``birdsim fly FLOCK --out``) as the 3-D viewer's scene: the leader's
(bird 0) one-bird scene (:func:`birdsim.studio.scene.flight_scene`: its track, reference
path and plots), and every other bird's dressed geoms once more, on its own bodies
(keys ``"i:body"``) posed by replaying ITS log's ``qpos`` at the same frames; the world
(the arena's static geoms) is drawn once. ``flock`` tells the page the birds, the
flock's centre per frame and the camera distance that frames the whole flock."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.physics.units import scales
from birdsim.studio.scene import (
    ViewOptions,
    _round,
    body_track,
    flight_scene,
    frame_times,
    geoms_and_poses,
    log_bird,
)

#: A flock's page may be larger than one bird's (every bird's poses per frame).
MAX_FLOCK_VIEW_BYTES = 20_000_000
#: The follow cameras' distance for one bird [semispans] (web/src/viewer.js).
ONE_BIRD_DISTANCE = 4.5
#: The vertical field of view of the page's camera [degrees] (web/src/viewer.js).
FOVY_DEG = 45.0
#: The fraction of the view's height the flock's diameter (plus a wingspan) takes.
FLOCK_FRACTION = 1.0


def camera_distance(radius: float) -> float:
    """The follow cameras' distance parameter D [semispans] so that a flock of ``radius``
    (centre to farthest torso) and a wingspan fills :data:`FLOCK_FRACTION` of the view
    (the follow offset is about 1.14 D, web/src/viewer.js); never nearer than one bird's."""
    height = (2.0 * radius + 2.0) / FLOCK_FRACTION
    dist = height / (2.0 * math.tan(math.radians(FOVY_DEG) / 2.0))
    return max(ONE_BIRD_DISTANCE, dist / 1.14)


def flock_scene(
    birds: list[dict[str, Any]], options: ViewOptions | None = None, *, title: str = ""
) -> dict:
    """The viewer's scene of a flock: ``birds`` each bird's own log
    (:func:`birdsim.flight.flock_log.load_flock_log`), the leader first."""
    options = options or ViewOptions()
    lead = birds[0]
    scene = flight_scene(lead, options, title=title)
    t = frame_times(lead, options)
    keys = [sorted(scene["bodies"], key=int)]
    centre_parts = []
    for i, one in enumerate(birds):
        pos, _ = body_track(one)
        t_log = np.asarray(one["t"], dtype=float)
        centre_parts.append(np.column_stack([np.interp(t, t_log, pos[:, k]) for k in range(3)]))
        if i == 0:
            continue
        part = geoms_and_poses(one, t)
        moving = {b for b, p in part["bodies"].items() if p["frames"] > 1}
        mesh_key = {}
        for mid, mesh in part["meshes"].items():
            same = scene["meshes"].get(mid) == mesh
            mesh_key[mid] = mid if same else f"{i}:{mid}"
            if not same:
                scene["meshes"][mesh_key[mid]] = mesh
        for g in part["geoms"]:
            if str(g["body"]) not in moving:
                continue  # the arena: drawn once, with the leader's scene
            g = dict(g, body=f"{i}:{g['body']}")
            if "mesh" in g:
                g["mesh"] = mesh_key[str(g["mesh"])]
            scene["geoms"].append(g)
        mine = []
        for b in sorted(moving, key=int):
            p = part["bodies"][b]
            scene["bodies"][f"{i}:{b}"] = dict(p, name=f"bird{i}/{p['name']}")
            mine.append(f"{i}:{b}")
        keys.append(mine)
    torsos = np.stack(centre_parts)  # (birds, frames, 3) [semispans]
    centre = torsos.mean(axis=0)
    radius = float(np.max(np.linalg.norm(torsos - centre[None], axis=-1)))
    sc = scales(log_bird(lead))
    scene["n_birds"] = len(birds)
    scene["flock"] = {
        "n_birds": len(birds),
        "bodies": keys,
        "centre": _round(centre),
        "radius": round(radius, 4),
        "radius_length_units": round(radius * sc.length, 4),
        "camera_distance": round(camera_distance(radius), 4),
    }
    return scene


__all__ = ["MAX_FLOCK_VIEW_BYTES", "camera_distance", "flock_scene"]
