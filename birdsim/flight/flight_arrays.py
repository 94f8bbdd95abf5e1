"""A free flight's per-sample arrays (reduced units) from the simulation's step records,
and the attitude loop's wingbeat-mean estimate from the last wingbeat of samples."""

from __future__ import annotations

import functools
from typing import Any

import numpy as np

from birdsim.flight import fast_estimate
from birdsim.flight.attitude_jacobians import INPUTS
from birdsim.flight.body_attitude import FIT_BEATS, euler_zyx, wingbeat_fit_matrix
from birdsim.flight.simulate import C_SEED


def attitude_estimate(
    window: list,
    d: Any,
    per_beat: int,
    period: float,
    pitch_cmd: float,
    roll_cmd: float = 0.0,
    yaw_cmd: float = 0.0,
) -> tuple[np.ndarray, np.ndarray]:
    """Wingbeat-mean attitude error and body rates (seed body axes) over the last
    wingbeat of samples ``(quat, omega_body)`` (a list of pairs, or the pair of arrays): the error is the rotation vector that
    turns the body onto the command (``roll_cmd``, ``pitch_cmd``, ``yaw_cmd``), ``log(S^T S_cmd)``
    -- no Euler angles, so no gimbal lock at a steep body; before a whole wingbeat the
    missing samples are the start's."""
    if isinstance(window, tuple):  # the samples as two arrays (quat (n, 4), omega (n, 3))
        quat, rate = np.asarray(window[0], dtype=float), np.asarray(window[1], dtype=float)
        if not len(quat):
            window = []
    if not isinstance(window, tuple):
        if not window:
            window = [(np.array(d.qpos[3:7]), C_SEED * np.array(d.qvel[3:6]))]
        quat = np.array([w[0] for w in window])
        rate = np.array([w[1] for w in window])
    err = fast_estimate.error_rotvec(quat, pitch_cmd, roll_cmd, yaw_cmd)  # compiled
    if err is None:
        err = error_rotvec(quat, pitch_cmd, roll_cmd, yaw_cmd)
    n = FIT_BEATS * per_beat
    if len(quat) < n:
        pad = n - len(quat)
        err = np.vstack([np.repeat(err[:1], pad, axis=0), err])
        rate = np.vstack([np.zeros((pad, 3)), rate])
    fit = fit_matrix(n, period)
    return fit[0] @ err, fit[0] @ rate


def new_samples(
    fb: Any, record: list, start: int, blocks: list | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(t (n,), qpos (n, nq), qvel (n, nv)) of the step records ``record[start:]``
    (tuples: time, qpos, qvel, ...): the compiled step loop's own arrays of them where it
    left them for this record at this length (``fb.last_samples``: the same numbers), else
    made of the records.  ``blocks``: each call's arrays (t, qpos, qvel, the step loop's
    outputs) appended, or None where the records were read (:func:`flight_arrays`)."""
    got = fb.__dict__.pop("last_samples", None)
    if got is not None and got[0] is record and got[1] == len(record) == start + len(got[2]):
        if blocks is not None:
            blocks.append(got[2:])
        return np.array(got[2]), got[3], got[4]
    if blocks is not None:
        blocks.append(None)
    new = record[start:]
    return (
        np.array([r[0] for r in new]),
        np.array([r[1] for r in new]),
        np.array([r[2] for r in new]),
    )


def keep_last(window: tuple, new: tuple, n: int) -> tuple:
    """``window``'s arrays (samples along the first axis) with ``new``'s appended, the
    last ``n`` samples of each."""
    return tuple(np.concatenate([a, b])[-n:] for a, b in zip(window, new))


def error_rotvec(
    quat: np.ndarray, pitch_cmd: float, roll_cmd: float = 0.0, yaw_cmd: float = 0.0
) -> np.ndarray:
    """The rotation vectors (n, 3) of ``S^T S_cmd`` for MuJoCo quaternions ``quat`` (n, 4)
    (w, x, y, z): S the body's orientation in seed axes (``C R C``, C = diag(1, -1, -1),
    whose quaternion is (w, x, -y, -z)), S_cmd the Z-Y-X attitude: ``yaw_cmd`` about seed
    z, then ``pitch_cmd`` about y, then ``roll_cmd`` about x.
    Quaternion algebra, the numbers of scipy's ``Rotation`` (matrix product, then
    ``as_rotvec``) to round-off (``tests/test_step_kernel.py``), in a few numpy calls."""
    q = quat / np.sqrt(np.einsum("ij,ij->i", quat, quat))[:, None]
    w, x, y, z = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    c, s = np.cos(0.5 * pitch_cmd), np.sin(0.5 * pitch_cmd)
    v = np.empty((len(q), 3))
    if roll_cmd == 0.0 and yaw_cmd == 0.0:
        # conj(q_S) * q_cmd, q_cmd = (c, 0, s, 0)
        rw = w * c - y * s
        v[:, 0] = -x * c - z * s
        v[:, 1] = w * s + y * c
        v[:, 2] = z * c - x * s
    else:
        # q_cmd = (cy, 0, 0, sy) * (c, 0, s, 0) * (cr, sr, 0, 0)
        cr, sr = np.cos(0.5 * roll_cmd), np.sin(0.5 * roll_cmd)
        cy, sy = np.cos(0.5 * yaw_cmd), np.sin(0.5 * yaw_cmd)
        yp = (cy * c, -sy * s, cy * s, sy * c)  # (cy, 0, 0, sy) * (c, 0, s, 0)
        a2, b2, c2, d2 = _qmul(yp, (cr, sr, 0.0, 0.0))
        a1, b1, c1, d1 = w, -x, y, z  # conj(q_S)
        rw = a1 * a2 - b1 * b2 - c1 * c2 - d1 * d2
        v[:, 0] = a1 * b2 + b1 * a2 + c1 * d2 - d1 * c2
        v[:, 1] = a1 * c2 - b1 * d2 + c1 * a2 + d1 * b2
        v[:, 2] = a1 * d2 + b1 * c2 - c1 * b2 + d1 * a2
    flip = rw < 0.0  # the rotation of angle in [0, pi]
    rw = np.where(flip, -rw, rw)
    v[flip] *= -1.0
    nv = np.sqrt(np.einsum("ij,ij->i", v, v))
    angle = 2.0 * np.arctan2(nv, rw)
    small = angle <= 1e-3
    a2 = angle * angle
    with np.errstate(divide="ignore", invalid="ignore"):
        taylor = 2.0 + a2 / 12.0 + 7.0 * a2 * a2 / 2880.0
        scale = np.where(small, taylor, angle / np.sin(0.5 * angle))
    return scale[:, None] * v


def _qmul(p: tuple, q: tuple) -> tuple:
    """The quaternion product p q of (w, x, y, z) tuples."""
    a1, b1, c1, d1 = p
    a2, b2, c2, d2 = q
    return (
        a1 * a2 - b1 * b2 - c1 * c2 - d1 * d2,
        a1 * b2 + b1 * a2 + c1 * d2 - d1 * c2,
        a1 * c2 - b1 * d2 + c1 * a2 + d1 * b2,
        a1 * d2 + b1 * c2 - c1 * b2 + d1 * a2,
    )


@functools.lru_cache(maxsize=4)
def fit_matrix(n: int, period: float) -> np.ndarray:
    """:func:`birdsim.flight.body_attitude.wingbeat_fit_matrix` over FIT_BEATS, cached."""
    return wingbeat_fit_matrix(n, period, beats=FIT_BEATS)


def extend_rows(
    rows: dict,
    refs: dict,
    y_ref: Any,
    cmd: Any,
    tail: Any,
    att: Any,
    turn_cmd: Any,
    gates: tuple = (),
) -> None:
    """Append one control interval's references and controls to the flight's ``rows``,
    one entry per new log sample (``refs["x"]`` has one per sample).  The inputs are the
    ones flown: the loop's ``att.u`` with the entries an engaged gate of ``gates``
    (:mod:`birdsim.flight.flown_pitch`, :mod:`birdsim.flight.flown_lateral`; None where
    absent) chose instead (its ``flown_u``)."""
    n_new = len(refs["x"])
    rows["x_ref"].extend(np.asarray(refs["x"]).tolist())
    rows["z_ref"].extend(np.asarray(refs["z"]).tolist())
    rows["y_ref"].extend(np.asarray(y_ref).tolist())
    rows["Fx_demand"].extend([cmd.Fx] * n_new)
    rows["Fz_demand"].extend([cmd.Fz] * n_new)
    rows["climb_demand"].extend([cmd.climb] * n_new)
    rows["saturated"].extend([cmd.saturated] * n_new)
    rows["tail"].extend([(tail.elevation, tail.spread, tail.roll)] * n_new)
    u = att.u.copy()
    for gate in gates:
        if gate is not None and gate.flown_u is not None:
            u[gate.flown_u[0]] = gate.flown_u[1]
    rows["inputs"].extend([u] * n_new)
    rows["attitude_saturated"].extend([att.saturated] * n_new)
    if turn_cmd is not None:
        rows["bank_command"].extend([turn_cmd.bank] * n_new)
        rows["heading_command"].extend([turn_cmd.heading] * n_new)


def _from_blocks(blocks: list | None, n: int) -> tuple | None:
    """(t, qpos, qvel, moment, force, power, tail force) of the first ``n`` samples from
    :func:`new_samples`' blocks, as the records make them (contiguous arrays, the same
    numbers); None where a block is missing."""
    if not blocks or any(b is None for b in blocks) or sum(len(b[0]) for b in blocks) < n:
        return None
    out = np.concatenate([b[3] for b in blocks])[:n]
    t = np.array([x for b in blocks for x in b[0]][:n])
    qpos = np.concatenate([b[1] for b in blocks])[:n]
    qvel = np.concatenate([b[2] for b in blocks])[:n]
    parts = (out[:, 0:3], out[:, 3:6], out[:, 6], out[:, 7:10])
    return (t, qpos, qvel, *(np.ascontiguousarray(a) for a in parts))


def flight_arrays(
    record: list, rows: dict, names: tuple[str, ...], blocks: list | None = None
) -> dict[str, np.ndarray]:
    """The flight's per-sample arrays (reduced units) from the step records (or, where
    every control interval left them, :func:`new_samples`' ``blocks``: the same numbers)."""
    got = _from_blocks(blocks, len(record))
    if got is not None:
        t, qpos, qvel, moment, force, power, tail_force = got
    else:
        t = np.array([r[0] for r in record])
        qpos = np.array([r[1] for r in record])
        qvel = np.array([r[2] for r in record])
        moment = np.array([r[3] for r in record])
        force = np.array([r[4] for r in record])
        power = np.array([r[5] for r in record])
        tail_force = np.array([r[6] for r in record])
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
        "tail_force": tail_force,
        "power": power,
        "force_x": force[:, 0],
        "force_y": force[:, 1],
        "force_z": force[:, 2],
        "qpos": qpos,
        "qvel": qvel,
    }
    for i, (name, _kind, _b) in enumerate(INPUTS):
        arrays[f"u_{name}"] = inputs[:, i]
    return arrays


__all__ = ["attitude_estimate", "error_rotvec", "fit_matrix", "flight_arrays"]
