"""Lookup-table build speed: the full 11^3 table per model on all cores, and the lean
one-row path the optimiser relies on against the batched path, side by side.

Each table is built with the settings ``make tables`` builds it with (m5: the incidence
tie-break, the regularising pass at tolerance 0.03 with the neighbours' median to its fixed
point, then the plane moves: :data:`MAKE_SETTINGS`, :data:`MAKE_WEIGHTS`), so that the m5
line times the shipped table's build (issue 24's target).

``BIRDSIM_BENCH_TABLE_MODELS=base,m4`` limits the models (default: all six).
"""

from __future__ import annotations

import os
import resource
import time

from birdsim.physics.kinematics import MODELS
from birdsim.tables.build import BuildConfig, BuildSettings, Grid, build_table, solve_slice
from birdsim.tables.cost import CostWeights
from birdsim.tables.point import PointForces
from birdsim.tables.smoothness import table_smoothness

TARGETS = {"base": 10.0, "m4": 10.0, "m5": 60.0}  # s on 2 cores: issues 3 (base), 17 (m4), 24 (m5)
#: The settings of the Makefile's ``tables`` target where they are not the defaults.
MAKE_SETTINGS = {
    "m5": BuildSettings(
        smooth_tol=0.03,
        smooth_rounds=32,
        smooth_median=True,
        smooth_fixed_point=True,
        smooth_planes=True,
    )
}
#: ... and its cost weights where they are not the defaults.
MAKE_WEIGHTS = {"m5": CostWeights(incidence=1e-4)}


def _cpu_all() -> float:
    """CPU seconds of this process and its finished children (the worker processes)."""
    own, kids = (
        resource.getrusage(resource.RUSAGE_SELF),
        resource.getrusage(resource.RUSAGE_CHILDREN),
    )
    return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime


def _cpu(fn) -> float:
    t = time.process_time()
    fn()
    return time.process_time() - t


def point_ratio(model: str = "m4") -> None:
    """One V slice (121 cells): the optimiser's lean one-row path
    (:class:`birdsim.tables.point.PointForces`) vs the batched path called with one row
    (what SLSQP's requests cost before), interleaved, best of two (CPU seconds)."""
    cfg = BuildConfig(model, Grid.default(11))
    create = PointForces.create
    times: dict[str, list[float]] = {"lean": [], "batched": []}
    try:
        for _ in range(2):  # interleaved, best of two: other jobs share the machine
            for name, make in (("lean", create), ("batched", lambda *a: None)):
                PointForces.create = make  # type: ignore[method-assign]
                times[name].append(_cpu(lambda: solve_slice(cfg, 5)))
    finally:
        PointForces.create = create  # type: ignore[method-assign]
    a, b = min(times["lean"]), min(times["batched"])
    print(
        f"{model} slice V=0.5, 121 cells: lean one-row path {a:.2f} s CPU, batched path {b:.2f} s CPU -> {b / a:.2f}x"
    )


def full_tables(models: list[str]) -> None:
    jobs = os.cpu_count() or 1
    for model in models:
        t0, c0 = time.perf_counter(), _cpu_all()
        settings = MAKE_SETTINGS.get(model, BuildSettings())
        weights = MAKE_WEIGHTS.get(model, CostWeights())
        cfg = BuildConfig(model, Grid.default(11), weights=weights, settings=settings)
        t = build_table(cfg, jobs=jobs)
        dt, cpu = time.perf_counter() - t0, _cpu_all() - c0
        c = t.meta["counts"]
        rp = t.meta.get("regularising_pass", {})
        sm = table_smoothness(t)
        target = (
            f" (target < {TARGETS[model]:.0f} s: {'met' if dt < TARGETS[model] else 'MISSED'})"
            if model in TARGETS
            else ""
        )
        print(
            f"{model}{' (make tables settings)' if model in MAKE_SETTINGS else ''}: "
            f"11^3 table in {dt:.1f} s on {jobs} processes = {1331 / dt:.0f} cells/s{target}; "
            f"{cpu:.1f} CPU s (= {cpu / jobs:.1f} s on {jobs} idle cores); "
            f"{c['ok']} ok, {c['unreachable']} unreachable, {c['failed']} failed; "
            f"{t.evaluations.sum() / 1331:.0f} wingbeats evaluated per cell; "
            f"regularising pass {rp.get('seconds', 0):.1f} s of it ({rp.get('cells_resolved', 0)} cells re-solved), "
            f"zig-zag share {100 * sm.zigzag_share:.1f} %"
        )


def climb_table(model: str = "m4", target: float = 90.0) -> None:
    """The 4-axis table (11^3 x 7 climb rates) on all cores (issue 17: at most 90 s)."""
    jobs = os.cpu_count() or 1
    t0, c0 = time.perf_counter(), _cpu_all()
    t = build_table(BuildConfig(model, Grid.parse("", 11, climb=True)), jobs=jobs)
    dt, cpu = time.perf_counter() - t0, _cpu_all() - c0
    c = t.meta["counts"]
    print(
        f"{model}: 4-axis table 11^3 x 7 in {dt:.1f} s on {jobs} processes (target < {target:.0f} s: "
        f"{'met' if dt < target else 'MISSED'}); {cpu:.1f} CPU s; {c['ok']} ok, {c['unreachable']} unreachable, "
        f"{c['failed']} failed; {t.evaluations.sum() / t.evaluations.size:.0f} wingbeats evaluated per cell"
    )


def main() -> None:
    point_ratio("base")
    point_ratio("m4")
    wanted = os.environ.get("BIRDSIM_BENCH_TABLE_MODELS")
    models = [m.strip() for m in wanted.split(",")] if wanted else list(MODELS)
    full_tables(models)
    if not wanted or "m4" in models:
        climb_table("m4")


if __name__ == "__main__":
    main()
