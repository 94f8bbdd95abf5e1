"""Control-point kinematics: exact velocities, mirror convention, parameter checks."""

from __future__ import annotations

import math

import numpy as np
import pytest

import birdsim
from birdsim import Bird, get_model
from birdsim.errors import ParameterError, UnknownModelError
from birdsim.physics.kinematics import (
    JointState,
    Offset,
    joint_states,
    points_in_body,
    validate_params,
)

rng = np.random.default_rng(3)


def _random(model: str) -> dict[str, np.ndarray]:
    lo, hi = get_model(model).bounds
    x = lo + (hi - lo) * rng.random((4, len(lo)))
    return {n: x[:, i] for i, n in enumerate(get_model(model).param_names)}


def _points(model: str, params, bird: Bird, phases: np.ndarray):
    m = get_model(model)
    states = joint_states(m, params, bird, phases, trailing=1)
    out = []
    for chain, span, _ in m.chain_with_geometry(bird):
        pos, vel = points_in_body(chain, states, np.array([0.3 * span, span]))
        total = [sum(v[i] for v in vel.values()) for i in range(3)]
        out.append(
            (np.stack(np.broadcast_arrays(*pos), -1), np.stack(np.broadcast_arrays(*total), -1))
        )
    return out


@pytest.mark.parametrize("model", list(birdsim.MODELS))
def test_exact_velocity_equals_finite_difference(model):
    bird = Bird()
    params = _random(model)
    phases = np.linspace(0, 2 * np.pi, 17)
    h = 1e-5  # central difference: truncation ~h^2 = 1e-10, round-off ~1e-16/h = 1e-11
    exact = _points(model, params, bird, phases)
    ahead = _points(model, params, bird, phases + h)
    behind = _points(model, params, bird, phases - h)
    for (_, v), (pa, _), (pb, _) in zip(exact, ahead, behind):
        np.testing.assert_allclose(np.broadcast_to(v, pa.shape), (pa - pb) / (2 * h), atol=1e-8)


@pytest.mark.parametrize("model", ["m1", "m2", "m3", "m4", "m5"])
def test_left_wing_is_the_mirror_image(model):
    """The left wing's joints are the right wing's with flap and sweep angles negated
    (rotations about body x and z change sense in the mirror y -> -y) and the span
    along -y; its points are then the right wing's points mirrored, M = diag(1, -1, 1).
    The MuJoCo model builds its left wing with this convention."""
    m = get_model(model)
    bird = Bird()
    params = _random(model)
    phases = np.linspace(0, 2 * np.pi, 9)
    right = joint_states(m, params, bird, phases, trailing=1)
    flip = {"x": -1.0, "z": -1.0, "y": 1.0}
    left = {}
    for name, st in right.items():
        axis = next(j.axis for j in m.joints if j.name == name)
        f = flip[axis]
        left[name] = JointState(st.cos, f * st.sin, f * st.angle, f * st.rate)
    mirror = np.array([1.0, -1.0, 1.0])
    for chain, span, _ in m.chain_with_geometry(bird):
        r = np.array([0.5 * span])
        pos_r, vel_r = points_in_body(chain, right, r)
        # the left wing's chain: offsets along -y
        left_chain = tuple(
            Offset(-el.span, el.role) if isinstance(el, Offset) else el for el in chain
        )
        pos_l, vel_l = points_in_body(left_chain, left, -r)
        for i in range(3):
            left_i, right_i = np.broadcast_arrays(pos_l[i], mirror[i] * pos_r[i])
            np.testing.assert_allclose(left_i, right_i, atol=1e-14)
            vl = sum(v[i] for v in vel_l.values())
            vr = sum(v[i] for v in vel_r.values())
            left_i, right_i = np.broadcast_arrays(vl, mirror[i] * vr)
            np.testing.assert_allclose(left_i, right_i, atol=1e-14)


def test_base_model_translates_the_wing():
    # eq 55: CP velocity (0, 0, s/2 omega Phi_f cos wt), no rotation by flapping
    c = birdsim.evaluate_cycle("base", dict(pitch=0.3, flap_amp=1.0, twist_amp=0.2), 0.0, n=8)
    t = c.time
    np.testing.assert_allclose(c.cp_velocity_body[0, :, 2], 0.5 * np.cos(t), atol=1e-15)
    np.testing.assert_allclose(c.cp_velocity_body[0, :, :2], 0.0, atol=1e-15)
    np.testing.assert_allclose(c.cp_position_body[0, :, 1], 0.5, atol=1e-15)


def test_m3_velocity_is_eq73():
    th_sp, amp = 0.3, 1.1
    c = birdsim.evaluate_cycle(
        "m3", dict(pitch=0.3, flap_amp=amp, twist_amp=0.2, stroke_plane=th_sp), 0.0, n=16
    )
    t = c.time
    phi = amp * np.sin(t)
    w = 0.5 * amp * np.cos(t)
    expected = np.stack(
        [w * np.cos(phi) * np.sin(th_sp), -w * np.sin(phi), w * np.cos(phi) * np.cos(th_sp)], -1
    )
    np.testing.assert_allclose(c.cp_velocity_body[0], expected, atol=1e-15)


def test_m4_geometry_hand_is_a_third():
    b = Bird()
    arm, hand = b.panels("m4")
    assert (
        arm.span == pytest.approx(2 / 3)
        and hand.span == pytest.approx(1 / 3)
        and hand.root_offset == pytest.approx(2 / 3)
    )
    # with the wing still and flat the hand CP sits at the arm span plus half the hand
    p = dict(
        pitch=0.0,
        flap_amp=0.0,
        twist_amp=0.0,
        stroke_plane=0.0,
        wrist_amp=0.0,
        wrist_bias=0.0,
        wrist_lag=0.0,
    )
    c = birdsim.evaluate_cycle("m4", p, 0.0, n=4)
    np.testing.assert_allclose(c.cp_position_body[1, 0], [0.0, 2 / 3 + 1 / 6, 0.0], atol=1e-15)


def test_guesses_are_inside_bounds():
    for m in birdsim.MODELS.values():
        for regime in ("hover", "cruise"):
            validate_params(m, m.guess(regime))
    with pytest.raises(ParameterError, match="regime='glide' is unknown; allowed: hover, cruise"):
        get_model("m1").guess("glide")


def test_parameter_errors_are_one_clear_line():
    m = get_model("m1")
    good = dict(pitch=0.1, flap_amp=0.2, twist_amp=0.3)
    cases = {
        "unknown": ({**good, "sweep": 0.1}, "'sweep' is unknown"),
        "missing": ({"pitch": 0.1, "flap_amp": 0.2}, "'twist_amp' is missing"),
        "bounds": ({**good, "twist_amp": 1.0}, "out of bounds"),
        "nan": ({**good, "pitch": math.nan}, "not finite"),
        "text": ({**good, "pitch": "abc"}, "not a number"),
    }
    for label, (params, text) in cases.items():
        with pytest.raises(ParameterError, match=text) as info:
            validate_params(m, params)
        assert "\n" not in str(info.value), label
    with pytest.raises(UnknownModelError, match="allowed: base, m1, m2, m3, m4, m5"):
        get_model("m6")
    with pytest.raises(birdsim.BirdsimError, match="speed"):
        birdsim.evaluate_cycle("m1", good, -1.0)
    with pytest.raises(birdsim.BirdsimError, match="speed"):
        birdsim.evaluate_cycle("m1", good, math.nan)
