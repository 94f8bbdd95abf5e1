"""Batches of flights (``birdsim fly A B C ...``, ``--batch FILE``, ``--jobs N``,
``--dask tcp://...|local:N``): each flight one task on a :class:`concurrent.futures.Executor`
(a local pool of fresh worker processes, :func:`local_executor`, or dask.distributed's
``Client.get_executor()`` as the table build uses it, :mod:`birdsim.tables.cluster`), run with
the BLAS libraries on one thread (:func:`birdsim.tables.runner.run_pinned`), so every
executor flies the same flights bit for bit (``tests/test_fly_batch.py``).

A task (:func:`run_job`) loads its bird, table and manoeuvre, flies and returns the log
arrays and the summary (or the one-line error of a bad entry); the submitting process
writes the logs (atomically, :func:`birdsim.flight.flightlog.save_log`), one per entry,
named after the entry (``<index>-<name>.npz`` in ``--out DIR``).  A failed entry is one
line on stderr naming it; the others are written; the exit status is then 2.

Batch file: one source per line (a preset name or a manoeuvre/path ``.toml``, relative
paths from the batch file's folder), ``#`` starts a comment, at most
:data:`MAX_JOBS` entries.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from concurrent.futures import Executor, ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from birdsim.errors import BirdsimError

#: At most this many flights in one batch.
MAX_JOBS = 10_000


@dataclass(frozen=True)
class FlightJob:
    """One flight of a batch (picklable: paths and numbers only)."""

    index: int
    source: str
    model: str
    bird: str | None = None
    table: str | None = None
    gusts: tuple[str, ...] = ()
    attitude: str | None = None
    open_loop: bool = False
    seconds: float | None = None

    @property
    def label(self) -> str:
        """``<index>-<name>``: the entry's log name (the source's stem)."""
        stem = Path(self.source).stem if self.source.endswith(".toml") else self.source
        return f"{self.index:03d}-{re.sub(r'[^A-Za-z0-9_.-]+', '_', stem)}"


def read_batch(path: str | Path) -> list[str]:
    """The sources listed in a batch file (one per line, ``#`` comments; a relative
    ``.toml`` path is taken from the batch file's folder)."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise BirdsimError(
            f"--batch {str(p)!r} cannot be read ({type(exc).__name__}); allowed: a text file with one manoeuvre per line"
        ) from None
    out = []
    for line in text.splitlines():
        entry = line.split("#", 1)[0].strip()
        if not entry:
            continue
        if entry.endswith(".toml") and not Path(entry).is_absolute():
            entry = str(p.parent / entry)
        out.append(entry)
    if not out:
        raise BirdsimError(
            f"--batch {str(p)!r} lists no manoeuvre; allowed: one preset or .toml file per line"
        )
    return out


def check_count(n: int) -> None:
    if n > MAX_JOBS:
        raise BirdsimError(f"the batch has {n} flights; allowed: at most {MAX_JOBS}")


def run_job(job: FlightJob) -> dict[str, Any]:
    """Fly one entry: {"label", "arrays", "info"} or {"label", "error"} (a bad entry:
    one line naming it).  Top level and picklable for every executor."""
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import DemandSchedule, fly, parse_gust
    from birdsim.flight.manoeuvre import MAX_BEATS, Manoeuvre
    from birdsim.flight.path_file import attitude_for, get_flight
    from birdsim.flight.simulate import SimConfig
    from birdsim.flight.summary_units import with_units
    from birdsim.physics.kinematics import get_model

    try:
        flight = get_flight(job.source, turning=True)
        attitude = attitude_for(flight, job.attitude, job.source)
        model = get_model(job.model).name
        gusts = [parse_gust(g) for g in job.gusts]
        bird = load_bird(job.bird)
        if bird.gravity <= 0:
            raise BirdsimError(
                f"--bird {bird.name!r} has gravity={bird.gravity:g}; allowed: gravity > 0 for free flight"
            )
        table = load_table_for(bird, model, job.table)
        reference = DemandSchedule(flight) if isinstance(flight, Manoeuvre) else flight
        beats = (
            job.seconds / bird.period
            if job.seconds is not None
            else float(reference.duration_beats)
        )
        if beats > MAX_BEATS:
            raise BirdsimError(f"{beats:g} wingbeats; allowed: at most {MAX_BEATS:g} wingbeats")
        result = fly(
            reference,
            table,
            bird,
            model,
            beats=beats,
            gusts=gusts,
            open_loop=job.open_loop,
            config=SimConfig(attitude=attitude),
        )
        arrays = log_arrays(result, reference.name)
        phases = (
            flight.regime if isinstance(flight, Manoeuvre) else getattr(reference, "regime", None)
        )
        info = with_units(summary(arrays, phases=phases), bird)
    except BirdsimError as exc:
        return {"label": job.label, "error": f"entry {job.index} ({job.source}): {exc}"}
    return {"label": job.label, "arrays": arrays, "info": info}


def _pinned(fn: Callable[[Any], dict[str, Any]], job: Any) -> dict[str, Any]:
    from birdsim.tables.runner import run_pinned

    return run_pinned(fn, job)  # type: ignore[arg-type]


def run_batch(
    jobs: list[Any], executor: Executor, fn: Callable[[Any], dict[str, Any]] = run_job
) -> list[dict[str, Any]]:
    """``fn(job)`` (default :func:`run_job`) of every job on ``executor``, results in
    the jobs' order (an exception a task raises beyond a bad entry propagates)."""
    futures = [executor.submit(_pinned, fn, job) for job in jobs]
    return [f.result() for f in futures]


def local_executor(jobs: int) -> Executor:
    """The local pool: ``jobs`` fresh worker processes (the ``spawn`` start method, as
    Dask's workers are started), also for one job.  Measured: flights in fresh
    processes are bitwise equal whatever the pool or cluster (spawned pools of 1 and 2,
    Dask local:2), while the same flight in a process that did other work first (a
    forked worker, the submitting process) may differ in the last bits (numpy's
    summation order follows the arrays' memory alignment), so a batch never flies in
    the submitting process."""
    import multiprocessing

    from birdsim.tables.runner import _ignore_sigint

    return ProcessPoolExecutor(
        max_workers=jobs,
        mp_context=multiprocessing.get_context("spawn"),
        initializer=_ignore_sigint,
    )


__all__ = [
    "MAX_JOBS",
    "FlightJob",
    "check_count",
    "local_executor",
    "read_batch",
    "run_batch",
    "run_job",
]
