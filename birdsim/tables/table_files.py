"""The two files of a lookup table: ``<stem>.npz`` (arrays) and ``<stem>.json``
(metadata, human readable, including the SHA-256 of the ``.npz`` so that a mismatched
pair is detected), both carrying :data:`TABLE_FORMAT_VERSION`.

This module knows the container (paths, version, checksum, atomic writes, refusing to
overwrite); which arrays and which metadata a table holds is
:mod:`birdsim.tables.lookup`'s business (``LookupTable.save``, ``load_table``).
"""

from __future__ import annotations

import hashlib
import io
import json
import zipfile
from pathlib import Path
from typing import Any

import numpy as np

from birdsim.io import check_output, write_atomic
from birdsim.tables.table_error import TableError

#: Bump when the file layout changes; tables of another version are refused on load.
TABLE_FORMAT_VERSION = 1

#: What reading a damaged ``.npz`` (or building a table from it) can raise.
UNREADABLE = (KeyError, ValueError, TypeError, OSError, EOFError, zipfile.BadZipFile)


def table_paths(path: str | Path) -> tuple[Path, Path]:
    """(``<stem>.npz``, ``<stem>.json``) for a path given with either suffix or none."""
    p = Path(path)
    if p.suffix in (".npz", ".json"):
        p = p.with_suffix("")
    return p.with_name(p.name + ".npz"), p.with_name(p.name + ".json")


def write_table_files(
    path: str | Path,
    arrays: dict[str, np.ndarray],
    *,
    meta_kept: dict[str, Any],
    meta: dict[str, Any],
    meta_after: dict[str, Any],
    force: bool,
) -> tuple[Path, Path]:
    """Write a table's two files atomically; refuse to overwrite without ``force``.

    Args:
        path: the ``.npz`` or ``.json`` file, or their common stem.
        arrays: the ``.npz`` entries, written after ``format_version``.
        meta_kept: JSON entries carried over (e.g. a loaded table's); an entry that
            a later argument sets again keeps its place.
        meta: JSON entries written after ``format_version``, then come ``npz_sha256``
            and ``npz_file``.
        meta_after: JSON entries written after the checksum.
        force: overwrite existing files.

    Returns:
        (``npz`` path, ``json`` path).

    Raises:
        BirdsimError: either file exists and ``force`` is False (``check_output``).
    """
    npz_path, json_path = table_paths(path)
    check_output(npz_path, force)
    check_output(json_path, force, arg="path (json)")
    buf = io.BytesIO()
    np.savez_compressed(buf, format_version=np.array(TABLE_FORMAT_VERSION), **arrays)
    data = buf.getvalue()
    out = dict(meta_kept)
    out.update(format_version=TABLE_FORMAT_VERSION)
    out.update(meta)
    out.update(npz_sha256=hashlib.sha256(data).hexdigest(), npz_file=npz_path.name)
    out.update(meta_after)
    write_atomic(npz_path, data)
    write_atomic(json_path, (json.dumps(out, indent=2, sort_keys=False) + "\n").encode())
    return npz_path, json_path


def read_table_files(path: str | Path) -> tuple[dict[str, np.ndarray], dict[str, Any], Path]:
    """Read a table's two files and check that they belong together.

    Args:
        path: the ``.npz`` or ``.json`` file, or their common stem.

    Returns:
        (the ``.npz`` arrays, the JSON metadata, the ``.npz`` path).  The version
        stored inside the ``.npz`` is checked by :func:`check_npz_version`.

    Raises:
        TableError: one line naming the file when either file is missing, unreadable,
            truncated, not a table, of another format version (JSON), or when the two
            do not belong together (checksum).
    """
    npz_path, json_path = table_paths(path)
    if npz_path.is_file() and not json_path.is_file():  # e.g. a flight log of `birdsim fly`
        raise TableError(
            f"table file {str(npz_path)!r} has no {json_path.name!r} beside it; allowed: a table "
            "written by `birdsim tables build` (its .npz and .json together; a flight log is not a table)"
        )
    for p in (npz_path, json_path):
        if not p.is_file():
            raise TableError(
                f"table file {str(p)!r} does not exist; allowed: a table written by `birdsim tables build`"
            )
    try:
        meta = json.loads(json_path.read_text())
        if not isinstance(meta, dict):
            raise ValueError("not a JSON object")
    except (OSError, ValueError) as exc:
        raise TableError(f"table file {str(json_path)!r} is unreadable: {exc}") from None
    version = meta.get("format_version")
    if version != TABLE_FORMAT_VERSION:
        raise TableError(
            f"table file {str(json_path)!r} has format version {version!r}; this birdsim reads version "
            f"{TABLE_FORMAT_VERSION}: rebuild it with `birdsim tables build`"
        )
    try:
        data = npz_path.read_bytes()
    except OSError as exc:
        raise TableError(f"table file {str(npz_path)!r} is unreadable: {exc.strerror}") from None
    if hashlib.sha256(data).hexdigest() != meta.get("npz_sha256"):
        raise TableError(
            f"table files {str(npz_path)!r} and {str(json_path)!r} do not belong together (checksum mismatch); "
            "allowed: the pair written by one `birdsim tables build`"
        )
    try:
        with np.load(io.BytesIO(data), allow_pickle=False) as z:
            arrays = {k: z[k] for k in z.files}
    except UNREADABLE as exc:
        raise unreadable(npz_path, exc) from None
    return arrays, meta, npz_path


def unreadable(npz_path: Path, exc: Exception) -> TableError:
    """The one-line error for a ``.npz`` that cannot be read or built into a table."""
    why = f"missing {exc}" if isinstance(exc, KeyError) else str(exc)
    return TableError(f"table file {str(npz_path)!r} is unreadable or incomplete: {why}")


def check_npz_version(arrays: dict[str, np.ndarray], npz_path: Path) -> None:
    """Refuse a ``.npz`` whose own ``format_version`` is not :data:`TABLE_FORMAT_VERSION`.

    Raises:
        TableError: the version differs, or is missing or not a number.
    """
    try:
        npz_version = int(arrays["format_version"])
    except UNREADABLE as exc:
        raise unreadable(npz_path, exc) from None
    if npz_version != TABLE_FORMAT_VERSION:
        raise TableError(
            f"table file {str(npz_path)!r} has format version {npz_version}; allowed: {TABLE_FORMAT_VERSION}"
        )
