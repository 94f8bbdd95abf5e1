"""m5's dressed hand folds: the primaries fan closed in proportion to the wrist's flexion
and reopen when it extends (birdsim.mujoco.fan); m3/m4 keep their dress untouched."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest

from birdsim.mujoco.fan import FAN_SHUT_FLEXION, PrimaryFan, fan_fraction, primary_fan
from birdsim.mujoco.model import build_model
from birdsim.mujoco.visual import PRIMARIES
from birdsim.physics.bird import Bird

PIGEON = Bird.from_toml("models/pigeon.toml")


def _body_verts(m: mujoco.MjModel, g: int) -> np.ndarray:
    """The vertices of mesh geom ``g`` in its body's frame."""
    mid = int(m.geom_dataid[g])
    v = m.mesh_vert[m.mesh_vertadr[mid] : m.mesh_vertadr[mid] + m.mesh_vertnum[mid]]
    rot = np.zeros(9)
    mujoco.mju_quat2Mat(rot, m.geom_quat[g])
    return m.geom_pos[g] + v @ rot.reshape(3, 3).T


def _geoms(m: mujoco.MjModel, prefix: str) -> list[int]:
    return [g for g in range(m.ngeom) if m.geom(g).name.startswith(prefix)]


def _feathers(m: mujoco.MjModel, side: str) -> list[int]:
    """The primaries' geoms, innermost first."""
    return [m.geom(f"vis_{side}_hand_primary_{k}").id for k in range(PRIMARIES)]


def _set_fold(m: mujoco.MjModel, q: float) -> np.ndarray:
    qpos = m.qpos0.copy()
    for side in "rl":
        qpos[m.jnt_qposadr[m.joint(f"{side}_wrist_sweep").id]] = q
    return qpos


@pytest.mark.parametrize("model", ["m3", "m4"])
@pytest.mark.parametrize("bird", [Bird(), PIGEON], ids=["seed", "pigeon"])
def test_other_models_keep_their_dress(model, bird):
    """m3/m4: one mesh per colour as before, no fan: the renderer's hook leaves every
    geom pose (and MuJoCo's same-frame flags) exactly as built."""
    m = build_model(model, bird)
    names = [m.geom(g).name for g in range(m.ngeom)]
    assert "vis_r_hand_primaries" in names and not any("_primary_" in n for n in names)
    pos, quat, same = m.geom_pos.copy(), m.geom_quat.copy(), m.geom_sameframe.copy()
    assert PrimaryFan.for_model(m, bird) is None
    assert np.array_equal(m.geom_pos, pos) and np.array_equal(m.geom_quat, quat)
    assert np.array_equal(m.geom_sameframe, same)


def test_m5_open_fan_is_m4s_primaries():
    """m5 dresses each primary as its own geom; extended (no fold) they are m4's
    primaries (the same vertices in the hand's frame, to MuJoCo's float32 storage), and a fan posed
    at zero flexion leaves them where the model put them."""
    m4, m5 = build_model("m4", PIGEON), build_model("m5", PIGEON)
    fan = PrimaryFan.for_model(m5, PIGEON)
    rest = m5.geom_pos.copy(), m5.geom_quat.copy()
    fan.pose(_set_fold(m5, 0.0))
    assert np.array_equal(m5.geom_pos, rest[0]) and np.array_equal(m5.geom_quat, rest[1])
    for side in "rl":
        a = np.vstack([_body_verts(m4, g) for g in _geoms(m4, f"vis_{side}_hand_primaries")])
        feathers = _feathers(m5, side)
        assert len(feathers) == PRIMARIES
        b = np.vstack([_body_verts(m5, g) for g in feathers])
        key = lambda v: v[np.lexsort(np.round(v, 6).T)]  # noqa: E731
        # MuJoCo stores mesh vertices in float32: 1e-8 m on a hand of 0.11 m
        np.testing.assert_allclose(key(a), key(b), rtol=0, atol=1e-8)


@pytest.mark.parametrize("q", [0.1, 0.3, FAN_SHUT_FLEXION, 2.0, -0.2])
def test_primaries_fan_closed_in_proportion_to_the_fold(q):
    """Each primary turns rigidly in the hand's plane about its root by
    f(q) delta_k towards the outermost one (f = q / FAN_SHUT_FLEXION, clipped to [0, 1]):
    the inner primaries turn most, the fan's spread narrows by f of the open one (its
    axes parallel when shut); the left hand mirrors the right; extending reopens it."""
    m = build_model("m5", PIGEON)
    fan = PrimaryFan.for_model(m, PIGEON)
    hand_span = PIGEON.semispan * PIGEON.hand_span_fraction
    open_pose = m.geom_pos.copy(), m.geom_quat.copy()

    def directions(side):
        roots, _ = primary_fan(
            hand_span, PIGEON.panels("m5")[1].chord, 1.0 if side == "l" else -1.0
        )
        out = []
        for g, r in zip(_feathers(m, side), roots):
            v = _body_verts(m, g)[:, :2]
            d = np.linalg.norm(v - r, axis=1)
            out.append(v[np.argmax(d)] - r)  # the tip, farthest from the root
        return np.array(out)

    open_dirs = {s: directions(s) for s in "rl"}
    fan.pose(_set_fold(m, q))
    f = float(fan_fraction(q))
    assert f == pytest.approx(min(max(q / FAN_SHUT_FLEXION, 0.0), 1.0))
    for side in "rl":
        d0, d1 = open_dirs[side], directions(side)
        ang = lambda d: np.arctan2(d[:, 1], d[:, 0])  # noqa: E731
        turned = np.angle(np.exp(1j * (ang(d1) - ang(d0))))
        _, delta = primary_fan(
            hand_span, PIGEON.panels("m5")[1].chord, 1.0 if side == "l" else -1.0
        )
        np.testing.assert_allclose(turned, f * delta, atol=1e-9)
        # the open fan is wide (innermost to outermost primary's axis), closing by f of it
        assert abs(delta[0]) > math.radians(30) and delta[-1] == 0.0
        assert np.all(np.abs(delta[:-1]) > np.abs(delta[1:]))  # inner primaries turn most
        spread0 = np.angle(np.exp(1j * (ang(d0)[-1] - ang(d0)[0])))
        spread1 = np.angle(np.exp(1j * (ang(d1)[-1] - ang(d1)[0])))
        assert spread1 == pytest.approx(spread0 - f * delta[0], abs=1e-9)
        np.testing.assert_allclose(np.linalg.norm(d1, axis=1), np.linalg.norm(d0, axis=1))
    np.testing.assert_allclose(directions("l") * [1, -1], directions("r"), atol=1e-12)
    fan.pose(_set_fold(m, 0.0))  # the wing extends: the fan reopens
    np.testing.assert_allclose(m.geom_pos, open_pose[0], atol=1e-15)
    np.testing.assert_allclose(m.geom_quat, open_pose[1], atol=1e-15)


def test_fan_is_a_drawing_only():
    """The primaries are massless, contact-free visual geoms on the hand: posing them
    changes no body pose, passive or bias force."""
    m = build_model("m5", PIGEON)
    fan = PrimaryFan.for_model(m, PIGEON)
    for g in _geoms(m, "vis_r_hand_primary_"):
        assert m.geom_contype[g] == 0 and m.geom_conaffinity[g] == 0 and m.geom_group[g] == 2
        assert m.body(int(m.geom_bodyid[g])).name == "r_hand"
    qpos = _set_fold(m, 0.8)
    d = mujoco.MjData(m)
    d.qpos[:], d.qvel[:] = qpos, 0.3
    mujoco.mj_forward(m, d)
    before = d.xpos.copy(), d.qfrc_passive.copy(), d.qfrc_bias.copy()
    fan.pose(qpos)
    mujoco.mj_forward(m, d)
    assert np.array_equal(d.xpos, before[0]) and np.array_equal(d.qfrc_passive, before[1])
    assert np.array_equal(d.qfrc_bias, before[2])
