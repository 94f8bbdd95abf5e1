"""Finding the shipped table for a bird and a model.

Tables are built for the bird they fly (:meth:`LookupTable.require_bird`): the seed bird's
are ``tables/<model>.npz``, another bird's ``tables/<bird name>-<model>.npz`` (the pigeon:
``tables/pigeon-m3.npz``). :func:`shipped_table` picks the one whose recorded bird has the
same reduced bird, reading only the small ``.json`` beside each table; among those, a bird
that flies (a mass and a gravity) gets first the one whose grid covers the grid of its
presets' demands (:func:`birdsim.flight.preset_grid.preset_grid`) at least as finely, so
that a user's bird whose reduced bird is the seed's is not handed the coarse general
``tables/m3.npz`` (issue 28, item 2).
"""

from __future__ import annotations

import json
import math
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

    Candidates, in order: ``<bird.name>-<model>.npz``, ``<model>.npz``, any ``*-<model>.npz``;
    of those built for ``bird``'s reduced bird, the first whose grid covers the bird's
    presets (:func:`covers_presets`), else the first whose node spacing in Fx and Fz is
    the finest, else the first.

    Raises:
        TableError: no table there fits (one line saying how to build one).
    """
    folder = table_folder() if folder is None else Path(folder)
    names = [f"{bird.name}-{model}.npz", f"{model}.npz"] + sorted(
        p.name for p in folder.glob(f"*-{model}.npz")
    )
    seen = set()
    found: list[tuple[Path, dict]] = []
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
            found.append((npz, meta.get("grid", {})))
    if found:
        return _best(found, bird)
    raise TableError(
        f"--bird {bird.name!r}: no table in {str(folder)!r} was built for this bird and "
        f"model {model}; "
        f"allowed: build one with `birdsim tables build --model {model} --bird FILE --out "
        f"{folder}/{bird.name}-{model}.npz` or pass --table"
    )


def _spacing(values: list[float]) -> float:
    return float(max(b - a for a, b in zip(values, values[1:]))) if len(values) > 1 else math.inf


def covers_presets(grid: dict, bird: Bird) -> bool:
    """Whether a table grid (``{"Fx": [...], "Fz": [...], "V": [...]}``, the ``.json``'s)
    spans the grid of ``bird``'s preset demands with node spacings no coarser."""
    from birdsim.flight.preset_grid import preset_grid
    from birdsim.tables.grid import Grid

    need = Grid.parse(preset_grid(bird))
    tol = 1e-9
    for axis in ("Fx", "Fz", "V"):
        have, want = grid.get(axis) or [], list(getattr(need, axis))
        if not have or min(have) > want[0] + tol or max(have) < want[-1] - tol:
            return False
        if _spacing(have) > _spacing(want) + tol:
            return False
    return True


def _best(found: list[tuple[Path, dict]], bird: Bird) -> Path:
    """The first table that covers the presets of a bird that flies, else the finest."""
    if len(found) == 1 or not (bird.mass > 0 and bird.gravity > 0):
        return found[0][0]
    for npz, grid in found:
        try:
            if covers_presets(grid, bird):
                return npz
        except (TypeError, ValueError):
            continue

    def coarseness(item: tuple[Path, dict]) -> float:
        try:
            return max(_spacing(list(item[1][a])) for a in ("Fx", "Fz"))
        except (KeyError, TypeError, ValueError):
            return math.inf

    return min(found, key=coarseness)[0]  # min keeps the first of equals


__all__ = ["PACKAGE_TABLES", "covers_presets", "shipped_table", "table_folder"]
