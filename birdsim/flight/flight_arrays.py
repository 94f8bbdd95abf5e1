"""A free flight's per-sample arrays (reduced units) from the simulation's step records,
and the attitude loop's wingbeat-mean estimate from the last wingbeat of samples."""

from __future__ import annotations

import functools
from typing import Any

import numpy as np
from scipy.spatial.transform import Rotation

from birdsim.flight.attitude import FIT_BEATS, INPUTS, euler_zyx, wingbeat_fit_matrix
from birdsim.flight.simulate import C_SEED


def attitude_estimate(
    window: list, d: Any, per_beat: int, period: float, pitch_cmd: float, roll_cmd: float = 0.0
) -> tuple[np.ndarray, np.ndarray]:
    """Wingbeat-mean attitude error and body rates (seed body axes) over the last
    wingbeat of samples ``(quat, omega_body)``: the error is the rotation vector that
    turns the body onto the command (``roll_cmd``, ``pitch_cmd``, yaw 0), ``log(S^T S_cmd)``
    -- no Euler angles, so no gimbal lock at a steep body; before a whole wingbeat the
    missing samples are the start's."""
    if not window:
        window = [(np.array(d.qpos[3:7]), C_SEED * np.array(d.qvel[3:6]))]
    quat = np.array([w[0] for w in window])
    rate = np.array([w[1] for w in window])
    r_mj = Rotation.from_quat(quat[:, [1, 2, 3, 0]]).as_matrix()
    c = np.diag(C_SEED)
    s_body = c @ r_mj @ c
    # seed axes, Z-Y-X: yaw 0, then pitch about y, then roll about x
    s_cmd = Rotation.from_euler("ZYX", [0.0, pitch_cmd, roll_cmd]).as_matrix()
    err = Rotation.from_matrix(np.swapaxes(s_body, 1, 2) @ s_cmd).as_rotvec()
    n = FIT_BEATS * per_beat
    if len(window) < n:
        pad = n - len(window)
        err = np.vstack([np.repeat(err[:1], pad, axis=0), err])
        rate = np.vstack([np.zeros((pad, 3)), rate])
    fit = _fit_matrix(n, period)
    return fit[0] @ err, fit[0] @ rate


@functools.lru_cache(maxsize=4)
def _fit_matrix(n: int, period: float) -> np.ndarray:
    return wingbeat_fit_matrix(n, period, beats=FIT_BEATS)


def flight_arrays(record: list, rows: dict, names: tuple[str, ...]) -> dict[str, np.ndarray]:
    """The flight's per-sample arrays (reduced units) from the step records."""
    t = np.array([r[0] for r in record])
    qpos = np.array([r[1] for r in record])
    qvel = np.array([r[2] for r in record])
    moment = np.array([r[3] for r in record])
    force = np.array([r[4] for r in record])
    params = np.array(rows.pop("params"))
    euler = euler_zyx(qpos[:, 3:7])
    tail = np.array(rows.pop("tail"), dtype=float).reshape(-1, 3)
    inputs = np.array(rows.pop("inputs"), dtype=float)
    arrays = {
        "t": t,
        "x": qpos[:, 0],
        "y": qpos[:, 1],
        "z": qpos[:, 2],
        "vx": qvel[:, 0],
        "vy": qvel[:, 1],
        "vz": qvel[:, 2],
        **{
            k: np.asarray(v, dtype=bool if k.endswith("saturated") else float)
            for k, v in rows.items()
        },
        **{n: params[:, i] for i, n in enumerate(names)},
        "roll": euler[:, 0],
        "pitch": euler[:, 1],
        "yaw": euler[:, 2],
        "quat": qpos[:, 3:7],
        "omega_body": C_SEED * qvel[:, 3:6],
        "moment_aero": moment,
        "pitch_moment": moment[:, 1],
        "tail_elevation": tail[:, 0],
        "tail_spread": tail[:, 1],
        "tail_roll": tail[:, 2],
        "tail_force": np.array([r[6] for r in record]),
        "power": np.array([r[5] for r in record]),
        "force_x": force[:, 0],
        "force_y": force[:, 1],
        "force_z": force[:, 2],
        "qpos": qpos,
        "qvel": qvel,
    }
    for i, (name, _kind, _b) in enumerate(INPUTS):
        arrays[f"u_{name}"] = inputs[:, i]
    return arrays


__all__ = ["attitude_estimate", "flight_arrays"]
