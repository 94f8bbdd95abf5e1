"""A flock in the studio: a flock preset or a flock file of the studio's folder chosen as
the path is flown as ``birdsim fly FLOCK`` flies it (:func:`birdsim.flight.flock_fly.fly_flock`,
its birds in lockstep in one MuJoCo model when steered) and drawn with every bird
(:func:`birdsim.studio.flock_view.flock_scene`, as ``birdsim view`` draws a flock's log).

The flock's own file gives its birds, path, model and attitude: the page's bird, gusts
and open loop do not apply (refused in one line, as ``birdsim fly FLOCK`` refuses them).
"""

from __future__ import annotations

import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

from birdsim.errors import BirdsimError


def flock_beats(source: str) -> float:
    """The wingbeats every bird of the flock flies (its ``seconds`` or its path's length)."""
    from birdsim.flight.flock import load_birds, load_flock
    from birdsim.flight.path_file import get_flight

    flock = load_flock(source)
    if flock.seconds is not None:
        return float(flock.seconds) / load_birds(flock)[0].period
    return float(get_flight(flock.path, turning=True).duration_beats)


def fly_flock_request(
    req: Any, max_beats: float, progress: Callable[[float], None] | None = None
) -> tuple:
    """Fly the flock ``req.source``: (its stacked log, a summary with the page's keys:
    ``rms_error`` and ``max_error`` the worst bird's after the start, in the birds'
    length unit, ``wingbeats_saturated`` the saturated samples over 64 a wingbeat).

    Raises:
        BirdsimError: a page option that does not apply, a flock beyond the studio's length.
    """
    from birdsim.flight.flock import load_birds
    from birdsim.flight.flock_fly import flock_summary, fly_flock, jobs_for

    for name, bad in (("bird", req.bird), ("gusts", req.gusts), ("open loop", req.open_loop)):
        if bad:
            raise BirdsimError(
                f"{name} with the flock {Path(str(req.source)).name!r}; allowed: a flock's "
                "birds, path and model come from its file"
            )
    flock, jobs = jobs_for(str(req.source), req.model or "m3", seconds=req.seconds)
    beats = flock_beats(str(req.source)) if req.seconds is None else None
    if beats is None:
        beats = req.seconds / load_birds(flock)[0].period
    if beats > max_beats:
        raise BirdsimError(
            f"the flock flies {beats:g} wingbeats; allowed: at most {max_beats:g} here"
        )
    report = None
    if progress is not None:  # -n: n wingbeats flown by every bird; n: n birds flown

        def report(done: int) -> None:
            progress(-done if done < 0 else done / len(jobs) * beats)

    arrays = fly_flock(jobs, progress=report)
    semispan = load_birds(flock)[0].semispan
    info = flock_summary(arrays, semispan)
    worst = max(info["birds"], key=lambda b: b["rms_error_after_start"])
    info["rms_error"] = worst["rms_error_after_start"]
    info["max_error"] = worst["max_error_after_start"]
    info["wingbeats_saturated"] = info["saturated_samples"] / 64.0
    return arrays, info


def flock_birds(log: dict[str, Any]) -> list[dict]:
    """Each bird's own log of a flock's stacked ``log`` (as ``birdsim view`` reads them
    from the written log)."""
    from birdsim.flight.flightlog import save_log
    from birdsim.flight.flock_log import load_flock_log

    with tempfile.TemporaryDirectory(prefix="birdsim-studio-") as tmp:
        path = Path(tmp) / "flock.npz"
        save_log(log, path, True)
        return load_flock_log(path)[1]


__all__ = ["flock_beats", "flock_birds", "fly_flock_request"]
