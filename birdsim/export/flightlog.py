"""Export frames of a free flight: a flight log from ``birdsim fly --out`` or a flight
just flown (the arrays of :func:`birdsim.flight.flightlog.log_arrays`).

The log is read by the flight layer's own reader (:func:`birdsim.flight.flightlog.load_log`:
the format marker, the version and every required array; anything else is "not a birdsim
flight log", one line). The export samples it at its own frame rate exactly as
``birdsim render`` draws it (:func:`birdsim.flight.flightstates.resample`): the logged MuJoCo
state of the REDUCED model (lengths in semispans) is interpolated linearly between log
samples (at least 32 per wingbeat), its quaternions renormalised, and its lengths (the
root position, the heave slides) multiplied by the semispan, which gives the qpos of the
bird's own MJCF (``build_model(model, bird)`` is the reduced MJCF scaled by the semispan):
metres for the pigeon. So the body position at a frame is the log's ``x``, ``z``
interpolated at that frame's time.

Force columns (docs/export.md, CSV): ``Fx_demand``, ``Fz_demand`` as logged (the
dissertation's force, right wing + body drag, table units), ``V_air`` converted from the
bird's speed unit to omega s, and the achieved force: the wingbeat mean of the flown
parameters at that airspeed (:func:`birdsim.export.frames.achieved_forces`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from birdsim.export.frames import (
    ExportError,
    FrameSequence,
    achieved_forces,
    check_fps,
    frame_count,
    time_per_second,
)

#: Force and speed columns carried from a log into the CSV.
LOG_COLUMNS = ("Fx_demand", "Fz_demand", "V_air")


def read_flight_log(path: str | Path) -> dict[str, Any]:
    """Read a flight log written by ``birdsim fly --out``.

    Args:
        path: the ``.npz`` file.

    Returns:
        The log's arrays and scalars (and ``bird_obj``, its Bird).

    Raises:
        ExportError: a missing file, a file that is not an npz, or a log from another
            program (one line naming SOURCE).
    """
    from birdsim.flight.flightlog import LogError, load_log

    try:
        return load_log(path, "SOURCE")
    except LogError as exc:
        raise ExportError(str(exc)) from None


def _length_slices(m: Any) -> list[slice]:
    """qpos entries that are lengths: the free root's position and every slide joint."""
    import mujoco

    out = []
    for j in range(m.njnt):
        adr = int(m.jnt_qposadr[j])
        if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE:
            out.append(slice(adr, adr + 3))
        elif m.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE:
            out.append(slice(adr, adr + 1))
    return out


def frames_from_log(
    log: dict[str, Any],
    *,
    fps: float = 30.0,
    beat_rate: float | None = None,
    metres_per_unit: float = 1.0,
    seconds: float | None = None,
    source: str = "",
) -> FrameSequence:
    """Export frames of a flight log at ``fps`` (see the module docstring).

    Args:
        log: the log (:func:`read_flight_log` or ``log_arrays`` of a flight just flown).
        fps: frames per second of animation.
        beat_rate: wingbeats per second of animation (default: real time for an SI bird,
            2 for the seed bird).
        metres_per_unit: metres per bird length unit.
        seconds: animation length (default: the whole log; never beyond its end).
        source: what the frames come from (for the file's metadata).

    Returns:
        The frames; frame 0 is the log's first sample, times in the bird's time units.

    Raises:
        ExportError: a bad fps, beat rate or length; a log of fewer than two samples.
    """
    import tomllib

    from birdsim.flight.flightstates import _quaternion_slices, resample
    from birdsim.mujoco.legged import build_model_for
    from birdsim.physics.bird import Bird
    from birdsim.physics.kinematics import get_model
    from birdsim.physics.units import reduced_bird, scales

    fps = check_fps(fps)
    bird = log.get("bird_obj") or Bird.from_dict(tomllib.loads(str(log["bird"])))
    km = get_model(str(log["model"]))
    sc = scales(bird)
    t_log = np.asarray(log["t"], dtype=float)
    if t_log.size < 2:
        raise ExportError(
            "the flight log has fewer than two samples; allowed: a log of at least one sample interval"
        )
    per_s = time_per_second(bird, beat_rate)
    t0, t1 = float(t_log[0]), float(t_log[-1])
    if seconds is not None:
        if not (np.isfinite(seconds) and seconds > 0):
            raise ExportError(f"--seconds {seconds!r} is invalid; allowed: a number > 0")
        t1 = min(t1, t0 + seconds * per_s)
    n = frame_count(t1 - t0, fps, per_s)
    time = t0 + np.arange(n) * (per_s / fps)
    time = time[time <= t1 + 1e-9 * max(1.0, abs(t1))]
    m_red = build_model_for(km.name, reduced_bird(bird), np.asarray(log["qpos"]).shape[1])
    qpos = resample(t_log, np.asarray(log["qpos"], dtype=float), time)
    for sl in _quaternion_slices(m_red):
        qpos[:, sl] /= np.linalg.norm(qpos[:, sl], axis=1, keepdims=True)
    for sl in _length_slices(m_red):
        qpos[:, sl] *= sc.length
    params = {
        p: resample(t_log, np.asarray(log[p], dtype=float), time)
        for p in km.param_names
        if p in log
    }
    forces = {
        k: resample(t_log, np.asarray(log[k], dtype=float), time) for k in LOG_COLUMNS if k in log
    }
    if "V_air" in forces:
        forces["V_air"] = (
            forces["V_air"] / sc.speed
        )  # the bird's speed unit -> omega s (table units)
        if len(params) == len(km.param_names):
            forces.update(achieved_forces(km.name, bird, params, forces["V_air"]))
    return FrameSequence(
        model=km.name,
        bird=bird,
        fps=fps,
        time=time,
        qpos=qpos,
        params=params,
        forces=forces,
        source=source or f"free flight {str(log.get('manoeuvre', ''))}".strip(),
        metres_per_unit=metres_per_unit,
    )


__all__ = ["LOG_COLUMNS", "frames_from_log", "read_flight_log"]
