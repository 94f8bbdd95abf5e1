"""USD export of a flock: one stage with every bird (:mod:`birdsim.export.usd` per bird).

Each bird's stage is built as a one-bird export builds it
(:func:`birdsim.export.usd.build_stage`); its ``/World`` is copied under
``/World/bird_NN`` (``Sdf.CopySpec``: the geoms' meshes, their transform time samples,
materials and ``birdsim_body``; paths inside the copy are remapped to it), without the
scene's prims (lights, floor, perch), which are copied once from bird 0's stage to
``/World``.  Stage metadata as a one-bird export (z up, metres per unit, fps, time codes)
and ``customLayerData`` ``birdsim`` with ``n_birds`` and each bird's body prim.
"""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

from birdsim.export.frames import ExportError, FrameSequence

#: Prims of the one-bird stage that belong to the scene, not the bird (name parts).
SCENE_PARTS = ("floor", "perch", "Light")


def _is_scene(name: str) -> bool:
    return any(p in name for p in SCENE_PARTS)


def build_flock_stage(frames: list[FrameSequence], assets_dir: Path):  # -> pxr.Usd.Stage
    """One in-memory stage with every bird of ``frames`` (one FrameSequence per bird)."""
    from pxr import Sdf, Usd, UsdGeom, Vt

    from birdsim.export.usd import BODY_PRIM, build_stage

    dst = Usd.Stage.CreateInMemory()
    UsdGeom.Xform.Define(dst, Sdf.Path("/World"))
    layer = dst.GetRootLayer()
    bodies = []
    for i, fr in enumerate(frames):
        src_stage = build_stage(fr, assets_dir)  # kept alive: it owns its layer
        src = src_stage.GetRootLayer()
        root = Sdf.Path(f"/World/bird_{i:02d}")
        if not Sdf.CopySpec(src, Sdf.Path("/World"), layer, root):
            raise ExportError(f"bird {i}: USD could not copy the bird's prims")
        for child in list(dst.GetPrimAtPath(root).GetChildren()):
            if _is_scene(child.GetName()):
                dst.RemovePrim(child.GetPath())
        mats = dst.GetPrimAtPath(root.AppendChild("_materials"))
        for child in list(mats.GetChildren()) if mats else []:
            if _is_scene(child.GetName()):
                dst.RemovePrim(child.GetPath())
        bodies.append(str(root.AppendChild(Sdf.Path(BODY_PRIM).name)))
        if i == 0:  # the scene once, at /World (its materials at /World/_materials)
            world = src.GetPrimAtPath("/World")
            for spec in list(world.nameChildren):
                if _is_scene(spec.name):
                    Sdf.CopySpec(src, spec.path, layer, spec.path)
            for spec in list(src.GetPrimAtPath("/World/_materials").nameChildren):
                if _is_scene(spec.name):
                    if not dst.GetPrimAtPath("/World/_materials"):
                        dst.DefinePrim("/World/_materials")
                    Sdf.CopySpec(src, spec.path, layer, spec.path)
            meta = frames[0]
    UsdGeom.SetStageUpAxis(dst, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(dst, float(meta.metres_per_unit))
    dst.SetTimeCodesPerSecond(float(meta.fps))
    dst.SetFramesPerSecond(float(meta.fps))
    dst.SetStartTimeCode(0)
    dst.SetEndTimeCode(min(f.frames for f in frames) - 1)
    layer.customLayerData = {
        "birdsim": {
            "model": meta.model,
            "bird": meta.bird.name,
            "source": meta.source,
            "fps": float(meta.fps),
            "time_per_second": float(meta.time_per_second),
            "n_birds": len(frames),
            "bodies": Vt.StringArray(bodies),
        }
    }
    return dst


def write_usd_flock(frames: list[FrameSequence], out: str | Path) -> Path:
    """Write every bird's frames into one USD file ``out`` (atomically)."""
    from birdsim.export.usd import export_stage, require_usd

    require_usd()
    out = Path(out)
    work = Path(tempfile.mkdtemp(prefix="birdsim-usd-flock-"))
    try:
        export_stage(build_flock_stage(frames, work / (out.stem + "_assets")), out)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return out


__all__ = ["build_flock_stage", "write_usd_flock"]
