"""``birdsim fly FLOCK``: a flock file or a flock preset (:mod:`birdsim.flight.flock`),
every bird flown at its place by the leader's path (rule ``offsets``) or steered by
Reynolds' rules in lockstep (rule ``steer``), one log with a leading bird axis
(``--out``), a JSON summary (``--json``: per-bird path RMS, the smallest separation,
wall and CPU time)."""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from pathlib import Path

from birdsim.errors import BirdsimError


def _children_cpu() -> float:
    """User + system CPU seconds of this process's ended child processes."""
    t = os.times()
    return t.children_user + t.children_system


def run_flock(args: argparse.Namespace, source: str, seconds: float | None) -> int:
    from birdsim.commands.common import check_writable
    from birdsim.commands.fly_batch import _jobs_arg
    from birdsim.flight.flightlog import save_log
    from birdsim.flight.flock import load_birds
    from birdsim.flight.flock_fly import flock_summary, fly_flock, jobs_for
    from birdsim.physics.kinematics import get_model

    for flag, bad in (
        ("--gust", args.gust),
        ("--legs", args.legs),
        ("--open-loop", args.open_loop),
        ("--bird", args.bird),
        ("--table", args.table),
        ("--dask", args.dask),
    ):
        if bad:
            raise BirdsimError(
                f"{flag} with the flock {source!r}; allowed: a flock's birds, path and model come from its file (--attitude, --seconds, --jobs, --out, --json)"
            )
    out = Path(args.out) if args.out else None
    if out is not None:
        if out.suffix.lower() != ".npz":
            raise BirdsimError(f"--out {str(out)!r} does not end in .npz; allowed: a .npz path")
        check_writable(out, args.force)
    model = get_model(args.model).name
    flock, jobs = jobs_for(source, model, args.attitude, seconds)
    get_model(jobs[0].model)
    n_jobs = _jobs_arg(args.jobs)
    steer = flock.rule == "steer"
    wall0, cpu0, kids0 = time.perf_counter(), time.process_time(), _children_cpu()
    if n_jobs is None or n_jobs == 1 or steer:

        def progress(done: int) -> None:
            if args.quiet or args.json:
                return
            if done < 0:  # a steered flock: every bird -done wingbeats (lockstep)
                if -done % 4 == 0:
                    print(f"fly {flock.name}: {-done} wingbeats, every bird", file=sys.stderr)
            else:
                print(f"fly {flock.name}: bird {done}/{len(jobs)}", file=sys.stderr)

        # a steered flock on --jobs processes: its birds split, in lockstep across them
        arrays = fly_flock(jobs, progress=progress, processes=n_jobs or 1)
    else:
        from birdsim.flight.batch import local_executor

        with local_executor(n_jobs) as ex:
            arrays = fly_flock(jobs, ex)
    wall, cpu = time.perf_counter() - wall0, time.process_time() - cpu0
    semispan = load_birds(flock)[0].semispan
    info = flock_summary(arrays, semispan)
    info["model"] = jobs[0].model
    info["attitude"] = str(arrays["attitude"]) if arrays["attitude"].ndim == 0 else None
    info["wall_s"] = wall
    info["cpu_s_this_process"] = cpu
    info["cpu_s_child_processes"] = _children_cpu() - kids0
    info["jobs"] = n_jobs or 1
    if out is not None:
        save_log(arrays, out, args.force)
        info["log"] = str(out)
    if args.json:
        from birdsim.json_values import finite_or_none

        print(json.dumps(finite_or_none(info), indent=2, allow_nan=False))
    else:
        sep = info["min_separation_semispans"]
        rms = info["worst_rms_error_after_start_semispans"]
        print(
            f"flew flock {flock.name} ({info['n_birds']} birds, {info['model']}): "
            f"{info['seconds']:.3g} s, "
            + (  # after the first two wingbeats, as `birdsim fly` says it (nan: none flown)
                f"worst path RMS {rms:.3g} semispan, "
                if math.isfinite(rms)
                else "no path RMS (the flight ends within its first 2 wingbeats), "
            )
            + (f"closest two birds {sep:.3g} semispan, " if sep is not None else "")
            + f"{info['saturated_samples']} saturated sample(s), {wall:.1f} s wall"
            + (f"; wrote {out}" if out else "")
        )
    return 0
