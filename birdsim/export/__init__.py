"""Exports of a flight for animation tools: USD (MuJoCo's exporter), BVH (a skeleton) and
CSV (one row per frame).  Every format reads one :class:`~birdsim.export.frames.FrameSequence`
(:mod:`birdsim.export.frames`: the kinematic playback of a manoeuvre;
:mod:`birdsim.export.flightlog`: a free-flight log).  docs/export.md has the axes and units."""

from __future__ import annotations

from pathlib import Path

from birdsim.export.frames import ExportError, FrameSequence

#: Format name -> the file suffixes it accepts (the first is the default).
FORMATS = {"usd": (".usd", ".usda", ".usdc"), "bvh": (".bvh",), "csv": (".csv",)}


def check_format(fmt: str, out: Path | None = None) -> None:
    """One line for an unknown format or an output suffix that does not fit it."""
    if fmt not in FORMATS:
        raise ExportError(f"--format {fmt!r} is unknown; allowed: {', '.join(FORMATS)}")
    if out is not None and Path(out).suffix.lower() not in FORMATS[fmt]:
        raise ExportError(
            f"--out {str(out)!r} does not end in {' or '.join(FORMATS[fmt])}; allowed: a {fmt} path"
        )


def write(frames: FrameSequence, fmt: str, out: str | Path) -> Path:
    """Write ``frames`` in format ``fmt`` (usd, bvh, csv) to ``out`` atomically.

    Raises:
        ExportError: unknown format, a suffix that does not fit, usd-core missing, BVH of
            the base model.
    """
    check_format(fmt, Path(out))
    if fmt == "usd":
        from birdsim.export.usd import write_usd

        return write_usd(frames, out)
    if fmt == "bvh":
        from birdsim.export.bvh import write_bvh

        return write_bvh(frames, out)
    from birdsim.export.csv import write_csv

    return write_csv(frames, out)


__all__ = ["FORMATS", "ExportError", "FrameSequence", "check_format", "write"]
