"""The kinematic driver: MuJoCo's CP sites move exactly as the analytic kinematics say;
qvel and qacc are the time derivatives of qpos and qvel; set_pose's contract."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from birdsim import Bird, evaluate_cycle, get_model
from birdsim.errors import BirdsimError
from birdsim.mujoco.driver import set_pose, trajectory
from birdsim.mujoco.model import aero_sites, build_model
from birdsim.physics.examples import EXAMPLES

C = np.diag([1.0, -1.0, -1.0])


def _cases():
    cases = [(ex.model, ex.params, ex.speed) for ex in EXAMPLES]
    rng = np.random.default_rng(2024)
    for name in ("base", "m1", "m2", "m3", "m4", "m5"):
        lo, hi = get_model(name).bounds
        cases.append((name, dict(zip(get_model(name).param_names, rng.uniform(lo, hi))), 0.3))
    return cases


@pytest.mark.parametrize("case", _cases(), ids=lambda c: c[0])
def test_cp_sites_move_as_the_analytic_kinematics(case):
    name, params, speed = case
    bird = Bird(semispan=1.3, chord=0.8, hand_chord=0.6, omega=1.7)
    n = 12
    cyc = evaluate_cycle(name, params, speed, bird=bird, n=n, check_bounds=False)
    m = build_model(name, bird)
    d = mujoco.MjData(m)
    tr = trajectory(m, name, params, cyc.time, bird, check_bounds=False)
    torso = m.body("torso").id
    sites = [s for s in aero_sites(name, bird) if s.side == "r"]
    res = np.zeros(6)
    for i in range(n):
        d.qpos[:], d.qvel[:] = tr.qpos[i], tr.qvel[i]
        mujoco.mj_forward(m, d)
        r = d.xmat[torso].reshape(3, 3)
        for k, s in enumerate(sites):
            sid = m.site(s.site).id
            pos_body = C @ r.T @ (d.site_xpos[sid] - d.xpos[torso])
            mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_SITE, sid, res, 0)
            vel_body = C @ r.T @ res[3:]
            # two independent computations of the same chain: agreement to rounding (1e-12)
            np.testing.assert_allclose(pos_body, cyc.cp_position_body[k, i], atol=1e-12)
            np.testing.assert_allclose(vel_body, cyc.cp_velocity_body[k, i], atol=1e-12)


@pytest.mark.parametrize("name", ["base", "m2", "m3", "m4"])
def test_qvel_and_qacc_are_the_time_derivatives(name):
    m = build_model(name)
    params = get_model(name).guess("hover")
    t = np.array([0.3, 1.1, 4.0])
    h = 1e-5
    mid = trajectory(m, name, params, t)
    plus = trajectory(m, name, params, t + h)
    minus = trajectory(m, name, params, t - h)
    for i in range(t.size):
        dq = np.zeros(m.nv)
        mujoco.mj_differentiatePos(m, dq, 2 * h, minus.qpos[i], plus.qpos[i])
        # central differences: truncation ~h^2 = 1e-10, rounding ~1e-16/h = 1e-11
        np.testing.assert_allclose(dq, mid.qvel[i], atol=1e-8)
        np.testing.assert_allclose((plus.qvel[i] - minus.qvel[i]) / (2 * h), mid.qacc[i], atol=1e-8)


def test_set_pose_pitch_position_and_velocity():
    m = build_model("m1")
    d = mujoco.MjData(m)
    set_pose(
        m,
        d,
        {"flap": 0.2},
        pitch=0.4,
        position_seed=(1.0, 2.0, -3.0),
        velocity_seed=(0.5, 0.0, -0.1),
    )
    torso = m.body("torso").id
    np.testing.assert_allclose(d.xpos[torso], [1.0, -2.0, 3.0])
    # nose up: the torso's x axis tilts towards +z by the pitch
    np.testing.assert_allclose(
        d.xmat[torso].reshape(3, 3)[:, 0], [np.cos(0.4), 0.0, np.sin(0.4)], atol=1e-15
    )
    np.testing.assert_allclose(d.qvel[:3], [0.5, 0.0, 0.1])
    set_pose(m, d, {}, pitch=0.0)  # position None keeps the torso where it is
    np.testing.assert_allclose(d.xpos[torso], [1.0, -2.0, 3.0])


def test_set_pose_rejects_bad_input_in_one_line():
    m = build_model("m1")
    d = mujoco.MjData(m)
    with pytest.raises(BirdsimError, match="names joint 'knee'; allowed: heave"):
        set_pose(m, d, {"knee": 0.1}, pitch=0.0)
    with pytest.raises(BirdsimError, match="joint elbow is not in this model; allowed: m5"):
        set_pose(m, d, {"elbow": 0.1}, pitch=0.0)
    with pytest.raises(BirdsimError, match="position_seed"):
        set_pose(m, d, {}, pitch=0.0, position_seed=(0.0, np.nan, 0.0))
    with pytest.raises(BirdsimError, match="flap is not finite"):
        set_pose(m, d, {"flap": np.inf}, pitch=0.0)
    # NaN times went straight into qpos
    with pytest.raises(BirdsimError, match="times=nan is not finite"):
        trajectory(m, "m1", get_model("m1").guess("hover"), np.array([0.0, np.nan]))
