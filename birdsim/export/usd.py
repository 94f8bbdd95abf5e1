"""USD export through MuJoCo's own exporter (``mujoco.usd.exporter.USDExporter``).

Needs the optional extra ``birdsim[usd]`` (usd-core). The exporter turns every visual geom
of the MJCF (the bird and the world: floor, perch) into a mesh prim under ``/World``,
written ONCE (points, normals, material), and per frame writes only each geom's
``xformOp:transform`` time sample and, on change, its visibility; one time sample per
export frame, time code = frame index.  birdsim adds:

* stage metadata: ``upAxis`` Z (MuJoCo's world: x forward, y left, z up),
  ``metersPerUnit`` (the bird's length unit in metres: 1 for the pigeon, in metres; the
  non-dimensional seed bird is drawn at 1 semispan = 1 m), ``timeCodesPerSecond`` = fps,
  ``startTimeCode`` 0 and ``endTimeCode`` = frames - 1 (MuJoCo's exporter sets the end
  one past the last sample and 60 time codes per second; both are corrected);
* ``/World/birdsim_body``: an Xform following the torso origin (translate + orient time
  samples), the body position a consumer can read without knowing the geoms;
* ``customLayerData`` ``birdsim``: model, bird name, source, fps and time per second.

The file is ``.usd``/``.usdc`` (binary crate) or ``.usda`` (text), written to a temporary
sibling and renamed.  Textures (none in the shipped MJCF) would be written beside the
file in ``<name>_assets/``.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

from birdsim.export.frames import ExportError, FrameSequence

USD_SUFFIXES = (".usd", ".usda", ".usdc")
BODY_PRIM = "/World/birdsim_body"
#: Segments per half turn of the spheres, capsules and cylinders MuJoCo's exporter
#: tessellates (its default 100 makes 20 000 vertices per sphere: 7.6 MB and 9 s of
#: Python for the dressed bird's ellipsoids before the first frame; 24 is smooth at the
#: bird's size on screen and writes about 16 times less).
PRIMITIVE_RESOLUTION = 24


class _primitive_resolution:
    """Within the block, MuJoCo's exporter tessellates primitives at ``resolution``
    (it has no option for it: its ``mesh_factory`` default is swapped and restored)."""

    def __init__(self, resolution: int) -> None:
        self.resolution = resolution

    def __enter__(self) -> None:
        import mujoco.usd.shapes as shapes

        self.shapes, self.original = shapes, shapes.mesh_factory
        original, resolution = self.original, self.resolution

        def mesh_factory(mesh_config, texture_type, resolution_=None):  # type: ignore[no-untyped-def]
            return original(mesh_config, texture_type, resolution_ or resolution)

        shapes.mesh_factory = mesh_factory

    def __exit__(self, *exc: object) -> None:
        self.shapes.mesh_factory = self.original


class UsdMissingError(ExportError):
    """usd-core is not installed."""


def require_usd() -> None:
    """One line naming the extra when usd-core (pxr) or mujoco.usd is missing."""
    import importlib

    try:
        importlib.import_module("pxr")
        importlib.import_module("mujoco.usd.exporter")
    except ImportError:
        raise UsdMissingError(
            "--format usd needs usd-core, which is not installed; allowed: pip install 'birdsim[usd]' (or --format bvh/csv)"
        ) from None


def build_stage(frames: FrameSequence, assets_dir: Path):  # -> pxr.Usd.Stage
    """The USD stage of ``frames`` (in memory), via MuJoCo's USDExporter."""
    import mujoco
    from mujoco.usd.exporter import USDExporter
    from pxr import Gf, Sdf, UsdGeom

    from birdsim.mujoco.legged import build_model_for

    m = build_model_for(frames.model, frames.bird, frames.qpos.shape[1])  # legs if any
    d = mujoco.MjData(m)
    work = tempfile.mkdtemp(prefix="birdsim-usd-")
    try:
        exp = USDExporter(
            m,
            height=16,
            width=16,
            output_directory="pkg",
            output_directory_root=work,
            verbose=False,
        )
        # textures are referenced beside the output file, not in the exporter's frames/ layout
        exp.texture_files = [f"{assets_dir.name}/{Path(f).name}" for f in exp.texture_files]
        with _primitive_resolution(PRIMITIVE_RESOLUTION):
            for k in range(frames.frames):
                d.qpos[:] = frames.qpos[k]
                mujoco.mj_kinematics(m, d)
                mujoco.mj_camlight(m, d)
                exp.update_scene(d)
        stage = exp.stage
        for geom in exp.geom_refs.values():  # the exporter's own end-of-clip visibility step
            geom.update_visibility(False, geom.last_visible_frame + 1)
        if m.ntex:
            shutil.copytree(Path(work) / "pkg" / "assets", assets_dir, dirs_exist_ok=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, float(frames.metres_per_unit))
    stage.SetTimeCodesPerSecond(float(frames.fps))
    stage.SetFramesPerSecond(float(frames.fps))
    stage.SetStartTimeCode(0)
    stage.SetEndTimeCode(frames.frames - 1)
    body = UsdGeom.Xform.Define(stage, Sdf.Path(BODY_PRIM))
    translate = body.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble)
    orient = body.AddOrientOp(UsdGeom.XformOp.PrecisionDouble)
    for k in range(frames.frames):
        p, q = frames.body_position[k], frames.body_quat[k]
        translate.Set(Gf.Vec3d(*map(float, p)), k)
        orient.Set(Gf.Quatd(float(q[0]), Gf.Vec3d(*map(float, q[1:]))), k)
    stage.GetRootLayer().customLayerData = {
        "birdsim": {
            "model": frames.model,
            "bird": frames.bird.name,
            "source": frames.source,
            "fps": float(frames.fps),
            "time_per_second": float(frames.time_per_second),
        }
    }
    return stage


def write_usd(frames: FrameSequence, out: str | Path) -> Path:
    """Write ``frames`` as USD to ``out`` (atomically).

    Args:
        frames: the frame source.
        out: a ``.usd``, ``.usdc`` or ``.usda`` path.

    Returns:
        The path written.

    Raises:
        UsdMissingError: usd-core is not installed.
    """

    require_usd()
    out = Path(out)
    return export_stage(build_stage(frames, out.with_name(out.stem + "_assets")), out)


def export_stage(stage, out: Path) -> Path:
    """Write a built USD ``stage``'s root layer to ``out`` atomically (a sibling temporary
    file, then a rename); a failed write is one line naming ``--out``."""
    from birdsim.io import temporary_sibling

    tmp = temporary_sibling(out)
    try:
        if not stage.GetRootLayer().Export(str(tmp)):
            raise ExportError(
                f"--out {str(out)!r}: USD could not write the file; allowed: a path in a writable folder"
            )
        os.replace(tmp, out)
    finally:
        if tmp.exists():
            tmp.unlink()
    return out


__all__ = [
    "BODY_PRIM",
    "USD_SUFFIXES",
    "UsdMissingError",
    "build_stage",
    "require_usd",
    "write_usd",
]
