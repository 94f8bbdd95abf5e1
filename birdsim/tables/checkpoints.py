"""Checkpoints of a table build: one ``.npz`` per finished task in a folder stamped
with the build's digest, so that an interrupted build resumes where it stopped."""

from __future__ import annotations

import fnmatch
import io
import json
import shutil
import zipfile
from pathlib import Path
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.io import write_atomic


def _is_checkpoint_file(name: str) -> bool:
    """A name that :class:`Checkpoints` writes (write_atomic's temporaries included)."""
    return name == "config.sha" or any(fnmatch.fnmatchcase(name, p) for p in _CHECKPOINT_PATTERNS)


_CHECKPOINT_PATTERNS = tuple(
    p
    for stem in ("slice_V*", "line_Fx*", "cline_Fx*", "smooth_r*")
    for p in (f"{stem}.npz", f".{stem}.npz.*.partial.npz")
)


class Checkpoints:
    """Finished tasks of one build, one ``.npz`` per task in a folder stamped with the
    build's :meth:`~birdsim.tables.grid.BuildConfig.stamp` (``config.sha``: the digest,
    then the stamp as JSON).  A folder of another configuration, birdsim version or
    numerical code is cleared (the build starts afresh) and :attr:`discarded` says why
    in one line.  A folder holding anything but checkpoint files (``config.sha``,
    ``slice_V*.npz``, ``line_Fx*.npz`` and their temporaries), or a path that is a file,
    is refused, never cleared.  The folder is removed by :meth:`remove` once the table
    is safely written."""

    def __init__(
        self, folder: Path | None, digest: str, stamp: dict[str, Any] | None = None
    ) -> None:
        self.folder = folder
        self.discarded: str | None = None
        self.kept = 0  # finished parts of an earlier build of this configuration, reused
        if folder is None:
            return
        stamp_file = folder / "config.sha"
        if folder.exists() and not folder.is_dir():
            raise BirdsimError(
                f"checkpoint_dir {str(folder)!r} is a file; allowed: a folder used only for checkpoints"
            )
        if folder.exists():
            foreign = sorted(p.name for p in folder.iterdir() if not _is_checkpoint_file(p.name))
            if foreign:
                raise BirdsimError(
                    f"checkpoint_dir {str(folder)!r} holds {foreign[0]!r}, not a checkpoint; allowed: a new or empty "
                    "folder, or one written by an earlier build (it is cleared and removed)"
                )
        if folder.exists():
            old_digest, old_stamp = _read_stamp(stamp_file)
            if old_digest != digest:
                if any(
                    _is_checkpoint_file(p.name) and p.name != "config.sha" for p in folder.iterdir()
                ):
                    self.discarded = (
                        f"checkpoints in {str(folder)!r} were written by {_difference(old_stamp, stamp)}; "
                        "they are discarded and the build starts afresh"
                    )
                shutil.rmtree(folder)
            else:
                self.kept = sum(1 for p in folder.iterdir() if p.suffix == ".npz")
        folder.mkdir(parents=True, exist_ok=True)
        stamp_file.write_text(digest + "\n" + json.dumps(stamp or {}, sort_keys=True) + "\n")

    def load(self, name: str) -> dict[str, np.ndarray] | None:
        if self.folder is None or not (self.folder / f"{name}.npz").is_file():
            return None
        try:
            with np.load(self.folder / f"{name}.npz") as z:
                data = {k: z[k] for k in z.files}
            return data if {"params", "cost", "evaluations", "converged"} <= set(data) else None
        except (OSError, ValueError, EOFError, zipfile.BadZipFile):
            return None  # a damaged checkpoint is recomputed

    def save(self, name: str, arrays: dict[str, np.ndarray]) -> None:
        if self.folder is None:
            return
        buf = io.BytesIO()
        np.savez(buf, **arrays)
        write_atomic(self.folder / f"{name}.npz", buf.getvalue())

    def remove(self) -> None:
        if self.folder is not None and self.folder.exists():
            shutil.rmtree(self.folder)


def _read_stamp(path: Path) -> tuple[str | None, dict[str, Any]]:
    """(digest, stamp) of a ``config.sha`` (None, {} when missing or unreadable)."""
    try:
        lines = path.read_text().splitlines()
    except (OSError, UnicodeDecodeError):
        return None, {}
    try:
        stamp = json.loads(lines[1]) if len(lines) > 1 else {}
    except ValueError:
        stamp = {}
    return (lines[0].strip() if lines else None), (stamp if isinstance(stamp, dict) else {})


def _difference(old: dict[str, Any], new: dict[str, Any] | None) -> str:
    """What differs between two stamps, in words."""
    new = new or {}
    if not old:
        return "an unknown earlier build (no readable stamp)"
    if old.get("package_version") != new.get("package_version"):
        return f"birdsim {old.get('package_version')} (this is {new.get('package_version')})"
    if old.get("code") != new.get("code"):
        return "another version of the physics or optimiser code"
    if old.get("optimiser") != new.get("optimiser"):
        return f"other optimiser settings ({old.get('optimiser')})"
    return "a build of another configuration (grid, bird, cost weights or solver settings)"
