"""Finding the shipped table for a bird and a model.

Tables are built for the bird they fly (:meth:`LookupTable.require_bird`): the seed bird's
are ``tables/<model>.npz``, another bird's ``tables/<bird name>-<model>.npz`` (the pigeon:
``tables/pigeon-m3.npz``). :func:`shipped_table` picks the one whose recorded bird has the
same reduced bird, reading only the small ``.json`` beside each table.
"""

from __future__ import annotations

import json
from pathlib import Path

from birdsim.physics.bird import Bird
from birdsim.physics.units import same_reduced_bird
from birdsim.tables.lookup import TableError

#: The repository's table folder (used when ``./tables`` does not exist).
PACKAGE_TABLES = Path(__file__).resolve().parents[2] / "tables"


def table_folder() -> Path:
    """``./tables`` when it exists, else the repository's ``tables/``."""
    local = Path("tables")
    return local if local.is_dir() else PACKAGE_TABLES


def shipped_table(bird: Bird, model: str, folder: Path | None = None) -> Path:
    """The ``.npz`` table in ``folder`` (default :func:`table_folder`) built for ``bird``'s
    reduced bird and ``model``.

    Candidates, in order: ``<bird.name>-<model>.npz``, ``<model>.npz``, any ``*-<model>.npz``.

    Raises:
        TableError: no table there fits (one line saying how to build one).
    """
    folder = table_folder() if folder is None else Path(folder)
    names = [f"{bird.name}-{model}.npz", f"{model}.npz"] + sorted(
        p.name for p in folder.glob(f"*-{model}.npz")
    )
    seen = set()
    for name in names:
        if name in seen:
            continue
        seen.add(name)
        npz = folder / name
        meta_path = npz.with_suffix(".json")
        if not (npz.is_file() and meta_path.is_file()):
            continue
        try:
            meta = json.loads(meta_path.read_text())
            if meta.get("model") != model:
                continue
            built_for = Bird.from_dict(meta["bird"])
        except (OSError, ValueError, KeyError, TypeError):
            continue
        if same_reduced_bird(built_for, bird):
            return npz
    raise TableError(
        f"--bird {bird.name!r}: no table in {str(folder)!r} was built for this bird and "
        f"model {model}; "
        f"allowed: build one with `birdsim tables build --model {model} --bird FILE --out "
        f"{folder}/{bird.name}-{model}.npz` or pass --table"
    )


__all__ = ["PACKAGE_TABLES", "shipped_table", "table_folder"]
