"""Where numba keeps birdsim's compiled kernels: a folder named by their sources.

numba's on-disk cache (``cache=True``) checks only the source file of the function it
loads: a compiled helper it calls from another module may have changed (an upgrade, an
edit) and the cached machine code of the caller still runs the old helper, silently.
Unless the user chose the folder (``NUMBA_CACHE_DIR``; one inherited from a birdsim
parent process is birdsim's, not the user's), birdsim points numba's cache at
``<user cache>/birdsim/numba/<digest>``, where the digest covers the text of every
birdsim module that mentions numba, and numba's and Python's versions: any change to
one of them gives a fresh folder (one cold compile, as after a clean install). Where
that folder cannot be written, numba's own default (``__pycache__`` beside the sources)
stays. Importing birdsim does this (``CACHE_FOLDER``).
"""

from __future__ import annotations

import hashlib
import os
import sys
import tempfile
from importlib import metadata
from pathlib import Path

PACKAGE_ROOT = Path(__file__).resolve().parent
_OURS = "BIRDSIM_NUMBA_CACHE_DIR"  # the folder birdsim set, told apart from the user's


def sources_digest(root: Path = PACKAGE_ROOT) -> str:
    """A 16-hex digest of the ``.py`` files under ``root`` that mention numba (path and
    text), with numba's and Python's versions."""
    h = hashlib.sha256()
    try:
        h.update(metadata.version("numba").encode())
    except metadata.PackageNotFoundError:
        h.update(b"no numba")
    h.update(sys.version.encode())
    for path in sorted(root.rglob("*.py")):
        text = path.read_bytes()
        if b"numba" in text:
            h.update(path.relative_to(root).as_posix().encode() + b"\0" + text + b"\0")
    return h.hexdigest()[:16]


def cache_folder(root: Path = PACKAGE_ROOT) -> Path:
    """The folder for this build's kernels under the user's cache
    (``$XDG_CACHE_HOME`` or ``~/.cache``)."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "birdsim" / "numba" / sources_digest(root)


def _writable(folder: Path) -> bool:
    try:
        folder.mkdir(parents=True, exist_ok=True)
        tempfile.TemporaryFile(dir=folder).close()
    except OSError:
        return False
    return True


def use_source_keyed_cache() -> Path | None:
    """Point numba's cache at :func:`cache_folder` unless ``NUMBA_CACHE_DIR`` is set or
    the folder cannot be written; the folder used, or None where numba's choice stays."""
    chosen = os.environ.get("NUMBA_CACHE_DIR")
    if chosen and chosen != os.environ.get(_OURS):  # the user's choice (not a parent's)
        return None
    folder = cache_folder()
    if not _writable(folder):
        return None
    os.environ["NUMBA_CACHE_DIR"] = str(folder)  # read when numba is first imported
    os.environ[_OURS] = str(folder)  # a child process of other sources keys its own
    config = sys.modules.get("numba.core.config")
    if config is not None:  # numba imported before birdsim: its config is read already
        config.CACHE_DIR = str(folder)
    return folder


CACHE_FOLDER = use_source_keyed_cache()
