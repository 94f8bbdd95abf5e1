"""BVH read back with the `bvh` library: frame count and time, the skeleton, the body
position at three frames (1e-4 semispan), one wingbeat per period, and the wrist and
tip positions by forward kinematics against MuJoCo's."""

import math

import mujoco
import numpy as np
import pytest
from export_helpers import (
    CHECK_FRAMES,
    FPS,
    FRAMES_PER_BEAT,
    cruise_frames,
    one_beat_per_period,
    reference_body_position,
)

from birdsim.errors import BirdsimError
from birdsim.export.bvh import build_bvh, write_bvh  # pybvh is imported only when writing
from birdsim.mujoco.model import build_model

bvh = pytest.importorskip("bvh")
pytest.importorskip("pybvh")

SCALE = 0.3
FROM_BVH = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])  # MuJoCo = FROM_BVH @ BVH


@pytest.fixture(scope="module")
def parsed(tmp_path_factory):
    path = tmp_path_factory.mktemp("bvh") / "cruise.bvh"
    write_bvh(cruise_frames(SCALE), path)
    return bvh.Bvh(path.read_text())


def _rot(axis, deg):
    a = math.radians(deg)
    c, s = math.cos(a), math.sin(a)
    return {
        "X": np.array([[1, 0, 0], [0, c, -s], [0, s, c]]),
        "Y": np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
        "Z": np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
    }[axis]


def _local(parsed, frame, joint):
    """BVH semantics: channels in the listed order, R = R1 R2 R3 (intrinsic)."""
    chans = parsed.joint_channels(joint)
    vals = parsed.frame_joint_channels(frame, joint, chans)
    r, pos = np.eye(3), np.zeros(3)
    for ch, v in zip(chans, vals):
        if ch.endswith("rotation"):
            r = r @ _rot(ch[0], v)
        else:
            pos["XYZ".index(ch[0])] = v
    return r, pos


def _world(parsed, frame, chain, tip_offset=None):
    """World position (BVH axes) of the last joint of ``chain`` (or of an offset past it)."""
    rot, pos = np.eye(3), np.zeros(3)
    for j in chain:
        r, p = _local(parsed, frame, j)
        pos = pos + rot @ (np.array(parsed.joint_offset(j)) + p)
        rot = rot @ r
    return pos if tip_offset is None else pos + rot @ tip_offset


def test_frames_and_rate(parsed):
    assert parsed.nframes == cruise_frames(SCALE).frames
    assert parsed.frame_time == pytest.approx(1.0 / FPS, rel=1e-9)


def test_skeleton_is_named_after_the_mjcf_joints(parsed):
    names = parsed.get_joints_names()
    assert names == [
        "root",
        "r_shoulder",
        "r_wrist_flap",
        "r_wrist_twist",
        "l_shoulder",
        "l_wrist_flap",
        "l_wrist_twist",
    ]
    assert len(parsed.joint_channels("root")) == 6
    assert all(len(parsed.joint_channels(j)) == 3 for j in names[1:])
    m = build_model("m4")
    for name in names:
        assert mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, name) >= 0


def test_body_position_at_three_frames(parsed):
    ref = reference_body_position()
    for k in CHECK_FRAMES:
        p = np.array(
            parsed.frame_joint_channels(k, "root", ["Xposition", "Yposition", "Zposition"])
        )
        assert np.allclose(FROM_BVH @ p / SCALE, ref[k], atol=1e-4)


def test_shoulder_flaps_once_per_wingbeat(parsed):
    flap = [parsed.frame_joint_channel(k, "r_shoulder", "Xrotation") for k in range(parsed.nframes)]
    one_beat_per_period(np.radians(flap), FRAMES_PER_BEAT)


def test_forward_kinematics_matches_mujoco(parsed):
    """Wrist and hand tip of both wings from the BVH channels equal MuJoCo's (1e-4 semispan):
    the Euler convention, the axes and the offsets are right."""
    fr = cruise_frames(SCALE)
    m = build_model("m4")
    d = mujoco.MjData(m)
    for k in (3, 8, 40):
        d.qpos[:] = fr.qpos[k]
        mujoco.mj_kinematics(m, d)
        for side, sign in (("r", -1.0), ("l", 1.0)):
            chain = ["root", f"{side}_shoulder", f"{side}_wrist_flap", f"{side}_wrist_twist"]
            wrist = FROM_BVH @ _world(parsed, k, chain) / SCALE
            assert np.allclose(wrist, d.xpos[m.body(f"{side}_hand").id], atol=1e-4)
            tip_bvh = (
                np.array([0.0, 0.0, -sign * fr.bird.semispan * fr.bird.hand_span_fraction]) * SCALE
            )
            tip = FROM_BVH @ _world(parsed, k, chain, tip_bvh) / SCALE
            hand = m.body(f"{side}_hand").id
            tip_mj = d.xpos[hand] + d.xmat[hand].reshape(3, 3) @ np.array(
                [0.0, sign * fr.bird.semispan * fr.bird.hand_span_fraction, 0.0]
            )
            assert np.allclose(tip, tip_mj, atol=1e-4)


def test_base_model_is_refused():
    from dataclasses import replace

    with pytest.raises(BirdsimError, match="heave"):
        build_bvh(replace(cruise_frames(), model="base"))
