"""The free flight's fast paths (issue 22's speed target) compute what the plain paths
compute.

Tolerances: the compiled step (birdsim.flight.step_kernel) against the numpy step, one
wingbeat from the same state: 1e-12 (a Cholesky solve instead of an inverse and naive
sums instead of BLAS: round-off of a few ulp, grown over 128 steps); the attitude
error by quaternion algebra against scipy's Rotation: 1e-14 (round-off of the matrix
path); everything else exactly (bit for bit): the same floating-point operations in
the same order (the callback on Python floats, the prescription of both wings in one
pass, the ball joints, one prescription for every Jacobian input)."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from birdsim.flight import step_kernel
from birdsim.flight.attitude import INPUTS, JAC_SAMPLES, JAC_STEP, measured_jacobian, split_inputs
from birdsim.flight.flight_arrays import error_rotvec
from birdsim.flight.simulate import C_SEED, FreeBird, SimConfig
from birdsim.mujoco.ball import ball_state
from birdsim.mujoco.model import hinge_axis, pitch_quat
from birdsim.mujoco.tail import TailControls, tail_force, tail_frame
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import JOINTS, get_model

BIRD = Bird.from_toml("models/seed-bird.toml")


def _params(model: str) -> np.ndarray:
    kin = get_model(model)
    guess = kin.guess("cruise")
    return np.array([guess[n] for n in kin.param_names])


def _free_bird(model: str = "m4") -> FreeBird:
    return FreeBird(model, BIRD, _params(model), config=SimConfig(attitude="free"))


def _beat(fb: FreeBird, params: np.ndarray, left: np.ndarray) -> list:
    n = fb.config.steps_per_beat
    pres = fb.schedule.advance(params, np.arange(n) * fb.h, 0.0, n * fb.h, left)
    fb.start(np.array([0.0, 0.0, 6.0]), np.array([0.5, 0.0, 0.0]), pres)
    fb.cb.tail_controls = TailControls(0.1, 0.8, 0.05)
    rec: list = []
    times = fb.time + np.arange(n) * fb.h
    fb.step_many(fb.schedule.advance(params, times, fb.time, n * fb.h, left), np.zeros(3), rec, 2)
    return rec


def test_compiled_step_agrees_with_the_numpy_step(monkeypatch):
    if not step_kernel.AVAILABLE:
        pytest.skip("numba missing: the numpy path is the only one")
    params = _params("m4")
    left = params.copy()
    left[get_model("m4").param_names.index("flap_amp")] -= 0.05  # an asymmetric wingbeat
    out = {}
    for compiled in (True, False):
        monkeypatch.setattr(step_kernel, "AVAILABLE", compiled)
        with _free_bird() as fb:
            rec = _beat(fb, params, left)
            out[compiled] = (rec, fb.P, fb.X, fb.L, fb.projection_max, fb.root_applied_max)
    (ra, *sa), (rb, *sb) = out[True], out[False]
    assert len(ra) == len(rb) == 64
    for a, b in zip(ra, rb):
        assert a[0] == b[0]  # time
        for x, y in zip(a[1:], b[1:]):
            np.testing.assert_allclose(x, y, rtol=0, atol=1e-12)
    for x, y in zip(sa[:3], sb[:3]):
        np.testing.assert_allclose(x, y, rtol=0, atol=1e-12)
    assert sa[3] == pytest.approx(sb[3], rel=1e-6)  # the projection's size
    assert sa[4] == sb[4] == 0.0  # no force or torque on the root, exactly
    assert abs(ra[-1][1][1]) > 1e-6  # the asymmetric wingbeat moved the body sideways


def test_attitude_error_matches_scipy_rotation():
    rng = np.random.default_rng(5)
    c = np.diag(C_SEED)
    for scale in (1e-7, 1e-3, 0.1, 1.0, 5.0):
        quat = np.array([1.0, 0.0, 0.0, 0.0]) + scale * rng.normal(size=(64, 4))
        pitch = float(rng.uniform(-1.4, 1.4))
        r_mj = Rotation.from_quat(quat[:, [1, 2, 3, 0]]).as_matrix()
        s_cmd = Rotation.from_euler("y", pitch).as_matrix()
        want = Rotation.from_matrix(np.swapaxes(c @ r_mj @ c, 1, 2) @ s_cmd).as_rotvec()
        np.testing.assert_allclose(error_rotvec(quat, pitch), want, rtol=0, atol=1e-14)


@pytest.mark.parametrize("model", ["m3", "m4", "m5"])
def test_callback_on_floats_is_the_numpy_callback(model):
    fb = _free_bird(model)
    m, d, cb = fb.m, fb.d, fb.cb
    rng = np.random.default_rng(6)
    pres = fb.schedule.advance(_params(model), np.arange(8) * 0.3, 0.0, 2.4)
    assert cb._scalar and cb.single
    for k in range(8):
        d.qpos[:] = pres.qpos[k]
        d.qpos[3:7] = pitch_quat(float(rng.uniform(-0.5, 0.5)))
        d.qvel[:] = pres.qvel[k] + 0.1 * rng.normal(size=m.nv)
        m.opt.wind[:] = rng.normal(size=3) * 0.2
        mujoco.mj_fwdPosition(m, d)
        mujoco.mj_comVel(m, d)
        got = []
        for scalar in (True, False):
            cb._scalar = scalar
            d.qfrc_passive[:] = 0.0
            cb(m, d)
            got.append(d.qfrc_passive.copy())
        cb._scalar = True
        # the float path uses the math module, the array path numpy's vectorised sqrt, sin
        # and cos: the same operations, rounded alike except where numpy's SIMD functions
        # (AVX-512 on Intel) differ from libm by an ULP: measured 5.6e-17 on forces of 0.3-0.45
        np.testing.assert_allclose(got[0], got[1], rtol=0, atol=1e-15)
        assert np.any(got[0] != 0.0)


def test_tail_force_takes_its_frame_as_rows():
    ctl = TailControls(0.2, 0.7, -0.1)
    frame = tail_frame(ctl.clipped())
    for vel in ([0.5, 0.01, -0.05], [-0.2, 0.0, 0.1], [0.3, -0.1, 0.4]):
        a = tail_force(np.array(vel), ctl, span=0.5, length=0.4, rho=1.0, frame=frame)
        b = tail_force(vel, ctl, span=0.5, length=0.4, rho=1.0, frame=frame.tolist())
        assert np.array_equal(a[0], b[0]) and a[1] == b[1]


def _ball_reference(axes, q, qd, qdd):
    """The composition as the driver computed it before (quaternion products with the
    identity first, the rotation chain from an identity)."""

    def quat_mul(a, b):
        w1, x1, y1, z1 = np.moveaxis(a, -1, 0)
        w2, x2, y2, z2 = np.moveaxis(b, -1, 0)
        return np.stack(
            [
                w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
                w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
                w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
            ],
            axis=-1,
        )

    def rot(axis, angle):
        k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
        s, c = np.sin(angle)[:, None, None], np.cos(angle)[:, None, None]
        return np.eye(3) + s * k + (1.0 - c) * (k @ k)

    n, t = len(axes), len(q[0])
    quat = np.tile([1.0, 0.0, 0.0, 0.0], (t, 1))
    for a, ang in zip(axes, q):
        half = 0.5 * ang
        quat = quat_mul(quat, np.concatenate([np.cos(half)[:, None], np.sin(half)[:, None] * a], 1))
    rots = [rot(a, ang) for a, ang in zip(axes, q)]
    v, b = [None] * n, np.tile(np.eye(3), (t, 1, 1))
    for k in range(n - 1, -1, -1):
        v[k] = np.einsum("tji,j->ti", b, axes[k])
        b = rots[k] @ b
    alpha, outer = np.zeros((t, 3)), np.zeros((t, 3))
    for k in range(n - 1, -1, -1):
        rate = qd[k][:, None]
        alpha += v[k] * qdd[k][:, None] - rate * np.cross(outer, v[k])
        outer = outer + v[k] * rate
    return quat, outer, alpha


@pytest.mark.parametrize("side", ["r", "l"])
def test_ball_state_is_the_reference_composition(side):
    axes = [hinge_axis(side, JOINTS[j].axis) for j in ("sweep", "stroke", "flap", "twist")]
    rng = np.random.default_rng(7)
    for trial in range(50):
        t = int(rng.integers(1, 33))
        q, qd, qdd = ([rng.normal(size=t) for _ in range(4)] for _ in range(3))
        if trial % 2:
            q[0][:] = 0.0  # a joint at rest (zeros in the products)
        for x, y in zip(ball_state(axes, q, qd, qdd), _ball_reference(axes, q, qd, qdd)):
            assert np.array_equal(x, y)


def test_both_wings_in_one_pass_are_two_passes():
    fb = _free_bird("m4")
    sched = fb.schedule
    names = sched.names
    t = 16
    times = np.arange(t) * fb.h
    rng = np.random.default_rng(8)
    p = _params("m4") + 0.01 * rng.normal(size=(t, len(names)))
    dp, ddp = 0.1 * rng.normal(size=p.shape), rng.normal(size=p.shape)
    left = (p + 0.02, dp - 0.1, ddp * 0.5)
    # shoulder offsets (right sweep, dihedral, left sweep, dihedral)
    sw = 0.01 * rng.normal(size=(t, 4))
    got = sched.prescribe(times, p, dp, ddp, left=left, shoulder=(sw, 0 * sw, 0 * sw))
    from birdsim.mujoco.driver import wing_arrays

    right_j = sched._joints(times, p, dp, ddp, (sw[:, :2], 0 * sw[:, :2], 0 * sw[:, :2]))
    left_j = sched._joints(times, *left, (sw[:, 2:], 0 * sw[:, 2:], 0 * sw[:, 2:]))
    qpos, qvel, qacc = wing_arrays(fb.m, *right_j, samples=t, left=left_j)
    wings = fb.part.wing_dofs
    assert np.array_equal(got.qvel[:, wings], qvel[:, wings])
    assert np.array_equal(got.qacc[:, wings], qacc[:, wings])
    assert np.array_equal(got.qpos[:, 7:], qpos[:, 7:])


def test_one_prescription_for_every_jacobian_input_is_one_per_input():
    with _free_bird("m4") as fb:
        params, pitch, speed = _params("m4"), 0.15, 0.5
        m0, jac = measured_jacobian(fb, params, pitch, speed)
        # the measurement as it was: one prescription and mj_forward per input and phase
        m, cb, sched, d = fb.m, fb.cb, fb.schedule, mujoco.MjData(fb.m)
        n = JAC_SAMPLES
        times = np.arange(n) * (fb.red.period / n)
        out = []
        for i in range(len(INPUTS) + 1):
            u = np.zeros(len(INPUTS))
            if i:
                u[i - 1] = JAC_STEP
            right, left, shoulder, tail = split_inputs(sched.names, params, u)
            z = np.zeros((n, len(sched.names)))
            sw = np.tile(np.concatenate([shoulder, shoulder]), (n, 1))
            pres = sched.prescribe(
                times,
                np.tile(right, (n, 1)),
                z,
                z,
                left=(np.tile(left, (n, 1)), z, z),
                shoulder=(sw, 0 * sw, 0 * sw),
            )
            cb.tail_controls = tail
            acc = np.zeros(3)
            for k in range(n):
                d.qpos[:], d.qvel[:] = pres.qpos[k], pres.qvel[k]
                d.qpos[:3], d.qpos[3:7] = (0.0, 0.0, 6.0), pitch_quat(pitch)
                d.qvel[:3], d.qvel[3:6] = (speed, 0.0, 0.0), 0.0
                mujoco.mj_forward(m, d)
                acc += d.qfrc_passive[3:6]
            out.append(acc / n * np.array([1.0, -1.0, -1.0]))
    assert np.array_equal(m0, out[0])
    assert np.array_equal(jac, np.stack([(o - out[0]) / JAC_STEP for o in out[1:]], axis=1))
