"""Every shipped table rebuilds: one task of its build, rerun on this machine and this
code, gives the committed wingbeats (issue 21).

The build records in the table's provenance (``reproduce``) the V slice with the most
reachable cells that kept the slice task's answer through the V passes, the climb
passes and the regularising pass, and those cells.  Rerunning that task
(:func:`birdsim.tables.sweeps.solve_slice`, with BLAS on one thread as every build task
runs) must give those cells' committed parameters to 1e-9 rad: far above round-off (the
same task is bitwise equal on this machine; with BLAS on two threads it differs by
3e-11), far below what a change of the optimiser or of the cost does to an optimum
(1e-6 rad or more).  The whole build, every pass included, is compared in the slow test
below (base) and in docs/performance.md (all eight tables, rebuilt twice).
"""

from __future__ import annotations

import re
import time

import numpy as np
import pytest
from table_platform import same_platform

from birdsim.tables.build import build_table, config_from_meta
from birdsim.tables.lookup import load_table
from birdsim.tables.runner import run_pinned
from birdsim.tables.shipped import PACKAGE_TABLES
from birdsim.tables.sweeps import solve_slice

SHIPPED = sorted(p.stem for p in PACKAGE_TABLES.glob("*.npz"))


def test_every_table_is_listed():
    assert set(SHIPPED) == {
        *("base", "m1", "m2", "m3", "m4", "m5"),
        *("pigeon-m3", "pigeon-m5", "seed-m3", "seed-m3-climb"),
    }


#: Reachable cells the recorded slice must hold: 20 for every table (exceptions by stem
#: here).  The m5 tables needed 2 and 17 while m5's shoulder flap was bounded by pi/4 (363
#: of 1331 and 1746 of 6069 cells ok); with pi/2 their slices hold 32 and 264.
MIN_OK: dict[str, int] = {}


def test_birdsim_pins_the_haswell_kernels():
    """In a fresh process without OPENBLAS_CORETYPE, importing birdsim first gives every
    OpenBLAS (numpy's, scipy's) the Haswell kernels on a CPU with AVX2 and FMA."""
    import os
    import subprocess
    import sys

    from birdsim.blas_kernel import REQUIRED_FLAGS, cpu_flags

    if not REQUIRED_FLAGS <= cpu_flags():
        pytest.skip("the CPU has no AVX2 and FMA: OpenBLAS chooses")
    env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_CORETYPE"}
    code = (
        "import birdsim, numpy, scipy.linalg; from birdsim.blas_kernel import blas_kernels; "
        "print(blas_kernels())"
    )
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    assert out.stdout.strip() == "['Haswell']", out.stderr


def _rebuild_slice(stem: str) -> tuple[np.ndarray, np.ndarray, float]:
    t = load_table(PACKAGE_TABLES / f"{stem}.npz")
    same_platform(t)
    rec = t.meta["reproduce"]
    assert re.fullmatch(r"[0-9a-f]{40}", t.meta["git_commit"]), t.meta["git_commit"]  # clean code
    cfg = config_from_meta(t)
    k, c = rec["V_index"], rec["climb_index"]
    assert rec["task"] == f"slice_V{k:03d}" + ("" if c is None else f"_C{c:03d}")
    t0 = time.perf_counter()
    out = run_pinned(solve_slice, cfg, k) if c is None else run_pinned(solve_slice, cfg, k, c)
    seconds = time.perf_counter() - t0
    cells = np.array(rec["cells"])
    mine = out["params"][cells[:, 0], cells[:, 1]]
    layer = t.params[:, :, k] if c is None else t.params[:, :, k, c]
    # a real share of the slice, reachable cells among them: not a handful of cells at
    # the bounds
    assert len(cells) >= 0.25 * layer.shape[0] * layer.shape[1], len(cells)
    status = t.status[:, :, k] if c is None else t.status[:, :, k, c]
    assert np.sum(status[cells[:, 0], cells[:, 1]] == "ok") >= MIN_OK.get(stem, 20)
    return mine, layer[cells[:, 0], cells[:, 1]], seconds


@pytest.mark.parametrize("stem", SHIPPED)
def test_one_slice_of_the_shipped_table_rebuilds_to_1e_9_rad(stem):
    """One V slice: 121 cells (11^3 tables), 357 (flight tables), 240 (climb table); 0.6-2.9
    CPU s each on this machine, 11 CPU s for the eight."""
    mine, committed, _ = _rebuild_slice(stem)
    assert np.max(np.abs(mine - committed)) <= 1e-9


@pytest.mark.slow
def test_the_whole_base_table_rebuilds_to_1e_9_rad():
    """Every pass (slices, V lines, backward passes, regularising pass), 1331 cells."""
    t = load_table(PACKAGE_TABLES / "base.npz")
    same_platform(t)
    again = build_table(config_from_meta(t), jobs=2)
    assert np.max(np.abs(again.params - t.params)) <= 1e-9
    np.testing.assert_array_equal(again.status, t.status)
