"""Issue 27's batches on Dask: 8 flights (m4 free cruise, 10 wingbeats each) on the local
pool of two fresh worker processes and on a Dask ``local:2`` cluster, side by side in
one run: wall time including each executor's start-up, and whether the logs are
bitwise equal.  Target: Dask within 15 % of the local pool's time, bitwise equal."""

from __future__ import annotations

import time

import numpy as np

from birdsim.flight.batch import FlightJob, local_executor, run_batch

FLIGHTS = 8
SECONDS = 50.0  # 10 wingbeats of the seed bird (period 5)


def _jobs() -> list[FlightJob]:
    return [FlightJob(k, "cruise", "m4", attitude="free", seconds=SECONDS) for k in range(FLIGHTS)]


def main() -> None:
    try:
        import distributed  # noqa: F401
    except ImportError:  # pragma: no cover
        print("dask.distributed missing (pip install 'birdsim[cluster]'): skipped")
        return
    from birdsim.tables.cluster import dask_executor

    w0 = time.perf_counter()
    pool = local_executor(2)
    try:
        local = run_batch(_jobs(), pool)
    finally:
        pool.shutdown()
    w1 = time.perf_counter()
    with dask_executor("local:2") as executor:
        remote = run_batch(_jobs(), executor)
    w2 = time.perf_counter()
    same = all(
        all(np.array_equal(v, b["arrays"][k]) for k, v in a["arrays"].items())
        for a, b in zip(local, remote)
    )
    t_local, t_dask = w1 - w0, w2 - w1
    print(
        f"{FLIGHTS} flights (m4 free cruise, 10 wingbeats): local pool of 2 {t_local:.1f} s, "
        f"Dask local:2 {t_dask:.1f} s (wall, start-up included); Dask / local "
        f"{t_dask / t_local:.2f} (target <= 1.15); bitwise equal: {same}"
    )


if __name__ == "__main__":
    main()
