"""Lookup tables of optimal wingbeats over the demand grid (Fx, Fz, V), optionally with
a fourth axis ``climb`` (vertical speed relative to the air, positive up).

A table holds, per cell of the grid, the optimal parameters of one kinematic model,
the cost and its fractions, the achieved force and power, a status and the number of
cycle evaluations spent, plus provenance metadata.  It is stored as two files with the
same stem: ``<name>.npz`` (arrays) and ``<name>.json`` (metadata, human readable,
including the SHA-256 of the ``.npz`` so that a mismatched pair is detected).

Forces are the dissertation's (right wing + body drag, seed earth axes, Fz < 0 up).
Interpolation is multilinear over (Fx, Fz, V[, climb]) (scipy's RegularGridInterpolator):
it reproduces the grid values exactly at the nodes, is monotone between them and
never overshoots the parameter bounds.  A table without a climb axis is for level
flight: it answers climb = 0 only.

Where things are: the table (its arrays, views, lookups) and ``load_table`` here; the
two-file container (paths, version, checksum) in :mod:`birdsim.tables.table_files`;
checking demands against the grid in :mod:`birdsim.tables.demand_points`;
:class:`TableError` in :mod:`birdsim.tables.table_error`; the per-cell moments and
Jacobians in :mod:`birdsim.tables.jacobians`.  This module re-exports ``TableError``,
``TABLE_FORMAT_VERSION`` and ``table_paths``, so ``from birdsim.tables.lookup import
TableError, table_paths`` keeps working.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import MODELS
from birdsim.tables import fast_lookup
from birdsim.tables.cost import FRACTION_NAMES
from birdsim.tables.demand_points import cells_around, check_level_climb, demand_points
from birdsim.tables.table_error import TableError
from birdsim.tables.table_files import (
    TABLE_FORMAT_VERSION,
    UNREADABLE,
    check_npz_version,
    read_table_files,
    table_paths,
    unreadable,
    write_table_files,
)

__all__ = [
    "ACHIEVED_NAMES",
    "AXES",
    "CLIMB",
    "STATUS_NAMES",
    "TABLE_FORMAT_VERSION",
    "LookupTable",
    "TableError",
    "load_table",
    "table_paths",
]

AXES = ("Fx", "Fz", "V")
#: The optional fourth axis (after V): vertical speed relative to the air, positive up.
CLIMB = "climb"
STATUS_NAMES = ("ok", "unreachable", "failed")
ACHIEVED_NAMES = ("Fx", "Fz", "P")


@dataclass(frozen=True, eq=False)
class LookupTable:
    """Optimal wingbeats of ``model`` over the grid ``axes`` (Fx, Fz, V and optionally
    climb), arrays indexed ``[i_Fx, i_Fz, i_V, (i_climb,) ...]``."""

    model: str
    bird: Bird
    param_names: tuple[str, ...]
    axes: dict[str, np.ndarray]
    params: np.ndarray  # nFx x nFz x nV x d (radians)
    cost: np.ndarray  # nFx x nFz x nV
    cost_fractions: np.ndarray  # nFx x nFz x nV x 4 (FRACTION_NAMES)
    achieved: np.ndarray  # nFx x nFz x nV x 3: Fx, Fz (dissertation force), P
    status_code: np.ndarray  # nFx x nFz x nV, uint8 index into STATUS_NAMES
    evaluations: np.ndarray  # nFx x nFz x nV, cycle evaluations spent on the cell
    meta: dict[str, Any] = field(default_factory=dict)
    converged: np.ndarray | None = (
        None  # nFx x nFz x nV, SLSQP's own convergence flag of the kept answer
    )
    #: per-cell moments and Jacobians (birdsim.tables.jacobians), stored or None; see
    #: :meth:`moment_jacobians` (computes and caches them when absent)
    jacobians: Any = None

    def __post_init__(self) -> None:
        if not all(a in self.axes for a in AXES) or set(self.axes) - set(AXES + (CLIMB,)):
            raise TableError(
                f"table axes {sorted(self.axes)} are invalid; allowed: Fx, Fz, V and optionally climb"
            )
        shape = tuple(len(self.axes[a]) for a in self.axis_names)
        d = len(self.param_names)
        expected = {
            "params": shape + (d,),
            "cost": shape,
            "cost_fractions": shape + (len(FRACTION_NAMES),),
            "achieved": shape + (3,),
            "status_code": shape,
            "evaluations": shape,
        }
        if self.converged is None:
            object.__setattr__(self, "converged", np.ones(shape, dtype=bool))
        expected["converged"] = shape
        for name, want in expected.items():
            got = np.shape(getattr(self, name))
            if got != want:
                raise TableError(
                    f"table array {name} has shape {got}; expected {want} for grid {shape} and {d} parameters"
                )
        for a in self.axis_names:
            ax = np.asarray(self.axes[a], dtype=float)
            if (
                ax.ndim != 1
                or ax.size < 2
                or np.any(np.diff(ax) <= 0)
                or not np.all(np.isfinite(ax))
            ):
                raise TableError(
                    f"table axis {a}={ax.tolist()} is invalid; allowed: >= 2 finite increasing values"
                )
        model = MODELS.get(self.model) if isinstance(self.model, str) else None
        if model is None:
            raise TableError(f"table model {self.model!r} is unknown; allowed: {', '.join(MODELS)}")
        if tuple(self.param_names) != model.param_names:
            raise TableError(
                f"table param_names={list(self.param_names)} do not match model {self.model}; "
                f"allowed: {', '.join(model.param_names)}"
            )
        if self.jacobians is not None:
            from birdsim.tables.jacobians import check_jacobians

            check_jacobians(self, self.jacobians)
        codes = np.asarray(self.status_code)
        if codes.dtype.kind not in "iu" or np.any(codes < 0) or np.any(codes >= len(STATUS_NAMES)):
            raise TableError(
                f"table array status_code holds {codes.dtype} values in [{codes.min()}, {codes.max()}]; "
                f"allowed: integers 0..{len(STATUS_NAMES) - 1} ({', '.join(STATUS_NAMES)})"
            )

    # ---- views -----------------------------------------------------------------------

    @property
    def axis_names(self) -> tuple[str, ...]:
        """("Fx", "Fz", "V") or ("Fx", "Fz", "V", "climb")."""
        return AXES + ((CLIMB,) if CLIMB in self.axes else ())

    @property
    def has_climb(self) -> bool:
        return CLIMB in self.axes

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(self.axes[a]) for a in self.axis_names)

    @property
    def status(self) -> np.ndarray:
        """Per-cell status strings: ``ok``, ``unreachable`` or ``failed``."""
        return np.asarray(STATUS_NAMES, dtype=object)[self.status_code].astype(str)

    @property
    def demands(self) -> np.ndarray:
        """The demanded (Fx, Fz, V[, climb]) of every cell, grid shape x number of axes."""
        return np.stack(
            np.meshgrid(*(self.axes[a] for a in self.axis_names), indexing="ij"), axis=-1
        )

    @property
    def force_error(self) -> np.ndarray:
        """max(|Fx - Fx_d|, |Fz - Fz_d|) per cell."""
        d = self.demands
        return np.maximum(
            np.abs(self.achieved[..., 0] - d[..., 0]), np.abs(self.achieved[..., 1] - d[..., 1])
        )

    def param(self, name: str) -> np.ndarray:
        """One parameter over the grid (nFx x nFz x nV)."""
        if name not in self.param_names:
            raise TableError(
                f"parameter {name!r} is not in this {self.model} table; allowed: {', '.join(self.param_names)}"
            )
        return self.params[..., self.param_names.index(name)]

    def require_model(self, model: str) -> None:
        """Refuse to drive ``model`` with a table made for another model."""
        if model != self.model:
            raise TableError(
                f"table is for model {self.model!r}, asked to drive model {model!r}; allowed: a table built for {model!r}"
            )

    def require_bird(self, bird: Bird) -> None:
        """Refuse to fly ``bird`` with a table built for another reduced bird (one line).

        A table serves every bird with the same reduced bird exactly (forces in
        ``rho omega^2 s^3 c``, speeds in ``omega s``; :mod:`birdsim.physics.units`).
        """
        from birdsim.physics.units import same_reduced_bird

        if not same_reduced_bird(self.bird, bird):
            raise TableError(
                f"table for model {self.model} was built for bird {self.bird.name!r}, whose reduced bird differs from "
                f"bird {bird.name!r}'s; allowed: a table built for it (`birdsim tables build --model {self.model} --bird FILE`)"
            )

    # ---- interpolation ---------------------------------------------------------------

    def _points(
        self, Fx: Any, Fz: Any, V: Any, clip: bool, climb: Any = 0.0
    ) -> tuple[np.ndarray, tuple[int, ...]]:
        if not self.has_climb:
            check_level_climb(climb, clip)
        values = {"Fx": Fx, "Fz": Fz, "V": V, CLIMB: climb}
        return demand_points(self.axes, self.axis_names, values, clip)

    def _interpolator(self) -> RegularGridInterpolator:
        cached = self.__dict__.get("_rgi")
        if cached is None:
            grid = tuple(np.asarray(self.axes[a], dtype=float) for a in self.axis_names)
            values = np.concatenate([self.params, self.achieved, self.cost[..., None]], axis=-1)
            cached = RegularGridInterpolator(grid, values, method="linear")
            object.__setattr__(self, "_rgi", cached)
        return cached

    def lookup_many(
        self, Fx: Any, Fz: Any, V: Any, clip: bool = False, *, climb: Any = 0.0
    ) -> dict[str, np.ndarray]:
        """Vectorised lookup: arrays (broadcast together) in, a dict of arrays of their
        shape out: every parameter plus ``achieved_Fx``, ``achieved_Fz``, ``achieved_P``
        and ``cost`` (interpolated).  Out-of-grid demands raise unless ``clip``;
        ``climb`` (positive up) other than 0 needs a table with a climb axis."""
        point = fast_lookup.scalar_point(self.axes, self.axis_names, (Fx, Fz, V), climb, clip)
        pts, shape = point if point is not None else self._points(Fx, Fz, V, clip, climb)
        vals = self._values(pts)
        d = len(self.param_names)
        names = list(self.param_names) + [f"achieved_{n}" for n in ACHIEVED_NAMES] + ["cost"]
        return {n: vals[:, k].reshape(shape) for k, n in enumerate(names[: d + 4])}

    def interpolant(self) -> fast_lookup.Interpolant:
        """The grid and values made ready for the compiled interpolation (kept)."""
        fast = self.__dict__.get("_fast")
        if fast is None:
            rgi = self._interpolator()
            fast = fast_lookup.Interpolant(rgi.grid, rgi.values)
            object.__setattr__(self, "_fast", fast)
        return fast

    def _values(self, pts: np.ndarray) -> np.ndarray:
        """The interpolated (parameters, achieved Fx, Fz, P, cost) at ``pts`` (n, axes)."""
        vals = fast_lookup.interpolate(self.interpolant(), pts)  # scipy's numbers, compiled
        return self._interpolator()(pts) if vals is None else vals

    def lookup_row(self, Fx: float, Fz: float, V: float) -> np.ndarray | None:
        """:meth:`lookup_many`'s numbers for one level demand of floats, clipped to the
        grid, as one row (parameters in ``param_names`` order, then achieved Fx, Fz, P
        and the cost), without the dict; None where :meth:`lookup_many` is needed."""
        point = fast_lookup.scalar_point(self.axes, self.axis_names, (Fx, Fz, V), 0.0, True)
        return None if point is None else self._values(point[0])[0]

    def lookup(
        self, Fx: float, Fz: float, V: float, clip: bool = False, *, climb: float = 0.0
    ) -> dict[str, float]:
        """The interpolated optimal parameters for one demand.

        Args:
            Fx, Fz: demanded mean force, the dissertation's (right wing + body drag, seed
                earth axes, Fz < 0 up), in the table's force units.
            V: flight speed, in the table's speed units.
            clip: clip a demand outside the grid to its edge instead of refusing it.
            climb: vertical speed relative to the air, positive up, in the table's speed
                units (0 = level flight; a table without a climb axis answers only 0).

        Returns:
            Parameter name -> value (radians), multilinear between the grid nodes.

        Raises:
            TableError: a demand that is not a finite number, or outside the grid
                without ``clip`` (one line naming ``Fx``, ``Fz`` or ``V``).
        """
        out = self.lookup_many(Fx, Fz, V, clip, climb=climb)
        return {n: float(out[n]) for n in self.param_names}

    def status_at(
        self, Fx: float, Fz: float, V: float, clip: bool = False, *, climb: float = 0.0
    ) -> str:
        """The worst status of the grid cells around a demand (ok < unreachable < failed)."""
        pts, _ = self._points(Fx, Fz, V, clip, climb)
        codes = self.status_code[np.ix_(*cells_around(self.axes, self.axis_names, pts[0]))]
        return STATUS_NAMES[int(codes.max())]

    # ---- moments and Jacobians (issue 22) ----------------------------------------------

    def moment_jacobians(self):
        """Every cell's moments and Jacobians (:class:`birdsim.tables.jacobians.TableJacobians`,
        table units): the stored ones, else computed now and cached on the table."""
        from birdsim.tables.jacobians import cached_jacobians

        return cached_jacobians(self)

    def lookup_jacobians(
        self, Fx: float, Fz: float, V: float, clip: bool = False, *, climb: float = 0.0
    ) -> dict[str, np.ndarray]:
        """Moments and Jacobians at one demand, multilinear between the cells as
        :meth:`lookup` (``birdsim.tables.jacobians.interpolate_jacobians``)."""
        from birdsim.tables.jacobians import interpolate_jacobians

        return interpolate_jacobians(self, self._points(Fx, Fz, V, clip, climb)[0])

    # ---- files -----------------------------------------------------------------------

    def save(self, path: str | Path, force: bool = False) -> tuple[Path, Path]:
        """Write ``<stem>.npz`` and ``<stem>.json`` atomically; refuse to overwrite without ``force``."""
        from birdsim.tables.jacobians import to_arrays

        arrays = {
            **{f"axis_{a}": np.asarray(self.axes[a], dtype=float) for a in self.axis_names},
            "params": self.params,
            "cost": self.cost,
            "cost_fractions": self.cost_fractions,
            "achieved": self.achieved,
            "status_code": self.status_code.astype(np.uint8),
            "evaluations": self.evaluations.astype(np.int64),
            "converged": np.asarray(self.converged, dtype=bool),
            **({} if self.jacobians is None else to_arrays(self.jacobians)),
        }
        meta = dict(
            model=self.model,
            param_names=list(self.param_names),
            axes={a: [float(x) for x in self.axes[a]] for a in self.axis_names},
            status_names=list(STATUS_NAMES),
            fraction_names=list(FRACTION_NAMES),
            achieved_names=list(ACHIEVED_NAMES),
            bird=self.bird.to_dict(),
        )
        after = {} if self.jacobians is None else {"jacobians": self.jacobians.meta()}
        return write_table_files(
            path, arrays, meta_kept=self.meta, meta=meta, meta_after=after, force=force
        )


def load_table(path: str | Path) -> LookupTable:
    """Read a table written by :meth:`LookupTable.save` / ``birdsim tables build``.

    Args:
        path: the ``.npz`` or ``.json`` file, or their common stem.

    Returns:
        The table (arrays indexed ``[i_Fx, i_Fz, i_V, ...]``).

    Raises:
        TableError: one line naming the file when either file is missing, unreadable,
            truncated, not a table, of another format version, or when the two do not
            belong together (checksum).
    """
    from birdsim.tables.jacobians import from_arrays

    arrays, meta, npz_path = read_table_files(path)
    try:
        table = LookupTable(
            model=str(meta["model"]),
            bird=Bird.from_dict(meta["bird"]),
            param_names=tuple(meta["param_names"]),
            axes={
                a: arrays[f"axis_{a}"]
                for a in AXES + (CLIMB,)
                if a in AXES or f"axis_{a}" in arrays
            },
            params=arrays["params"],
            cost=arrays["cost"],
            cost_fractions=arrays["cost_fractions"],
            achieved=arrays["achieved"],
            status_code=arrays["status_code"],
            evaluations=arrays["evaluations"],
            meta=meta,
            converged=arrays.get("converged"),
            jacobians=from_arrays(arrays, meta),
        )
    except TableError:
        raise
    except UNREADABLE as exc:
        raise unreadable(npz_path, exc) from None
    check_npz_version(arrays, npz_path)
    return table
