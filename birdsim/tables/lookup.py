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
"""

from __future__ import annotations

import hashlib
import io
import json
import zipfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from birdsim.errors import BirdsimError
from birdsim.io import check_output, write_atomic
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import MODELS
from birdsim.tables.cost import FRACTION_NAMES

#: Bump when the file layout changes; tables of another version are refused on load.
TABLE_FORMAT_VERSION = 1
AXES = ("Fx", "Fz", "V")
#: The optional fourth axis (after V): vertical speed relative to the air, positive up.
CLIMB = "climb"
STATUS_NAMES = ("ok", "unreachable", "failed")
ACHIEVED_NAMES = ("Fx", "Fz", "P")


class TableError(BirdsimError):
    """A table file that cannot be read, or a lookup it cannot answer."""


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
        values = {"Fx": Fx, "Fz": Fz, "V": V, CLIMB: climb}
        arrays = {}
        if not self.has_climb:
            self._level_only(climb, clip)
        for a in self.axis_names:
            try:
                arr = np.asarray(values[a], dtype=float)
            except (TypeError, ValueError):
                raise TableError(f"{a}={values[a]!r} is not a number") from None
            if not np.all(np.isfinite(arr)):
                bad = arr[~np.isfinite(arr)].flat[0] if arr.ndim else float(arr)
                raise TableError(
                    f"{a}={bad} is not finite; allowed: a number in [{self.axes[a][0]:g}, {self.axes[a][-1]:g}]"
                )
            lo, hi = float(self.axes[a][0]), float(self.axes[a][-1])
            if clip:
                arr = np.clip(arr, lo, hi)
            else:
                # 1e-12: a demand printed from the axis itself must count as inside
                out = (arr < lo - 1e-12) | (arr > hi + 1e-12)
                if np.any(out):
                    bad = float(arr[out].flat[0]) if arr.ndim else float(arr)
                    raise TableError(
                        f"{a}={bad:g} is outside the table grid; allowed: [{lo:g}, {hi:g}] (or clip=True)"
                    )
                arr = np.clip(arr, lo, hi)
            arrays[a] = arr
        b = np.broadcast_arrays(*(arrays[a] for a in self.axis_names))
        return np.stack([x.ravel() for x in b], axis=-1), b[0].shape

    def _level_only(self, climb: Any, clip: bool) -> None:
        """A table without a climb axis answers climb = 0 (or anything, clipped to 0)."""
        try:
            arr = np.asarray(climb, dtype=float)
        except (TypeError, ValueError):
            raise TableError(f"climb={climb!r} is not a number") from None
        if not np.all(np.isfinite(arr)):
            raise TableError(
                f"climb={arr[~np.isfinite(arr)].flat[0] if arr.ndim else float(arr)} is not finite; allowed: 0 (this table has no climb axis)"
            )
        if not clip and np.any(np.abs(arr) > 1e-12):
            bad = float(arr[np.abs(arr) > 1e-12].flat[0]) if arr.ndim else float(arr)
            raise TableError(
                f"climb={bad:g} is outside the table grid; allowed: 0 (a table without a climb axis is for level flight; "
                "build one with `birdsim tables build --climb`, or clip=True / --clip)"
            )

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
        pts, shape = self._points(Fx, Fz, V, clip, climb)
        vals = self._interpolator()(pts)
        d = len(self.param_names)
        names = list(self.param_names) + [f"achieved_{n}" for n in ACHIEVED_NAMES] + ["cost"]
        return {n: vals[:, k].reshape(shape) for k, n in enumerate(names[: d + 4])}

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
        idx = []
        for k, a in enumerate(self.axis_names):
            ax = self.axes[a]
            i = int(np.clip(np.searchsorted(ax, pts[0, k]) - 1, 0, len(ax) - 2))
            near = [i, i + 1]
            for j in (i, i + 1):  # on a node: that node only
                if abs(ax[j] - pts[0, k]) < 1e-12:
                    near = [j]
            idx.append(near)
        codes = self.status_code[np.ix_(*idx)]
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

        npz_path, json_path = table_paths(path)
        check_output(npz_path, force)
        check_output(json_path, force, arg="path (json)")
        buf = io.BytesIO()
        np.savez_compressed(
            buf,
            format_version=np.array(TABLE_FORMAT_VERSION),
            **{f"axis_{a}": np.asarray(self.axes[a], dtype=float) for a in self.axis_names},
            params=self.params,
            cost=self.cost,
            cost_fractions=self.cost_fractions,
            achieved=self.achieved,
            status_code=self.status_code.astype(np.uint8),
            evaluations=self.evaluations.astype(np.int64),
            converged=np.asarray(self.converged, dtype=bool),
            **({} if self.jacobians is None else to_arrays(self.jacobians)),
        )
        data = buf.getvalue()
        meta = dict(self.meta)
        meta.update(
            format_version=TABLE_FORMAT_VERSION,
            model=self.model,
            param_names=list(self.param_names),
            axes={a: [float(x) for x in self.axes[a]] for a in self.axis_names},
            status_names=list(STATUS_NAMES),
            fraction_names=list(FRACTION_NAMES),
            achieved_names=list(ACHIEVED_NAMES),
            bird=self.bird.to_dict(),
            npz_sha256=hashlib.sha256(data).hexdigest(),
            npz_file=npz_path.name,
        )
        if self.jacobians is not None:
            meta["jacobians"] = self.jacobians.meta()
        write_atomic(npz_path, data)
        write_atomic(json_path, (json.dumps(meta, indent=2, sort_keys=False) + "\n").encode())
        return npz_path, json_path


def table_paths(path: str | Path) -> tuple[Path, Path]:
    """(``<stem>.npz``, ``<stem>.json``) for a path given with either suffix or none."""
    p = Path(path)
    if p.suffix in (".npz", ".json"):
        p = p.with_suffix("")
    return p.with_name(p.name + ".npz"), p.with_name(p.name + ".json")


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

    npz_path, json_path = table_paths(path)
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
        npz_version = int(arrays["format_version"])
    except TableError:
        raise
    except (KeyError, ValueError, TypeError, OSError, EOFError, zipfile.BadZipFile) as exc:
        why = f"missing {exc}" if isinstance(exc, KeyError) else str(exc)
        raise TableError(
            f"table file {str(npz_path)!r} is unreadable or incomplete: {why}"
        ) from None
    if npz_version != TABLE_FORMAT_VERSION:
        raise TableError(
            f"table file {str(npz_path)!r} has format version {npz_version}; allowed: {TABLE_FORMAT_VERSION}"
        )
    return table
