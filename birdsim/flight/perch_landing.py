"""Landing on a perch with legs (issue 25): free flight down to the touchdown, then the
contact phase of :func:`birdsim.flight.legwork.touchdown` (docs/legs.md, "Legs,
contact, take-off and landing").

The path is the preset's (approach and flare) ending in a hover over the perch at the
height from which a fall reaches the measured touchdown speed
(:func:`~birdsim.flight.legwork.touchdown_speed`: ``v^2 / 2 g`` above the touchdown
height, 0.15 semispans, 5 cm for the pigeon).  The touchdown height and point are where
the torso is when its legs, vertical and at their standing length, reach the perch at
the flight's final pitch.  ``fly`` flies it with the legs tucked; at its end the
contact phase starts from that state: the legs have reached out to standing length
under the centre of mass over the hover's last half wingbeat (prescribed in flight like
the wings, :func:`reach_motion`), the wings stop where they are (their velocity
set to zero; they fold back to :data:`~birdsim.flight.contact.REST_WINGS` over a
wingbeat from the touchdown), the bird drops onto the perch, the legs brake it and the hips lower it
to the standing pitch.  (A path that flies the descent down to the touchdown speed
saturated the table in its last two wingbeats and arrived 0.1 semispan high.)
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np

from birdsim.flight.contact import REST_WINGS, STEPS_PER_BEAT, ContactBird
from birdsim.flight.freeflight import FlightResult, fly
from birdsim.flight.leg_motion import LegMotion, LegPlan
from birdsim.flight.legwork import touchdown, touchdown_speed
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.flight.path_checks import PERCH_X, rest_supports
from birdsim.flight.perched import (
    PERCH_TOP,
    STAND_PITCH,
    _contact_rows,
    _join,
    first_pose,
    rest_surface,
)
from birdsim.flight.simulate import SimConfig
from birdsim.flight.wingbeat import WingbeatSchedule
from birdsim.mujoco.driver import wing_arrays
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird

TWO_PI = 2.0 * math.pi
#: Wingbeats of the contact phase after the touchdown.
STAND_BEATS = 18.0
#: The hips lower the body to the standing pitch over this long after the braking
#: (wingbeats; over 5 the torso moved at 0.002-0.004 omega s, above 1 % of the
#: perch-to-perch cruise speed 0.2, for 5 wingbeats)
LOWER_BEATS = 16.0
#: The legs reach out from tucked over the hover's last REACH_BEATS (wingbeats).
REACH_BEATS = 0.5


def touchdown_pose(
    model: str, bird: Bird, pitch: float, surface: np.ndarray = PERCH_TOP
) -> tuple[float, float]:
    """Torso x and height (semispans) when the soles touch ``surface`` (the perch top
    by default) at ``pitch`` with the legs vertical (the hips sit ahead of the torso
    origin at a pitched body)."""
    with ContactBird(model, bird) as cb:
        cb.place_standing(surface, pitch)
        return float(cb.d.qpos[0]), float(cb.d.qpos[2])


def reach_motion(model: str, bird: Bird, end_beats: float, pitch: float) -> LegMotion:
    """The legs' reach in flight: from tucked to standing length, the hips to put the
    feet under the centre of mass at ``pitch`` (:meth:`ContactBird.hip_for`), over the
    last REACH_BEATS before ``end_beats`` (a cosine blend: at rest at both ends)."""
    with ContactBird(model, bird) as cb:
        q, hip = cb.muscle.q_stand, cb.hip_for(pitch)
    dur = REACH_BEATS * TWO_PI
    return LegMotion(end_beats * TWO_PI - dur, dur, 0.0, q, 0.0, hip)


def landing_path(preset: FlightPath, z_hover: float, x_td: float = PERCH_X) -> FlightPath:
    """The preset's landing ending in a hover at ``z_hover`` over the touchdown point
    (module docstring); the approach from its highest keyframe on no lower than the
    hover."""
    end = preset.keyframes[-1]
    low = rest_supports(preset)[1] == "ground"
    # the approach from its highest keyframe on no lower than the hover
    top = int(np.argmax([k.z for k in preset.keyframes[:-1]])) if len(preset.keyframes) > 1 else 0
    keys = [
        k if i < top else replace(k, z=max(k.z, z_hover))
        for i, k in enumerate(preset.keyframes[:-1])
    ]
    if preset.form == "position":
        keys.append(PathKeyframe(end.t, z_hover, x=x_td, vx=0.0, y=end.y, vy=0.0, regime="hover"))
        return FlightPath(
            preset.name,
            end.t,
            False,
            False,
            tuple(keys),
            preset.description,
            scene=preset.scene,
            low_end=low,
        )
    keys.append(PathKeyframe(end.t, z_hover, V=0.0, regime="hover"))
    draft = FlightPath(
        preset.name, end.t, False, False, tuple(keys), scene=preset.scene, low_end=low
    )
    x_end = float(draft.state(end.t * TWO_PI).x)
    return FlightPath(
        preset.name,
        end.t,
        False,
        False,
        tuple(keys),
        preset.description,
        x0=x_td - x_end,
        scene=preset.scene,
        low_end=low,
    )


def land(
    preset: FlightPath,
    table: Any,
    bird: Bird,
    model: str,
    *,
    config: SimConfig = SimConfig(),
    progress: Any = None,
    tuck: LegMotion | None = None,
) -> FlightResult:
    """Fly ``preset`` (a path ending at rest on the perch) down to the touchdown and
    stand: the joined log with ``foot_force``, ``on_perch``, ``phase``; figures in
    ``meta["legs"]``.  ``tuck``: the legs' motion at the path's start (a take-off's)."""
    v_td = touchdown_speed()
    drop = v_td**2 / (2.0 * reduced_bird(bird).gravity)
    pitch_end = math.radians(78.0)
    surface = rest_surface(preset, -1)
    for _ in range(2):  # the touchdown pose depends on the pitch the flight ends at
        x_td, z_td = touchdown_pose(model, bird, pitch_end, surface)
        path = landing_path(preset, z_td + drop, x_td)
        reach = reach_motion(model, bird, path.duration_beats, pitch_end)
        motion = reach if tuck is None else LegPlan((tuck, reach))
        cfg = replace(config, legs=True, leg_motion=motion)
        result = fly(path, table, bird, model, config=cfg, progress=progress)
        a = result.arrays
        t_beats = a["t"] / TWO_PI
        i = len(a["t"]) - 1
        if abs(float(a["pitch"][i]) - pitch_end) < math.radians(1.0):
            break
        pitch_end = float(a["pitch"][i])
    every = max(1, 128 // config.log_per_beat)
    with ContactBird(model, bird, perches=preset.scene) as cb:
        q = a["qpos"][i].copy()  # the legs reached out in flight (reach_motion)
        pitch = float(a["pitch"][i])
        # the wings stop at this instant's pose of the flown wingbeat (posed: the logged
        # one exactly), then fold back once the feet touch
        params = np.array([a[n][i] for n in result.param_names])
        sched = WingbeatSchedule(cb.m, cb.kin, cb.red, params, smoothing=TWO_PI)
        stopped = first_pose(sched, params, float(a["t"][i]))
        pose = wing_arrays(cb.m, stopped)[0][0]
        pq = cb._pres_qpos()
        q[pq] = pose[pq]
        cb.hold_qpos = q.copy()
        cb.hip_ref = cb.hip_for(pitch)
        cb.d.qpos[:] = q
        # the wings stop (internal forces: the whole bird keeps its linear momentum), the
        # body's rotation with them
        cb.d.qvel[:] = a["qvel"][i]
        cb.d.qvel[cb.legs] = 0.0
        cb.d.qvel[cb.hips] = 0.0
        v_com = cb.com()[1]
        cb.d.qvel[:] = 0.0
        cb.d.qvel[:3] = v_com
        cb.time = float(a["t"][i])
        td = touchdown(
            cb,
            surface,
            None,
            STAND_BEATS,
            pitch_to=STAND_PITCH,
            rise_beats=LOWER_BEATS,
            fold=(stopped, REST_WINGS),
            balance=config.attitude == "free",
        )
        rows = _contact_rows(td.record, cb, np.array([a[n][i] for n in result.param_names]), every)
    flight = {k: np.asarray(v)[: i + 1] for k, v in a.items()}
    n = len(flight["t"])
    flight["foot_force"] = np.zeros(n)
    flight["on_perch"] = np.zeros(n, dtype=bool)
    flight["phase"] = np.array(["flight"] * n)
    joined = _join(flight, rows, 0.0)
    e = np.hypot(flight["x"] - flight["x_ref"], flight["z"] - flight["z_ref"])
    skip = t_beats[: i + 1] >= 2.0
    meta = dict(result.meta)
    # at rest against the approach's speed: the path's fastest (the landing preset's
    # cruise, 0.5; a take-off's flight into a landing, its cruise between the perches)
    v_app = float(
        np.max(
            np.hypot(
                flight["x_ref"][1:] - flight["x_ref"][:-1],
                flight["z_ref"][1:] - flight["z_ref"][:-1],
            )
            / np.diff(flight["t"])
        )
    )
    # the whole bird's centre of mass, every step from the first contact (the torso's
    # origin also swings about the hips as they lower the body: 0.002-0.003 omega s)
    first = int(np.argmax(td.record["foot_normal"] > 0.0))
    sp = td.record["com_speed"][first:]
    above = np.nonzero(sp >= 0.01 * v_app)[0]
    per_beat = STEPS_PER_BEAT
    meta["legs"] = {
        "approach_speed": v_app,
        "rest_beats_vs_approach": (above[-1] + 1 if len(above) else 0) / per_beat,
        "touchdown_beats": float(t_beats[i]),
        "touchdown_speed": td.touchdown_speed,
        "touchdown_speed_target": v_td,
        "peak_foot_force_over_weight": td.peak_foot_over_weight,
        "rest_beats": td.rest_beats,
        "final_offset": [float(v) for v in td.final_offset],
        "weight_carried": td.weight_carried,
        "rms_error_to_touchdown": float(np.sqrt(np.mean(e[skip] ** 2))),
        "touchdown_height": z_td,
        "touchdown_pitch_deg": math.degrees(float(a["pitch"][i])),
        "root_applied_max_contact": td.root_applied_max,
    }
    return replace(result, arrays=joined, bird=bird, meta=meta)


__all__ = ["land", "landing_path", "touchdown_pose"]
