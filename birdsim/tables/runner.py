"""Running the tasks of a table build on an executor: the inline executor
(``jobs=1``), the local process pool (workers ignore Ctrl-C and are terminated at
once on an interruption) and the loop that skips checkpointed tasks and saves finished
ones."""

from __future__ import annotations

from collections.abc import Callable
from concurrent.futures import Executor, Future, ProcessPoolExecutor, as_completed
from typing import Any

import numpy as np

from birdsim.tables.checkpoints import Checkpoints


class _InlineExecutor(Executor):
    """Runs each task at submission (``jobs=1``): no processes, same code path."""

    def submit(self, fn: Callable[..., Any], /, *args: Any, **kwargs: Any) -> Future:  # type: ignore[override]
        fut: Future = Future()
        try:
            fut.set_result(fn(*args, **kwargs))
        except BaseException as exc:  # noqa: BLE001 - handed to the caller through the future
            fut.set_exception(exc)
        return fut


def _run(
    tasks: dict[str, tuple[Callable[..., dict[str, np.ndarray]], tuple[Any, ...]]],
    executor: Executor,
    checkpoints: Checkpoints,
    tick: Callable[[int], None],
    cells_per_task: int,
) -> dict[str, dict[str, np.ndarray]]:
    done: dict[str, dict[str, np.ndarray]] = {}
    futures = {}
    for name, (fn, args) in tasks.items():
        cached = checkpoints.load(name)
        if cached is not None:
            done[name] = cached
            tick(cells_per_task)
        else:
            futures[executor.submit(run_pinned, fn, *args)] = name
    try:
        for fut in as_completed(futures):
            name = futures[fut]
            done[name] = fut.result()
            checkpoints.save(name, done[name])
            tick(cells_per_task)
    except BaseException:
        # an interruption or a failed task: keep every other task that has finished
        for fut, name in futures.items():
            if name not in done and fut.done() and not fut.cancelled() and fut.exception() is None:
                checkpoints.save(name, fut.result())
        raise
    return done


def run_pinned(fn: Callable[..., dict[str, np.ndarray]], *args: Any) -> dict[str, np.ndarray]:
    """Run one task with the BLAS libraries on one thread.  SLSQP's small linear algebra
    gives results that differ in the last bits (1e-10 in a table) with the number of
    BLAS threads, which differs between this process, pool workers and Dask workers
    (Dask sets OPENBLAS_NUM_THREADS=1): pinned, every executor builds the same table."""
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=1, user_api="blas"):
        return fn(*args)


def _ignore_sigint() -> None:
    """Worker initializer: Ctrl-C is the parent's to handle (it stops the workers)."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _stop_workers(executor: ProcessPoolExecutor) -> None:
    """Terminate a ProcessPoolExecutor's workers (running tasks are abandoned)."""
    import signal
    import threading

    main = threading.current_thread() is threading.main_thread()
    previous = (
        signal.signal(signal.SIGINT, signal.SIG_IGN) if main else None
    )  # a second Ctrl-C cannot cut this short
    try:
        terminate = getattr(executor, "terminate_workers", None)  # Python >= 3.14
        if terminate is not None:
            terminate()
        else:
            for proc in list((getattr(executor, "_processes", None) or {}).values()):
                proc.terminate()
        executor.shutdown(wait=False, cancel_futures=True)
    finally:
        if main and previous is not None:
            signal.signal(signal.SIGINT, previous)
