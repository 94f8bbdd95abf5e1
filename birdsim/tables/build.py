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
   candidates are polished too (multi-start) and the best answer wins; another branch
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
:mod:`.runner` (executors and the task loop) and :mod:`.finish` (final check, provenance,
the final write).  Their public names are re-exported here.
"""
from __future__ import annotations

import os
import time
from collections.abc import Callable
from concurrent.futures import Executor, ProcessPoolExecutor
from pathlib import Path

import numpy as np

from birdsim.physics.kinematics import get_model
from birdsim.tables.checkpoints import Checkpoints
from birdsim.tables.finish import final_check, finish_table, write_table
from birdsim.tables.grid import MAX_CELLS, MAX_NODES, BuildConfig, BuildSettings, Grid, config_from_meta, sub_grid
from birdsim.tables.lookup import LookupTable
from birdsim.tables.runner import _InlineExecutor, _ignore_sigint, _run, _stop_workers
from birdsim.tables.sweeps import IDLE_WRIST, canonical_params, solve_slice, solve_v_line

__all__ = [
    "MAX_CELLS", "MAX_NODES", "IDLE_WRIST", "BuildConfig", "BuildSettings", "Checkpoints", "Grid",
    "build_table", "canonical_params", "config_from_meta", "final_check", "finish_table",
    "solve_slice", "solve_v_line", "sub_grid", "write_table",
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
        notify: receives one-line notes (checkpoints discarded and why).
    Returns:
        The table (provenance in ``meta``).
    Raises:
        BirdsimError: invalid checkpoint folder, or ``out`` could not be written.
    """
    model = get_model(cfg.model)
    g = cfg.grid
    t0 = time.perf_counter()
    ckpt = Checkpoints(Path(checkpoint_dir) if checkpoint_dir else None, cfg.digest(), cfg.stamp())
    if ckpt.discarded and notify is not None:
        notify(ckpt.discarded)
    ncells = int(np.prod(g.shape))
    passes = 2 if cfg.settings.v_passes else 1
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=passes * ncells, unit="cell", desc=f"tables {cfg.model}", leave=False)
    tick = (lambda k: bar.update(k)) if bar is not None else (lambda k: None)
    own = executor is None
    if own:
        jobs = jobs or os.cpu_count() or 1
        executor = _InlineExecutor() if jobs == 1 else ProcessPoolExecutor(max_workers=jobs, initializer=_ignore_sigint)
    assert executor is not None
    try:
        X, evals, conv = _sweep(cfg, executor, ckpt, tick)
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
    table.meta.update(build_seconds=round(seconds, 3), cells_per_second=round(ncells / seconds, 2), jobs=jobs if own else "executor")
    if out is not None:
        write_table(table, out, force, ckpt)
    else:
        ckpt.remove()
    return table


def _sweep(
    cfg: BuildConfig, executor: Executor, ckpt: Checkpoints, tick: Callable[[int], None]
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The slices, then the V lines: (params, evaluations, converged) over the grid."""
    g = cfg.grid
    slices = _run(
        {f"slice_V{k:03d}": (solve_slice, (cfg, k)) for k in range(len(g.V))},
        executor, ckpt, tick, len(g.Fx) * len(g.Fz),
    )
    X = np.stack([slices[f"slice_V{k:03d}"]["params"] for k in range(len(g.V))], axis=2)
    cost = np.stack([slices[f"slice_V{k:03d}"]["cost"] for k in range(len(g.V))], axis=2)
    evals = np.stack([slices[f"slice_V{k:03d}"]["evaluations"] for k in range(len(g.V))], axis=2)
    conv = np.stack([slices[f"slice_V{k:03d}"]["converged"] for k in range(len(g.V))], axis=2)
    if cfg.settings.v_passes:
        lines = _run(
            {f"line_Fx{i:03d}": (solve_v_line, (cfg, i, X[i], cost[i], conv[i])) for i in range(len(g.Fx))},
            executor, ckpt, tick, len(g.Fz) * len(g.V),
        )
        X = np.stack([lines[f"line_Fx{i:03d}"]["params"] for i in range(len(g.Fx))], axis=0)
        evals = evals + np.stack([lines[f"line_Fx{i:03d}"]["evaluations"] for i in range(len(g.Fx))], axis=0)
        conv = np.stack([lines[f"line_Fx{i:03d}"]["converged"] for i in range(len(g.Fx))], axis=0)
    return X, evals, conv
