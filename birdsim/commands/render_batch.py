"""``birdsim render`` with several manoeuvres, ``--batch FILE``, ``--jobs N`` or ``--dask``:
each entry rendered by ``birdsim render`` itself in a worker (the same executors as a
batch of flights, :mod:`birdsim.flight.batch`: fresh local processes or a Dask
cluster), the video returned as bytes and written by the submitting process to
``--out DIR/<index>-<name>.mp4`` (atomically; nothing overwritten without ``--force``).
One line per failed entry on stderr, naming it; the others are written; exit 2 if any
failed.  ``--still`` and ``--sheet`` take one manoeuvre."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from birdsim.errors import BirdsimError

#: the batch's own options, not passed on to each entry's render
_BATCH_KEYS = ("batch", "jobs", "dask", "func")


@dataclass(frozen=True)
class RenderJob:
    """One entry: its index, source, log name and the render options (a dict of the
    command's arguments, picklable)."""

    index: int
    source: str
    label: str
    options: tuple[tuple[str, Any], ...]
    #: the command's ``run`` (birdsim.commands.render.run; pickled by name)
    runner: Callable[[argparse.Namespace], int]


def run_render_job(job: RenderJob) -> dict[str, Any]:
    """Render one entry into a temporary file and return its bytes, or the entry's one
    line error.  Top level and picklable for every executor."""
    import contextlib
    import io
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / f"{job.label}.mp4"
        args = argparse.Namespace(**dict(job.options))
        args.manoeuvre, args.out, args.quiet, args.force = job.source, str(out), True, True
        args.batch = args.jobs = args.dask = None
        text = io.StringIO()
        try:
            with contextlib.redirect_stdout(text):
                job.runner(args)
        except BirdsimError as exc:
            return {"label": job.label, "error": f"entry {job.index} ({job.source}): {exc}"}
        lines = [ln for ln in text.getvalue().splitlines() if ln.startswith("wrote ")]
        return {"label": job.label, "video": out.read_bytes(), "line": lines[-1] if lines else ""}


def run_many(
    args: argparse.Namespace, sources: list[str], runner: Callable[[argparse.Namespace], int]
) -> int:
    """The batch; ``runner``: the render command's ``run`` (each entry's render)."""
    import os

    from birdsim.commands.common import check_writable
    from birdsim.commands.fly_batch import _jobs_arg, check_sources
    from birdsim.flight.batch import FlightJob, check_count, local_executor, run_batch
    from birdsim.io import write_atomic

    check_count(len(sources))
    if getattr(args, "still", None) or getattr(args, "sheet", None):
        raise BirdsimError("--still/--sheet with a batch; allowed: one MANOEUVRE with them")
    jobs_n = _jobs_arg(args.jobs)
    if args.dask is not None:
        from birdsim.tables.cluster import parse_scheduler

        parse_scheduler(args.dask)
        if jobs_n is not None:
            raise BirdsimError(
                f"--jobs {args.jobs} with --dask {args.dask!r}; allowed: one of them (the cluster has its own workers)"
            )
    out = Path(args.out) if args.out else Path("renders")
    if out.suffix.lower() == ".mp4":
        raise BirdsimError(
            f"--out {str(out)!r} is a .mp4 file; allowed: a folder for the batch's videos (one <index>-<name>.mp4 per entry)"
        )
    check_sources(sources)
    options = tuple((k, v) for k, v in sorted(vars(args).items()) if k not in _BATCH_KEYS)
    labels = [FlightJob(k, src, "").label for k, src in enumerate(sources)]
    jobs = [
        RenderJob(k, src, lab, options, runner) for k, (src, lab) in enumerate(zip(sources, labels))
    ]
    out.mkdir(parents=True, exist_ok=True)
    for job in jobs:
        check_writable(out / f"{job.label}.mp4", args.force)
    if args.dask is not None:
        from birdsim.tables.cluster import dask_executor

        with dask_executor(args.dask) as executor:
            results = run_batch(jobs, executor, run_render_job)
    else:
        executor = local_executor(jobs_n or min(len(jobs), os.cpu_count() or 1))
        try:
            results = run_batch(jobs, executor, run_render_job)
        finally:
            executor.shutdown()
    failed = 0
    for job, res in zip(jobs, results):
        if "error" in res:
            print(f"render: {res['error']}", file=sys.stderr)
            failed += 1
            continue
        path = out / f"{job.label}.mp4"
        write_atomic(path, res["video"])
        print(f"entry {job.index} {job.source}: wrote {path} ({res['line'].split('(', 1)[-1]}")
    return 2 if failed else 0


__all__ = ["RenderJob", "run_many", "run_render_job"]
