"""The free body's attitude figures of a flight log, as ``birdsim fly --json`` reports
them under ``attitude`` (issue 22's targets; docs/free-body.md).

Per whole wingbeat (the log's samples in blocks of one wingbeat from t = 0; a last,
partial wingbeat left out): the wingbeat-mean pitch minus the wingbeat-mean command, its
RMS after ``skip_beats``; the largest wingbeat-mean roll and yaw (Euler angles, ZYX,
docs/conventions.md); the median within-wingbeat pitch rocking (peak to peak; a posed body
shows none) after ``skip_beats``; the attitude-saturated samples.  Degrees.

The log's Euler angles keep pitch within +-90 degrees, so a body rocking past the vertical
(a landing's flare) reads there as roll and yaw of 180 degrees and a pitch folded back
below 90.  The figures take each sample in the other Z-Y-X triple of the same rotation,
``(yaw + pi, pi - pitch, roll + pi)``, wherever that keeps |roll| within 90 degrees
(:func:`unfolded_euler`): the pitch then runs on past 90 degrees and roll and yaw stay
what they are.

"""

from __future__ import annotations

import math
from typing import Any

import numpy as np


def unfolded_euler(
    yaw: np.ndarray, pitch: np.ndarray, roll: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Z-Y-X Euler angles (rad) of the same rotations, each sample in the triple whose
    |roll| is at most pi/2: ``(yaw +- pi, +-pi - pitch, roll +- pi)`` where |roll| > pi/2,
    the input elsewhere; every angle stays within [-pi, pi]."""
    yaw, pitch, roll = (np.asarray(a, dtype=float) for a in (yaw, pitch, roll))
    flip = np.abs(roll) > 0.5 * math.pi
    return (
        np.where(flip, np.where(yaw >= 0.0, yaw - math.pi, yaw + math.pi), yaw),
        np.where(flip, np.where(pitch >= 0.0, math.pi - pitch, -math.pi - pitch), pitch),
        np.where(flip, np.where(roll >= 0.0, roll - math.pi, roll + math.pi), roll),
    )


def attitude_figures(arrays: dict[str, Any], skip_beats: int = 2) -> dict[str, float | int]:
    """See the module docstring; ``arrays`` a one-bird flight log's (``t`` in any unit,
    ``omega`` in its inverse, absent in a flight's reduced arrays: 1; ``pitch``,
    ``pitch_command``, ``roll``, ``yaw`` in rad)."""
    t = np.asarray(arrays["t"], dtype=float)
    beats_flown = t[-1] * float(arrays.get("omega", 1.0)) / (2.0 * math.pi) if t.size else 0.0
    n = int(round(t.size / beats_flown)) if beats_flown > 0 else 0
    beats = t.size // n if n else 0

    yaw, pitch, roll = unfolded_euler(arrays["yaw"], arrays["pitch"], arrays["roll"])
    angles = {"yaw": yaw, "pitch": pitch, "roll": roll}

    def per_beat(key: str, f: Any = np.mean) -> np.ndarray:
        a = angles[key] if key in angles else np.asarray(arrays[key], dtype=float)
        a = a[: beats * n]
        return f(a.reshape(beats, n), axis=1) if beats else np.zeros(0)

    pitch_error = (per_beat("pitch") - per_beat("pitch_command"))[skip_beats:]
    rocking = per_beat("pitch", np.ptp)[skip_beats:]
    nan = float("nan")
    return {
        "wingbeat_mean_pitch_rms_error_deg": math.degrees(float(np.sqrt(np.mean(pitch_error**2))))
        if pitch_error.size
        else nan,
        "wingbeat_mean_roll_max_deg": math.degrees(float(np.abs(per_beat("roll")).max()))
        if beats
        else nan,
        "wingbeat_mean_yaw_max_deg": math.degrees(float(np.abs(per_beat("yaw")).max()))
        if beats
        else nan,
        "rocking_median_deg": math.degrees(float(np.median(rocking))) if rocking.size else nan,
        "attitude_saturated_samples": int(np.sum(arrays["attitude_saturated"])),
    }


__all__ = ["attitude_figures", "unfolded_euler"]
