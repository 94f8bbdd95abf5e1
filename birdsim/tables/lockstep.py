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
from birdsim.tables.cost import forces, forces_and_gradients
from birdsim.physics.kinematics import KinematicModel

T = TypeVar("T")


class Batcher:
    """Collects ``(X, speed, climb)`` requests of ``parties`` threads and answers them
    with one call of :func:`birdsim.tables.cost.forces` (values) and one of
    :func:`birdsim.tables.cost.forces_and_gradients` (gradients)."""

    def __init__(self, model: KinematicModel, bird: Bird, n: int, parties: int) -> None:
        self.model, self.bird, self.n = model, bird, n
        self.active = parties
        self.cond = threading.Condition()
        self.pending: dict[int, tuple[bool, np.ndarray, float, float]] = {}
        self.results: dict[int, Any] = {}
        self.calls = 0
        self.rank: dict[int, int] = {}  # thread ident -> job index (a fixed row order)

    def _flush(self) -> None:
        # rows in job order, not arrival order: the batch is then the same on every run
        items = sorted(self.pending.items(), key=lambda item: self.rank.get(item[0], 0))
        self.pending.clear()
        for want_grad in (False, True):
            group = [(tid, req) for tid, req in items if req[0] == want_grad]
            if not group:
                continue
            X = np.concatenate([x for _, (_, x, _, _) in group])
            V = np.concatenate([np.full(len(x), v) for _, (_, x, v, _) in group])
            C = np.concatenate([np.full(len(x), c) for _, (_, x, _, c) in group])
            try:
                if want_grad:
                    vals, grads = forces_and_gradients(self.model, X, V, self.bird, self.n, C)
                    arrays = (*vals, *grads)
                else:
                    arrays = forces(self.model, X, V, self.bird, self.n, C)
                self.calls += 1
                start = 0
                for tid, (_, x, _, _) in group:
                    stop = start + len(x)
                    part = tuple(a[start:stop] for a in arrays)
                    self.results[tid] = (part[:3], part[3:]) if want_grad else part
                    start = stop
            except BaseException as exc:  # noqa: BLE001 - re-raised in every waiting thread
                for tid, _ in group:
                    self.results[tid] = exc
        self.cond.notify_all()

    def _request(self, want_grad: bool, X: np.ndarray, speed: float, climb: float) -> Any:
        tid = threading.get_ident()
        with self.cond:
            self.pending[tid] = (want_grad, np.atleast_2d(X), float(speed), float(climb))
            if len(self.pending) >= self.active:
                self._flush()
            while tid not in self.results:
                self.cond.wait()
            out = self.results.pop(tid)
        if isinstance(out, BaseException):
            raise out
        return out

    def evaluate(self, X: np.ndarray, speed: float, climb: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Mean (Fx, Fz, P) of the rows of X, batched with the other threads' requests."""
        return self._request(False, X, speed, climb)

    def gradients(self, X: np.ndarray, speed: float, climb: float = 0.0) -> Any:
        """``((Fx, Fz, P), (dFx, dFz, dP))`` of the rows of X, batched likewise."""
        return self._request(True, X, speed, climb)

    def leave(self) -> None:
        """A thread is done: the others no longer wait for it."""
        with self.cond:
            self.active -= 1
            if self.pending and len(self.pending) >= self.active:
                self._flush()


class _Evaluator:
    """What a lockstep job gets: ``evaluator(X, speed, climb=0)`` gives values,
    ``evaluator.gradients(X, speed, climb=0)`` values and exact gradients."""

    def __init__(self, values: Callable[..., Any], gradients: Callable[..., Any]) -> None:
        self._values, self.gradients = values, gradients

    def __call__(self, X: np.ndarray, speed: float, climb: float = 0.0) -> Any:
        return self._values(X, speed, climb)


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
        return [
            jobs[0](
                _Evaluator(
                    lambda X, v, c=0.0: forces(model, X, v, bird, n, c),
                    lambda X, v, climb=0.0: forces_and_gradients(model, X, v, bird, n, climb),
                )
            )
        ]
    batcher = Batcher(model, bird, n, len(jobs))
    evaluator = _Evaluator(batcher.evaluate, batcher.gradients)

    def wrap(k: int) -> T:
        with batcher.cond:
            batcher.rank[threading.get_ident()] = k
        try:
            return jobs[k](evaluator)
        finally:
            batcher.leave()

    with ThreadPoolExecutor(max_workers=len(jobs)) as pool:
        return list(pool.map(wrap, range(len(jobs))))
