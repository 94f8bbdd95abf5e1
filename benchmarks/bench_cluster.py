"""Table builds on Dask and with the climb axis: the cost model of docs/tables.md.

* per-task overhead of a ``local:2`` cluster (no-op tasks through the build's runner);
* the same table on the local pool and on ``local:2`` (wall, bitwise equality);
* CPU seconds per cell of a 4-axis m4 build (a corner of the grid), extrapolated to the
  11 x 11 x 11 x 7 table on this machine and to 21 x 21 x 21 x 11 on 64 workers.

Needs ``birdsim[cluster]``; prints one line and returns without it.
``BIRDSIM_BENCH_CLIMB_GRID`` overrides the 4-axis corner (a --grid spec).
"""

from __future__ import annotations

import math
import os
import resource
import time

from birdsim.tables.build import BuildConfig, Grid, build_table

POOL_GRID = "Fx=-0.5:0.5:11,Fz=-0.5:0:11,V=0:1:6"  # m1, 726 cells: 6 slices + 11 lines
CLIMB_GRID = "Fx=-0.5:0.5:5,Fz=-0.5:0:5,V=0:1:3,climb=-0.5:0.5:3"  # m4, 225 cells


def _cpu_children() -> float:
    own, kids = (
        resource.getrusage(resource.RUSAGE_SELF),
        resource.getrusage(resource.RUSAGE_CHILDREN),
    )
    return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime


def _noop() -> dict:
    return {}


def overhead(ex, n: int = 200) -> float:
    """Seconds per task of the executor (submit, run a no-op, return), in flight together."""
    from birdsim.tables.runner import run_pinned

    t0 = time.perf_counter()
    futures = [ex.submit(run_pinned, _noop) for _ in range(n)]
    for f in futures:
        f.result()
    return (time.perf_counter() - t0) / n


def pool_vs_dask() -> tuple[float, float]:
    from birdsim.tables.cluster import dask_executor

    cfg = BuildConfig("m1", Grid.parse(POOL_GRID))
    t0 = time.perf_counter()
    pool = build_table(cfg, jobs=2)
    t_pool = time.perf_counter() - t0
    t0 = time.perf_counter()
    with dask_executor("local:2") as ex:
        t_start = time.perf_counter() - t0
        per_task = overhead(ex)
        t1 = time.perf_counter()
        dask = build_table(cfg, executor=ex)
        t_dask = time.perf_counter() - t1
    same = all(
        getattr(pool, k).tobytes() == getattr(dask, k).tobytes()
        for k in ("params", "cost", "status_code")
    )
    cells = math.prod(cfg.grid.shape)
    print(
        f"m1 {'x'.join(map(str, cfg.grid.shape))} ({cells} cells, tasks of {cfg.grid.shape[0] * cfg.grid.shape[1]} cells): "
        f"local pool (2 processes) {t_pool:.1f} s, Dask local:2 {t_dask:.1f} s (+{100 * (t_dask / t_pool - 1):.0f} %; "
        f"cluster start {t_start:.1f} s not counted), bitwise identical: {same}; per-task overhead {1e3 * per_task:.1f} ms"
    )
    return per_task, t_dask


def climb_cost(per_task: float) -> None:
    spec = os.environ.get("BIRDSIM_BENCH_CLIMB_GRID", CLIMB_GRID)
    cfg = BuildConfig("m4", Grid.parse(spec))
    c0, t0 = _cpu_children(), time.perf_counter()
    t = build_table(cfg, jobs=2)
    cpu, wall = _cpu_children() - c0, time.perf_counter() - t0
    cells = math.prod(cfg.grid.shape)
    per_cell = cpu / cells
    print(
        f"m4 4-axis corner {'x'.join(map(str, cfg.grid.shape))} ({cells} cells): {wall:.1f} s wall, {cpu:.1f} CPU s "
        f"= {1e3 * per_cell:.0f} ms per cell = {1 / per_cell:.1f} cells/s per worker process; "
        f"{t.meta['counts']['ok']} ok"
    )
    full = 11 * 11 * 11 * 7
    print(
        f"  -> 11x11x11x7 m4 ({full} cells) on 2 idle cores: about {full * per_cell / 2 / 60:.1f} min"
    )
    # 21^3 x 11 on 64 workers: phases run one after the other; a phase of T tasks of
    # c cells each takes ceil(T / 64) waves of c * per_cell (+ overhead) seconds
    n, nv, nc, w = 21, 21, 11, 64
    phases = [
        (nv * nc, n * n),
        (n * nc, n * nv),
        (n * nv, n * nc),
    ]  # slices, V lines, climb lines: (tasks, cells per task)
    # upper bound: every phase charged the whole per-cell cost; lower: perfectly spread
    upper = sum(math.ceil(T / w) * (c * per_cell + per_task) for T, c in phases)
    lower = n**3 * nc * per_cell / w + sum(math.ceil(T / w) for T, _ in phases) * per_task
    print(
        f"  -> 21x21x21x11 m4 ({n**3 * nc} cells) on {w} workers: between {lower / 60:.1f} min (work spread perfectly) "
        f"and {upper / 60:.1f} min (each of the 3 phases, 231, 231 and 441 tasks, charged the whole per-cell cost)"
    )


def main() -> None:
    import importlib.util

    if importlib.util.find_spec("distributed") is None:
        print("dask.distributed is not installed (pip install 'birdsim[cluster]'): skipped")
        return
    per_task, _ = pool_vs_dask()
    climb_cost(per_task)


if __name__ == "__main__":
    main()
