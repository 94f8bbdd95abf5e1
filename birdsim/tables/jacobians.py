"""Per-cell moments and Jacobians of a lookup table's wingbeats.

For every cell's stored (symmetric) wingbeat, at the cell's speed and climb, with no
control input and no body rate: the whole bird's mean force and moment (seed body axes,
about the torso origin) and their derivatives with respect to the control inputs of
:data:`birdsim.physics.moments.CONTROL_INPUTS` and the body rate (p, q, r).  In table
units: computed for the table's reduced bird (:func:`birdsim.physics.units.reduced_bird`),
as the table's forces are.  A :class:`birdsim.tables.lookup.LookupTable` carries them
(stored in the file, or computed on first use and cached); they are interpolated
multilinearly like the wingbeat.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from birdsim.physics.bird import Bird
from birdsim.physics.cycle import DEFAULT_SAMPLES, sample_phases
from birdsim.physics.moments import CONTROL_INPUTS, input_model
from birdsim.physics.units import reduced_bird, same_reduced_bird
from birdsim.tables.table_error import TableError

#: The arrays, each over the grid: grid + (3,) or grid + (3, k) or grid + (3, 3).
FIELDS = ("force_body", "moment_body", "force_du", "moment_du", "force_drate", "moment_drate")
#: The npz key of each field.
NPZ_PREFIX = "jac_"


class GridTable(Protocol):
    """What this module reads of a :class:`birdsim.tables.lookup.LookupTable` (a
    protocol, so that the table, which calls this module, is not imported here)."""

    @property
    def model(self) -> str: ...
    @property
    def bird(self) -> Bird: ...
    @property
    def param_names(self) -> tuple[str, ...]: ...
    @property
    def axes(self) -> dict[str, np.ndarray]: ...
    @property
    def params(self) -> np.ndarray: ...
    @property
    def jacobians(self) -> Any: ...
    @property
    def axis_names(self) -> tuple[str, ...]: ...
    @property
    def has_climb(self) -> bool: ...
    @property
    def shape(self) -> tuple[int, ...]: ...
    @property
    def demands(self) -> np.ndarray: ...
    def require_bird(self, bird: Bird) -> None: ...


@dataclass(frozen=True, eq=False)
class TableJacobians:
    """Moments and Jacobians over a table's grid (see the module docstring).

    ``force_du``/``moment_du``: grid x 3 x k (inputs in ``inputs`` order);
    ``force_drate``/``moment_drate``: grid x 3 x 3 (columns d/dp, d/dq, d/dr; the
    diagonal of ``moment_drate`` is the roll, pitch and yaw damping);
    ``force_body``/``moment_body``: grid x 3.  ``bird``: the reduced bird they belong to.
    """

    inputs: tuple[tuple[str, str], ...]
    bird: Bird
    samples: int
    force_body: np.ndarray
    moment_body: np.ndarray
    force_du: np.ndarray
    moment_du: np.ndarray
    force_drate: np.ndarray
    moment_drate: np.ndarray

    def meta(self) -> dict[str, Any]:
        """What the table's JSON records about them."""
        return {
            "inputs": [list(i) for i in self.inputs],
            "bird": self.bird.to_dict(),
            "samples": self.samples,
            "axes": "seed body axes (x forward, y right wing, z down), about the torso origin",
        }


def table_jacobians(
    table: GridTable,
    bird: Bird | None = None,
    *,
    n: int = DEFAULT_SAMPLES,
    backend: str = "kernel",
) -> TableJacobians:
    """Moments and Jacobians of every cell's stored wingbeat.

    Args:
        table: a lookup table.
        bird: the bird to fly with it (refused in one line when its reduced bird is not
            the table's); None: the table's own.
        n: samples per wingbeat.
        backend: ``"kernel"`` (exact derivatives) or ``"numpy"`` (central differences).

    Returns:
        A :class:`TableJacobians` in table units.

    Raises:
        TableError: a bird whose reduced bird differs from the table's.
    """
    from birdsim.physics.moments_eval import whole_bird

    if bird is not None:
        table.require_bird(bird)
    rb = reduced_bird(table.bird)
    mx = input_model(table.model)
    shape = table.shape
    flat = table.params.reshape(-1, len(table.param_names))
    cells = flat.shape[0]
    sym: dict[str, np.ndarray] = {}
    for name in mx.param_names:
        if name in table.param_names:
            sym[name] = np.ascontiguousarray(flat[:, table.param_names.index(name)])
        else:
            sym[name] = np.zeros(cells)  # an input parameter the model does not optimise
    dem = table.demands.reshape(cells, -1)
    speed = np.ascontiguousarray(dem[:, 2])
    climb = np.ascontiguousarray(dem[:, 3]) if table.has_climb else np.zeros(cells)
    k = len(CONTROL_INPUTS[mx.name])
    out = whole_bird(
        mx,
        sym,
        speed,
        climb,
        np.zeros((cells, 3)),
        np.zeros((cells, k)),
        rb,
        sample_phases(n, False),
        jacobians=True,
        backend=backend,
    )
    arrays = {f: out[f].reshape(shape + out[f].shape[1:]) for f in FIELDS}
    return TableJacobians(CONTROL_INPUTS[mx.name], rb, int(n), **arrays)


def cached_jacobians(table: GridTable) -> TableJacobians:
    """The table's stored Jacobians, else computed now and cached on the table."""
    if table.jacobians is None:
        object.__setattr__(table, "jacobians", table_jacobians(table))
        table.__dict__.pop("_jac_rgi", None)
    return table.jacobians


def interpolate_jacobians(table: GridTable, points: np.ndarray) -> dict[str, np.ndarray]:
    """Every field at one grid point (1 x axes, from ``LookupTable._points``), multilinear
    between the cells: ``force_body``, ``moment_body`` (3,), ``force_du``, ``moment_du``
    (3, k), ``force_drate``, ``moment_drate`` (3, 3)."""
    jac = cached_jacobians(table)
    n = len(table.shape)
    rgi = table.__dict__.get("_jac_rgi")
    if rgi is None:
        grid = tuple(np.asarray(table.axes[a], dtype=float) for a in table.axis_names)
        flat = np.concatenate([getattr(jac, f).reshape(table.shape + (-1,)) for f in FIELDS], n)
        rgi = RegularGridInterpolator(grid, flat)
        object.__setattr__(table, "_jac_rgi", rgi)
    vals = rgi(points)[0]
    out, lo = {}, 0
    for f in FIELDS:
        shape = getattr(jac, f).shape[n:]
        size = int(np.prod(shape))
        out[f] = vals[lo : lo + size].reshape(shape)
        lo += size
    return out


def check_jacobians(table: GridTable, jac: TableJacobians) -> None:
    """Refuse (one line) Jacobians that belong to another reduced bird, other inputs or
    another grid than ``table``'s."""
    if not same_reduced_bird(jac.bird, table.bird):
        raise TableError(
            f"table for model {table.model} carries Jacobians computed for bird {jac.bird.name!r}, whose "
            f"reduced bird differs from the table's ({table.bird.name!r}); allowed: Jacobians of this table "
            f"(`birdsim tables jacobians TABLE --force` recomputes them)"
        )
    if tuple(map(tuple, jac.inputs)) != CONTROL_INPUTS[table.model]:
        raise TableError(
            f"table Jacobians are for inputs {list(jac.inputs)}; allowed: {list(CONTROL_INPUTS[table.model])} "
            "(`birdsim tables jacobians TABLE --force` recomputes them)"
        )
    for f in FIELDS:
        got = np.shape(getattr(jac, f))
        if got[: len(table.shape)] != table.shape:
            raise TableError(
                f"table Jacobian array {f} has shape {got}; expected the grid {table.shape} first"
            )


def from_arrays(arrays: dict[str, np.ndarray], meta: dict[str, Any]) -> TableJacobians | None:
    """The stored Jacobians of a table file (None when it has none)."""
    if not all(NPZ_PREFIX + f in arrays for f in FIELDS) or "jacobians" not in meta:
        return None
    m = meta["jacobians"]
    return TableJacobians(
        inputs=tuple(tuple(i) for i in m["inputs"]),
        bird=Bird.from_dict(m["bird"]),
        samples=int(m["samples"]),
        **{f: arrays[NPZ_PREFIX + f] for f in FIELDS},
    )


def to_arrays(jac: TableJacobians) -> dict[str, np.ndarray]:
    """The npz entries of :class:`TableJacobians`."""
    return {NPZ_PREFIX + f: np.asarray(getattr(jac, f), dtype=float) for f in FIELDS}
