"""Take-off from and landing on a perch with legs (issue 25): the contact phases of
:mod:`birdsim.flight.legwork` joined to free flight (:func:`birdsim.flight.freeflight.fly`).

Take-off: the bird stands on the perch at :data:`STAND_PITCH` with its wings folded
back (:func:`~birdsim.flight.contact.rest_wings`: folded for m5), its hips raise the body to the pitch
of the first wingbeat, it crouches while its wings open to that wingbeat's first pose,
and jumps (:class:`~birdsim.flight.legwork.JumpProfile`).  At lift-off
(the feet's normal force zero) the flight takes over: a path from the lift-off state
(torso position, the centre of mass's velocity as the path's slope) through a keyframe
at the top of the jump's climb (:func:`liftoff_path`) into the preset's later keyframes,
flown by ``fly`` with the legs tucked.

Hand-over (a limitation, documented in docs/legs.md): ``fly`` starts a new MuJoCo
state from the lift-off state -- its trim moves the start by its probe wingbeat's mean
error (logged as ``handover_shift``), and the wings start beating at the first
wingbeat's phase from rest.  The legs tuck in flight over TUCK_BEATS from their
lift-off pose (a cosine blend, prescribed like the wings: no step).
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np

from birdsim.flight.attitude import INPUTS
from birdsim.flight.contact import STEPS_PER_BEAT, ContactBird, rest_wings
from birdsim.flight.controller import Controller, gains_for
from birdsim.flight.flight_arrays import flight_arrays
from birdsim.flight.freeflight import FlightResult, fly
from birdsim.flight.leg_motion import LegMotion
from birdsim.flight.legwork import PHASES, JumpProfile, jump
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.flight.path_checks import PERCH_X, PERCH_Y, rest_supports
from birdsim.flight.simulate import SimConfig
from birdsim.flight.wingbeat import WingbeatSchedule
from birdsim.mujoco.driver import wing_arrays
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird

TWO_PI = 2.0 * math.pi
#: Body pitch of a standing bird (rad, nose up): 20 degrees, a drawing choice.
STAND_PITCH = math.radians(20.0)
#: The arena's perch bar top (semispans): axis at 1.5, radius 0.04 (birdsim.mujoco.arena).
PERCH_TOP = np.array([PERCH_X, PERCH_Y, 1.54])
#: The take-off path rejoins the preset's keyframes from this wingbeat on.
#: Deceleration of the jump's climb on the path after lift-off, in g.
CLIMB_DECELERATION = 0.1
#: The legs tuck over this long after lift-off (wingbeats).
TUCK_BEATS = 0.5


def rest_surface(path: FlightPath, end: int) -> np.ndarray:
    """The world point under the feet (semispans) where ``path`` rests at its start
    (``end`` 0) or its end (``end`` -1): the top of its perch, or the ground under it."""
    support = rest_supports(path)[0 if end == 0 else 1]
    if support is None:
        raise ValueError(
            f"path {path.name!r} does not rest at its {'start' if end == 0 else 'end'}"
        )
    st = path.state(path.keyframes[end].t * TWO_PI)
    return np.array(path.scene.surface(support, st.x, st.y))


def first_wingbeat(path: FlightPath, table: Any, red: Bird) -> tuple[np.ndarray, float]:
    """The table's wingbeat parameters and pitch for the path's first state (feed-forward,
    as ``fly`` starts)."""
    ctl = Controller(table, red, gains_for(red))
    names = ctl.names
    ref0 = path.state(0.0)
    cmd = ctl.command(ref0, None, np.zeros(2), 0.0)
    if "pitch" not in names:
        return cmd.params, 0.0
    cmd = ctl.command(ref0, None, np.zeros(2), float(cmd.params[names.index("pitch")]))
    return cmd.params, float(cmd.params[names.index("pitch")])


def first_pose(sched: WingbeatSchedule, params: np.ndarray, t: float = 0.0) -> dict:
    """The wings' core joint angles of the wingbeat ``params`` at reduced time ``t``."""
    z = np.zeros((1, len(params)))
    angles = sched._joints(np.array([t]), np.asarray(params)[None, :], z, z)[0]
    return {k: float(np.asarray(v).reshape(-1)[0]) for k, v in angles.items()}


def liftoff_path(
    preset: FlightPath, position: np.ndarray, velocity: np.ndarray, gravity: float
) -> FlightPath:
    """The take-off path from the lift-off state: the climb rate of the jump brought to
    zero at :data:`CLIMB_DECELERATION` g (the wings keep carrying the weight: a path
    that stops the jump's climb faster asks the wings for less than the table's least
    lift, 280 saturated samples), then the preset's keyframes that lie later and
    higher."""
    vz = max(float(velocity[2]), 0.0)
    rise = vz**2 / (2.0 * CLIMB_DECELERATION * gravity)
    t_apex = 2.0 * rise / vz / TWO_PI if vz > 0 else 1.0
    z_apex = float(position[2]) + rise
    # the preset's keyframes from the first one later and higher than the apex on
    ks = preset.keyframes
    j = next((i for i, k in enumerate(ks) if k.t > t_apex and k.z > z_apex), len(ks))
    later = ks[j:] if j < len(ks) else ks[-1:] if preset.perch_end else ()
    s1 = preset.state(t_apex * TWO_PI)
    if preset.form == "position":  # the lift-off's x, then the preset's x at the apex
        x_apex = max(float(s1.x), float(position[0]))
        keys: tuple[PathKeyframe, ...] = (
            PathKeyframe(
                0.0,
                float(position[2]),
                x=float(position[0]),
                vx=float(velocity[0]),
                vz=vz,
                y=float(position[1]) if preset.is_3d else None,
                regime="lift-off",
            ),
            PathKeyframe(
                t_apex,
                z_apex,
                x=x_apex,
                y=float(s1.y) if preset.is_3d else None,
                regime="climb-out",
            ),
            *later,
        )
        return FlightPath(
            preset.name,
            preset.duration_beats,
            False,
            preset.perch_end,
            keys,
            preset.description,
            scene=preset.scene,
        )
    keys = (
        PathKeyframe(
            0.0, float(position[2]), V=max(float(velocity[0]), 0.0), vz=vz, regime="lift-off"
        ),
        PathKeyframe(t_apex, z_apex, V=float(math.hypot(s1.vx, s1.vy)), regime="climb-out"),
        *later,
    )
    return FlightPath(
        preset.name,
        preset.duration_beats,
        False,
        preset.perch_end,
        keys,
        preset.description,
        x0=float(position[0]),
        scene=preset.scene,
    )


def _contact_rows(rec: dict, cb: ContactBird, params: np.ndarray, every: int) -> dict:
    """The contact phase as ``flight_arrays`` rows (no path: the reference is where the
    bird is; no demands; the wings' parameters those of the held first wingbeat)."""
    idx = np.arange(0, len(rec["t"]), every)
    weight = np.array([0.0, 0.0, -cb.weight])
    records = [
        (
            rec["t"][i],
            rec["qpos"][i],
            rec["qvel"][i],
            np.zeros(3),
            rec["foot_force"][i] + weight,
            0.0,
            np.zeros(3),
        )
        for i in idx
    ]
    n = len(idx)
    q = rec["qpos"][idx]
    rows = {
        "Fx_demand": [0.0] * n,
        "Fz_demand": [0.0] * n,
        "climb_demand": [0.0] * n,
        "V_air": list(np.linalg.norm(rec["qvel"][idx, :3], axis=1)),
        "saturated": [False] * n,
        "x_ref": list(q[:, 0]),
        "y_ref": list(q[:, 1]),
        "z_ref": list(q[:, 2]),
        "params": [params] * n,
        "pitch_command": [cb.hip_ref] * n,
        "tail": [(0.0, 0.0, 0.0)] * n,
        "inputs": [np.zeros(len(INPUTS))] * n,
        "attitude_saturated": [False] * n,
    }
    arrays = flight_arrays(records, rows, tuple(cb.kin.param_names))
    arrays["foot_force"] = rec["foot_normal"][idx]
    arrays["on_perch"] = rec["on_feet"][idx].astype(bool)
    arrays["phase"] = np.array([PHASES[p] for p in rec["phase"][idx]])
    return arrays


def _join(first: dict, second: dict, t_shift: float) -> dict:
    out = {}
    for k, v in second.items():
        a = np.asarray(first[k]) if k in first else None
        b = np.asarray(v)
        if k == "t":
            b = b + t_shift
        if a is not None and a.dtype.kind != "U":
            b = b.astype(a.dtype, copy=False)
        out[k] = b if a is None else np.concatenate([a, b])
    return out


def take_off(
    preset: FlightPath,
    table: Any,
    bird: Bird,
    model: str,
    *,
    config: SimConfig = SimConfig(),
    profile: JumpProfile | None = None,
    progress: Any = None,
    trim: bool = False,
    land: Any = None,
) -> FlightResult:
    """Stand, jump and fly ``preset`` (a path starting at rest on a perch or the
    ground; one that also ends at rest lands there with ``land``, i.e.
    :func:`~birdsim.flight.perch_landing.land`, its figures in
    ``meta["legs"]["landing"]``): the joined log (reduced units) with ``foot_force``,
    ``on_perch``, ``phase``; figures in ``meta["legs"]``."""
    red = reduced_bird(bird)
    surface = rest_surface(preset, 0)
    params0, pitch0 = first_wingbeat(preset, table, red)
    every = STEPS_PER_BEAT // config.log_per_beat
    for _ in range(2):  # the path (and so its first pitch) depends on the lift-off state
        with ContactBird(model, bird, perches=preset.scene) as cb:
            sched = WingbeatSchedule(
                cb.m, cb.kin, cb.red, params0, smoothing=config.smoothing_beats * TWO_PI
            )
            first = first_pose(sched, params0)
            rest = rest_wings(model)
            cb.hold_qpos = wing_arrays(cb.m, rest)[0][0]  # standing: wings folded back
            cb.place_standing(surface, STAND_PITCH)
            jr = jump(
                cb,
                profile or JumpProfile(),
                after_beats=0.0,
                pitch_to=pitch0,
                unfold=(rest, first),
            )
            lo_pos = cb.d.qpos[:3].copy()
            # the legs tuck in flight from their lift-off pose (prescribed like the wings)
            tuck = LegMotion(
                0.0,
                TUCK_BEATS * TWO_PI,
                float(np.mean(cb.d.qpos[cb.leg_q])),
                0.0,
                float(np.mean(cb.d.qpos[cb.hip_q])),
                0.0,
            )
            rows = _contact_rows(jr.record, cb, params0, every)
        path = liftoff_path(preset, lo_pos, jr.liftoff_velocity, red.gravity)
        params1, pitch1 = first_wingbeat(path, table, red)
        if abs(pitch1 - pitch0) < 1e-3:
            break
        params0, pitch0 = params1, pitch1
    landing: dict | None = None
    if preset.perch_end:  # at rest at both ends: the flight ends in a touchdown
        if land is None:
            raise ValueError(f"path {preset.name!r} ends at rest: take_off needs land=")
        result = land(path, table, bird, model, config=config, progress=progress, tuck=tuck)
        flight = dict(result.arrays)
        landing = dict(result.meta.get("legs", {}))
    else:
        result = fly(
            path,
            table,
            bird,
            model,
            config=replace(config, legs=True, leg_motion=tuck),
            progress=progress,
            trim=trim,
        )
        flight = dict(result.arrays)
        n = len(flight["t"])
        flight["foot_force"] = np.zeros(n)
        flight["on_perch"] = np.zeros(n, dtype=bool)
        flight["phase"] = np.array(["flight"] * n)
    keep = rows["t"] < jr.liftoff_time - 1e-12
    rows = {k: v[keep] for k, v in rows.items()}
    joined = _join(rows, flight, jr.liftoff_time)
    fl = flight["phase"] == "flight"
    e = np.hypot(flight["x"] - flight["x_ref"], flight["z"] - flight["z_ref"])[fl]
    start = flight["qpos"][0, :3]
    meta = dict(result.meta)
    meta["legs"] = {
        "liftoff_beats": jr.liftoff_time / TWO_PI,
        "liftoff_velocity": [float(v) for v in jr.liftoff_velocity],
        "leg_share": jr.leg_share,
        "peak_foot_force_over_weight": jr.peak_foot_over_weight,
        "push_beats": jr.push_beats,
        "rms_error_from_liftoff": float(np.sqrt(np.mean(e**2))),
        "max_error_from_liftoff": float(np.max(e)),
        "handover_shift": float(np.linalg.norm(start - lo_pos)),
        "first_pitch_deg": math.degrees(pitch0),
        "root_applied_max_contact": jr.root_applied_max,
    }
    if landing is not None:
        meta["legs"]["landing"] = landing
    return replace(result, arrays=joined, bird=bird, meta=meta)


__all__ = [
    "PERCH_TOP",
    "STAND_PITCH",
    "first_wingbeat",
    "liftoff_path",
    "rest_surface",
    "take_off",
]
