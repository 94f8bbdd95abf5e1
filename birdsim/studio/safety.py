"""What the studio may touch: files inside the folder it was started in, and nothing
named with ``..`` or an absolute path elsewhere."""

from __future__ import annotations

from pathlib import Path, PurePosixPath, PureWindowsPath

from birdsim.errors import BirdsimError


class OutsideError(BirdsimError):
    """A request naming a file outside the studio's folder."""


def inside(root: Path, name: str, what: str = "file") -> Path:
    """The file ``name`` (relative to ``root``) if it lies inside ``root``.

    Raises:
        OutsideError: an absolute path, a ``..`` component, or a link leading out.
    """
    text = str(name)
    if not text or "\x00" in text:
        raise OutsideError(
            f"{what} {text!r} is empty or invalid; allowed: a file in the studio's folder"
        )
    pure = PurePosixPath(text.replace("\\", "/"))
    if pure.is_absolute() or PureWindowsPath(text).drive or ".." in pure.parts:
        raise OutsideError(
            f"{what} {text!r} is outside the studio's folder; allowed: a path relative to the folder it was started in, without '..'"
        )
    base = root.resolve()
    path = (base / pure).resolve()
    if path != base and base not in path.parents:
        raise OutsideError(
            f"{what} {text!r} leads outside the studio's folder; allowed: a file in {str(base)!r}"
        )
    return path


def toml_files(root: Path, limit: int = 200, depth: int = 3) -> list[str]:
    """The .toml files under ``root`` (relative, sorted; at most ``depth`` folders down;
    hidden folders, virtual environments and node_modules skipped; at most ``limit``)."""
    import os

    base = root.resolve()
    out: list[str] = []
    for here, dirs, files in os.walk(base):
        rel_dir = Path(here).relative_to(base)
        dirs[:] = sorted(
            d
            for d in dirs
            if not d.startswith(".")
            and d not in ("node_modules", "build", "__pycache__")
            and len(rel_dir.parts) < depth
        )
        for f in sorted(files):
            if f.endswith(".toml") and f != "pyproject.toml":
                out.append((rel_dir / f).as_posix())
    return sorted(out)[:limit]


__all__ = ["OutsideError", "inside", "toml_files"]
