"""The flight log: a free flight's samples in the bird's own units, as ``.npz``.

Per sample (``log_per_beat`` per wingbeat, >= 32):

==============  ===============================================================
t               time [the bird's time unit: s for the pigeon]
x, z            torso origin, x forward, z UP [the bird's length unit]
vx, vz          its velocity [length / time]
x_ref, y_ref,   the path [length] (y_ref: 0 for a path in the vertical plane)
z_ref
pitch           body pitch, nose up [rad] (Euler Z-Y-X, docs/conventions.md)
roll, yaw       body roll (right wing down) and yaw (nose right) [rad]
pitch_command   the table's (commanded) body pitch [rad]
y, vy           torso origin's y (to the bird's LEFT, MuJoCo world) and its speed
quat            torso orientation, MuJoCo (w, x, y, z)
omega_body      body rates (p, q, r), seed body axes x fwd / y right / z down [1/time]
moment_aero     aerodynamic moment about the centre of mass, seed body axes
                (attitude posed: the hidden holding moment) [force x length]
tail_elevation, tail controls [rad, fraction of tail_span, rad]
tail_spread,
tail_roll
tail_force      tail's aerodynamic force, seed body axes [force]
u_<input>       the attitude loop's inputs (birdsim.flight.attitude.INPUTS) [rad]
attitude_saturated  the attitude loop's bounds bound and the moment fell short (bool)
<param>         each wingbeat parameter by its table name [rad] (smoothed, flown)
Fx_demand,      the table force asked for: ONE wing + body drag, seed axes
Fz_demand       (Fz < 0 up), in TABLE units rho omega^2 s^3 c (not converted)
V_air           airspeed of the torso [length / time]
saturated       the demand was outside the table's reach (bool)
pitch_moment    nose-up moment: attitude free, what the wings, tail and body produce
                about the centre of mass; posed, the hidden moment that holds the
                prescribed pitch [force x length]
power           mechanical power of both wings' joints [the bird's power unit]
force_x,        whole-bird aerodynamic force + weight, world x / z [force]
force_z
qpos, qvel      MuJoCo state of the REDUCED model (for rendering a log)
==============  ===============================================================

Scalars: ``mass`` (whole bird), ``gravity`` (magnitude), ``model``, ``bird`` (the bird's
TOML text), ``omega`` (rad per time unit), ``format`` (= :data:`LOG_FORMAT`, which marks a
birdsim flight log), ``version``, ``manoeuvre``, ``param_names``, ``open_loop``.
"""

from __future__ import annotations

import io
import math
import zipfile
from pathlib import Path
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.flight.freeflight import FlightResult
from birdsim.io import check_output, write_atomic
from birdsim.physics.bird import Bird
from birdsim.physics.units import scales

LOG_FORMAT = "birdsim-flight-log"
LOG_VERSION = 1
TWO_PI = 2.0 * math.pi


class LogError(BirdsimError):
    """A file that is not a readable birdsim flight log."""


def log_arrays(result: FlightResult, manoeuvre: str = "") -> dict[str, np.ndarray]:
    """The log's arrays and scalars in the bird's own units (see the module docstring)."""
    import tomli_w

    sc = scales(result.bird)
    a = result.arrays
    out: dict[str, np.ndarray] = {
        "t": a["t"] * sc.time,
        "x": a["x"] * sc.length,
        "z": a["z"] * sc.length,
        "vx": a["vx"] * sc.speed,
        "vz": a["vz"] * sc.speed,
        "x_ref": a["x_ref"] * sc.length,
        "y_ref": a["y_ref"] * sc.length,
        "z_ref": a["z_ref"] * sc.length,
        "pitch": a["pitch"],
        **{n: a[n] for n in result.param_names},
        "Fx_demand": a["Fx_demand"],
        "Fz_demand": a["Fz_demand"],
        "V_air": a["V_air"] * sc.speed,
        "saturated": a["saturated"].astype(bool),
        "pitch_moment": a["pitch_moment"] * sc.force * sc.length,
        "power": a["power"] * sc.power,
        "force_x": a["force_x"] * sc.force,
        "force_z": a["force_z"] * sc.force,
        "qpos": a["qpos"],
        "qvel": a["qvel"],
        # the free attitude (issue 22): lengths, speeds, moments and forces converted
        "y": a["y"] * sc.length,
        "vy": a["vy"] * sc.speed,
        "climb_demand": a["climb_demand"] * sc.speed,
        "roll": a["roll"],
        "yaw": a["yaw"],
        "pitch_command": a["pitch_command"],
        "quat": a["quat"],
        "omega_body": a["omega_body"] / sc.time,
        "moment_aero": a["moment_aero"] * sc.force * sc.length,
        "tail_elevation": a["tail_elevation"],
        "tail_spread": a["tail_spread"],
        "tail_roll": a["tail_roll"],
        "tail_force": a["tail_force"] * sc.force,
        "force_y": a["force_y"] * sc.force,
        "attitude_saturated": a["attitude_saturated"].astype(bool),
        **{k: a[k] for k in a if k.startswith("u_")},
        # a turning flight's commanded bank and heading (rad)
        **{k: a[k] for k in ("bank_command", "heading_command") if k in a},
        "attitude": np.array(result.meta.get("attitude", "posed")),
        "mass": np.array(result.bird.mass),
        "gravity": np.array(result.bird.gravity),
        "model": np.array(result.model),
        "bird": np.array(tomli_w.dumps(result.bird.to_dict())),
        "omega": np.array(result.bird.omega),
        "format": np.array(LOG_FORMAT),
        "version": np.array(LOG_VERSION),
        "manoeuvre": np.array(manoeuvre),
        "param_names": np.array(list(result.param_names)),
        "open_loop": np.array(result.open_loop),
    }
    if "foot_force" in a:  # legs and contact (issue 25)
        out["foot_force"] = a["foot_force"] * sc.force
        out["on_perch"] = np.asarray(a["on_perch"], dtype=bool)
        out["phase"] = np.asarray(a["phase"]).astype(str)
    return out


def save_log(arrays: dict[str, np.ndarray], path: str | Path, force: bool = False) -> Path:
    """Write the log atomically; an existing file needs ``force``."""
    path = check_output(Path(path), force)
    if path.suffix.lower() != ".npz":
        raise LogError(f"--out {str(path)!r} does not end in .npz; allowed: a .npz path")
    buf = io.BytesIO()
    np.savez_compressed(buf, **arrays)
    write_atomic(path, buf.getvalue())
    return path


REQUIRED = (
    "t",
    "x",
    "z",
    "vx",
    "vz",
    "x_ref",
    "z_ref",
    "pitch",
    "Fx_demand",
    "Fz_demand",
    "V_air",
    "saturated",
    "pitch_moment",
    "qpos",
    "qvel",
    "mass",
    "gravity",
    "model",
    "bird",
    "omega",
    "param_names",
)


def load_log(path: str | Path, arg: str = "LOG") -> dict[str, Any]:
    """Read a flight log; one line for a missing file or a file from another program.

    Returns:
        dict of arrays (and ``bird_obj``: the Bird parsed from the log's TOML text).
    """
    import tomllib

    p = Path(path)
    if not p.is_file():
        raise LogError(
            f"{arg} {str(p)!r} does not exist; allowed: a flight log written by `birdsim fly --out`"
        )
    try:
        with np.load(p, allow_pickle=False) as z:
            data = {k: z[k] for k in z.files}
    except (OSError, ValueError, EOFError, zipfile.BadZipFile) as exc:
        raise LogError(
            f"{arg} {str(p)!r} is not a .npz file ({exc}); allowed: a flight log written by `birdsim fly --out`"
        ) from None
    if str(data.get("format", "")) != LOG_FORMAT:
        raise LogError(
            f"{arg} {str(p)!r} is not a birdsim flight log (no format={LOG_FORMAT!r} marker); allowed: a log written by `birdsim fly --out`"
        )
    if int(data.get("version", -1)) != LOG_VERSION:
        raise LogError(
            f"{arg} {str(p)!r} has log version {data.get('version')}; this birdsim reads version {LOG_VERSION}"
        )
    if "n_birds" in data:  # a flock's log (birdsim.flight.flock_fly): per-bird arrays
        raise LogError(
            f"{arg} {str(p)!r} is a flock's log ({int(data['n_birds'])} birds); allowed: a one-bird flight log (the studio does not take a flock yet; birdsim render, export and view do)"
        )
    missing = [k for k in REQUIRED if k not in data]
    if missing:
        raise LogError(
            f"{arg} {str(p)!r} lacks array {missing[0]!r}; allowed: a complete flight log"
        )
    try:
        data["bird_obj"] = Bird.from_dict(tomllib.loads(str(data["bird"])))
    except (ValueError, TypeError) as exc:
        raise LogError(f"{arg} {str(p)!r}: its bird is unreadable: {exc}") from None
    return data


def summary(
    arrays: dict[str, Any], *, skip_beats: float = 2.0, phases: Any = None
) -> dict[str, Any]:
    """What ``birdsim fly --json`` prints: errors, final state, saturation, power.

    Errors are distances |p - p_ref| in the bird's length unit; ``*_after_start`` leaves
    out the first ``skip_beats`` wingbeats.  ``phases``: a callable t_beats -> label (the
    path's regime) for per-phase errors.
    """
    omega = float(arrays["omega"])
    t_beats = np.asarray(arrays["t"]) * omega / TWO_PI
    ex = np.asarray(arrays["x"]) - np.asarray(arrays["x_ref"])
    ez = np.asarray(arrays["z"]) - np.asarray(arrays["z_ref"])
    # three-dimensional where the log has the side (a free body off its path, a turn)
    ey = (
        np.asarray(arrays["y"]) - np.asarray(arrays["y_ref"])
        if "y" in arrays and "y_ref" in arrays
        else np.zeros_like(ex)
    )
    err = np.hypot(np.hypot(ex, ey), ez)
    late = t_beats >= skip_beats
    sat = np.asarray(arrays["saturated"], dtype=bool)
    beat_index = np.floor(t_beats + 1e-9).astype(int)
    moment = np.asarray(arrays["pitch_moment"])
    beats = sorted(set(beat_index.tolist()))
    per_beat_mean = [float(moment[beat_index == b].mean()) for b in beats]
    per_beat_peak = [float(np.abs(moment[beat_index == b]).max()) for b in beats]

    last = t_beats > t_beats[-1] - 1.0 + 1e-9 if t_beats.size else np.zeros(0, bool)

    def rms(x: np.ndarray) -> float:
        return float(np.sqrt(np.mean(np.square(x)))) if x.size else float("nan")

    out: dict[str, Any] = {
        "manoeuvre": str(arrays.get("manoeuvre", "")),
        "model": str(arrays["model"]),
        "bird": Bird.from_dict(__import__("tomllib").loads(str(arrays["bird"]))).name,
        "open_loop": bool(arrays.get("open_loop", False)),
        "samples": int(t_beats.size),
        "wingbeats": round(float(t_beats[-1] + (t_beats[1] - t_beats[0])), 6)
        if t_beats.size > 1
        else 0.0,
        "rms_error": rms(err),
        "max_error": float(err.max()) if err.size else float("nan"),
        "rms_error_after_start": rms(err[late]),
        "max_error_after_start": float(err[late].max()) if np.any(late) else float("nan"),
        "rms_altitude_error_after_start": rms(ez[late]),
        "rms_side_error_after_start": rms(ey[late]),
        "final_position": [float(arrays["x"][-1]), float(arrays["z"][-1])],
        "final_reference": [float(arrays["x_ref"][-1]), float(arrays["z_ref"][-1])],
        "final_speed": float(np.hypot(arrays["vx"][-1], arrays["vz"][-1])),
        # the body bobs within a wingbeat: "at rest" is the last wingbeat's mean velocity
        "final_mean_speed": float(
            np.hypot(
                np.mean(np.asarray(arrays["vx"])[last]), np.mean(np.asarray(arrays["vz"])[last])
            )
        ),
        "saturated_samples": int(sat.sum()),
        "wingbeats_saturated": int(len(set(beat_index[sat].tolist()))),
        "mean_power": float(np.mean(arrays["power"])) if "power" in arrays else float("nan"),
        "pitch_moment_mean": float(np.mean(moment)),
        "pitch_moment_peak": float(np.abs(moment).max()),
        "pitch_moment_per_wingbeat": {"mean": per_beat_mean, "peak": per_beat_peak},
        "units": "bird's own (length, time, force x length, power); Fx/Fz_demand in table units",
        "force": "Fx_demand, Fz_demand: right wing + body drag (the dissertation's flapcost force), Fz < 0 is up; "
        "force_x, force_z of the log: whole bird (2 wings + body drag) + weight, world x / z up",
    }
    if str(arrays.get("attitude", "posed")) == "free" and np.ndim(arrays["pitch"]) == 1:
        from birdsim.flight.attitude_summary import attitude_figures

        out["attitude"] = attitude_figures(arrays, skip_beats=int(skip_beats))
    if phases is not None:
        labels = np.array([phases(float(tb)) for tb in t_beats])
        out["phases"] = {
            str(lab): {
                "rms_error": rms(err[labels == lab]),
                "max_error": float(err[labels == lab].max()),
                "wingbeats": float((labels == lab).sum() / max(1, len(t_beats)) * out["wingbeats"]),
            }
            for lab in dict.fromkeys(labels.tolist())
        }
    return out


__all__ = ["LOG_FORMAT", "LOG_VERSION", "LogError", "load_log", "log_arrays", "save_log", "summary"]
