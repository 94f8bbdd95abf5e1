"""Flying a flock (:mod:`birdsim.flight.flock`): every bird its own free flight at its
place by the leader's path (rule ``offsets``: one after another in this process or one
task per bird on the batch executor, :mod:`birdsim.flight.batch`) or steered by Reynolds'
rules in lockstep (rule ``steer``: :func:`fly_steered`), and the flock's log with a
leading bird axis.

Places: on a planar leader path x and z shift the path itself (the bird flies from and
along the shifted path) and y is applied by translation of the flown state (``y``,
``y_ref``, ``qpos[..., 1]``): the free-flight loop flies paths in the x-z plane at y = 0,
and nothing in free flight depends on y (uniform gravity and wind, contacts off), so this
is exact.  On a turning leader path (or with the rule ``steer``) the bird flies a
:class:`birdsim.flight.steering.FlockPath` (its place along the leader's track, the
steering's displacement added), started at y = 0 and moved back by the same translation.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.flight.flock import Flock, FlockError, load_bird, load_birds, load_flock

#: Log keys that are not per-sample arrays although one-dimensional.
_NOT_SAMPLES = ("param_names",)


@dataclass(frozen=True)
class FlockJob:
    """One bird of a flock (picklable: the flock file's source and numbers)."""

    source: str
    index: int
    model: str
    attitude: str | None = None
    seconds: float | None = None


def shifted_path(path: Any, dx: float, dz: float) -> Any:
    """``path`` (a FlightPath, reduced units) moved by dx forward and dz up (semispans)."""
    kfs = tuple(replace(k, z=k.z + dz, x=None if k.x is None else k.x + dx) for k in path.keyframes)
    return replace(path, keyframes=kfs, x0=path.x0 + dx)


@dataclass
class BirdSetup:
    """What one bird of a flock flies (reduced units): its reference, bird, table,
    attitude, wingbeats, and the side offset applied by translation (planar rule only)."""

    index: int
    flock: Flock
    bird: Any
    reference: Any
    table: Any
    attitude: str
    beats: float
    dy: float
    phases: Any


def prepare_bird(job: FlockJob) -> BirdSetup:
    """Bird ``job.index``'s reference and settings.  A leader path that turns (or the
    rule ``steer``) gives a :class:`birdsim.flight.steering.FlockPath` (the offset turned
    with the leader's heading, the steering's displacement added); a planar path under
    the rule ``offsets`` the path shifted in x and z and the side offset by translation.

    Raises:
        FlockError: one line naming the bird.
    """
    from birdsim.commands.common import load_table_for
    from birdsim.flight.manoeuvre import MAX_BEATS
    from birdsim.flight.path import FlightPath, PathError
    from birdsim.flight.path_file import attitude_for, get_flight
    from birdsim.flight.steering import FlockPath

    flock = load_flock(job.source)  # checked as a whole by jobs_for
    bird = load_bird(flock, job.index)
    entry = flock.birds[job.index]
    source = entry.path or flock.path
    flight = get_flight(source, turning=True)
    if not isinstance(flight, FlightPath) or flight.perch_start or flight.perch_end:
        raise FlockError(
            f"flock {flock.name!r}: bird {job.index}: path {source!r}; allowed: a path "
            "(position or speed keyframes) that neither starts nor ends on the perch"
        )
    steer = flock.rule == "steer"
    attitude = job.attitude or ("free" if steer else None)
    attitude = attitude_for(flight, attitude, source)
    offset = np.array(entry.offset) / bird.semispan
    dx, dy, dz = offset
    if steer or flight.is_3d:
        reference = FlockPath(flight, offset, turn_offset=flight.is_3d)
        dy = reference.shift_y  # flown from y = 0, moved back (FlockPath)
    else:
        try:
            reference = shifted_path(flight, dx, dz)
        except PathError as exc:
            raise FlockError(f"flock {flock.name!r}: bird {job.index}: {exc}") from None
    if job.seconds is not None:
        beats = job.seconds / bird.period
    else:  # every bird for the leader path's length
        beats = float(get_flight(flock.path, turning=True).duration_beats)
    if beats > MAX_BEATS:
        raise FlockError(f"{beats:g} wingbeats; allowed: at most {MAX_BEATS:g} wingbeats")
    table = load_table_for(bird, job.model, None)
    phases = getattr(flight, "regime", None)
    return BirdSetup(job.index, flock, bird, reference, table, attitude, beats, dy, phases)


def fly_setup(setup: BirdSetup, model: str, control_hook: Any = None) -> dict[str, Any]:
    """Fly one prepared bird: {"index", "arrays", "info"} (the bird's own units)."""
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import fly
    from birdsim.flight.simulate import SimConfig

    bird = setup.bird
    result = fly(
        setup.reference,
        setup.table,
        bird,
        model,
        beats=setup.beats,
        config=SimConfig(attitude=setup.attitude),
        control_hook=control_hook,
    )
    arrays = log_arrays(result, setup.flock.name)
    if setup.dy:
        dy = setup.dy
        arrays["y"] = arrays["y"] + dy * bird.semispan
        arrays["y_ref"] = arrays["y_ref"] + dy * bird.semispan
        arrays["qpos"] = arrays["qpos"].copy()
        arrays["qpos"][:, 1] += dy
    steering_at = getattr(setup.reference, "steering_at", None)
    if steering_at is not None:  # the steering's displacement of the reference (bird units)
        t_red = np.asarray(arrays["t"]) / bird.period * 2.0 * math.pi
        arrays["steer"] = steering_at(t_red) * bird.semispan
    info = summary(arrays, phases=setup.phases)
    return {"index": setup.index, "arrays": arrays, "info": info}


def fly_bird(job: FlockJob) -> dict[str, Any]:
    """Fly bird ``job.index`` of the flock: {"index", "arrays", "info"} or {"index", "error"}
    (one line naming the bird).  Top level and picklable for every executor."""
    try:
        return fly_setup(prepare_bird(job), job.model)
    except BirdsimError as exc:
        return {"index": job.index, "error": str(exc)}


def fly_steered(jobs: list[FlockJob], progress: Any = None, processes: int = 1) -> dict:
    """Fly every bird of a steered flock in lockstep (:mod:`birdsim.flight.flock_lockstep`)
    and stack their logs; ``progress(beats_done, beats)`` after every wingbeat.
    ``processes`` > 1: the birds split between that many processes, their states
    exchanged at every control update (:mod:`birdsim.flight.flock_parallel`)."""
    if processes > 1:
        from birdsim.flight.flock_parallel import fly_parallel

        logs = fly_parallel(steered_logs, jobs, processes, progress)
    else:
        logs = steered_logs(jobs, progress=progress)
    return stack_logs(logs, load_flock(jobs[0].source))


def steered_logs(
    jobs: list[FlockJob], local: Any = None, exchange: Any = None, progress: Any = None
) -> list[dict[str, np.ndarray]]:
    """The logs of the birds ``local`` (default all) of a steered flock flown in lockstep
    here; ``exchange(lock)`` brings the other birds' states at every control update."""
    from birdsim.flight import flock_step
    from birdsim.flight.flock_lockstep import Lockstep, run_lockstep
    from birdsim.flight.simulate import SimConfig
    from birdsim.physics.units import reduced_bird

    setups = [prepare_bird(job) for job in jobs]
    flock = setups[0].flock
    cfg = SimConfig()
    dt = 2.0 * math.pi / cfg.control_per_beat
    gravity = reduced_bird(setups[0].bird).gravity
    paths = [s.reference for s in setups]
    lock = Lockstep(
        paths, flock.steering, gravity, dt, flock_step.SHARED_MODEL, local=local, exchange=exchange
    )
    if progress is not None:
        per_beat, beats = cfg.control_per_beat, setups[0].beats
        lock.on_update = lambda k: (k + 1) % per_beat or progress((k + 1) // per_beat, beats)

    def fly_one(i: int, hook: Any) -> dict:
        g = lock.local[i]
        return fly_setup(setups[g], jobs[g].model, hook)

    return [r["arrays"] for r in run_lockstep(fly_one, lock)]


def jobs_for(
    source: str, model: str, attitude: str | None = None, seconds: float | None = None
) -> tuple[Flock, list[FlockJob]]:
    """The flock (checked: its birds parse, their starts apart, a posed body on no path
    that turns) and one job per bird."""
    from birdsim.flight.path_file import attitude_for, get_flight

    flock = load_flock(source)
    load_birds(flock)
    model = flock.model or model
    attitude = attitude or flock.attitude
    if attitude == "posed":  # refused here in one line, not once a bird per worker
        for path in dict.fromkeys(b.path or flock.path for b in flock.birds):
            attitude_for(get_flight(path, turning=True), attitude, path)
    seconds = seconds if seconds is not None else flock.seconds
    return flock, [FlockJob(source, b.index, model, attitude, seconds) for b in flock.birds]


def fly_flock(
    jobs: list[FlockJob], executor: Any = None, progress: Any = None, processes: int = 1
) -> dict:
    """Fly every bird (in this process, or on ``executor``) and stack their logs; a
    steered flock in lockstep (:func:`fly_steered`; in ``processes`` processes).
    ``progress(n)``: n birds flown, or (steered) -n wingbeats flown by every bird."""
    if load_flock(jobs[0].source).rule == "steer":
        if executor is not None:
            raise FlockError(
                "an executor with a steered flock (rule 'steer'); allowed: processes "
                "(its birds fly in lockstep)"
            )
        report = None if progress is None else lambda b, n: progress(-b)
        return fly_steered(jobs, report, processes)
    if executor is None:
        results = []
        for job in jobs:
            results.append(fly_bird(job))
            if progress is not None:
                progress(len(results))
    else:
        from birdsim.flight.batch import run_batch

        results = run_batch(jobs, executor, fly_bird)
    for r in results:
        if "error" in r:
            raise FlockError(f"bird {r['index']}: {r['error']}")
    flock = load_flock(jobs[0].source)
    return stack_logs([r["arrays"] for r in results], flock)


def stack_logs(logs: list[dict[str, np.ndarray]], flock: Flock) -> dict[str, np.ndarray]:
    """One log from the birds' logs: every per-sample array with a leading bird axis
    ((N, samples, ...)); a scalar the same for every bird kept, else one per bird (N,);
    ``n_birds``, ``offset`` (N, 3; the bird's length unit) and ``flock`` added."""
    n = len(logs[0]["t"])
    if any(len(log["t"]) != n for log in logs):
        raise FlockError(
            f"flock {flock.name!r}: the birds' logs have {sorted({len(g['t']) for g in logs})} "
            "samples; allowed: the same number (the same period and duration)"
        )
    out: dict[str, np.ndarray] = {}
    for key, first in logs[0].items():
        if any(key not in log for log in logs):
            continue  # e.g. a turn's bank_command, absent where a bird's path is still straight
        vals = [log[key] for log in logs]
        per_sample = first.ndim >= 1 and first.shape[0] == n and key not in _NOT_SAMPLES
        if per_sample or first.ndim == 0 and any(not np.array_equal(v, first) for v in vals):
            out[key] = np.stack(vals)
        else:
            out[key] = first
    out["bird"] = np.array([str(log["bird"]) for log in logs])
    out["n_birds"] = np.array(len(logs))
    out["offset"] = np.array([b.offset for b in flock.birds], dtype=float)
    out["flock"] = np.array(flock.name)
    return out


def min_separation(arrays: dict[str, np.ndarray]) -> tuple[float, int, int, int]:
    """The smallest distance between two birds' torso origins over every sample (the
    bird's length unit), and the pair and sample where it happens."""
    pos = np.stack([arrays["x"], arrays["y"], arrays["z"]], axis=-1)  # (N, S, 3)
    best = (math.inf, -1, -1, -1)
    for i in range(1, pos.shape[0]):
        d = np.linalg.norm(pos[:i] - pos[i][None], axis=-1)  # (i, S)
        j, k = np.unravel_index(int(np.argmin(d)), d.shape)
        if d[j, k] < best[0]:
            best = (float(d[j, k]), int(j), i, int(k))
    return best


def flock_summary(arrays: dict[str, np.ndarray], semispan: float) -> dict[str, Any]:
    """Per-bird figures (path RMS after the first two wingbeats, in the bird's length unit
    and in semispans; saturated samples) and the flock's smallest separation."""
    from birdsim.flight.flightlog import summary

    n = int(arrays["n_birds"])
    birds = []
    for i in range(n):
        one = {k: (v[i] if _per_bird(k, v, arrays) else v) for k, v in arrays.items()}
        s = summary(one)
        birds.append(
            {
                "index": i,
                "rms_error_after_start": s["rms_error_after_start"],
                "rms_error_after_start_semispans": s["rms_error_after_start"] / semispan,
                "max_error_after_start": s["max_error_after_start"],
                "saturated_samples": s["saturated_samples"],
            }
        )
    dmin, a, b, k = min_separation(arrays) if n > 1 else (math.inf, -1, -1, -1)
    return {
        "flock": str(arrays["flock"]),
        "n_birds": n,
        "samples": int(arrays["t"].shape[-1]),
        "seconds": float(arrays["t"][0, -1]),
        "worst_rms_error_after_start_semispans": max(
            b_["rms_error_after_start_semispans"] for b_ in birds
        ),
        "saturated_samples": int(sum(b_["saturated_samples"] for b_ in birds)),
        "min_separation": dmin if n > 1 else None,
        "min_separation_semispans": dmin / semispan if n > 1 else None,
        "min_separation_pair": [a, b] if n > 1 else None,
        "min_separation_time": float(arrays["t"][0, k]) if n > 1 else None,
        "birds": birds,
        # a steered flock: the largest displacement of a reference by the rules
        "max_steering": float(np.abs(arrays["steer"]).max()) if "steer" in arrays else None,
    }


def _per_bird(key: str, v: np.ndarray, arrays: dict[str, np.ndarray]) -> bool:
    n = int(arrays["n_birds"])
    return key not in ("offset",) and v.ndim >= 1 and v.shape[0] == n and key != "param_names"


def bird_log(arrays: dict[str, np.ndarray], i: int) -> dict[str, np.ndarray]:
    """Bird ``i``'s own log from a flock's (as a one-bird flight's log)."""
    skip = ("n_birds", "offset", "flock")
    return {k: (v[i] if _per_bird(k, v, arrays) else v) for k, v in arrays.items() if k not in skip}


__all__ = [
    "BirdSetup",
    "FlockJob",
    "bird_log",
    "flock_summary",
    "fly_bird",
    "fly_flock",
    "fly_setup",
    "fly_steered",
    "prepare_bird",
    "jobs_for",
    "min_separation",
    "shifted_path",
    "stack_logs",
]
