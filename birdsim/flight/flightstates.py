"""A free flight (a log, or a simulation just run) as the renderer's
:class:`birdsim.render.states.StateSequence`: the video's instants resampled from the
log, the path drawn as a thin line, position error and saturation in the overlay.

The MuJoCo states of a flight are the REDUCED model's (lengths in semispans, one
wingbeat = 2 pi); the sequence is drawn with the MJCF of the reduced bird, which is the
bird's own MJCF scaled to a semispan of 1 (the same name, so the same plumage).  The
overlay speaks the bird's units (seconds and metres for the pigeon).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird, scales

TWO_PI = 2.0 * math.pi
WHITE, AMBER = (255, 255, 255), (255, 190, 60)


def _quaternion_slices(m: Any) -> list[slice]:
    """qpos slices holding quaternions (free and ball joints)."""
    import mujoco

    out = []
    for j in range(m.njnt):
        kind = m.jnt_type[j]
        adr = int(m.jnt_qposadr[j])
        if kind == mujoco.mjtJoint.mjJNT_FREE:
            out.append(slice(adr + 3, adr + 7))
        elif kind == mujoco.mjtJoint.mjJNT_BALL:
            out.append(slice(adr, adr + 4))
    return out


def resample(t_log: np.ndarray, values: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Linear interpolation of the rows of ``values`` (T, n) at ``t`` (held at the ends)."""
    idx = np.clip(np.searchsorted(t_log, t, side="right") - 1, 0, len(t_log) - 2)
    w = np.clip((t - t_log[idx]) / (t_log[idx + 1] - t_log[idx]), 0.0, 1.0)
    if values.ndim == 1:
        return values[idx] * (1 - w) + values[idx + 1] * w
    return values[idx] * (1 - w)[:, None] + values[idx + 1] * w[:, None]


def flight_states(log: dict[str, Any], options: Any, *, title: str = "") -> Any:
    """The StateSequence of a flight log (:func:`birdsim.flight.flightlog.load_log` or
    ``log_arrays``) for a video with ``options`` (fps, beats_per_second,
    trail_substeps, seconds: video length, default the whole flight).

    Raises:
        BirdsimError: a log too short to draw (fewer than two samples).
    """
    import tomllib

    from birdsim.mujoco.legged import build_model_for
    from birdsim.render.states import StateSequence

    bird = log.get("bird_obj") or Bird.from_dict(tomllib.loads(str(log["bird"])))
    red = reduced_bird(bird)
    sc = scales(bird)
    model = str(log["model"])
    omega = float(log["omega"])
    t_log = np.asarray(log["t"], dtype=float) * omega / TWO_PI  # wingbeats
    if t_log.size < 2:
        raise BirdsimError(
            "the flight log has fewer than two samples; allowed: a log of at least one sample interval"
        )
    flown = float(t_log[-1])
    sub = max(1, int(options.trail_substeps))
    seconds = options.seconds if options.seconds is not None else flown / options.beats_per_second
    frames = max(1, int(round(seconds * options.fps)))
    t = np.arange(frames * sub) * (options.beats_per_second / (options.fps * sub))
    t = np.minimum(t, flown)
    m = build_model_for(model, red, np.asarray(log["qpos"]).shape[1])  # legs if logged
    qpos = resample(t_log, np.asarray(log["qpos"], dtype=float), t)
    for sl in _quaternion_slices(m):
        q = qpos[:, sl]
        qpos[:, sl] = q / np.linalg.norm(q, axis=1, keepdims=True)
    qvel = resample(t_log, np.asarray(log["qvel"], dtype=float), t)
    ref = np.column_stack(
        [
            np.asarray(log["x_ref"]) / sc.length,
            np.asarray(log["y_ref"]) / sc.length if "y_ref" in log else np.zeros(t_log.size),
            np.asarray(log["z_ref"]) / sc.length,
        ]
    )
    names = [str(n) for n in np.asarray(log["param_names"]).tolist()]
    sampled = {
        k: resample(t_log, np.asarray(log[k], dtype=float), t)
        for k in ("x", "z", "x_ref", "z_ref", "V_air", "Fx_demand", "Fz_demand", "pitch_moment")
    }
    # the side error (a free body off its path, a turn); 0 for a log without y
    sampled["ey"] = (
        resample(t_log, np.asarray(log["y"], float) - np.asarray(log["y_ref"], float), t)
        if "y_ref" in log and "y" in log
        else np.zeros(t.size)
    )
    sat = np.asarray(log["saturated"], dtype=bool)[
        np.clip(np.searchsorted(t_log, t, side="right") - 1, 0, t_log.size - 1)
    ]
    params = {n: resample(t_log, np.asarray(log[n], dtype=float), t) for n in names if n in log}
    free = str(log.get("attitude", "posed")) == "free"
    tail = None
    if free:  # the free attitude (issue 22): Euler angles, tail, attitude saturation
        euler = {
            k: resample(t_log, np.asarray(log[k], dtype=float), t) for k in ("roll", "pitch", "yaw")
        }
        tail = np.column_stack(
            [
                resample(t_log, np.asarray(log[k], dtype=float), t)
                for k in ("tail_elevation", "tail_spread", "tail_roll")
            ]
        )
        att_sat = np.asarray(log["attitude_saturated"], dtype=bool)[
            np.clip(np.searchsorted(t_log, t, side="right") - 1, 0, t_log.size - 1)
        ]
    unit_l = "semispans" if sc.length == 1.0 else "m"
    unit_t = "s" if sc.time != 1.0 else "time units"
    manoeuvre = str(log.get("manoeuvre", "")) or title
    loop = "open loop" if bool(log.get("open_loop", False)) else "closed loop"

    def overlay(k: int) -> list:
        ex = sampled["x"][k] - sampled["x_ref"][k]
        ez = sampled["z"][k] - sampled["z_ref"][k]
        lines: list = [
            (
                f"t = {t[k] / omega * TWO_PI:6.2f} {unit_t} ({t[k]:5.2f} wingbeats)   {manoeuvre}   free flight, {loop}, model {model}",
                WHITE,
            ),
            (
                f"position error x {ex:+.3f}  z {ez:+.3f} {unit_l}   airspeed {sampled['V_air'][k]:.2f}",
                WHITE,
            ),
        ]
        if params:
            half = (len(params) + 1) // 2
            items = list(params.items())
            for chunk in (items[:half], items[half:]):
                if chunk:
                    lines.append(("   ".join(f"{n} {v[k]:.2f}" for n, v in chunk), WHITE))
        if free:
            deg = {n: np.degrees(v[k]) for n, v in euler.items()}
            lines.append(
                (
                    f"attitude free: roll {deg['roll']:+.1f}  pitch {deg['pitch']:+.1f}  yaw {deg['yaw']:+.1f} deg   "
                    f"tail {np.degrees(tail[k, 0]):+.0f} deg   pitch moment {sampled['pitch_moment'][k]:+.3g}",
                    WHITE,
                )
            )
            if att_sat[k]:
                lines.append(
                    ("attitude saturated: the wings and tail cannot deliver the moment", AMBER)
                )
        else:
            lines.append((f"tail moment {sampled['pitch_moment'][k]:+.3g}", WHITE))
        if sat[k]:
            lines.append(("saturated: the demand is beyond the table's reach", AMBER))
        return lines

    def brief(k: int) -> list:
        """The default overlay: time and flight, position error and airspeed, saturation."""
        err = math.hypot(
            math.hypot(sampled["x"][k] - sampled["x_ref"][k], sampled["ey"][k]),
            sampled["z"][k] - sampled["z_ref"][k],
        )
        unit_v = "m/s" if unit_l == "m" else "omega s"
        lines: list = [
            (
                f"t {t[k] / omega * TWO_PI:5.2f} {unit_t} ({t[k]:4.1f} wingbeats)  {manoeuvre}",
                WHITE,
            ),
            (f"error {err:.3f} {unit_l}   airspeed {sampled['V_air'][k]:.2f} {unit_v}", WHITE),
        ]
        if sat[k]:
            lines.append(("saturated: beyond the table's reach", AMBER))
        return lines

    demanded = np.column_stack([sampled["Fx_demand"], np.zeros(t.size), sampled["Fz_demand"]])
    return StateSequence(
        model=model,
        bird=red,
        t_beats=t,
        qpos=qpos,
        qvel=qvel,
        overlay=overlay,
        reference_path=ref,
        instants_per_frame=sub,
        title=title or manoeuvre,
        demanded_force=demanded,
        brief=brief,
        tail=tail,
    )


__all__ = ["flight_states", "resample"]
