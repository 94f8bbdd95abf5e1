"""Landing on a perch with legs (issue 25): free flight down to the touchdown, then the
contact phase of :func:`birdsim.flight.legwork.touchdown` (docs/legs.md, "Legs,
contact, take-off and landing").

The path is the preset's approach, levelling off above the perch (the flare's start),
descending onto a steep glide at the measured touchdown speed
(:func:`~birdsim.flight.legwork.touchdown_speed`, 1 m/s for the pigeon, at
:data:`TOUCHDOWN_GLIDE` below the horizontal) and ending at the touchdown point moving
at that velocity: where the torso is when its legs, at standing length and leaning
forward (:data:`LEAN`), touch the perch at the flight's final pitch.  ``fly`` flies it
with the legs tucked, then reaching out (prescribed in flight like the wings,
:func:`reach_motion`), on past the path's end; the flight is cut at the last logged
sample before a foot touches (:func:`_handover`) and the contact phase starts from that
state: the wings stop where they are (their velocity set to zero, the whole bird
keeping its momentum) and fold back to their rest pose (:func:`~birdsim.flight.contact.rest_wings`: folded for m5) over
a wingbeat, the legs brake the body within a few hundredths of a semispan, and the hips
balance it and lower it to the standing pitch.  The flight is flown again (at most
:data:`PASSES` times) until the pitch, the feet's aim and the arrival speed agree with
the touchdown pose (the posed controller overshoots the steep descent).
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import mujoco
import numpy as np

from birdsim.flight.contact import STEPS_PER_BEAT, ContactBird, rest_wings
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

TWO_PI = 2.0 * math.pi
#: Wingbeats of the contact phase after the touchdown.
STAND_BEATS = 18.0
#: The hips lower the body to the standing pitch over this long after the braking
#: (wingbeats; over 5 the torso moved at 0.002-0.004 omega s, above 1 % of the
#: perch-to-perch cruise speed 0.2, for 5 wingbeats)
LOWER_BEATS = 16.0
#: The legs reach out from tucked over REACH_BEATS (wingbeats), done REACH_LEAD before the
#: planned touchdown (the flight may arrive a little early).
REACH_BEATS = 0.5
REACH_LEAD = 0.5
#: Passes of the flight: the touchdown pose for the pitch arrived at, the touchdown point
#: moved by the feet's miss (accepted under X_TOL semispans), the path's touchdown speed
#: scaled by (measured / target arrival speed)^-SPEED_STEP (accepted within SPEED_TOL):
#: the posed controller overshoots the descent it is asked for by up to 35 %
PASSES = 6
X_TOL = 0.005
SPEED_TOL = 0.05
SPEED_STEP = 0.7
#: The flight goes on past the path's end (along its end tangent, through the touchdown
#: point) for this long at most (wingbeats): the feet touch when the bird gets there.
OVERRUN_BEATS = 1.0
#: The touchdown velocity's angle below the horizontal (rad): its horizontal part 0.016
#: omega s (the bird arrives at 0.017-0.023), under the 0.02-0.05 at which the feet slid
#: off the bar's front in the flare tried before (docs/legs.md, "A flare onto the feet").
TOUCHDOWN_GLIDE = math.radians(75.0)
#: The flare and the glide: the approach levels off FLARE_BEATS + GLIDE_BEATS before the
#: touchdown, descends onto a glide at the touchdown velocity over FLARE_BEATS (a quintic
#: from level: at most about half a g downwards, the wings carrying the rest) and glides
#: GLIDE_BEATS onto the touchdown point (1.2 semispans of descent, 0.39 m for the pigeon).
FLARE_BEATS = 3.5
GLIDE_BEATS = 1.5
#: The approach's keyframes closer than this to the flare (wingbeats) are left out.
APPROACH_GAP = 2.0
#: The legs lean forward at the touchdown, the feet ahead of the centre of mass by this
#: fraction of the leg (the lean's sine): their braking force then stops the forward speed
#: too.  On a bar (seed bird, landing preset): 0.05-0.1 the bird pitched forward off the
#: bar, 0.15-0.2 it stood, 0.3 its feet slid off the front.
LEAN = 0.2
#: On the ground (flat: friction stops the forward speed): leaning 0.2, the centre of mass
#: came to rest 0.04 behind the feet and crept back for 2.4 wingbeats; upright, the
#: pigeon bounced.
LEAN_GROUND = 0.1
#: On a bar the feet are aimed at the point whose normal leans back by AIM times the legs'
#: lean (the back slope: the legs' push on the feet has less to slide along); 0 and 1
#: each lost one of the four perch landings (seed and pigeon, preset and perch-to-perch).
AIM = 0.5
#: Once the legs have braked, they stretch to standing over this long (wingbeats): over
#: 0.5 the rise threw the body up and unloaded the grip; over 1.0 and more the bird was
#: still rising 2 wingbeats after the touchdown.
STAND_UP_BEATS = 0.75


def touchdown_velocity() -> tuple[float, float]:
    """The path's velocity at the touchdown (vx forward, vz up; omega s): the measured
    touchdown speed (:func:`~birdsim.flight.legwork.touchdown_speed`) at
    :data:`TOUCHDOWN_GLIDE` below the horizontal."""
    v = touchdown_speed()
    return v * math.cos(TOUCHDOWN_GLIDE), -v * math.sin(TOUCHDOWN_GLIDE)


def touchdown_pose(
    model: str, bird: Bird, pitch: float, surface: np.ndarray = PERCH_TOP
) -> tuple[float, float]:
    """Torso x and height (semispans) when the soles touch ``surface`` (the perch top
    by default) at ``pitch`` with the legs vertical (the hips sit ahead of the torso
    origin at a pitched body)."""
    with ContactBird(model, bird) as cb:
        cb.place_standing(surface, pitch)
        return float(cb.d.qpos[0]), float(cb.d.qpos[2])


def reach_motion(
    model: str, bird: Bird, end_beats: float, pitch: float, lead: float = 0.0
) -> LegMotion:
    """The legs' reach in flight: from tucked to standing length, the hips to put the
    feet under the centre of mass at ``pitch`` (:meth:`ContactBird.hip_for`), over the
    last REACH_BEATS before ``end_beats`` (a cosine blend: at rest at both ends)."""
    with ContactBird(model, bird) as cb:
        reach = cb.geom.length - cb.geom.foot_radius
        q = cb.muscle.q_stand
        hip = cb.hip_for(pitch) - math.asin(max(-1.0, min(1.0, lead / reach)))
    dur = REACH_BEATS * TWO_PI
    return LegMotion(end_beats * TWO_PI - dur, dur, 0.0, q, 0.0, hip)


def landing_path(
    preset: FlightPath,
    z_td: float,
    x_td: float = PERCH_X,
    *,
    flare_beats: float = FLARE_BEATS,
    glide_beats: float = GLIDE_BEATS,
    speed_scale: float = 1.0,
) -> FlightPath:
    """The preset's approach ending at the touchdown point ``(x_td, z_td)`` moving at the
    touchdown velocity (:func:`touchdown_velocity`): the approach's keyframes before the
    flare (from its highest on no lower than the flare), a level keyframe where the
    flare begins, ``flare_beats + glide_beats`` before the end, one where the descent
    has reached the touchdown velocity, ``glide_beats`` before the end, and the
    touchdown (module docstring); ``speed_scale`` scales the touchdown velocity (the
    flight's arrival calibrated to the measured speed: :func:`land`)."""
    end = preset.keyframes[-1]
    low = rest_supports(preset)[1] == "ground"
    vx_td, vz_td = (speed_scale * v for v in touchdown_velocity())
    t_glide = end.t - glide_beats
    t_flare = t_glide - flare_beats
    z_glide = z_td - vz_td * glide_beats * TWO_PI
    # a quintic from level to the glide's rate, at most about half a g (docs/legs.md)
    z_flare = z_glide - 0.5 * vz_td * flare_beats * TWO_PI
    before = [k for k in preset.keyframes[:-1] if k.t < t_flare - APPROACH_GAP]
    top = int(np.argmax([k.z for k in before])) if before else 0
    keys = [k if i < top else replace(k, z=max(k.z, z_flare)) for i, k in enumerate(before)]
    tail = (
        (t_flare, z_flare, None, "flare"),
        (t_glide, z_glide, vz_td, ""),
        (end.t, z_td, vz_td, "touchdown"),
    )
    if preset.form == "position":
        # at the touchdown's horizontal speed over the flare and glide
        x0 = x_td - vx_td * (end.t - t_flare) * TWO_PI
        if keys and keys[-1].x is not None and keys[-1].x > x0:
            raise ValueError("the approach's last keyframe is beyond the flare's start")
        for t, z, vz, label in tail:
            x = x_td - vx_td * (end.t - t) * TWO_PI
            keys.append(PathKeyframe(t, z, x=x, vx=vx_td, vz=vz, y=end.y, regime=label))
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
    for t, z, vz, label in tail:
        keys.append(PathKeyframe(t, z, V=vx_td, vz=vz, regime=label))
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


def _bar_reach(path: FlightPath, cb: ContactBird) -> float:
    """The feet's centres' distance from the axis of the bar ``path`` ends on (0 on the
    ground)."""
    support = rest_supports(path)[1] or ""
    if not support.startswith("perch"):
        return 0.0
    return path.scene.perches[int(support.split()[1]) - 1].radius + cb.geom.foot_radius


def _handover(cb: ContactBird, qpos: np.ndarray, after: np.ndarray) -> tuple[int, float]:
    """The flight's last logged sample before a foot touches anything (among the samples
    where ``after``; the last sample if none touches) and the feet's mean x there."""
    m, d = cb.m, cb.d
    feet = set(int(f) for f in cb.feet)
    last = len(qpos) - 1
    for j in np.nonzero(after)[0]:
        d.qpos[:] = qpos[j]
        mujoco.mj_fwdPosition(m, d)
        if any(
            (d.contact[k].geom1 in feet or d.contact[k].geom2 in feet) and d.contact[k].dist < 0.0
            for k in range(d.ncon)
        ):
            last = max(int(j) - 1, 0)
            break
    d.qpos[:] = qpos[last]
    mujoco.mj_kinematics(m, d)
    return last, float(d.geom_xpos[cb.feet, 0].mean())


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
    pitch_end = math.radians(78.0)
    surface = rest_surface(preset, -1)
    probe = ContactBird(model, bird, perches=preset.scene)  # kinematics only (not entered)
    leg = probe.geom.length - probe.geom.foot_radius
    # the feet ahead of the centre of mass by ``lean`` of the leg, aimed at the point of
    # the bar whose normal lies along the leaning legs (on the ground: the target)
    bar = _bar_reach(preset, probe)
    lean = LEAN if bar > 0.0 else LEAN_GROUND
    aim = float(surface[0]) - AIM * bar * lean
    shift = aim - float(surface[0]) - lean * leg  # the torso's x from the legs-vertical pose
    scale = 1.0  # the touchdown velocity's: calibrates the flight's arrival speed
    best = None
    for _ in range(PASSES):  # the touchdown pose depends on the pitch and x arrived at
        x_td, z_td = touchdown_pose(model, bird, pitch_end, surface)
        path = landing_path(preset, z_td, x_td + shift, speed_scale=scale)
        reach = reach_motion(model, bird, path.duration_beats - REACH_LEAD, pitch_end, lean * leg)
        motion = reach if tuck is None else LegPlan((tuck, reach))
        cfg = replace(config, legs=True, leg_motion=motion)
        beats = path.duration_beats + OVERRUN_BEATS
        result = fly(path, table, bird, model, config=cfg, progress=progress, beats=beats)
        a = result.arrays
        t_beats = a["t"] / TWO_PI
        i, feet_x = _handover(probe, a["qpos"], t_beats >= path.keyframes[-3].t)
        dx = feet_x - aim
        probe.d.qvel[:] = a["qvel"][i]
        arrival = float(np.linalg.norm(probe.com()[1])) / v_td
        miss = max(
            abs(float(a["pitch"][i]) - pitch_end) / math.radians(1.0),
            abs(dx) / X_TOL,
            abs(arrival - 1.0) / SPEED_TOL,
        )
        if miss < 1.0:
            break
        # none agreed: the contact phase starts from the best pass, unsaturated first
        # (the free pigeon's flight saturates or not from one pass to the next)
        key = (bool(np.any(a["saturated"])), miss)
        if best is None or key < best[0]:
            best = (key, result, i, dx, z_td)
        pitch_end = float(a["pitch"][i])
        shift -= dx
        scale /= arrival**SPEED_STEP
    else:
        _, result, i, dx, z_td = best
        a = result.arrays
        t_beats = a["t"] / TWO_PI
    every = max(1, 128 // config.log_per_beat)
    with ContactBird(model, bird, perches=preset.scene) as cb:
        q = a["qpos"][i].copy()  # the legs reached out in flight (reach_motion)
        # the wings stop at this instant's pose of the flown wingbeat (posed: the logged
        # one exactly), then fold back once the feet touch
        params = np.array([a[n][i] for n in result.param_names])
        sched = WingbeatSchedule(cb.m, cb.kin, cb.red, params, smoothing=TWO_PI)
        stopped = first_pose(sched, params, float(a["t"][i]))
        pose = wing_arrays(cb.m, stopped)[0][0]
        pq = cb._pres_qpos()
        q[pq] = pose[pq]
        cb.hold_qpos = q.copy()
        cb.hip_ref = float(np.mean(q[cb.hip_q]))  # as the legs reached (a lead)
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
            fold=(stopped, rest_wings(model)),
            balance=True,
            stand_beats=STAND_UP_BEATS,
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
        "touchdown_velocity": [float(v_com[0]), float(v_com[2])],
        "touchdown_velocity_path": list(touchdown_velocity()),
        "feet_miss_at_handover": dx,
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
