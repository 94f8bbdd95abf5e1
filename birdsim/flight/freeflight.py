"""Fly a path (or an open-loop demand schedule) in MuJoCo: the loop that ties the
simulation (:mod:`birdsim.flight.simulate`), the controller
(:mod:`birdsim.flight.controller`) and the wingbeat schedule together.

Everything here is in REDUCED units (lengths in semispans, time in 1 / omega, one
wingbeat = 2 pi, velocities in semispan omega, table forces); :mod:`birdsim.flight.flightlog`
converts a result to the bird's own units.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError, limits_text, magnitude_ok
from birdsim.flight import flight_arrays as step_records
from birdsim.flight import turning
from birdsim.flight.air_angle import straight_air_angle
from birdsim.flight.attitude import FIT_BEATS
from birdsim.flight.attitude_commands import bank_command, command_filter, straight_commands
from birdsim.flight.controller import Controller, ErrorWindow, Gains, gains_for
from birdsim.flight.demand_schedule import DemandSchedule, RefState
from birdsim.flight.disturbed_gains import DisturbedGains
from birdsim.flight.fast_errors import air_speeds, straight_samples
from birdsim.flight.fast_interval import interval
from birdsim.flight.flight_arrays import attitude_estimate, extend_rows, flight_arrays, keep_last
from birdsim.flight.flight_result import FlightResult
from birdsim.flight.float_ops import clip_float
from birdsim.flight.flown_lateral import flown_lateral_for
from birdsim.flight.flown_pitch import flown_pitch_for
from birdsim.flight.gust import Gust, GustError, parse_gust, wind_at
from birdsim.flight.path_integral import (
    FREE_BIAS_MARGIN,
    INTEGRAL_LIMIT,
    integral_step,
    within_band,
)
from birdsim.flight.pitch_plan import PitchPlan, feedforward_pitch
from birdsim.flight.pitch_section import section_source
from birdsim.flight.simulate import C_SEED, FreeBird, SimConfig
from birdsim.flight.track import TrackFrame, is_three_d
from birdsim.flight.trim import sample_reference, trim_rotation, trim_start
from birdsim.flight.turning import TURN_PITCH_PLAN, attitude_loop_for, turn_command, turn_pitch
from birdsim.flight.wingbeat import INPUT_SMOOTHING_BEATS, WingbeatSchedule
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird, scales

TWO_PI = 2.0 * math.pi
#: Time constant (wingbeats) of the body's pitch command (attitude free, with a
#: stroke plane): the table's pitch smoothed; the stroke plane turns by the difference.
PITCH_COMMAND_BEATS = 3.0
#: How far (rad) the compensated stroke plane may leave the table's bounds (those bound
#: the optimiser's search, not the shoulder).
SP_MARGIN = 0.8
#: Wingbeats ahead the stroke plane's compensation predicts the body's pitch (the estimated
#: pitch rate times this): the lag of its two cascaded smoothing filters (docs/free-body.md).
SP_LEAD = 2.0 * INPUT_SMOOTHING_BEATS
#: The attitude loop's Jacobians and M_0 at the commanded pitch on a straight path (free-body.md).
JAC_AT_COMMAND = True
#: Plan the free body's pitch command along the known path (birdsim.flight.pitch_plan).
PITCH_PLAN = True
PLAN_PER_BEAT = 2
MAG_LEAD = 0.0  # (measured 0.5, 0.75 wingbeats: circle RMS 0.29, 0.32; kept 0)


def fly(
    reference: Any,
    table: Any,
    bird: Bird,
    model: str,
    *,
    beats: float | None = None,
    gusts: Sequence[Gust] = (),
    open_loop: bool = False,
    config: SimConfig = SimConfig(),
    gains: Gains | None = None,
    to_table: Any = None,
    aero: bool = True,
    gravity: bool = True,
    progress: Any = None,
    trim: bool = True,
    attitude_loop: bool = True,
    stroke_compensation: bool = True,
    control_hook: Any = None,
) -> FlightResult:
    """Fly ``reference`` (a FlightPath in reduced units, or a DemandSchedule) with
    ``table`` for ``beats`` wingbeats (default: the reference's duration).

    Args:
        bird: the bird in its own units (the simulation uses its reduced bird).
        gusts: winds in the bird's velocity units, times in wingbeats.
        open_loop: feed-forward only (no feedback).
        progress: optional callable(beats_done) for a progress bar.
        trim: start on the periodic orbit of the first wingbeat (see :func:`birdsim.flight.trim.trim_start`).
        control_hook: callable(k, t, fb) at every control update (a flock's lockstep).
    Returns:
        FlightResult with arrays t, x, y, z, vx, vz, x_ref, z_ref, pitch, <params>,
        Fx_demand, Fz_demand, climb_demand (the table's climb; 0 for a level table),
        V_air, saturated, pitch_moment, power, force_x, force_z, qpos, qvel (reduced units).
    Raises:
        BirdsimError: non-finite demands, a diverging simulation.
    """
    red = reduced_bird(bird)
    speed = scales(bird).speed
    beats = float(reference.duration_beats if beats is None else beats)
    if not (math.isfinite(beats) and beats > 0 and magnitude_ok(beats)):
        raise BirdsimError(
            f"beats={beats!r} is invalid; allowed: a positive finite number of wingbeats, {limits_text()}"
        )
    gains = gains or gains_for(red)
    demands_only = bool(getattr(reference, "open_loop_demands", False))
    no_table = (lambda *a, **k: (0.0, 0.0)) if demands_only else None
    ctl = Controller(
        table, red, gains, open_loop=open_loop or demands_only, to_table=to_table or no_table
    )
    names = ctl.names
    per_beat_ctl = config.control_per_beat
    steps_ctl = config.steps_per_beat // per_beat_ctl
    every = config.steps_per_beat // config.log_per_beat
    n_ctl = int(math.ceil(beats * per_beat_ctl - 1e-9))

    # a path with a side component: the path loop in its track frame, banked (turning)
    track = None
    if not demands_only and is_three_d(reference, beats * TWO_PI):
        if config.attitude != "free":
            raise BirdsimError(
                "a path with a side component (keyframe y) needs attitude='free' "
                "(--attitude free): a posed body cannot bank"
            )
        track = TrackFrame(reference, beats * TWO_PI, red.gravity)
    path = reference if track is None else track
    lateral_corr = [0.0]  # turning: the lateral loop's sideways acceleration (to the left)

    def command(t: float, est: Any, integral: np.ndarray, pitch: float) -> Any:
        w = wind_at(gusts, t / TWO_PI, speed)
        if demands_only:
            fx, fz, v = reference.demands(t)
            return ctl.lookup_table_force(fx, fz, v - float(w[0]))
        if track is None:
            return ctl.command_at(path, t, est, integral, pitch, (float(w[0]), float(w[2])))
        # turning: the force in the banked plane carries the weight, the path's vertical
        # acceleration and the commanded sideways one (the plan's and the lateral loop's)
        ts = track.state(t)
        ahead = track.state(t + MAG_LEAD * TWO_PI) if MAG_LEAD > 0 else ts
        a_left = ahead.a_lat + lateral_corr[0]
        az = math.hypot(ahead.az_up + red.gravity, a_left) - red.gravity
        w_along = track.wind_along(t, w)
        return ctl.command(replace(ts, az=az), est, integral, pitch, (w_along, float(w[2])))

    ref0 = path.state(0.0)
    pitch0 = 0.0
    cmd = command(0.0, None, np.zeros(2), pitch0)
    if "pitch" in names:
        cmd = command(0.0, None, np.zeros(2), float(cmd.params[names.index("pitch")]))
    window = ErrorWindow(config.log_per_beat, TWO_PI)
    per_sample = (
        *("Fx_demand", "Fz_demand", "climb_demand", "V_air", "saturated"),
        *("x_ref", "y_ref", "z_ref"),
    )
    rows: dict[str, list] = {
        k: []
        for k in (*per_sample, "params", "pitch_command", "tail", "inputs", "attitude_saturated")
    }
    if track is not None:  # the turn's commanded bank and heading (world, rad)
        rows["bank_command"], rows["heading_command"] = [], []
    record: list = []
    free = config.attitude == "free"
    with FreeBird(model, bird, cmd.params, config=config, aero=aero, gravity=gravity) as fb:
        h = fb.h
        pos0, vel0 = np.array([ref0.x, 0.0, ref0.z]), np.array([ref0.vx, 0.0, ref0.vz])
        integral = np.zeros(2)
        int_limit = INTEGRAL_LIMIT * red.gravity / gains.ki if red.gravity > 0 else np.inf
        if trim:
            if not ctl.open_loop and gains.ki > 0:
                # the wingbeat's real mean force differs a little from the table's (the body
                # bobs, the wings weigh): the integral starts where it cancels the difference
                probe = trim_rotation if free else trim_start  # free: the rotation trimmed
                *_, bias = probe(fb, path, cmd.params, pos0, vel0, config, every)
                if free:
                    int_limit = np.maximum(int_limit, FREE_BIAS_MARGIN * np.abs(bias) / gains.ki)
                integral = np.clip(bias / gains.ki, -int_limit, int_limit)
                cmd = command(
                    0.0,
                    (np.zeros(2), np.zeros(2), ref0.vx),
                    integral,
                    float(cmd.params[names.index("pitch")]) if "pitch" in names else 0.0,
                )
                fb.schedule = WingbeatSchedule(
                    fb.m, fb.kin, fb.red, cmd.params, smoothing=config.smoothing_beats * TWO_PI
                )
            pos0, vel0, history, _ = trim_start(fb, path, cmd.params, pos0, vel0, config, every)
            for e_pos, e_vel, vx in history:  # the wingbeat before the start, on the orbit
                window.add(e_pos, e_vel, vx)
        # the start's prescription from the schedule that will be flown (after the trim)
        zeros = np.zeros((1, len(names)))
        pres = fb.schedule.prescribe(np.zeros(1), cmd.params[None, :], zeros, zeros)
        omega0, d_pitch0 = getattr(fb, "start_rotation", (None, 0.0))
        fb.start(pos0, vel0, pres, pitch=float(pres.pitch[0]) - d_pitch0, omega_body=omega0)
        att = attitude_loop_for(fb, free and attitude_loop, track, JAC_AT_COMMAND)
        band = turning.integral_band(track, att)  # the path integral's
        gates = flown_pitch_for(free, track is None), flown_lateral_for(free, track)
        flown, flown_lat = gates  # the flown-prediction gates (flare's pitch, side gust's)
        slowed = DisturbedGains(ctl, att, free and track is None)  # (disturbed_gains)
        if free and trim and hasattr(fb, "start_moment"):
            att.preset_integral(fb.start_moment, cmd.params, float(pres.pitch[0]), float(ref0.vx))
        compensate = free and stroke_compensation and "stroke_plane" in names
        pitch_ref: float | None = None
        tau_ref = PITCH_COMMAND_BEATS * TWO_PI if compensate else 0.0
        sp_index = names.index("stroke_plane") if compensate else -1
        sp_bounds = (
            (fb.kin.params[sp_index].lower - SP_MARGIN, fb.kin.params[sp_index].upper + SP_MARGIN)
            if compensate
            else None
        )
        plan = None
        if compensate and (track is None or TURN_PITCH_PLAN) and PITCH_PLAN and "pitch" in names:
            plan = PitchPlan(
                feedforward_pitch(ctl, path, names),
                n_ctl,
                steps_ctl * h,
                tau_ref,
                float(fb.schedule.output[names.index("pitch")]),
                stride=max(1, per_beat_ctl // PLAN_PER_BEAT),
            )
        lat_int, turn_cmd = [0.0] if flown_lat is None else flown_lat.lateral_integral, None
        roll_ref = roll_rate_ref = roll_acc_ref = 0.0  # turning's bank command (filtered)
        att_window = (np.empty((0, 4)), np.empty((0, 3)))  # quat, C_SEED omega (FIT_BEATS)
        lat_window: Any = np.empty((0, 2)) if track is None else []  # (y, vy); turning: pairs
        dt_ctl, n_fit = steps_ctl * h, FIT_BEATS * config.log_per_beat
        comp_pitch = section_source(att, config.log_per_beat, dt_ctl, compensate and track is None)
        step_offsets, blocks = np.arange(steps_ctl) * h, []  # steps' times; samples' arrays
        for k in range(n_ctl):
            t = fb.time
            _ = control_hook and control_hook(k, t, fb)  # a flock's lockstep
            pitch = float(fb.schedule.output[names.index("pitch")]) if "pitch" in names else 0.0
            est = window.estimate() if window.ep else None
            cmd = command(t, est, integral, pitch)
            if (
                est is not None
                and not cmd.saturated
                and not ctl.open_loop
                and gains.ki > 0
                and within_band(est[0], band, lat_window if track is None else None)
            ):
                # anti-windup: frozen while saturated or far off the path (a gust; straight:
                # the side offset too; nearer in a cruise turn: turning.integral_band), and
                # bounded: it only trims the table's mean force's mismatch with the flown one
                integral = integral_step(integral, dt_ctl, est[0], int_limit)
            wind = wind_at(gusts, t / TWO_PI, speed)
            integral, int_limit = slowed.step(integral, int_limit, wind)  # next step's gains
            left = offset = None
            if free:
                v_est = float(est[2]) if est is not None else float(ref0.vx)
                if pitch_ref is None:
                    pitch_ref, pitch_rate_ref = pitch, 0.0
                # the body's pitch command: the table's pitch through a critically damped
                # second-order filter of time constant PITCH_COMMAND_BEATS (the stroke
                # plane takes the difference); its rate and acceleration feed forward
                if plan is not None:  # planned along the known path (no lag)
                    pitch_ref, pitch_rate_ref, pitch_acc_ref = plan.step(k, pitch)
                else:
                    pitch_ref, pitch_rate_ref, pitch_acc_ref = command_filter(
                        pitch_ref, pitch_rate_ref, pitch, tau_ref, dt_ctl
                    )
                if track is not None and plan is not None:  # a slow turn's lowered body
                    pitch3 = turn_pitch(track, t, (pitch_ref, pitch_rate_ref, pitch_acc_ref))
                    pitch_ref, pitch_rate_ref, pitch_acc_ref = pitch3
                turn_cmd = None
                if track is None:
                    roll_cmd = bank_command(lat_window, config.log_per_beat, red.gravity)
                    yaw_cmd = 0.0
                else:  # turning: banked about the heading (birdsim.flight.bank)
                    turn_cmd, lat_accel, (roll_ref, roll_rate_ref) = turn_command(
                        track,
                        t,
                        lat_window,
                        config.log_per_beat,
                        red.gravity,
                        (roll_ref, roll_rate_ref),
                        dt_ctl,
                        (pitch_ref, pitch_rate_ref, pitch_acc_ref),
                        lat_int,
                        att.inertia,
                    )
                    roll_cmd, yaw_cmd = turn_cmd.roll, turn_cmd.yaw
                    lateral_corr[0] = lat_accel - track.state(t).a_lat
                    turning.straight_parts(att, track, t)  # the straight parts' loop
                zyx_pitch = pitch_ref if turn_cmd is None else turn_cmd.pitch
                err, rates = attitude_estimate(
                    att_window, fb.d, config.log_per_beat, TWO_PI, zyx_pitch, roll_cmd, yaw_cmd
                )
                # the airspeed along the heading, as the path loop's (straight: along x)
                v_air = v_est - (float(wind[0]) if track is None else track.wind_along(t, wind))
                air = (v_air, 0.0)  # and the angle of the path loop's air path (air_angle)
                if track is None:
                    w_xz, est_air = (float(wind[0]), float(wind[2])), None if ctl.open_loop else est
                    air = (v_air, straight_air_angle(path.state(t), est_air, w_xz))
                ref3 = (pitch_ref, pitch_rate_ref, pitch_acc_ref)  # wingbeat-mean pitch:
                body_pitch, err, rates, p_demand = comp_pitch(att_window, ref3, err, rates, *air)
                at_cmd = att.straight  # the Jacobians measured at the command (else the body's)
                jac_pitch, jac_params = (pitch_ref if at_cmd else body_pitch), None
                if compensate:
                    # the stroke plane turns by the table's minus the body's pitch, SP_LEAD ahead
                    offset = np.zeros(len(names))
                    q_turn = 0.0 if turn_cmd is None else float(turn_cmd.turn_rates[1])
                    lead = (float(rates[1]) - q_turn) * SP_LEAD * TWO_PI  # not the turn's q
                    # the table's pitch as its target, not the smoothed output (free-body.md)
                    p_table = cmd.params[names.index("pitch")] if "pitch" in names else pitch
                    sp = cmd.params[sp_index] + p_table - (body_pitch + lead)
                    offset[sp_index] = clip_float(sp, *sp_bounds) - cmd.params[sp_index]
                    jac_params = cmd.params + offset
                    if at_cmd:  # the stroke plane compensated for the command
                        sp = cmd.params[sp_index] + p_table - jac_pitch
                        jac_params[sp_index] = clip_float(sp, *sp_bounds)
                if turn_cmd is None:
                    rates3 = (roll_rate_ref, pitch_rate_ref), (roll_acc_ref, pitch_acc_ref)
                    rate_cmd, acc_cmd, turn_rates = straight_commands(pitch_ref, roll_cmd, *rates3)
                else:
                    rate_cmd, acc_cmd = turn_cmd.rate, turn_cmd.acc
                    turn_rates = turn_cmd.rate  # the damping of the commanded rates in M_0
                right, left, shoulder, tail = att.update(
                    cmd.params,
                    pitch_ref,
                    v_air,
                    err,
                    rates,
                    dt_ctl,
                    rate_cmd=rate_cmd,
                    acc_cmd=acc_cmd,
                    turn_rates=turn_rates,
                    jac_params=jac_params,
                    jac_pitch=jac_pitch,
                    pitch_demand=p_demand,
                )
                fb.schedule.shoulder_target = shoulder
                fb.cb.tail_controls = tail
                args4 = (right, left, offset, wind)  # the interval's (flown_pitch, flown_lateral)
                if flown is not None:  # where the loop's model stops holding (flown_pitch)
                    ref3 = (pitch_ref, float(rate_cmd[1]), float(acc_cmd[1]))
                    flown.step(att, fb, args4, ref3, cmd.params, err[1])
                if flown_lat is not None:  # the lateral inputs likewise (flown_lateral)
                    cmd3 = (zyx_pitch, roll_cmd, yaw_cmd, roll_ref, roll_rate_ref, pitch_ref)
                    right, left = flown_lat.step(att, fb, args4, cmd.params, cmd3, err)
            else:
                right = cmd.params
            start, times = len(record), t + step_offsets  # advance and steps: fast_interval
            pres = interval(fb, right, times, t, dt_ctl, left, offset, wind, record, every)
            t_new, q_new, v_new = step_records.new_samples(fb, record, start, blocks)
            if track is None:
                refs, e_pos, e_vel, v_air_new, att_window, lat_window = straight_samples(
                    reference, t_new, q_new, v_new, wind, att_window, lat_window, n_fit
                )
                v_along, y_ref = v_new[:, 0], np.zeros(len(t_new))
            else:
                e_pos, e_vel, v_along, lateral, refs = track.errors(
                    t_new, q_new[:, :3], v_new[:, :3]
                )
                lat_window.extend(map(tuple, lateral))
                del lat_window[: max(0, len(lat_window) - n_fit)]
                y_ref, v_air_new = refs["y"], air_speeds(v_new, wind)  # |v - wind|
                att_window = keep_last(att_window, (q_new[:, 3:7], C_SEED * v_new[:, 3:6]), n_fit)
            window.add_many(e_pos, e_vel, v_along)
            rows["V_air"].extend(v_air_new)
            rows["params"].extend(pres.params[: len(t_new) * every : every])
            rows["pitch_command"].extend(
                pres.pitch[: len(t_new) * every : every]
                if pitch_ref is None
                else [pitch_ref] * len(t_new)
            )
            extend_rows(rows, refs, y_ref, cmd, fb.cb.tail_controls, att, turn_cmd, gates)
            if progress is not None:
                progress((k + 1) / per_beat_ctl)
        projection = fb.projection_max
        root_applied = fb.root_applied_max
    keep = sum(1 for r in record if r[0] <= beats * TWO_PI + 1e-9)  # whole intervals flown
    record = record[:keep]
    rows = {k: v[:keep] for k, v in rows.items()}
    arrays = flight_arrays(record, rows, names, blocks)
    result = FlightResult(arrays, bird, model, names, gains, open_loop or demands_only, projection)
    result.meta["root_applied_max"] = root_applied
    result.meta["attitude"] = config.attitude
    result.meta["attitude_loop"] = bool(free and attitude_loop)
    return result


__all__ = [
    "DemandSchedule",
    "FlightResult",
    "Gust",
    "GustError",
    "RefState",
    "fly",
    "sample_reference",
    "parse_gust",
    "wind_at",
]
