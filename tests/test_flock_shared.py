"""A steered flock's birds in one MuJoCo model (issue 27 item 2; birdsim/flight/flock_model.py,
flock_step.py): the shared model's blocks are the one-bird models, its mass matrix's
blocks are theirs, and the flock flown in it is the flock flown bird by bird in lockstep.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from test_flock_steering import _flock  # noqa: E402 (the tests' flock file writer)

from birdsim.flight import flock_step
from birdsim.flight.flock_fly import fly_flock, jobs_for
from birdsim.flight.flock_model import DataMap, build_flock_model, copy_in
from birdsim.mujoco.model import build_model
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird

pytestmark = pytest.mark.skipif(flock_step.run_flock_steps is None, reason="needs numba")


def _one(red):
    m = build_model("m3", red, scene=False)
    m.opt.timestep = red.period / 128
    m.opt.gravity[:] = (0.0, 0.0, -red.gravity)
    return m


def test_the_shared_model_is_the_one_bird_models_side_by_side():
    """Three birds: each block's masses, frames and dynamics are its own model's.  After
    one step from the same state the shared data's block equals the one-bird data's
    bitwise (MuJoCo's per-tree arithmetic is the same; the trees never touch), and the
    dense mass matrix filled from the shared sparse rows is ``mj_fullM``'s."""
    red = reduced_bird(Bird())
    one = _one(red)
    shared, blocks = build_flock_model([("m3", red, one)] * 3)
    assert (shared.nq, shared.nv, shared.nbody) == (3 * one.nq, 3 * one.nv, 1 + 3 * (one.nbody - 1))
    D = mujoco.MjData(shared)
    rng = np.random.default_rng(1)
    ones = []
    for b in blocks:
        d = mujoco.MjData(one)
        d.qpos[:3] = rng.normal(size=3)
        d.qpos[7:] += rng.normal(scale=0.2, size=one.nq - 7)
        d.qvel[:] = rng.normal(scale=0.5, size=one.nv)
        copy_in(D, d, b)
        mujoco.mj_step(one, d)
        ones.append(d)
    mujoco.mj_step(shared, D)
    data_map = DataMap(shared, one, 3)
    M = np.zeros((one.nv, one.nv))
    for b, d in zip(blocks, ones):
        back = mujoco.MjData(one)
        data_map.copy_out(D, back, b)
        for name in ("qpos", "qvel", "qacc", "site_xpos", "qfrc_bias"):
            assert np.array_equal(getattr(back, name), getattr(d, name)), (b.index, name)
        for name in ("xpos", "xmat", "subtree_com", "cvel", "cinert"):  # the world's row apart
            assert np.array_equal(getattr(back, name)[1:], getattr(d, name)[1:]), (b.index, name)
        fill = getattr(flock_step._fill_block, "py_func", flock_step._fill_block)
        fill(D.M, shared.M_rowadr, shared.M_rownnz, shared.M_colind, b.dof, M)
        full = np.zeros((one.nv, one.nv))
        mujoco.mj_fullM(one, d, full)
        assert np.array_equal(M, full), b.index


def test_the_shared_model_flies_the_lockstep_flight(tmp_path, monkeypatch):
    """Three steered birds, 2 wingbeats: stepped in one model (one compiled call over
    every bird's sites and blocks) and bird by bird in lockstep.  Tolerance 1e-12
    semispan: the same arithmetic on the same numbers; measured bitwise equal."""
    offsets = [(0.0, 0.0, 0.0), (-3.5, 3.5, 0.0), (-3.5, -3.5, 0.0)]
    _, jobs = jobs_for(_flock(tmp_path, "steer", offsets), "m3", seconds=2.0 * 2.0 * np.pi)
    calls = []
    step = flock_step.SharedFlock.step
    monkeypatch.setattr(flock_step.SharedFlock, "step", lambda s: calls.append(1) or step(s))
    monkeypatch.setattr(flock_step, "SHARED_MODEL", True)
    shared = fly_flock(jobs)
    assert len(calls) == 16  # 8 control intervals a wingbeat, every bird in each call
    monkeypatch.setattr(flock_step, "SHARED_MODEL", False)
    alone = fly_flock(jobs)
    assert len(calls) == 16
    for k in ("x", "y", "z", "qpos", "qvel", "power", "steer", "pitch"):
        diff = np.max(np.abs(np.asarray(shared[k], float) - np.asarray(alone[k], float)))
        assert diff <= 1e-12, (k, diff)
    assert float(np.max(np.abs(shared["steer"]))) > 0.0  # the rules acted


def test_two_processes_fly_the_one_process_flight(tmp_path):
    """The same three steered birds split between two processes (states exchanged at
    every control update): the flight of one process.  Tolerance 1e-9 semispan: the same
    arithmetic in fresh processes, whose numpy sums may differ in the last bits with the
    arrays' alignment (docs/fast-flight.md, "Batches"); the 12-bird preset over 36
    wingbeats on 2 processes was measured within 3e-11 semispan (qvel 2.2e-10)."""
    offsets = [(0.0, 0.0, 0.0), (-3.5, 3.5, 0.0), (-3.5, -3.5, 0.0)]
    _, jobs = jobs_for(_flock(tmp_path, "steer", offsets), "m3", seconds=2.0 * 2.0 * np.pi)
    one = fly_flock(jobs)
    two = fly_flock(jobs, processes=2)
    for k in ("x", "y", "z", "qpos", "qvel", "steer"):
        diff = np.max(np.abs(np.asarray(one[k], float) - np.asarray(two[k], float)))
        assert diff <= 1e-9, (k, diff)
    assert float(np.max(np.abs(two["steer"]))) > 0.0
