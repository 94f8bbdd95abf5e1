"""MuJoCo cross-check of the whole-bird mean moment with an asymmetric wingbeat, with
and without a body rate.

The torso is held at the wingbeat's pitch (gravity and contacts off, the freestream as
``opt.wind``), the two wings follow different prescriptions (the right and left wings of
:func:`birdsim.physics.moments.wing_params`), and ``mj_inverse`` gives the torque that
holds the root at the N analytic samples, aero callback on and off (the difference
removes the wings' inertial torques exactly, as ``mujoco/crosscheck.py`` does for the
force).  A free joint's rotational generalised force is the torque about the body's
origin (the torso origin, where the core's moments are taken) in the body's own frame
(MuJoCo axes), so seed body axes are ``diag(1, -1, -1)`` of it.  Both sides use the same
blade-element force on the same control points, so the means agree to round-off (1e-12
against moments of O(0.01-0.1)).
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from birdsim.mujoco.callback import aero_forces
from birdsim.mujoco.crosscheck import HOLD_POSITION_SEED, held_model
from birdsim.mujoco.driver import set_root, wing_arrays
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import sample_phases
from birdsim.physics.kinematics import get_model
from birdsim.physics.moments import input_model, wing_params, wingbeat_moments

C = np.array([1.0, -1.0, -1.0])


def _side_arrays(m, mx, params, times, bird):
    p = {k: np.broadcast_to(np.asarray(v, dtype=float), times.shape) for k, v in params.items()}
    angles, rates, accs = {}, {}, {}
    for name, motion in mx.joint_motion(p, bird).items():
        q, qd, qdd = motion.at(bird.omega * times, bird.omega)
        angles[name], rates[name], accs[name] = (
            np.broadcast_to(x, times.shape) for x in (q, qd, qdd)
        )
    return wing_arrays(m, angles, rates, accs, samples=times.shape[0])


def _left_indices(m):
    qpos, dof = [], []
    for j in range(m.njnt):
        if m.joint(j).name.startswith("l_"):
            size_q = {0: 7, 1: 4, 2: 1, 3: 1}[int(m.jnt_type[j])]
            size_v = {0: 6, 1: 3, 2: 1, 3: 1}[int(m.jnt_type[j])]
            qpos += list(range(m.jnt_qposadr[j], m.jnt_qposadr[j] + size_q))
            dof += list(range(m.jnt_dofadr[j], m.jnt_dofadr[j] + size_v))
    return np.array(qpos), np.array(dof)


@pytest.mark.parametrize(
    "model, V, rate",
    [
        ("m1", 0.5, (0.0, 0.0, 0.0)),
        ("m3", 0.0, (0.0, 0.0, 0.0)),
        ("m3", 0.6, (0.0, 0.0, 0.0)),
        ("m4", 0.4, (0.0, 0.0, 0.0)),
        ("m3", 0.5, (0.3, -0.2, 0.25)),
        ("m4", 0.0, (-0.2, 0.1, 0.3)),
    ],
)
def test_mean_moment_matches_mujoco_with_asymmetric_wings(model, V, rate):
    # with a body rate the torso turns at omega at its pitched attitude in every sample
    # (the free joint's angular velocity is in the body frame, MuJoCo axes: C omega); the
    # callback's site velocities then carry omega x r, as the core's elements do
    bird = Bird()
    params = get_model(model).guess("hover" if V == 0 else "cruise")
    u = np.array([0.06, 0.08, -0.05, 0.1])
    right, left = wing_params(model, params, u)
    mx = input_model(model)
    n = 64
    times = sample_phases(n, False) / bird.omega
    m = held_model(model, params, V, bird)
    qpos, qvel, qacc = _side_arrays(m, mx, right, times, bird)
    lq, lv, lacc = _side_arrays(m, mx, left, times, bird)
    iq, iv = _left_indices(m)
    qpos[:, iq], qvel[:, iv], qacc[:, iv] = lq[:, iq], lv[:, iv], lacc[:, iv]
    set_root(m, qpos, qvel, pitch=params["pitch"], position_seed=HOLD_POSITION_SEED)
    qvel[:, 3:6] = C * np.asarray(rate)
    d = mujoco.MjData(m)

    def held_torque() -> np.ndarray:
        out = np.zeros((n, 3))
        for i in range(n):
            d.qpos[:], d.qvel[:], d.qacc[:] = qpos[i], qvel[i], qacc[i]
            mujoco.mj_inverse(m, d)
            out[i] = d.qfrc_inverse[3:6]
        return out.mean(axis=0)

    off = held_torque()
    with aero_forces(m, model, bird):
        on = held_torque()
    mujoco_moment = -(on - off) * C
    core = wingbeat_moments(model, params, V, bird, u=u, n=n, body_rate=rate)
    assert np.abs(core.moment_body[[0, 2]]).max() > 1e-3  # the asymmetry rolls and yaws
    np.testing.assert_allclose(mujoco_moment, core.moment_body, rtol=0, atol=1e-12)
