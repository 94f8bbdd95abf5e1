"""CSV export: one row per frame, for users who plot or retarget the motion themselves.

Columns, in order:

* ``frame``, ``time`` (the bird's time units: seconds for an SI bird), ``anim_seconds``
  (seconds of animation, ``frame / fps``);
* ``x``, ``y``, ``z``: the torso origin in the MuJoCo world (x forward, y left, z up),
  the bird's length units; ``qw``, ``qx``, ``qy``, ``qz``: its orientation;
* every wing joint of the MJCF: hinges and slides by their joint name (radians; a heave
  slide in length units), each shoulder ball as its quaternion ``<joint>_qw..qz``;
* every wingbeat parameter by its table name (radians);
* ``Fx_demand``, ``Fz_demand``, ``Fx_achieved``, ``Fz_achieved``: the dissertation's
  force (the RIGHT wing plus body drag, seed earth axes, Fz < 0 is up) in table force
  units rho omega^2 s^3 c; ``V_demand``, ``V_air`` in omega s (when the source knows them).
"""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from birdsim.export.frames import FrameSequence
from birdsim.io import write_atomic


def joint_columns(frames: FrameSequence) -> dict[str, np.ndarray]:
    """Every non-root joint of the MJCF as named columns (balls as quaternions)."""
    import mujoco

    from birdsim.mujoco.legged import build_model_for

    m = build_model_for(frames.model, frames.bird, frames.qpos.shape[1])  # legs if any
    cols: dict[str, np.ndarray] = {}
    for j in range(m.njnt):
        kind = m.jnt_type[j]
        if kind == mujoco.mjtJoint.mjJNT_FREE:
            continue
        name = m.joint(j).name
        adr = m.jnt_qposadr[j]
        if kind == mujoco.mjtJoint.mjJNT_BALL:
            for k, c in enumerate("wxyz"):
                cols[f"{name}_q{c}"] = frames.qpos[:, adr + k]
        else:
            cols[name] = frames.qpos[:, adr]
    return cols


def columns(frames: FrameSequence) -> dict[str, np.ndarray]:
    """The CSV's columns, in order (see the module docstring)."""
    n = frames.frames
    cols: dict[str, np.ndarray] = {
        "frame": np.arange(n),
        "time": frames.time,
        "anim_seconds": np.arange(n) / frames.fps,
    }
    for k, c in enumerate("xyz"):
        cols[c] = frames.body_position[:, k]
    for k, c in enumerate("wxyz"):
        cols[f"q{c}"] = frames.body_quat[:, k]
    cols.update(joint_columns(frames))
    cols.update(frames.params)
    cols.update(frames.forces)
    return cols


def write_csv(frames: FrameSequence, out: str | Path) -> Path:
    """Write ``frames`` as CSV to ``out`` (atomically).

    Args:
        frames: the frame source.
        out: the output path (its folder must exist and be writable).

    Returns:
        The path written.
    """
    cols = columns(frames)
    names = list(cols)
    data = np.column_stack([np.asarray(cols[k], dtype=float) for k in names]) + 0.0  # no '-0'
    buf = io.StringIO()
    buf.write(",".join(names) + "\n")
    fmt = ["%d"] + ["%.10g"] * (len(names) - 1)
    np.savetxt(buf, data, delimiter=",", fmt=fmt)
    out = Path(out)
    write_atomic(out, buf.getvalue().encode())
    return out


__all__ = ["columns", "joint_columns", "write_csv"]
