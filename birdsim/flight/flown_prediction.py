"""A free flight's own continuation predicted from its state (reduced units): the flight's
MjData, momenta, wingbeat schedule and tail copied, flown on with the inputs held, and
put back bit for bit.  The pitch plant of the flying, rocking body as the flight has it
(the held-body Jacobians see the periodic rocking only): used by
:mod:`birdsim.flight.flown_pitch` (the flare's gate) and ``scripts/flown_pitch_study.py``
(docs/free-body.md, "the landing: a pitch plant from the flown state")."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator

import mujoco
import numpy as np

from birdsim.flight.fast_interval import interval
from birdsim.mujoco.tail import TailControls

#: Samples per wingbeat of a prediction.
SAMPLES = 16


@contextlib.contextmanager
def restored(fb) -> Iterator[None]:
    """Everything a flight's interval changes in ``fb`` (a FreeBird) saved and put back
    on exit: the MjData in place, the model's wind, every attribute of the bird, its
    callback, its schedule and the schedule's two filters (arrays in place)."""
    m, d = fb.m, fb.d
    saved_d = mujoco.MjData(m)
    mujoco.mj_copyData(saved_d, m, d)
    wind = m.opt.wind.copy()
    s = fb.schedule
    attrs = []
    for obj in (fb, fb.cb, s, s.filter, s.input_filter):
        items = dict(obj.__dict__)
        arrays = {k: v.copy() for k, v in items.items() if isinstance(v, np.ndarray)}
        attrs.append((obj, items, arrays))
    try:
        yield
    finally:
        mujoco.mj_copyData(d, m, saved_d)
        m.opt.wind[:] = wind
        for obj, items, arrays in attrs:
            obj.__dict__.clear()
            obj.__dict__.update(items)
            for k, v in arrays.items():
                items[k][...] = v


def predict(
    fb, args: tuple, shoulder: np.ndarray, tail: TailControls, beats: float
) -> tuple[np.ndarray, np.ndarray]:
    """(times (n,), the body's quaternions (n, 4), w x y z) of ``fb``'s flight continued
    for ``beats`` wingbeats from now (:func:`predict_root`)."""
    t, qpos = predict_root(fb, args, shoulder, tail, beats)
    return t, qpos[:, 3:7]


def predict_root(
    fb, args: tuple, shoulder: np.ndarray, tail: TailControls, beats: float
) -> tuple[np.ndarray, np.ndarray]:
    """(times (n,), the root's coordinates (n, 7): world position in semispans, then the
    quaternion w x y z) of ``fb``'s flight continued for ``beats`` wingbeats from now,
    :data:`SAMPLES` a wingbeat, with ``args`` (the flight's next interval's right and left
    wingbeat targets, stroke-plane offset and wind), the shoulder target ``shoulder``
    (sweep, dihedral) and ``tail`` held; ``fb`` is left as it was (:func:`restored`)."""
    right, left, offset, wind = args
    n = int(round(beats * fb.config.steps_per_beat))
    rec: list = []
    with restored(fb):
        # a flock's lockstep replaces this bird's step_many to step every bird together; a
        # prediction is this bird's own look-ahead, stepped alone (put back on exit)
        fb.__dict__.pop("step_many", None)
        fb.schedule.shoulder_target = np.asarray(shoulder, dtype=float)
        fb.cb.tail_controls = tail
        t = fb.time
        every = fb.config.steps_per_beat // SAMPLES
        interval(fb, right, t + np.arange(n) * fb.h, t, n * fb.h, left, offset, wind, rec, every)
    return np.array([r[0] for r in rec]), np.array([r[1][0:7] for r in rec])


def nose_up(quat: np.ndarray, base: np.ndarray | None = None) -> np.ndarray:
    """The nose-up rotation (rad) of ``quat`` (n, 4; w x y z) from ``base`` (default: the
    world) about the base's body y axis (MuJoCo: nose up about -y), unfolded past 90
    degrees (within +-180)."""
    quat = np.asarray(quat, dtype=float)
    if base is None:
        base = np.tile([1.0, 0.0, 0.0, 0.0], (len(quat), 1))
    w0, v0, w1, v1 = base[:, 0], base[:, 1:], quat[:, 0], quat[:, 1:]
    w = w0 * w1 + np.sum(v0 * v1, axis=1)  # conj(base) * quat
    v = w0[:, None] * v1 - w1[:, None] * v0 - np.cross(v0, v1)
    s = np.where(w < 0.0, -1.0, 1.0)
    return -2.0 * np.arctan2(s * v[:, 1], s * w)


__all__ = ["SAMPLES", "nose_up", "predict", "predict_root", "restored"]
