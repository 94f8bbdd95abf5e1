"""Forces drawn by the renderer are the aero callback's forces, and the overlay's
achieved force is the dissertation's (right wing + body drag) wingbeat mean."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from birdsim import Bird, evaluate_cycle
from birdsim.mujoco.callback import AeroCallback
from birdsim.mujoco.driver import set_pose
from birdsim.mujoco.model import aero_sites, build_model
from birdsim.render.forces import dissertation_force, site_forces, wingbeat_mean


@pytest.mark.parametrize("name, strips", [("m4", 1), ("m2", 3)])
def test_site_forces_are_the_callbacks(name, strips):
    bird = Bird(strips=strips, body_drag_area=0.7)
    m = build_model(name, bird)
    m.opt.wind[:] = (-0.8, 0.1, 0.05)
    d = mujoco.MjData(m)
    set_pose(
        m,
        d,
        {"flap": 0.3, "twist": -0.2, "wrist_flap": 0.1, "stroke": 0.2},
        {"flap": 1.0, "twist": 0.7, "wrist_flap": -0.4},
        pitch=0.15,
    )
    mujoco.mj_kinematics(m, d)
    mujoco.mj_comPos(m, d)
    sites = aero_sites(name, bird)
    ids = [m.site(s.site).id for s in sites]
    forces, drag = site_forces(mujoco, m, d, sites, ids, m.site("torso_cp").id, bird)
    d.qfrc_passive[:] = 0.0
    AeroCallback(m, name, bird)(m, d)
    got = np.zeros(m.nv)
    for f, sid in zip(forces, ids):
        mujoco.mj_applyFT(m, d, f, np.zeros(3), d.site_xpos[sid], int(m.site_bodyid[sid]), got)
    tid = m.site("torso_cp").id
    mujoco.mj_applyFT(m, d, drag, np.zeros(3), d.site_xpos[tid], int(m.site_bodyid[tid]), got)
    if strips == 1:  # single element at the site: no moment, the generalised forces agree fully
        np.testing.assert_allclose(got, d.qfrc_passive, rtol=0, atol=1e-12)
    else:  # strips add moments about the site: the root's force components still agree
        np.testing.assert_allclose(got[:3], d.qfrc_passive[:3], rtol=0, atol=1e-12)
    assert np.abs(forces).max() > 1e-3 and np.linalg.norm(drag) > 1e-3


def test_achieved_force_is_the_cycles_dissertation_force():
    """Hold the bird at a wingbeat (the cross-check's setting) and average the drawn
    forces over it: the core's right wing + body drag mean, to 1e-9."""
    from birdsim.mujoco.crosscheck import HOLD_POSITION_SEED, held_model
    from birdsim.mujoco.driver import trajectory

    params = {
        "pitch": 0.1,
        "flap_amp": 0.6,
        "twist_amp": 0.3,
        "stroke_plane": 0.2,
        "wrist_amp": 0.3,
        "wrist_bias": 0.0,
        "wrist_lag": 0.2,
    }
    bird = Bird()
    cyc = evaluate_cycle("m4", params, 0.8, bird=bird, n=64)
    m = held_model("m4", params, 0.8, bird)
    d = mujoco.MjData(m)
    traj = trajectory(m, "m4", params, cyc.time, bird, position_seed=HOLD_POSITION_SEED)
    sites = aero_sites("m4", bird)
    ids = [m.site(s.site).id for s in sites]
    hist = []
    for k in range(len(cyc.time)):
        d.qpos[:], d.qvel[:] = traj.qpos[k], traj.qvel[k]
        mujoco.mj_kinematics(m, d)
        mujoco.mj_comPos(m, d)
        f, drag = site_forces(mujoco, m, d, sites, ids, m.site("torso_cp").id, bird)
        hist.append(dissertation_force(f, drag, [s.side for s in sites], bird))
    mean = np.mean(hist, axis=0)
    np.testing.assert_allclose(
        mean[[0, 2]], [float(cyc.mean.Fx), float(cyc.mean.Fz)], rtol=1e-9, atol=1e-12
    )  # mean.Fx includes the body drag


def test_wingbeat_mean():
    t = np.arange(400) / 40.0  # 40 samples per beat
    x = 2.0 + np.sin(2 * np.pi * t)
    np.testing.assert_allclose(
        wingbeat_mean(x, t), 2.0, atol=1e-12
    )  # whole beats only, also at the ends
    y = wingbeat_mean(np.column_stack([x, 3 * t]), t)
    np.testing.assert_allclose(
        y[20:-20, 1], 3 * t[20:-20], atol=1e-12
    )  # a ramp passes unchanged (centred)
