"""USD read back with pxr: frame range and rate, units, the body position at three
frames (1e-4 semispan after the unit scale), one wingbeat per wingbeat period."""

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

from birdsim.export.usd import BODY_PRIM, write_usd  # pxr is imported only when writing

pxr = pytest.importorskip("pxr")
Usd = pytest.importorskip("pxr.Usd")
UsdGeom = pytest.importorskip("pxr.UsdGeom")

SCALE = 0.3  # metres per unit: positions read back are divided by it


@pytest.fixture(scope="module")
def stage(tmp_path_factory):
    path = tmp_path_factory.mktemp("usd") / "cruise.usd"
    write_usd(cruise_frames(SCALE), path)
    return Usd.Stage.Open(str(path))


def _prim(stage, geom_name):
    hits = [p for p in stage.Traverse() if p.GetName().startswith(f"Mesh_Xform_{geom_name}_id")]
    assert len(hits) == 1, [p.GetName() for p in stage.Traverse()]
    return UsdGeom.Xformable(hits[0])


def test_stage_metadata(stage):
    n = cruise_frames(SCALE).frames
    assert stage.GetTimeCodesPerSecond() == FPS
    assert stage.GetStartTimeCode() == 0 and stage.GetEndTimeCode() == n - 1
    assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z
    assert UsdGeom.GetStageMetersPerUnit(stage) == pytest.approx(SCALE)
    samples = UsdGeom.Xformable(stage.GetPrimAtPath(BODY_PRIM)).GetTimeSamples()
    assert samples == list(range(n))  # one time sample per frame


def test_body_position_at_three_frames(stage):
    ref = reference_body_position()  # semispans (the seed bird's length unit)
    body = UsdGeom.Xformable(stage.GetPrimAtPath(BODY_PRIM))
    torso = _prim(stage, "torso_body")  # MuJoCo's own geom transform (centred on the torso origin)
    for k in CHECK_FRAMES:
        for xf in (body, torso):
            p = np.array(xf.ComputeLocalToWorldTransform(k).ExtractTranslation())
            metres = p * UsdGeom.GetStageMetersPerUnit(stage)
            assert np.allclose(metres / SCALE, ref[k], atol=1e-4), (k, metres / SCALE, ref[k])


def test_meshes_are_written_once(stage):
    mesh = next(p for p in stage.Traverse() if p.GetTypeName() == "Mesh")
    assert UsdGeom.Mesh(mesh).GetPointsAttr().GetNumTimeSamples() == 0


def test_wing_flaps_once_per_wingbeat(stage):
    """The right arm panel's rotation about the body's x axis (the flap, sec. 3.2)."""
    arm = _prim(stage, "r_arm_panel")
    n = cruise_frames(SCALE).frames
    angle = []
    for k in range(n):
        m = np.array(
            arm.ComputeLocalToWorldTransform(k).ExtractRotationMatrix()
        )  # rows = images of the axes
        tipward = -m[1]  # the right panel spans along its -y axis
        angle.append(np.arctan2(tipward[2], -tipward[1]))  # elevation of the right wing's span
    one_beat_per_period(np.array(angle), FRAMES_PER_BEAT)
