"""The contact phases are deterministic (issue 25): a leg law must not read MuJoCo's
contact forces inside a step (between ``mj_step1`` and ``mj_step2`` ``efc_force`` is
not solved yet and holds whatever its arena memory held: the landing's peak foot force
came out 3.27 or 3.14 x weight from run to run of the same code)."""

from __future__ import annotations

import mujoco
import numpy as np

from birdsim.flight.contact import ContactBird
from birdsim.flight.legwork import touchdown, touchdown_speed
from birdsim.flight.presets import demo_bird

PERCH_TOP = np.array([6.0, 0.0, 1.54])  # the arena's perch bar's top (semispans)


def _touchdown(monkeypatch, garbage: float):
    """A touchdown on the perch with ``efc_force`` overwritten by ``garbage`` after
    every ``mj_step1`` (what an uninitialised arena may hold)."""
    real = mujoco.mj_step1

    def step1(m, d):
        real(m, d)
        d.efc_force[:] = garbage

    monkeypatch.setattr(mujoco, "mj_step1", step1)
    with ContactBird("m3", demo_bird()) as cb:
        r = touchdown(cb, PERCH_TOP, touchdown_speed(), 3.0)
    monkeypatch.setattr(mujoco, "mj_step1", real)
    return r


def test_touchdown_does_not_read_unsolved_contact_forces(monkeypatch):
    runs = [_touchdown(monkeypatch, g) for g in (0.0, 1e3, 0.0)]
    # bitwise: the same inputs through MuJoCo give the same numbers, whatever the arena
    for r in runs[1:]:
        for k in ("qpos", "qvel", "foot_normal"):
            assert np.array_equal(r.record[k], runs[0].record[k]), k
        assert r.peak_foot_over_weight == runs[0].peak_foot_over_weight
        assert r.rest_beats == runs[0].rest_beats
    assert runs[0].peak_foot_over_weight > 1.0  # the legs did brake the fall
