"""The MJCF bird: built from the Bird, committed files in sync, loads and steps cleanly,
every element named, wings mirror each other."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from birdsim import Bird
from birdsim.errors import UnknownModelError
from birdsim.mujoco.driver import set_pose
from birdsim.mujoco.model import build_model, mjcf_texts

MODELS_DIR = Path(__file__).resolve().parents[1] / "models"
MODEL_NAMES = ("base", "m1", "m2", "m3", "m4")


def test_committed_mjcf_is_what_the_code_builds():
    # one source of truth: models/*.xml are regenerated from the Bird, byte for byte
    for name, text in mjcf_texts().items():
        assert (MODELS_DIR / name).read_text() == text, (
            f"run: python -m birdsim.mujoco.model models ({name})"
        )


def test_scene_file_matches_built_model():
    from_file = mujoco.MjModel.from_xml_path(str(MODELS_DIR / "scene.xml"))
    built = build_model("m4")
    for attr in ("nq", "nv", "nbody", "njnt", "ngeom", "nsite", "ncam", "nlight", "neq", "nkey"):
        assert getattr(from_file, attr) == getattr(built, attr), attr
    # to_xml writes 6 significant digits: positions and sizes agree to ~1e-6
    for attr in ("body_pos", "geom_size", "geom_pos", "site_pos", "body_mass", "jnt_axis"):
        np.testing.assert_allclose(
            getattr(from_file, attr), getattr(built, attr), atol=1e-5, err_msg=attr
        )
    assert from_file.vis.global_.offwidth == 1280 and from_file.vis.global_.offheight == 720
    assert from_file.opt.density == 0.0 and from_file.opt.viscosity == 0.0


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_loads_and_steps_one_second_without_warnings(name):
    m = build_model(name)
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, m.key("rest").id)
    set_pose(
        m,
        d,
        {"flap": 0.3, "twist": -0.2, "heave": 0.05, "wrist_flap": 0.1},
        {"flap": 1.0},
        pitch=0.2,
    )
    while d.time < 1.0:
        mujoco.mj_step(m, d)
    assert np.all(d.warning.number == 0), d.warning.number
    assert np.all(np.isfinite(d.qpos))


def test_every_element_named():
    m = build_model("m4")
    kinds = {
        "body": (m.nbody, mujoco.mjtObj.mjOBJ_BODY, 1),  # body 0 is MuJoCo's world
        "joint": (m.njnt, mujoco.mjtObj.mjOBJ_JOINT, 0),
        "geom": (m.ngeom, mujoco.mjtObj.mjOBJ_GEOM, 0),
        "site": (m.nsite, mujoco.mjtObj.mjOBJ_SITE, 0),
        "camera": (m.ncam, mujoco.mjtObj.mjOBJ_CAMERA, 0),
        "light": (m.nlight, mujoco.mjtObj.mjOBJ_LIGHT, 0),
        "equality": (m.neq, mujoco.mjtObj.mjOBJ_EQUALITY, 0),
        "key": (m.nkey, mujoco.mjtObj.mjOBJ_KEY, 0),
    }
    for kind, (n, obj, start) in kinds.items():
        for i in range(start, n):
            assert mujoco.mj_id2name(m, obj, i), f"{kind} {i} has no name"
    for name in ("track", "side", "top", "overview"):
        assert m.camera(name).id >= 0
    assert m.body("perch").id > 0 and m.geom("floor").id >= 0


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_left_wing_mirrors_right(name):
    m = build_model(name)
    d = mujoco.MjData(m)
    rng = np.random.default_rng(7)
    mirror = np.diag([1.0, -1.0, 1.0])
    torso = m.body("torso").id
    for _ in range(5):
        angles = dict(
            zip(
                ("heave", "sweep", "stroke", "flap", "twist", "wrist_flap", "wrist_twist"),
                rng.uniform(-1, 1, 7),
            )
        )
        set_pose(m, d, angles, pitch=float(rng.uniform(-1, 1)))
        r_torso = d.xmat[torso].reshape(3, 3)
        for part in ("arm", "hand"):
            rb, lb = m.body(f"r_{part}").id, m.body(f"l_{part}").id
            rel = lambda b, r=r_torso: r.T @ (d.xpos[b] - d.xpos[torso])  # noqa: E731
            rot = lambda b, r=r_torso: r.T @ d.xmat[b].reshape(3, 3)  # noqa: E731
            # positions mirror; orientations are the mirrored rotation M R M (1e-12: rounding)
            np.testing.assert_allclose(rel(lb), mirror @ rel(rb), atol=1e-12)
            np.testing.assert_allclose(rot(lb), mirror @ rot(rb) @ mirror, atol=1e-12)
        for site in ("cp_wing", "cp_arm", "cp_hand"):
            rs, ls = d.site_xpos[m.site(f"r_{site}").id], d.site_xpos[m.site(f"l_{site}").id]
            np.testing.assert_allclose(
                r_torso.T @ (ls - d.xpos[torso]),
                mirror @ r_torso.T @ (rs - d.xpos[torso]),
                atol=1e-12,
            )


def test_geometry_follows_the_bird():
    bird = Bird(
        semispan=1.6,
        chord=0.5,
        hand_chord=0.3,
        hand_span_fraction=0.4,
        cp_span_fraction=0.3,
        mass=2.5,
    )
    m = build_model("m4", bird)
    arm, hand = bird.panels("m4")
    np.testing.assert_allclose(m.geom("r_arm_panel").size[:2], [arm.chord / 2, arm.span / 2])
    np.testing.assert_allclose(m.geom("l_hand_panel").size[:2], [hand.chord / 2, hand.span / 2])
    np.testing.assert_allclose(m.site("r_cp_arm").pos, [0, -0.3 * arm.span, 0])
    np.testing.assert_allclose(m.site("l_cp_hand").pos, [0, 0.3 * hand.span, 0])
    np.testing.assert_allclose(m.body("r_hand").pos, [0, -arm.span, 0])
    np.testing.assert_allclose(m.site("r_cp_wing").pos, [0, -0.3 * 1.6, 0])
    assert m.body("torso").mass[0] == pytest.approx(2.5)
    # the single-panel models draw one panel of chord `chord` over the whole semispan
    m1 = build_model("m1", bird)
    assert m1.geom("r_hand_panel").size[0] == pytest.approx(bird.chord / 2)
    assert m.opt.timestep == pytest.approx(bird.period / 512)


@pytest.mark.parametrize("fraction", [0.0, 1.0])
@pytest.mark.parametrize("model", ["m1", "m4"])
def test_zero_span_panel_compiles(model, fraction):
    # Bird allows hand_span_fraction in [0, 1]; MuJoCo refuses a box of zero size, so
    # the zero-span panel keeps its geom as a sliver (its CP site and forces are exact:
    # the cross-check covers the physics)
    m = build_model(model, Bird(hand_span_fraction=fraction))
    empty = "r_hand_panel" if fraction == 0.0 else "r_arm_panel"
    assert 0 < m.geom(empty).size[1] <= 1e-6


def test_unknown_model_is_one_clear_error():
    with pytest.raises(UnknownModelError, match="model 'm9' is unknown; allowed: base"):
        build_model("m9")


# ---- the visual bird changes nothing physical ----------------------------------------


@pytest.mark.parametrize("name", ["base", "m4"])
def test_visual_geoms_change_no_dynamics(name):
    """The same model with and without the visual bird: identical masses and inertias,
    and identical mj_step / mj_inverse results under the aero callback (to 1e-12)."""
    from birdsim.mujoco.callback import aero_forces
    from birdsim.mujoco.visual import VISUAL_GROUP

    bird = Bird(gravity=9.81)
    with_vis, without = build_model(name, bird), build_model(name, bird, visuals=False)
    assert with_vis.ngeom > without.ngeom + 20  # the visual bird is there
    torso = with_vis.body("torso").id
    vis = np.flatnonzero(
        (with_vis.geom_group == VISUAL_GROUP)
        & (with_vis.body_rootid[with_vis.geom_bodyid] == torso)
    )
    assert len(vis) == with_vis.ngeom - without.ngeom
    assert np.all(with_vis.geom_contype[vis] == 0) and np.all(with_vis.geom_conaffinity[vis] == 0)
    for attr in (
        "body_mass",
        "body_inertia",
        "body_ipos",
        "body_iquat",
        "body_pos",
        "jnt_axis",
        "dof_armature",
        "site_pos",
    ):
        np.testing.assert_array_equal(getattr(with_vis, attr), getattr(without, attr), err_msg=attr)
    results = []
    for m in (with_vis, without):
        m.opt.wind[:] = (-0.7, 0.0, 0.0)
        d = mujoco.MjData(m)
        mujoco.mj_resetDataKeyframe(m, d, m.key("rest").id)
        set_pose(
            m,
            d,
            {"flap": 0.3, "twist": -0.2, "heave": 0.05, "wrist_flap": 0.1},
            {"flap": 1.0, "twist": 0.5},
            pitch=0.2,
        )
        with aero_forces(m, name, bird):
            mujoco.mj_inverse(m, d)
            inverse = d.qfrc_inverse.copy()
            for _ in range(200):
                mujoco.mj_step(m, d)
            results.append(
                (inverse, d.qpos.copy(), d.qvel.copy(), d.qacc.copy(), d.qfrc_passive.copy())
            )
    for a, b in zip(*results):
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-12)
    assert np.abs(results[0][4]).max() > 1e-3  # the aero forces were really on


def test_visual_geoms_change_no_crosscheck_figure(monkeypatch):
    """The cross-check's every number is the same with and without the visual bird."""
    import functools

    from birdsim.mujoco import crosscheck as cc

    params = {
        "pitch": 0.1,
        "flap_amp": 0.6,
        "twist_amp": 0.3,
        "stroke_plane": 0.2,
        "wrist_amp": 0.3,
        "wrist_bias": 0.0,
        "wrist_lag": 0.2,
    }
    a = cc.crosscheck("m4", params, 0.8, samples=32)
    monkeypatch.setattr(cc, "build_model", functools.partial(build_model, visuals=False))
    b = cc.crosscheck("m4", params, 0.8, samples=32)
    for field in (
        "analytic_seed",
        "inverse_seed",
        "inertial_residual_seed",
        "forward_seed",
        "inverse_history_seed",
    ):
        np.testing.assert_allclose(
            getattr(a, field), getattr(b, field), rtol=0, atol=1e-12, err_msg=field
        )
    assert abs(a.inverse_power - b.inverse_power) <= 1e-12
