"""The studio's flights: each request flown in a worker thread (one at a time), its
progress readable while it flies, the finished flights kept in memory (the newest
:data:`MAX_FLIGHTS`)."""

from __future__ import annotations

import itertools
import threading
import traceback
from collections import OrderedDict
from dataclasses import dataclass, field
from typing import Any

from birdsim.errors import BirdsimError
from birdsim.studio.flights import FlightRequest, check_sizes, fly_request

#: Finished flights kept (older ones are dropped: their downloads then answer 404).
MAX_FLIGHTS = 24


@dataclass
class Job:
    """One flight request: ``state`` running, done or error; ``progress`` in [0, 1]."""

    id: str
    request: FlightRequest
    state: str = "running"
    progress: float = 0.0
    error: str = ""
    flight: str = ""


@dataclass
class Flight:
    """A flown flight: its log (arrays), summary, scene (built on first use)."""

    id: str
    log: dict[str, Any]
    summary: dict[str, Any]
    label: str
    scene: dict[str, Any] | None = None
    lock: threading.Lock = field(default_factory=threading.Lock)


class Store:
    """Jobs and flights of one studio."""

    def __init__(self) -> None:
        self.jobs: OrderedDict[str, Job] = OrderedDict()
        self.flights: OrderedDict[str, Flight] = OrderedDict()
        self._ids = itertools.count(1)
        self._lock = threading.Lock()
        self._fly_lock = threading.Lock()  # one flight at a time: 2 cores are shared

    def submit(self, req: FlightRequest, label: str) -> Job:
        """Check the request's sizes now (one line on refusal), fly it in a thread."""
        check_sizes(req)
        with self._lock:
            job = Job(f"j{next(self._ids)}", req)
            self.jobs[job.id] = job
            while len(self.jobs) > 4 * MAX_FLIGHTS:
                self.jobs.popitem(last=False)
        threading.Thread(target=self._run, args=(job, label), daemon=True).start()
        return job

    def _run(self, job: Job, label: str) -> None:
        beats = None

        def progress(done: float) -> None:
            nonlocal beats
            total = beats or 1.0
            job.progress = max(0.0, min(1.0, done / total))

        try:
            with self._fly_lock:
                from birdsim.flight.flock import is_flock
                from birdsim.flight.path_file import get_flight

                if job.request.path is None and is_flock(str(job.request.source)):
                    from birdsim.studio.flock_flights import flock_beats

                    beats = flock_beats(str(job.request.source))
                elif job.request.path is None:
                    flight = get_flight(str(job.request.source), turning=True)
                    beats = float(getattr(flight, "duration_beats", 0) or 0) or None
                else:
                    beats = float(job.request.path.get("duration") or 0) or None
                log, info = fly_request(job.request, progress)
            with self._lock:
                fid = f"f{next(self._ids)}"
                self.flights[fid] = Flight(fid, log, info, label)
                while len(self.flights) > MAX_FLIGHTS:
                    self.flights.popitem(last=False)
            job.flight, job.progress, job.state = fid, 1.0, "done"
        except BirdsimError as exc:
            job.error, job.state = str(exc), "error"
        except Exception as exc:  # pragma: no cover - a bug: say it in one line, log it
            traceback.print_exc()
            job.error, job.state = f"internal error: {type(exc).__name__}: {exc}", "error"

    def flight(self, fid: str) -> Flight | None:
        return self.flights.get(fid)


__all__ = ["MAX_FLIGHTS", "Flight", "Job", "Store"]
