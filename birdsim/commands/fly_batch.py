"""``birdsim fly`` with several manoeuvres, ``--batch FILE``, ``--jobs N`` or ``--dask``:
the flights as tasks on an executor (:mod:`birdsim.flight.batch`), each log written to
``--out DIR/<index>-<name>.npz``; one line per failed entry on stderr, exit 2 if any
failed (the others are written)."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from birdsim.errors import BirdsimError


def _jobs_arg(raw: str | None) -> int | None:
    if raw is None:
        return None
    try:
        n = int(raw)
    except ValueError:
        n = 0
    if not 1 <= n <= 256:
        raise BirdsimError(f"--jobs {raw!r} is invalid; allowed: an integer from 1 to 256")
    return n


def check_sources(sources: list[str]) -> None:
    """Every entry that is not a file names a preset: a misspelt preset is refused in one
    line before any flight.  A file (missing, or bad inside) fails its own entry, the
    others are flown and written (on a cluster the files are the workers' to read)."""
    from birdsim.flight.path_file import get_flight

    for k, src in enumerate(sources):
        if "/" in src or Path(src).suffix.lower() in (".toml", ".npz") or Path(src).exists():
            continue
        try:
            get_flight(src, turning=True)
        except BirdsimError as exc:
            raise BirdsimError(f"entry {k} ({src}): {exc}") from None


def run_many(args: argparse.Namespace, sources: list[str], seconds: float | None) -> int:
    import os

    from birdsim.commands.common import check_writable
    from birdsim.flight.batch import FlightJob, check_count, local_executor, run_batch
    from birdsim.flight.freeflight import parse_gust
    from birdsim.flight.saturation import report_saturation
    from birdsim.physics.kinematics import get_model

    check_count(len(sources))
    if getattr(args, "legs", False):
        raise BirdsimError(
            f"--legs with {len(sources)} flights; allowed: --legs with one MANOEUVRE (batches fly without legs)"
        )
    jobs_n = _jobs_arg(args.jobs)
    if args.dask is not None:
        from birdsim.tables.cluster import parse_scheduler

        parse_scheduler(args.dask)
        if jobs_n is not None:
            raise BirdsimError(
                f"--jobs {args.jobs} with --dask {args.dask!r}; allowed: one of them (the cluster has its own workers)"
            )
    model = get_model(args.model).name
    for g in args.gust:
        parse_gust(g)
    out = Path(args.out) if args.out else None
    if out is not None and out.suffix.lower() == ".npz":
        raise BirdsimError(
            f"--out {str(out)!r} is a .npz file; allowed: a folder for the batch's logs (one <index>-<name>.npz per flight)"
        )
    check_sources(sources)
    jobs = [
        FlightJob(
            k,
            src,
            model,
            args.bird,
            args.table,
            tuple(args.gust),
            args.attitude,
            args.open_loop,
            seconds,
        )  # fmt: skip
        for k, src in enumerate(sources)
    ]
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        for job in jobs:
            check_writable(out / f"{job.label}.npz", args.force)
    if args.dask is not None:
        from birdsim.tables.cluster import dask_executor

        with dask_executor(args.dask) as executor:
            results = run_batch(jobs, executor)
    else:
        executor = local_executor(jobs_n or min(len(jobs), os.cpu_count() or 1))
        try:
            results = run_batch(jobs, executor)
        finally:
            executor.shutdown()
    failed = 0
    summaries = []
    for job, res in zip(jobs, results):
        if "error" in res:
            print(f"fly: {res['error']}", file=sys.stderr)
            failed += 1
            continue
        arrays, info = res["arrays"], res["info"]
        try:
            report_saturation(
                arrays, command="fly", bird_arg=args.bird, model=model, strict=args.strict
            )
        except BirdsimError as exc:
            print(f"fly: entry {job.index} ({job.source}): {exc}", file=sys.stderr)
            failed += 1
            continue
        info = {"entry": job.index, "source": job.source, **info}
        if out is not None:
            from birdsim.flight.flightlog import save_log

            path = out / f"{job.label}.npz"
            save_log(arrays, path, args.force)
            info["log"] = str(path)
        summaries.append(info)
        if not args.json:
            print(
                f"flew entry {job.index} {job.source} ({model}): {info['wingbeats']:.1f} wingbeats, "
                f"position error RMS {info['rms_error']:.3g}"
                + (f"; wrote {info['log']}" if "log" in info else "")
            )
    if args.json:
        from birdsim.json_values import finite_or_none

        print(json.dumps(finite_or_none(summaries), indent=2, allow_nan=False))
    return 2 if failed else 0


__all__ = ["run_many"]
