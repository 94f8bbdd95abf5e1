"""Lookup-table build speed: the full 11^3 table per model on all cores, and the two
batching tricks it relies on, measured side by side.

``BIRDSIM_BENCH_TABLE_MODELS=base,m4`` limits the models (default: all five).
"""

from __future__ import annotations

import os
import resource
import time

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.tables import sweeps as B
from birdsim.tables.build import BuildConfig, Grid, build_table, solve_slice
from birdsim.tables.cost import forces
from birdsim.tables.smoothness import table_smoothness
from birdsim.physics.kinematics import MODELS, get_model

TARGETS = {"base": 10.0, "m4": 60.0}  # seconds, issue 3


def _sequential(model, bird, n, jobs):
    return [job(lambda X, v: forces(model, X, v, bird, n)) for job in jobs]


def _cpu_all() -> float:
    """CPU seconds of this process and its finished children (the worker processes)."""
    own, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime


def _cpu(fn) -> float:
    t = time.process_time()
    fn()
    return time.process_time() - t


def lockstep_ratio(model: str = "base") -> None:
    """One V slice (121 cells) with the Fx lines in lockstep vs one cell after another."""
    cfg = BuildConfig(model, Grid.default(11))
    lock = B.run_lockstep
    times = {"lockstep": [], "sequential": []}
    try:
        for _ in range(2):  # interleaved, best of two: other jobs share the machine
            for name, fn in (("lockstep", lock), ("sequential", _sequential)):
                B.run_lockstep = fn
                times[name].append(_cpu(lambda: solve_slice(cfg, 5)))
    finally:
        B.run_lockstep = lock
    a, b = min(times["lockstep"]), min(times["sequential"])
    print(f"{model} slice V=0.5, 121 cells: lockstep {a:.2f} s CPU, sequential {b:.2f} s CPU -> {b / a:.2f}x")


def batched_gradient_ratio(model: str = "m4") -> None:
    """A central-difference gradient (2d+1 wingbeats): one batched call vs one by one."""
    m = get_model(model)
    lo, hi = m.bounds
    X = np.random.default_rng(0).uniform(lo, hi, (2 * lo.size + 1, lo.size))
    reps = 100
    t0 = time.perf_counter()
    for _ in range(reps):
        forces(m, X, 0.5, Bird(), 32)
    t1 = time.perf_counter()
    for _ in range(reps):
        for row in X:
            forces(m, row[None], 0.5, Bird(), 32)
    t2 = time.perf_counter()
    one, many = (t1 - t0) / reps, (t2 - t1) / reps
    print(f"{model} gradient, {len(X)} wingbeats at n=32: batched {1e3 * one:.2f} ms, one by one {1e3 * many:.2f} ms -> {many / one:.1f}x")


def full_tables(models: list[str]) -> None:
    jobs = os.cpu_count() or 1
    for model in models:
        t0, c0 = time.perf_counter(), _cpu_all()
        t = build_table(BuildConfig(model, Grid.default(11)), jobs=jobs)
        dt, cpu = time.perf_counter() - t0, _cpu_all() - c0
        c = t.meta["counts"]
        rp = t.meta.get("regularising_pass", {})
        sm = table_smoothness(t)
        target = f" (target < {TARGETS[model]:.0f} s: {'met' if dt < TARGETS[model] else 'MISSED'})" if model in TARGETS else ""
        print(
            f"{model}: 11^3 table in {dt:.1f} s on {jobs} processes = {1331 / dt:.0f} cells/s{target}; "
            f"{cpu:.1f} CPU s (= {cpu / jobs:.1f} s on {jobs} idle cores); "
            f"{c['ok']} ok, {c['unreachable']} unreachable, {c['failed']} failed; "
            f"{t.evaluations.sum() / 1331:.0f} wingbeats evaluated per cell; "
            f"regularising pass {rp.get('seconds', 0):.1f} s of it ({rp.get('cells_resolved', 0)} cells re-solved), "
            f"zig-zag share {100 * sm.zigzag_share:.1f} %"
        )


def main() -> None:
    batched_gradient_ratio("m4")
    lockstep_ratio("base")
    lockstep_ratio("m4")
    wanted = os.environ.get("BIRDSIM_BENCH_TABLE_MODELS")
    models = [m.strip() for m in wanted.split(",")] if wanted else list(MODELS)
    full_tables(models)


if __name__ == "__main__":
    main()
