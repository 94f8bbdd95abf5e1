"""Run many independent cell optimisations in lockstep so that their wingbeat
evaluations share ONE batched cycle evaluation.

scipy's SLSQP solves one problem per call and asks for one point (here: one point
plus its finite-difference neighbours) at a time.  A cycle evaluation costs a fixed
overhead of about 0.3 ms plus a little per parameter set, so evaluating the requests
of a dozen cells together is several times cheaper than one by one.  Each cell runs in
its own thread; its evaluator hands the request to a :class:`Batcher` and blocks; when
every still-running thread is waiting, the last one to arrive evaluates all requests
in one call and wakes the others.  Each cell gets the answer it would get alone
(the rows of a batched evaluation are independent).
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from typing import Any, TypeVar

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.tables.cost import forces
from birdsim.physics.kinematics import KinematicModel

T = TypeVar("T")


class Batcher:
    """Collects ``(X, speed)`` requests of ``parties`` threads and answers them with
    one call of :func:`birdsim.tables.cost.forces`."""

    def __init__(self, model: KinematicModel, bird: Bird, n: int, parties: int) -> None:
        self.model, self.bird, self.n = model, bird, n
        self.active = parties
        self.cond = threading.Condition()
        self.pending: dict[int, tuple[np.ndarray, float, float]] = {}
        self.results: dict[int, Any] = {}
        self.calls = 0
        self.rank: dict[int, int] = {}  # thread ident -> job index (a fixed row order)

    def _flush(self) -> None:
        # rows in job order, not arrival order: the batch is then the same on every run
        items = sorted(self.pending.items(), key=lambda item: self.rank.get(item[0], 0))
        self.pending.clear()
        X = np.concatenate([x for _, (x, _, _) in items])
        V = np.concatenate([np.full(len(x), v) for _, (x, v, _) in items])
        C = np.concatenate([np.full(len(x), c) for _, (x, _, c) in items])
        try:
            Fx, Fz, P = forces(self.model, X, V, self.bird, self.n, C if np.any(C != 0.0) else 0.0)
            self.calls += 1
            start = 0
            for tid, (x, _, _) in items:
                stop = start + len(x)
                self.results[tid] = (Fx[start:stop], Fz[start:stop], P[start:stop])
                start = stop
        except BaseException as exc:  # noqa: BLE001 - re-raised in every waiting thread
            for tid, _ in items:
                self.results[tid] = exc
        self.cond.notify_all()

    def evaluate(self, X: np.ndarray, speed: float, climb: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        tid = threading.get_ident()
        with self.cond:
            self.pending[tid] = (np.atleast_2d(X), float(speed), float(climb))
            if len(self.pending) >= self.active:
                self._flush()
            while tid not in self.results:
                self.cond.wait()
            out = self.results.pop(tid)
        if isinstance(out, BaseException):
            raise out
        return out

    def leave(self) -> None:
        """A thread is done: the others no longer wait for it."""
        with self.cond:
            self.active -= 1
            if self.pending and len(self.pending) >= self.active:
                self._flush()


def run_lockstep(
    model: KinematicModel,
    bird: Bird,
    n: int,
    jobs: Sequence[Callable[[Callable[[np.ndarray, float], tuple[np.ndarray, np.ndarray, np.ndarray]]], T]],
) -> list[T]:
    """Run ``job(evaluator)`` for every job in its own thread, all evaluations batched.
    ``evaluator(X, speed) -> (Fx, Fz, P)`` replaces :func:`birdsim.tables.cost.forces`."""
    if not jobs:
        return []
    if len(jobs) == 1:
        return [jobs[0](lambda X, v, climb=0.0: forces(model, X, v, bird, n, climb))]
    batcher = Batcher(model, bird, n, len(jobs))

    def wrap(k: int) -> T:
        with batcher.cond:
            batcher.rank[threading.get_ident()] = k
        try:
            return jobs[k](batcher.evaluate)
        finally:
            batcher.leave()

    with ThreadPoolExecutor(max_workers=len(jobs)) as pool:
        return list(pool.map(wrap, range(len(jobs))))
