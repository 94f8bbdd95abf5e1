"""A steered flock flown by several processes: the birds split into contiguous groups,
each group flown in lockstep (and in one MuJoCo model) by its own process, the birds'
states exchanged at every control update.

The rules need every bird's position and velocity at ``t_k``
(:mod:`birdsim.flight.steering`).  Each process holds every bird's path (its
:class:`birdsim.flight.steering.FlockPath`) but flies only its own group
(:func:`birdsim.flight.flock_fly.steered_logs` with ``local``); at every control update
its last bird sends the group's states to this process, which sends every bird's states
back to every group; each process then computes the rules for every bird from the same
numbers (so every process's copy of every bird's steering is the same) and sets them.
The processes are started with ``spawn`` (a fresh interpreter, as the batch pool's) and
run with BLAS on one thread.
"""

from __future__ import annotations

import multiprocessing
from typing import Any

import numpy as np

from birdsim.flight.flock import FlockError


def _worker(steered_logs: Any, jobs: list, local: list[int], conn: Any) -> None:
    """Fly the birds ``local`` of the flock with ``steered_logs``
    (:func:`birdsim.flight.flock_fly.steered_logs`, passed by name); their logs (or one
    error line) to ``conn``."""
    from threadpoolctl import threadpool_limits

    from birdsim.errors import BirdsimError

    def exchange(lock: Any) -> None:
        mine = lock.local
        conn.send(("state", mine, lock.pos[mine], lock.vel[mine], lock.time[mine]))
        reply = conn.recv()
        if reply is None:  # another group failed
            raise BirdsimError("stopped: another group of the flock failed")
        lock.pos[:], lock.vel[:], lock.time[:] = reply

    try:
        with threadpool_limits(limits=1, user_api="blas"):
            logs = steered_logs(jobs, local=local, exchange=exchange)
        conn.send(("done", local, logs))
    except BaseException as exc:  # noqa: BLE001 (one line to the parent)
        conn.send(("error", local, f"{exc}"))
    finally:
        conn.close()


def fly_parallel(steered_logs: Any, jobs: list, processes: int, progress: Any = None) -> list[dict]:
    """Fly a steered flock's birds on ``processes`` processes (at most one per bird), each
    group with ``steered_logs(jobs, local=..., exchange=...)``; every bird's log in the
    birds' order; ``progress(beats_done, beats)`` every wingbeat.

    Raises:
        FlockError: the first failed group's error (one line).
    """
    from birdsim.flight.simulate import SimConfig

    n = len(jobs)
    groups = [g.tolist() for g in np.array_split(np.arange(n), min(processes, n)) if len(g)]
    ctx = multiprocessing.get_context("spawn")
    conns, procs = [], []
    for g in groups:
        parent, child = ctx.Pipe()
        p = ctx.Process(target=_worker, args=(steered_logs, jobs, g, child), daemon=True)
        p.start()
        child.close()
        conns.append(parent)
        procs.append(p)
    logs: list[Any] = [None] * n
    per_beat = SimConfig().control_per_beat
    pos, vel, time = np.zeros((n, 3)), np.zeros((n, 3)), np.zeros(n)
    updates = 0
    try:
        active = list(range(len(groups)))
        while active:
            msgs = {j: _receive(conns[j], procs[j], groups[j]) for j in active}
            errors = [m[2] for m in msgs.values() if m[0] == "error"]
            if errors:
                for j in active:
                    if msgs[j][0] == "state":
                        conns[j].send(None)
                raise FlockError(f"birds {msgs[_first_error(msgs)][1]}: {errors[0]}")
            done = [j for j in active if msgs[j][0] == "done"]
            if done and len(done) != len(active):
                raise FlockError("flock processes out of step: some finished early")
            if done:
                for j in done:
                    for i, log in zip(msgs[j][1], msgs[j][2]):
                        logs[i] = log
                break
            for m in msgs.values():
                _, mine, p, v, t = m
                pos[mine], vel[mine], time[mine] = p, v, t
            for j in active:
                conns[j].send((pos, vel, time))
            updates += 1
            if progress is not None and updates % per_beat == 0:
                progress(updates // per_beat, None)
    finally:
        for p in procs:
            p.join(timeout=5)
            if p.is_alive():
                p.terminate()
    return logs


def _receive(conn: Any, proc: Any, group: list[int]) -> tuple:
    """The group's next message; an error if its process ended without one."""
    while not conn.poll(1.0):
        if not proc.is_alive() and not conn.poll(0.1):
            break
    try:
        return conn.recv()
    except EOFError:
        proc.join(timeout=5)
        return ("error", group, f"its process ended (exit code {proc.exitcode})")


def _first_error(msgs: dict) -> int:
    return next(j for j, m in msgs.items() if m[0] == "error")


__all__ = ["fly_parallel"]
