"""Output files: written atomically, never silently overwritten."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from birdsim.errors import BirdsimError


def check_output(path: Path, force: bool, arg: str = "path") -> Path:
    """Check that ``path`` can be written, before any work.

    Args:
        path: the output file.
        force: whether an existing file may be overwritten.
        arg: how the message names the output: the caller's Python argument (the CLI
            passes its flag, or maps the name to it).

    Returns:
        ``path`` as a :class:`Path`; its folder exists afterwards.

    Raises:
        BirdsimError: one line when the file exists (without ``force``), is a folder,
            or its folder cannot be made or written into (probed with a real file:
            permission bits do not bind root).
    """
    path = Path(path)
    if path.exists() and not force:
        raise BirdsimError(
            f"{arg} {str(path)!r} exists; allowed: a new path, or force=True to overwrite"
        )
    if path.exists() and path.is_dir():
        raise BirdsimError(f"{arg} {str(path)!r} is a directory; allowed: a file path")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        why = (
            "a parent is not a folder"
            if isinstance(exc, (FileExistsError, NotADirectoryError))
            else exc.strerror
        )
        raise BirdsimError(f"{arg} {str(path)!r} cannot be created: {why}") from None
    if not os.access(path.parent, os.W_OK):
        raise BirdsimError(
            f"{arg} {str(path)!r} is not writable; allowed: a path in a writable folder"
        )
    try:
        os.unlink(temporary_sibling(path))
    except OSError as exc:
        raise BirdsimError(
            f"{arg} {str(path)!r} is not writable: {exc.strerror}; allowed: a path in a writable folder"
        ) from None
    return path


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def temporary_sibling(path: Path) -> Path:
    """A fresh temporary file name in the same folder as ``path`` (same file system),
    with the permissions an ordinary new file gets (mkstemp's are 0600)."""
    fd, tmp = tempfile.mkstemp(
        prefix=f".{path.name}.", suffix=".partial" + path.suffix, dir=path.parent
    )
    os.fchmod(fd, 0o666 & ~_umask())
    os.close(fd)
    return Path(tmp)


def write_atomic(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary sibling and ``os.replace``."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = temporary_sibling(path)
    try:
        tmp.write_bytes(data)
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()
