"""The end of a table build: the final check of every cell at ``n_final`` samples
(the stored costs, forces and status come from it, never from the search), the
provenance, and the table itself."""

from __future__ import annotations

import subprocess
import time
from pathlib import Path
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.kinematics import KinematicModel
from birdsim.tables.checkpoints import Checkpoints
from birdsim.tables.cost import breakdown_from_forces, forces, other_cost
from birdsim.tables.grid import BuildConfig
from birdsim.tables.lookup import STATUS_NAMES, LookupTable


def _git_commit() -> str:
    here = Path(__file__).resolve().parent
    try:
        out = subprocess.run(
            ["git", "rev-parse", "HEAD"], cwd=here, capture_output=True, text=True, timeout=10
        )
        commit = out.stdout.strip() or "unknown"
        dirty = subprocess.run(
            ["git", "status", "--porcelain", "--", "."],
            cwd=here,
            capture_output=True,
            text=True,
            timeout=10,
        )
        return commit + ("-dirty" if dirty.stdout.strip() else "")
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def demand_grid(grid: Any) -> np.ndarray:
    """The demand (Fx, Fz, V[, climb]) of every cell: grid shape x number of axes."""
    return np.stack(
        np.meshgrid(
            *(np.asarray(getattr(grid, a), dtype=float) for a in grid.axis_names), indexing="ij"
        ),
        axis=-1,
    )


def final_check(cfg: BuildConfig, model: KinematicModel, X: np.ndarray) -> dict[str, np.ndarray]:
    """Cost terms, achieved forces and status of parameters X (grid shape x d) at n_final."""
    D = demand_grid(cfg.grid)
    Fx, Fz, P = forces(
        model, X, D[..., 2], cfg.bird, cfg.settings.n_final, D[..., 3] if D.shape[-1] > 3 else 0.0
    )
    other = other_cost(model, X, D[..., 2], cfg.weights)
    b = breakdown_from_forces(Fx, Fz, P, D[..., 0], D[..., 1], cfg.weights, other)
    err = np.maximum(np.abs(Fx - D[..., 0]), np.abs(Fz - D[..., 1]))
    status = np.where(
        err > cfg.settings.reach_tol, STATUS_NAMES.index("unreachable"), STATUS_NAMES.index("ok")
    )
    bad = ~(np.isfinite(b.total) & np.all(np.isfinite(X), axis=-1))
    status = np.where(bad, STATUS_NAMES.index("failed"), status).astype(np.uint8)
    return {
        "cost": np.asarray(b.total, dtype=float),
        "cost_fractions": b.fractions,
        "achieved": np.stack([Fx, Fz, P], axis=-1),
        "status_code": status,
    }


def finish_table(
    cfg: BuildConfig,
    model: KinematicModel,
    X: np.ndarray,
    evals: np.ndarray,
    converged: np.ndarray | None = None,
) -> LookupTable:
    from birdsim import __version__
    from birdsim.blas_kernel import blas_kernels
    from birdsim.simd_dispatch import numpy_simd

    chk = final_check(cfg, model, X)
    meta = {
        "force": "right wing + body drag (the dissertation's flapcost force), seed earth axes, Fz < 0 is up",
        "package_version": __version__,
        "git_commit": _git_commit(),
        "blas_kernels": blas_kernels(),
        "numpy_simd": numpy_simd(),
        "built_at": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        "config_sha": cfg.digest(),
        **{k: v for k, v in cfg.to_dict().items() if k != "bird"},
        "counts": {s: int(np.sum(chk["status_code"] == i)) for i, s in enumerate(STATUS_NAMES)},
        "not_converged": int(np.sum(~converged)) if converged is not None else 0,
    }
    return LookupTable(
        model=cfg.model,
        bird=cfg.bird,
        param_names=model.param_names,
        axes={a: np.asarray(getattr(cfg.grid, a), dtype=float) for a in cfg.grid.axis_names},
        params=X,
        evaluations=evals,
        converged=np.ones(X.shape[:-1], dtype=bool)
        if converged is None
        else converged.astype(bool),
        meta=meta,
        **chk,
    )


def write_table(
    table: LookupTable, out: str | Path, force: bool, checkpoints: Checkpoints
) -> tuple[Path, Path]:
    """Write ``table`` to ``out`` (``.npz`` + ``.json``, each atomically: a temporary
    sibling renamed into place) and only then remove the build's checkpoints.  A write
    that fails (disk full, unwritable target, Ctrl-C) leaves the checkpoints, so the
    same build resumes at once to the same table.

    Returns:
        The paths written (``.npz``, ``.json``).
    Raises:
        BirdsimError: the write failed (one line naming ``--out`` and the folder kept).
    """
    try:
        paths = table.save(out, force=force)
    except OSError as exc:
        kept = (
            f"; the finished build is kept in {str(checkpoints.folder)!r}: run the same command again to write it"
            if checkpoints.folder
            else ""
        )
        raise BirdsimError(
            f"--out {str(out)!r} could not be written: {exc.strerror or exc}{kept}"
        ) from None
    checkpoints.remove()
    return paths
