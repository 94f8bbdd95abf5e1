"""A flock's birds in lockstep: each bird's own free flight, all advancing one control
interval at a time, the steering rules (:mod:`birdsim.flight.steering`) computed from
every bird's state at every control update.

Each bird is flown by :func:`birdsim.flight.freeflight.fly` (its own MuJoCo model,
controller and callback) in its own thread, and the threads take turns: bird ``i`` runs
until its next control update (``fly``'s ``control_hook``), publishes its position and
velocity there, and hands the turn to bird ``i + 1``; the last bird, having seen every
bird's state at the same time ``t_k``, computes the rules for all of them and sets each
bird's steering for the interval ``[t_k, t_k+1)``; then bird 0 flies that interval, and
so on.  One thread runs at a time (one ``threading.Event`` per bird: a hand-over wakes
the next bird only), so the birds' simulations are exactly those of one process flying
them one after another with the references the rules set: the threads are coroutines,
not parallelism.  MuJoCo's
passive callback is process-wide: the bird holding the turn installs its own and
removes it when it hands the turn on.

With ``shared_model`` (the default of :func:`birdsim.flight.flock_fly.steered_logs`) the
birds are stepped in one MuJoCo model (:mod:`birdsim.flight.flock_step`): each bird's
``step_many`` hands its interval over at its turn and the last bird steps every bird in
one compiled call; each bird keeps its own controller and one-bird model.  ``local`` and
``exchange`` let several processes fly a flock (:mod:`birdsim.flight.flock_parallel`).
"""

from __future__ import annotations

import threading
from typing import Any

import mujoco
import numpy as np

from birdsim.errors import BirdsimError
from birdsim.flight.steering import FlockPath, SteeringConfig, rule_accelerations


class _Aborted(BirdsimError):
    """Another bird of the flock failed: this one stops too."""


class Lockstep:
    """The turn-taking of ``n`` birds and their published states (reduced units)."""

    def __init__(
        self,
        paths: list[FlockPath],
        cfg: SteeringConfig,
        gravity: float,
        dt: float,
        shared_model: bool = False,
        local: list[int] | None = None,
        exchange: Any = None,
    ):
        """``paths``: every bird's; ``local``: the birds flown here (default all: the
        others are flown by other processes, :mod:`birdsim.flight.flock_parallel`);
        ``exchange(lock)`` at every control update fills the other birds' rows of
        ``pos``, ``vel`` and ``time`` before the rules."""
        self.paths = paths
        self.cfg = cfg
        self.gravity = float(gravity)
        self.dt = float(dt)
        n_all = len(paths)
        self.local = list(range(n_all)) if local is None else [int(i) for i in local]
        n = len(self.local)
        self.n = n
        self.pos = np.zeros((n_all, 3))
        self.vel = np.zeros((n_all, 3))
        self.time = np.zeros(n_all)
        self.exchange = exchange
        # one event per bird: handing the turn on wakes the next bird only (a shared
        # condition variable woke every waiting bird at every hand-over)
        self.events = [threading.Event() for _ in range(n)]
        self.events[0].set()
        self.failed: str | None = None
        self.updates = 0
        #: optional callable(k) after the rules of control update k
        self.on_update: Any = None
        #: step every bird in one MuJoCo model (birdsim.flight.flock_step) where usable
        self.shared_model = shared_model
        self.fbs: list[Any] = [None] * n
        self.shared: Any = None

    # ---- turns -----------------------------------------------------------------------

    def wait_turn(self, i: int) -> None:
        self.events[i].wait()
        self.events[i].clear()
        if self.failed is not None:
            raise _Aborted(self.failed)

    def pass_turn(self, i: int) -> None:
        self.events[(i + 1) % self.n].set()

    def fail(self, message: str) -> None:
        if self.failed is None:
            self.failed = message
        for e in self.events:
            e.set()

    # ---- the control update ----------------------------------------------------------

    def hook(self, i: int) -> Any:
        """The ``i``-th local bird's ``control_hook`` for :func:`birdsim.flight.freeflight.fly`."""
        g = self.local[i]

        def control_hook(k: int, t: float, fb: Any) -> None:
            if k == 0 and self.shared_model:
                self._share(i, fb)
            self.pos[g] = fb.d.qpos[:3]
            self.pos[g, 1] += self.paths[g].shift_y  # the flown frame to the world's
            self.vel[g] = fb.d.qvel[:3]
            self.time[g] = t
            if i == self.n - 1:
                self.update()
            mujoco.set_mjcb_passive(None)
            self.pass_turn(i)
            self.wait_turn(i)
            mujoco.set_mjcb_passive(fb.cb)

        return control_hook

    def _share(self, i: int, fb: Any) -> None:
        """Bird ``i``'s first control update: its ``step_many`` hands its intervals to
        the shared model (built by the last bird, every bird's FreeBird known)."""
        from birdsim.flight.flock_step import SharedFlock

        self.fbs[i] = fb
        original = fb.step_many

        def step_many(pres: Any, wind: Any, record: Any = None, every: int = 1) -> None:
            if self.shared is None:
                return original(pres, wind, record, every)
            self.shared.pending[i] = (pres, wind, record, every)
            mujoco.set_mjcb_passive(None)
            if i == self.n - 1:
                self.shared.step()
            self.pass_turn(i)
            self.wait_turn(i)
            mujoco.set_mjcb_passive(fb.cb)
            return None

        fb.step_many = step_many
        if i == self.n - 1 and SharedFlock.usable(self.fbs):
            mujoco.set_mjcb_passive(None)  # compiling runs MuJoCo (no bird's callback)
            try:
                self.shared = SharedFlock(self.fbs)
            finally:
                mujoco.set_mjcb_passive(fb.cb)

    def update(self) -> None:
        """Every bird at the same time: the rules' accelerations, held for the interval."""
        if self.exchange is not None:
            self.exchange(self)
        t = float(self.time[0])
        if not np.allclose(self.time, t, rtol=0, atol=1e-9):
            raise BirdsimError(f"flock lockstep out of step: times {self.time.tolist()}")
        n_all = len(self.paths)
        goal, goal_v = np.zeros((n_all, 3)), np.zeros((n_all, 3))
        delta, delta_v = np.zeros((n_all, 3)), np.zeros((n_all, 3))
        for j, p in enumerate(self.paths):
            g = p.goal(np.array([t]))
            goal[j] = [g["x"][0], g["y"][0], g["z"][0]]
            goal_v[j] = [g["vx"][0], g["vy"][0], g["vz"][0]]
            # delta at t from the last interval's polynomial (0 before the first update)
            tau = t - p.t0
            delta[j] = p.delta + p.delta_vel * tau + 0.5 * p.delta_acc * tau * tau
            delta_v[j] = p.delta_vel + p.delta_acc * tau
        acc = rule_accelerations(
            self.pos, self.vel, goal, goal_v, delta, delta_v, self.cfg, self.gravity, t
        )
        for j, p in enumerate(self.paths):
            if not p.lateral:  # flown by the straight loop, which holds y
                acc[j, 1] = 0.0
            p.set_steering(t, delta[j], delta_v[j], acc[j])
        if self.on_update is not None:
            self.on_update(self.updates)
        self.updates += 1


def run_lockstep(fly_one: Any, lock: Lockstep) -> list[Any]:
    """Run ``fly_one(i, control_hook)`` for every bird in lockstep (one thread each, one
    running at a time); their results in order.

    Raises:
        BirdsimError: the first bird's error (one line naming the bird).
    """
    results: list[Any] = [None] * lock.n
    errors: list[tuple[int, BaseException]] = []

    def run(i: int) -> None:
        try:
            lock.wait_turn(i)
            results[i] = fly_one(i, lock.hook(i))
        except _Aborted:
            return
        except BaseException as exc:  # noqa: BLE001 (re-raised in the caller's thread)
            mujoco.set_mjcb_passive(None)
            errors.append((i, exc))
            lock.fail(f"bird {i}: {exc}")
            return
        lock.pass_turn(i)

    threads = [threading.Thread(target=run, args=(i,), daemon=True) for i in range(lock.n)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    if errors:
        i, exc = errors[0]
        if isinstance(exc, BirdsimError):
            raise BirdsimError(f"bird {i}: {exc}") from None
        raise exc
    return results


__all__ = ["Lockstep", "run_lockstep"]
