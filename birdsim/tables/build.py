"""Filling a lookup table: continuation sweeps with warm starts (dissertation sec. 4.1.1,
Fig. 39), parallel over an executor, checkpointed so that an interrupted build resumes.

Order of the work (the dissertation's stable order: Fz, then Fx, then V):

1. *Slices* (one task per V): a screen of ``screen`` space-filling candidate wingbeats
   is evaluated in ONE batched call and costed against every (Fx, Fz) demand of the
   slice at once.  Then Fx lines are swept from +Fx_max down (a backward pass in Fx),
   each line sweeping Fz from the strongest lift demand (most negative Fz) to 0, every
   cell warm-started from the previous cell.  Where the warm start is poor (its optimum
   is not better than the best screen candidate by ``screen_gap``: polishing a screen
   candidate often gains that much) the best ``starts`` screen
   candidates are polished too (multi-start; except polishes that cannot win, the
   polish rule of :func:`birdsim.tables.sweeps._solve_cell`) and the best answer wins; another branch
   replaces the warm-start branch only when it is cheaper by ``switch_margin``, which
   keeps the table smooth where the minima are nearly tied.  A backward pass in Fz
   (0 -> strongest lift) then re-solves every cell from those of its Fx/Fz neighbours
   that sit on another branch (farther than ``branch_tol``) and keeps what is cheaper.
2. *V passes* (one task per Fx line): a forward pass V = 0 -> V_max and a backward
   pass re-solve every cell from its V-neighbour (unless the neighbour's parameters are
   within ``branch_tol`` of the cell's: same branch); a re-solve replaces the cell when
   it is cheaper.  Optional under-relaxation (eq. 94, ``relax`` < 1) and the distance cost
   (eq. 93, ``CostWeights.distance``) act along this pass.
3. *Final check*: every cell is re-evaluated at ``n_final`` samples per wingbeat in one
   batched call; achieved forces, cost fractions and the status (``ok``,
   ``unreachable``: the optimum misses the demand by more than ``reach_tol``,
   ``failed``: non-finite) come from that check, never from the search.

Tasks are submitted to any :class:`concurrent.futures.Executor` (a
``ProcessPoolExecutor`` by default; dask.distributed's ``Client.get_executor()`` or
similar plugs in unchanged).  Each finished task is written to the checkpoint folder;
a rerun with the same configuration skips the finished tasks.

This module is the orchestration only; the parts live beside it: :mod:`.grid`
(configuration), :mod:`.sweeps` (the continuation passes), :mod:`.checkpoints`,
:mod:`.runner` (executors and the task loop), :mod:`.regularise` and :mod:`.plane_moves`
(the smoothing after the sweeps) and :mod:`.finish` (final check, provenance, the final
write).  Their public names are re-exported here.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from concurrent.futures import Executor, ProcessPoolExecutor
from pathlib import Path
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.kinematics import get_model
from birdsim.tables.checkpoints import Checkpoints
from birdsim.tables.cost import forces
from birdsim.tables.finish import demand_grid, final_check, finish_table, write_table
from birdsim.tables.grid import (
    MAX_CELLS,
    MAX_NODES,
    BuildConfig,
    BuildSettings,
    Grid,
    config_from_meta,
    sub_grid,
)
from birdsim.tables.lookup import LookupTable
from birdsim.tables.plane_moves import plane_moves
from birdsim.tables.regularise import CandidateMemo, smooth_cells, zigzag_cells
from birdsim.tables.runner import _ignore_sigint, _InlineExecutor, _run, _stop_workers
from birdsim.tables.sweeps import (
    IDLE_WRIST,
    canonical_params,
    solve_climb_line,
    solve_slice,
    solve_v_line,
)

__all__ = [
    "MAX_CELLS",
    "MAX_NODES",
    "IDLE_WRIST",
    "BuildConfig",
    "BuildSettings",
    "Checkpoints",
    "Grid",
    "build_table",
    "canonical_params",
    "config_from_meta",
    "final_check",
    "finish_table",
    "solve_climb_line",
    "solve_slice",
    "solve_v_line",
    "sub_grid",
    "write_table",
]


def build_table(
    cfg: BuildConfig,
    *,
    executor: Executor | None = None,
    jobs: int | None = None,
    checkpoint_dir: str | Path | None = None,
    progress: bool = False,
    out: str | Path | None = None,
    force: bool = False,
    notify: Callable[[str], None] | None = None,
    executor_name: str = "executor",
) -> LookupTable:
    """Build the table of ``cfg``.

    Args:
        cfg: grid, bird, cost weights and solver settings.
        executor: any concurrent.futures Executor (wins over ``jobs``).
        jobs: worker processes (1 = in this process; default: all cores).
        checkpoint_dir: folder for finished tasks (resume); removed once the table is
            written to ``out`` (or, without ``out``, once it is built).
        progress: show a tqdm bar of the cells done.
        out: write the table there (``.npz`` + ``.json``) before the checkpoints are
            removed, so that a failed write loses nothing.
        force: overwrite an existing ``out``.
        notify: receives one-line notes (checkpoints discarded and why, or reused).
        executor_name: how the provenance names a given ``executor`` (e.g. "dask local:2").
    Returns:
        The table (provenance in ``meta``).
    Raises:
        BirdsimError: invalid checkpoint folder, or ``out`` could not be written.
    """
    model = get_model(cfg.model)
    g = cfg.grid
    t0 = time.perf_counter()
    if jobs is not None and (isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1):
        raise BirdsimError(
            f"jobs={jobs!r} is invalid; allowed: an integer >= 1, or None (all cores)"
        )
    ckpt = Checkpoints(Path(checkpoint_dir) if checkpoint_dir else None, cfg.digest(), cfg.stamp())
    if ckpt.discarded and notify is not None:
        notify(ckpt.discarded)
    elif ckpt.kept and notify is not None:  # a resumed build says so
        notify(f"resuming: {ckpt.kept} finished part(s) in {str(checkpoint_dir)!r} are reused")
    ncells = int(np.prod(g.shape))
    passes = 1 + (1 + (g.climb is not None) if cfg.settings.v_passes else 0)
    bar = None
    if progress:
        from tqdm import tqdm

        # the bar counts cells (each continuation pass solves every cell once: a pass is 1/passes of a cell)
        bar = tqdm(
            total=ncells,
            unit="cell",
            desc=f"tables {cfg.model}",
            leave=False,
            disable=None,
            bar_format="{l_bar}{bar}| {n:.0f}/{total} cells [{elapsed}<{remaining}]",
        )
    tick = (lambda k: bar.update(k / passes)) if bar is not None else (lambda k: None)
    own = executor is None
    if own:
        jobs = jobs or os.cpu_count() or 1
        executor = (
            _InlineExecutor()
            if jobs == 1
            else ProcessPoolExecutor(max_workers=jobs, initializer=_ignore_sigint)
        )
    assert executor is not None
    try:
        X, cost, evals, conv, X_slices = _sweep(cfg, executor, ckpt, tick)
        if cfg.settings.smooth_tol > 0:
            X, evals, smoothing, best = _regularise(cfg, executor, ckpt, X, cost, evals)
            if cfg.settings.smooth_planes:
                X, evals, smoothing["plane_moves"] = plane_moves(cfg, X, best, evals)
    except BaseException:
        # Ctrl-C or a failed task: finished parts are saved; stop our workers now (a
        # second Ctrl-C inside shutdown(wait=True) used to leave them alive and the
        # process hanging at exit)
        if own and isinstance(executor, ProcessPoolExecutor):
            _stop_workers(executor)
        raise
    finally:
        if own:
            executor.shutdown(wait=True, cancel_futures=True)
        if bar is not None:
            bar.close()
    table = finish_table(cfg, model, X, evals, conv)
    seconds = time.perf_counter() - t0
    table.meta.update(
        build_seconds=round(seconds, 3),
        cells_per_second=round(ncells / seconds, 2),
        jobs=jobs if own else executor_name,
    )
    if cfg.settings.smooth_tol > 0:
        table.meta["regularising_pass"] = smoothing
    table.meta["reproduce"] = reproduce_record(X, X_slices, table.status == "ok")
    if out is not None:
        write_table(table, out, force, ckpt)
    else:
        ckpt.remove()
    return table


def reproduce_record(X: np.ndarray, X_slices: np.ndarray, ok: np.ndarray) -> dict[str, Any]:
    """Where the finished table can be checked in seconds: the V slice (at one climb
    node on a 4-axis grid) with the most reachable (``ok``) cells that kept the slice
    task's answer through the later passes (ties: the lowest index), and the (Fx, Fz)
    indices of all its cells that kept it.  Rebuilding that one task
    (:func:`solve_slice`) must give those cells' wingbeats
    (``tests/test_shipped_rebuild.py``)."""
    kept = np.all(X == X_slices, axis=-1)  # grid shape
    per_slice = (kept & ok).reshape(kept.shape[:2] + (-1,)).sum(axis=(0, 1))
    flat = int(np.argmax(per_slice))
    if kept.ndim == 3:
        k, c, mask = flat, None, kept[:, :, flat]
    else:
        k, c = divmod(flat, kept.shape[3])
        mask = kept[:, :, k, c]
    return {
        "task": f"slice_V{k:03d}" + ("" if c is None else f"_C{c:03d}"),
        "V_index": k,
        "climb_index": c,
        "cells": [[int(i), int(j)] for i, j in np.argwhere(mask)],
    }


def _sweep(
    cfg: BuildConfig, executor: Executor, ckpt: Checkpoints, tick: Callable[[int], None]
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The slices, the V lines and, on a grid with a climb axis, the climb lines:
    (params, cost at n_search, evaluations, converged, and the params as the slice
    tasks left them) over the grid.  Task names of a
    level-flight grid are those of before (``slice_V005``, ``line_Fx003``); a climb
    index adds ``_C002``; climb lines are ``cline_Fx003_V005``."""
    g = cfg.grid
    nfx, nfz, nv = len(g.Fx), len(g.Fz), len(g.V)
    climbs: list[int | None] = [None] if g.climb is None else list(range(len(g.climb)))
    nc = len(climbs)

    def sfx(c: int | None) -> str:
        return "" if c is None else f"_C{c:03d}"

    def extra(c: int | None) -> tuple[int, ...]:
        return () if c is None else (c,)

    d = len(get_model(cfg.model).param_names)
    X = np.zeros((nfx, nfz, nv, nc, d))
    cost = np.zeros((nfx, nfz, nv, nc))
    evals = np.zeros((nfx, nfz, nv, nc), dtype=np.int64)
    conv = np.zeros((nfx, nfz, nv, nc), dtype=bool)
    slices = _run(
        {
            f"slice_V{k:03d}{sfx(c)}": (solve_slice, (cfg, k) + extra(c))
            for c in climbs
            for k in range(nv)
        },
        executor,
        ckpt,
        tick,
        nfx * nfz,
    )
    for ci, c in enumerate(climbs):
        for k in range(nv):
            r = slices[f"slice_V{k:03d}{sfx(c)}"]
            X[:, :, k, ci], cost[:, :, k, ci], evals[:, :, k, ci], conv[:, :, k, ci] = (
                r["params"],
                r["cost"],
                r["evaluations"],
                r["converged"],
            )
    X_slices = X.copy()
    if cfg.settings.v_passes:
        lines = _run(
            {
                f"line_Fx{i:03d}{sfx(c)}": (
                    solve_v_line,
                    (cfg, i, X[i, :, :, ci], cost[i, :, :, ci], conv[i, :, :, ci]) + extra(c),
                )
                for ci, c in enumerate(climbs)
                for i in range(nfx)
            },
            executor,
            ckpt,
            tick,
            nfz * nv,
        )
        for ci, c in enumerate(climbs):
            for i in range(nfx):
                r = lines[f"line_Fx{i:03d}{sfx(c)}"]
                X[i, :, :, ci], cost[i, :, :, ci], conv[i, :, :, ci] = (
                    r["params"],
                    r["cost"],
                    r["converged"],
                )
                evals[i, :, :, ci] += r["evaluations"]
        if g.climb is not None:
            clines = _run(
                {
                    f"cline_Fx{i:03d}_V{k:03d}": (
                        solve_climb_line,
                        (cfg, i, k, X[i, :, k], cost[i, :, k], conv[i, :, k]),
                    )
                    for i in range(nfx)
                    for k in range(nv)
                },
                executor,
                ckpt,
                tick,
                nfz * nc,
            )
            for i in range(nfx):
                for k in range(nv):
                    r = clines[f"cline_Fx{i:03d}_V{k:03d}"]
                    X[i, :, k], cost[i, :, k], conv[i, :, k] = (
                        r["params"],
                        r["cost"],
                        r["converged"],
                    )
                    evals[i, :, k] += r["evaluations"]
    if g.climb is None:
        return X[:, :, :, 0], cost[..., 0], evals[..., 0], conv[..., 0], X_slices[:, :, :, 0]
    return X, cost, evals, conv, X_slices


#: Cells per task of the regularising pass: small enough to balance the cores.
SMOOTH_TASK_CELLS = 8


def _regularise(
    cfg: BuildConfig,
    executor: Executor,
    ckpt: Checkpoints,
    X: np.ndarray,
    cost: np.ndarray,
    evals: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, dict[str, Any], np.ndarray]:
    """The regularising pass (:mod:`birdsim.tables.regularise`): red-black rounds over
    the middle cells of zig-zags, tasks of a few cells of one colour, until a round
    removes no zig-zag cell (``smooth_fixed_point``: until a round changes no cell and
    no best cost).  Returns the new parameters, the evaluations, a summary for the
    provenance and the best cost found per cell (at n_search)."""
    model = get_model(cfg.model)
    names, st = model.param_names, cfg.settings
    X, evals = X.copy(), evals.copy()
    D = demand_grid(cfg.grid)
    Fx, Fz, _ = forces(
        model, X, D[..., 2], cfg.bird, st.n_search, D[..., 3] if D.shape[-1] > 3 else 0.0
    )
    ok = np.maximum(np.abs(Fx - D[..., 0]), np.abs(Fz - D[..., 1])) <= st.reach_tol
    best = np.asarray(cost, dtype=float).copy()
    t0 = time.perf_counter()
    summary: dict[str, Any] = {
        "rounds": 0,
        "cells_resolved": 0,
        "cells_changed": 0,
        "zigzag_cells": [],
    }
    memo = CandidateMemo()
    for r in range(st.smooth_rounds):
        worked, before = False, (X.copy(), best.copy())
        summary["zigzag_cells"].append(len(zigzag_cells(names, X, ok)))
        for colour in (0, 1):
            mids = zigzag_cells(names, X, ok)
            mids = mids[mids.sum(axis=1) % 2 == colour]
            if len(mids) == 0:
                continue
            worked = True
            # tasks of at most SMOOTH_TASK_CELLS cells and similar work (the cells of one
            # colour are independent: how they are grouped does not change the result)
            groups = memo.groups(mids, X, ok, st.smooth_median, SMOOTH_TASK_CELLS)
            tasks = {
                f"smooth_r{r}c{colour}_{k:03d}": (
                    smooth_cells,
                    (cfg, cells, X, ok, best[tuple(cells.T)], D, memo.for_cells(cells)),
                )
                for k, cells in enumerate(groups)
            }
            done = _run(tasks, executor, ckpt, lambda k: None, 0)
            for name, (_fn, args) in tasks.items():
                cells, res = args[1], done[name]
                memo.add(res)
                idx = tuple(cells.T)
                summary["cells_resolved"] += len(cells)
                summary["cells_changed"] += int(np.sum(np.any(res["params"] != X[idx], axis=-1)))
                X[idx] = res["params"]
                best[idx] = res["best"]
                evals[idx] += res["evaluations"]
        summary["rounds"] = r + 1
        if st.smooth_fixed_point:
            if np.array_equal(X, before[0]) and np.array_equal(best, before[1]):
                break  # a round that changed nothing: the next would repeat it
        elif not worked or summary["zigzag_cells"][-1] <= len(zigzag_cells(names, X, ok)):
            break  # no zig-zag left, or a round that removed none (the next would repeat it)
    summary["zigzag_cells"].append(len(zigzag_cells(names, X, ok)))
    summary["seconds"] = round(time.perf_counter() - t0, 3)
    return X, evals, summary, best
