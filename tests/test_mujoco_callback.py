"""The passive aero callback: adds to qfrc_passive, uninstalls itself always, acts only
on its own model, applies the core's element forces."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from birdsim import Bird
from birdsim.errors import BirdsimError
from birdsim.mujoco.callback import AeroCallback, aero_forces
from birdsim.mujoco.crosscheck import held_model
from birdsim.mujoco.driver import set_pose

PARAMS = {"pitch": 0.3, "flap_amp": 0.8, "twist_amp": 0.3, "stroke_plane": 0.2}


def _posed(m):
    d = mujoco.MjData(m)
    set_pose(
        m,
        d,
        {"stroke": 0.2, "flap": 0.4, "twist": -0.1},
        {"flap": 0.9, "twist": 0.2},
        pitch=0.3,
        position_seed=(0, 0, -2),
    )
    return d


def test_callback_adds_to_other_passive_forces():
    m = held_model("m3", PARAMS, 0.6, Bird())
    # springs and dampers on every wing dof and a spring on the heave: other passive forces
    m.dof_damping[6:] = 0.7
    m.jnt_stiffness[1:] = 2.0
    d = _posed(m)
    mujoco.mj_forward(m, d)
    springs = d.qfrc_passive.copy()
    with aero_forces(m, "m3") as cb:
        mujoco.mj_forward(m, d)
        both = d.qfrc_passive.copy()
        assert cb.calls >= 1
    m.dof_damping[:] = 0.0
    m.jnt_stiffness[:] = 0.0
    with aero_forces(m, "m3"):
        mujoco.mj_forward(m, d)
        aero = d.qfrc_passive.copy()
    assert np.abs(springs).max() > 0.1 and np.abs(aero).max() > 0.01  # both contributions present
    # additivity to rounding: the callback adds, it never overwrites
    np.testing.assert_allclose(both, springs + aero, atol=1e-13)


def test_removed_after_an_exception_in_the_block_and_in_the_callback():
    m = held_model("m1", {"pitch": 0.1, "flap_amp": 0.5, "twist_amp": 0.1}, 0.5, Bird())
    d = _posed(m)
    with pytest.raises(RuntimeError, match="outside"):
        with aero_forces(m, "m1"):
            raise RuntimeError("outside")
    assert mujoco.get_mjcb_passive() is None

    class Broken(Bird().polar.__class__):
        def force_panel(self, vx, vz, area, rho):
            raise ZeroDivisionError("inside the callback")

    with pytest.raises(ZeroDivisionError, match="inside the callback"):
        with aero_forces(m, "m1", Bird(polar=Broken())):
            mujoco.mj_step(m, d)
    assert mujoco.get_mjcb_passive() is None


def test_refuses_to_replace_a_foreign_callback():
    m = held_model("m1", {"pitch": 0.1, "flap_amp": 0.5, "twist_amp": 0.1}, 0.5, Bird())
    foreign = lambda m, d: None  # noqa: E731
    mujoco.set_mjcb_passive(foreign)
    try:
        with pytest.raises(BirdsimError, match="already installed"):
            with aero_forces(m, "m1"):
                pass
        assert mujoco.get_mjcb_passive() is foreign
    finally:
        mujoco.set_mjcb_passive(None)


def test_acts_only_on_its_own_model():
    mine = held_model("m1", {"pitch": 0.1, "flap_amp": 0.5, "twist_amp": 0.1}, 0.5, Bird())
    other = held_model("m1", {"pitch": 0.1, "flap_amp": 0.5, "twist_amp": 0.1}, 0.5, Bird())
    d = _posed(other)
    with aero_forces(mine, "m1") as cb:
        mujoco.mj_forward(other, d)
        assert cb.calls == 0
    assert np.all(d.qfrc_passive == 0.0)


def test_body_drag_alone_is_the_core_formula():
    # wings at rest, held body pitched by theta in a wind V: root force = 2 wings + drag;
    # with the wings edge-on (twist = -theta makes the panel x axis horizontal) the
    # wings' force is pure drag Cd0 q S each, so the root force is known in closed form
    bird = Bird()
    theta, v = 0.4, 0.7
    m = held_model("m1", {"pitch": theta, "flap_amp": 0.0, "twist_amp": 0.0}, v, bird)
    d = mujoco.MjData(m)
    set_pose(m, d, {"twist": -theta}, pitch=theta, position_seed=(0, 0, -2), forward=False)
    d.qacc[:] = 0.0
    with aero_forces(m, "m1"):
        mujoco.mj_inverse(m, d)
    aero_x = -d.qfrc_inverse[0]
    expected = (
        -0.5 * v * v * np.sin(theta) * bird.body_drag_area
        - 2 * bird.polar.cd0 * 0.5 * v * v * bird.semispan * bird.chord
    )
    assert aero_x == pytest.approx(expected, rel=1e-12)
    assert d.qfrc_inverse[2] == pytest.approx(0.0, abs=1e-14)


def test_strips_are_applied_along_the_span():
    bird = Bird(strips=5)
    m = held_model("m1", {"pitch": 0.1, "flap_amp": 0.5, "twist_amp": 0.1}, 0.5, bird)
    cb = AeroCallback(m, "m1", bird)
    assert cb.offsets.shape == (2, 5)
    # right wing offsets point to -y (outward), left to +y, symmetric about the CP
    np.testing.assert_allclose(cb.offsets[0], -cb.offsets[1])
    np.testing.assert_allclose(cb.areas.sum(axis=1), bird.semispan * bird.chord)


@pytest.mark.parametrize(
    "theta, v, climb", [(0.4, 0.7, 0.3), (0.2, 0.5, -0.4), (1.2, 0.0, 0.6), (0.4, 0.7, 0.0)]
)
def test_body_drag_of_a_climbing_body_is_the_cores(theta, v, climb):
    # The held body meets the air at (V, 0, climb) in the MuJoCo world (z up): the callback's
    # body drag (from the true air-relative velocity) must be evaluate_cycle's (Dx, Dz) for
    # that climb, turned into MuJoCo axes (C = diag(1, -1, -1)).  Same formula, different
    # arithmetic: 1e-12.
    from birdsim import evaluate_cycle

    bird = Bird()
    params = {"pitch": theta, "flap_amp": 0.0, "twist_amp": 0.0}
    m = held_model("m1", params, v, bird)
    m.opt.wind[2] = -climb  # the air moves down past a climbing body
    d = mujoco.MjData(m)
    set_pose(m, d, {}, pitch=theta, position_seed=(0, 0, -2), forward=False)
    mujoco.mj_forward(m, d)
    cb = AeroCallback(m, "m1", bird)
    d.qfrc_passive[:] = 0.0
    cb._apply_body_drag(m, d)
    cyc = evaluate_cycle("m1", params, v, climb=climb, bird=bird)
    expected = np.array([float(cyc.body_drag_x), 0.0, -float(cyc.body_drag_z)])
    np.testing.assert_allclose(d.qfrc_passive[:3], expected, rtol=0, atol=1e-12)
    if climb > 0:
        assert expected[2] < 0  # a climbing body is pushed down
