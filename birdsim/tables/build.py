"""Filling a lookup table: continuation sweeps with warm starts (dissertation sec. 4.1.1,
Fig. 39), parallel over an executor, checkpointed so that an interrupted build resumes.

Order of the work (the dissertation's stable order: Fz, then Fx, then V):

1. *Slices* (one task per V): a screen of ``screen`` space-filling candidate wingbeats
   is evaluated in ONE batched call and costed against every (Fx, Fz) demand of the
   slice at once.  Then Fx lines are swept from +Fx_max down (a backward pass in Fx),
   each line sweeping Fz from the strongest lift demand (most negative Fz) to 0, every
   cell warm-started from the previous cell.  Where the warm start is poor (its optimum
   is not better than the best screen candidate by ``screen_gap``: polishing a screen
   candidate often gains that much) the best ``starts`` screen
   candidates are polished too (multi-start) and the best answer wins; another branch
   replaces the warm-start branch only when it is cheaper by ``switch_margin``, which
   keeps the table smooth where the minima are nearly tied.  A backward pass in Fz
   (0 -> strongest lift) then re-solves every cell from those of its Fx/Fz neighbours
   that sit on another branch (farther than ``branch_tol``) and keeps what is cheaper.
2. *V passes* (one task per Fx line): a forward pass V = 0 -> V_max and a backward
   pass re-solve every cell from its V-neighbour (unless the neighbour's parameters are
   within ``branch_tol`` of the cell's: same branch); a re-solve replaces the cell when
   it is cheaper.  Optional under-relaxation (eq. 94, ``relax`` < 1) and the distance cost
   (eq. 93, ``CostWeights.distance``) act along this pass.
3. *Final check*: every cell is re-evaluated at ``n_final`` samples per wingbeat in one
   batched call; achieved forces, cost fractions and the status (``ok``,
   ``unreachable``: the optimum misses the demand by more than ``reach_tol``,
   ``failed``: non-finite) come from that check, never from the search.

Tasks are submitted to any :class:`concurrent.futures.Executor` (a
``ProcessPoolExecutor`` by default; dask.distributed's ``Client.get_executor()`` or
similar plugs in unchanged).  Each finished task is written to the checkpoint folder;
a rerun with the same configuration skips the finished tasks.
"""

from __future__ import annotations

import fnmatch
import hashlib
import json
import os
import shutil
import subprocess
import time
import zipfile
from collections.abc import Callable, Sequence
from concurrent.futures import Executor, Future, ProcessPoolExecutor, as_completed
from dataclasses import asdict, dataclass, field
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.tables.cost import CostWeights, breakdown_from_forces, forces, other_cost
from birdsim.errors import BirdsimError
from birdsim.io import write_atomic
from birdsim.physics.kinematics import KinematicModel, get_model
from birdsim.tables.lockstep import run_lockstep
from birdsim.tables.optimize import ForceProblem, box_corners, random_starts, slsqp
from birdsim.tables.lookup import AXES, STATUS_NAMES, LookupTable


# ---- configuration ------------------------------------------------------------------


#: Largest grid accepted: nodes per axis and cells in all (a count of 1e9 in --grid
#: used to exhaust memory before any check; a million cells is hours of building).
MAX_NODES = 1000
MAX_CELLS = 1_000_000


@dataclass(frozen=True)
class Grid:
    """The demand grid: increasing values of Fx, Fz (dissertation force) and V."""

    Fx: tuple[float, ...]
    Fz: tuple[float, ...]
    V: tuple[float, ...]

    def __post_init__(self) -> None:
        for a in AXES:
            ax = getattr(self, a)
            if len(ax) < 2 or any(not np.isfinite(x) for x in ax) or any(b <= a_ for a_, b in zip(ax, ax[1:])):
                raise BirdsimError(f"--grid {a}={list(ax)} is invalid; allowed: >= 2 finite increasing values")
        if self.V[0] < 0:
            raise BirdsimError(f"--grid V starts at {self.V[0]:g}; allowed: speeds >= 0")
        if len(self.Fx) * len(self.Fz) * len(self.V) > MAX_CELLS:
            raise BirdsimError(f"--grid {'x'.join(map(str, self.shape))} has too many cells; allowed: at most {MAX_CELLS} cells")

    @classmethod
    def default(cls, size: int = 11) -> "Grid":
        """DESIGN.md's default grid: Fx in [-0.5, 0.5], Fz in [-0.5, 0], V in [0, 1]."""
        return cls.parse("", size)

    @classmethod
    def parse(cls, spec: str, size: int = 11) -> "Grid":
        """``"Fx=-0.5:0.5:11,Fz=-0.5:0:11,V=0:1:11"`` (``lo:hi:count``) or explicit
        values ``"V=0|0.5|1"``; axes left out take the default range with ``size`` nodes."""
        if not isinstance(size, int) or not 2 <= size <= MAX_NODES:
            raise BirdsimError(f"--size {size!r} is invalid; allowed: an integer in [2, {MAX_NODES}]")
        defaults = {"Fx": (-0.5, 0.5), "Fz": (-0.5, 0.0), "V": (0.0, 1.0)}
        axes = {a: tuple(float(x) for x in np.linspace(*defaults[a], size)) for a in AXES}
        for part in filter(None, (s.strip() for s in spec.split(","))):
            name, sep, value = part.partition("=")
            name = name.strip()
            if not sep or name not in AXES:
                raise BirdsimError(f"--grid {part!r} is malformed; allowed: Fx=LO:HI:COUNT, Fz=..., V=... or NAME=A|B|C")
            try:
                if ":" in value:
                    lo, hi, count = value.split(":")
                    n = int(count)
                    if not 2 <= n <= MAX_NODES:
                        raise ValueError
                    axes[name] = tuple(float(x) for x in np.linspace(float(lo), float(hi), n))
                else:
                    axes[name] = tuple(float(x) for x in value.split("|"))
            except ValueError:
                raise BirdsimError(f"--grid {part!r} is malformed; allowed: {name}=LO:HI:COUNT (2 <= COUNT <= {MAX_NODES}) or {name}=A|B|C") from None
        return cls(**axes)

    @property
    def shape(self) -> tuple[int, int, int]:
        return (len(self.Fx), len(self.Fz), len(self.V))

    def to_dict(self) -> dict[str, list[float]]:
        return {a: list(getattr(self, a)) for a in AXES}


@dataclass(frozen=True)
class BuildSettings:
    """Solver settings of a table build (recorded in the table's provenance)."""

    n_search: int = 32  # samples per wingbeat during the search
    n_final: int = 64  # samples per wingbeat of the final check (the stored values)
    screen: int = 1024  # space-filling candidates per V slice, shared by its cells
    starts: int = 2  # screen candidates polished where the warm start is poor
    screen_gap: float = 0.02  # multi-start unless the warm start beats the best screen candidate by this
    always_polish: int = 1  # screen candidates polished even after a good warm start
    switch_margin: float = 1e-4  # another branch must beat the warm-start branch by this
    reach_tol: float = 0.01  # |achieved - demanded| force above which a cell is unreachable
    v_passes: bool = True  # forward and backward passes in V after the slices
    branch_tol: float = 0.25  # rad; a neighbour this close is on the same branch (no re-solve)
    relax: float = 1.0  # under-relaxation delta of eq. 94 along V (1 = off)
    maxiter: int = 100
    seed: int = 0

    def __post_init__(self) -> None:
        if not (0.0 < self.relax <= 1.0):
            raise BirdsimError(f"relax={self.relax!r} is invalid; allowed: 0 < relax <= 1")
        for name in ("n_search", "n_final", "screen", "maxiter"):
            if int(getattr(self, name)) < 2:
                raise BirdsimError(f"{name}={getattr(self, name)!r} is invalid; allowed: an integer >= 2")
        # written as "not (ok)" so that NaN is refused too (every comparison with NaN is False)
        if not self.reach_tol > 0:
            raise BirdsimError(f"reach_tol={self.reach_tol!r} is invalid; allowed: a number > 0")
        for name in ("starts", "always_polish", "switch_margin", "screen_gap", "branch_tol"):
            value = getattr(self, name)
            if not value >= 0:
                raise BirdsimError(f"{name}={value!r} is invalid; allowed: a number >= 0")


@dataclass(frozen=True)
class BuildConfig:
    """Everything that determines a table (hashed for the checkpoints)."""

    model: str
    grid: Grid
    bird: Bird = field(default_factory=Bird)
    weights: CostWeights = field(default_factory=CostWeights)
    settings: BuildSettings = field(default_factory=BuildSettings)

    def to_dict(self) -> dict[str, Any]:
        return {
            "model": self.model,
            "grid": self.grid.to_dict(),
            "bird": self.bird.to_dict(),
            "cost_weights": self.weights.to_dict(),
            "solver": asdict(self.settings),
        }

    def digest(self) -> str:
        return hashlib.sha256(json.dumps(self.to_dict(), sort_keys=True).encode()).hexdigest()[:16]


# ---- one cell -------------------------------------------------------------------------


def _problem(
    cfg: BuildConfig, model: KinematicModel, fx: float, fz: float, v: float, previous: np.ndarray | None, evaluator: Any = None
) -> ForceProblem:
    return ForceProblem(
        model, fx, fz, v, weights=cfg.weights, bird=cfg.bird, previous=previous, n=cfg.settings.n_search, evaluator=evaluator
    )


def _screen(cfg: BuildConfig, model: KinematicModel, v: float) -> tuple[np.ndarray, tuple[np.ndarray, ...], np.ndarray]:
    """Candidates (S x d), their (Fx, Fz, P) and their non-force cost, one batched call:
    scrambled Sobol points, the model's hover and cruise guesses and the box corners."""
    dummy = _problem(cfg, model, 0.0, 0.0, v, None)
    S = random_starts(dummy, cfg.settings.screen, cfg.settings.seed)
    guesses = [list(model.guess(r).values()) for r in ("hover", "cruise")]
    S = np.vstack([S, guesses, box_corners(dummy)])
    F = forces(model, S, v, cfg.bird, cfg.settings.n_search)
    return S, F, other_cost(model, S, v, cfg.weights)


def _solve_cell(
    cfg: BuildConfig,
    model: KinematicModel,
    fx: float,
    fz: float,
    v: float,
    warm: np.ndarray | None,
    screen: tuple[np.ndarray, tuple[np.ndarray, ...], np.ndarray],
    evaluator: Any = None,
) -> tuple[np.ndarray, float, int, bool]:
    """Warm-started SLSQP, multi-start from the screen where the warm start is poor.
    Returns (x, cost at n_search, cycle evaluations, SLSQP converged)."""
    st = cfg.settings
    S, (Fx, Fz, P), other = screen
    c = breakdown_from_forces(Fx, Fz, P, fx, fz, cfg.weights, other).total
    order = np.argsort(c)
    prob = _problem(cfg, model, fx, fz, v, warm if cfg.weights.distance > 0 else None, evaluator)
    best = None
    polish = max(st.starts, 1)
    if warm is not None:
        best = slsqp(prob, warm, maxiter=st.maxiter)
        if best.cost < c[order[0]] - st.screen_gap:
            polish = st.always_polish  # a good warm start: still try the best screen candidate(s)
    for k in order[:polish]:
        sol = slsqp(prob, S[k], maxiter=st.maxiter)
        if best is None or sol.cost < best.cost - st.switch_margin:
            best = sol
    assert best is not None
    return best.x, best.cost, prob.evaluations, best.converged


def _resolve_from(
    cfg: BuildConfig, model: KinematicModel, fx: float, fz: float, v: float, start: np.ndarray, evaluator: Any = None
) -> tuple[np.ndarray, float, int, bool]:
    prob = _problem(cfg, model, fx, fz, v, start if cfg.weights.distance > 0 else None, evaluator)
    sol = slsqp(prob, start, maxiter=cfg.settings.maxiter)
    return sol.x, sol.cost, prob.evaluations, sol.converged


#: A wrist amplitude below this (rad) counts as an idle wrist.
IDLE_WRIST = 1e-6


def canonical_params(model: KinematicModel, X: np.ndarray) -> np.ndarray:
    """Parameters with flat directions pinned: when the wrist is idle (amplitude below
    :data:`IDLE_WRIST`) its phase lag has no effect at all, so it is set to the model's
    lower bound 0 (in phase with the shoulder, what most active wrists choose) and the
    amplitude to 0.  The cost is unchanged; the table gets smoother
    and the V passes can recognise the same branch."""
    names = model.param_names
    if "wrist_amp" not in names:
        return X
    X = np.array(X, dtype=float, copy=True)
    amp, lag = names.index("wrist_amp"), names.index("wrist_lag")
    idle = X[..., amp] < IDLE_WRIST
    X[..., amp] = np.where(idle, 0.0, X[..., amp])
    X[..., lag] = np.where(idle, model.spec("wrist_lag").lower, X[..., lag])
    return X


def _improve_cell(
    cfg: BuildConfig, model: KinematicModel, fx: float, fz: float, v: float, starts: list[np.ndarray], evaluator: Any = None
) -> tuple[np.ndarray | None, float, int, bool]:
    """The best SLSQP answer from ``starts`` (None if there are none)."""
    prob = _problem(cfg, model, fx, fz, v, None, evaluator)
    best = None
    for x0 in starts:
        sol = slsqp(prob, x0, maxiter=cfg.settings.maxiter)
        if best is None or sol.cost < best.cost:
            best = sol
    if best is None:
        return None, np.inf, prob.evaluations, True
    return best.x, best.cost, prob.evaluations, best.converged


# ---- tasks (top-level functions: picklable for process and cluster executors) -----------


def solve_slice(cfg: BuildConfig, iv: int) -> dict[str, np.ndarray]:
    """Phase 1 for the slice V = grid.V[iv]: sweep Fz (inner) and Fx (outer, downwards).

    The first column (strongest lift demand) is a chain of warm starts from +Fx_max
    down; then every Fx line sweeps Fz upwards, the lines in lockstep (their
    evaluations batched, :mod:`birdsim.tables.lockstep`); then a backward pass in Fz re-solves
    each cell from its Fx/Fz neighbours on other branches."""
    model = get_model(cfg.model)
    g = cfg.grid
    v = g.V[iv]
    nfx, nfz, d = len(g.Fx), len(g.Fz), len(model.param_names)
    X = np.zeros((nfx, nfz, d))
    cost = np.zeros((nfx, nfz))
    evals = np.zeros((nfx, nfz), dtype=np.int64)
    conv = np.zeros((nfx, nfz), dtype=bool)
    screen = _screen(cfg, model, v)
    warm: np.ndarray | None = None
    for i in reversed(range(nfx)):  # Fx from +max down, Fz at the strongest lift demand
        X[i, 0], cost[i, 0], evals[i, 0], conv[i, 0] = _solve_cell(cfg, model, g.Fx[i], g.Fz[0], v, warm, screen)
        warm = X[i, 0]
    for j in range(1, nfz):  # Fz upwards to 0, all Fx lines at once
        jobs = [partial(_solve_cell, cfg, model, g.Fx[i], g.Fz[j], v, X[i, j - 1], screen) for i in range(nfx)]
        for i, (x, c, e, ok) in enumerate(run_lockstep(model, cfg.bird, cfg.settings.n_search, jobs)):
            X[i, j], cost[i, j], evals[i, j], conv[i, j] = x, c, e, ok
    X = canonical_params(model, X)
    if cfg.weights.distance == 0:
        # backward pass in Fz (0 -> strongest lift): each cell re-solved from those of its
        # Fx/Fz neighbours that sit on another branch; kept if cheaper
        for j in reversed(range(nfz)):
            jobs = []
            for i in range(nfx):
                near = [(i, j + 1), (i - 1, j), (i + 1, j)]
                starts = [
                    X[a, b].copy() for a, b in near
                    if 0 <= a < nfx and b < nfz and np.max(np.abs(X[a, b] - X[i, j])) >= cfg.settings.branch_tol
                ]
                jobs.append(partial(_improve_cell, cfg, model, g.Fx[i], g.Fz[j], v, starts))
            for i, (x, c, e, ok) in enumerate(run_lockstep(model, cfg.bird, cfg.settings.n_search, jobs)):
                evals[i, j] += e
                if x is not None and c < cost[i, j] - 1e-12:
                    X[i, j], cost[i, j], conv[i, j] = canonical_params(model, x), c, ok
    evals[-1, 0] += screen[0].shape[0]  # the screen, booked on the first cell
    return {"params": X, "cost": cost, "evaluations": evals, "converged": conv}


def solve_v_line(cfg: BuildConfig, ifx: int, X: np.ndarray, cost: np.ndarray, conv: np.ndarray) -> dict[str, np.ndarray]:
    """Phase 2 for the line Fx = grid.Fx[ifx] (arrays nFz x nV): a forward and a
    backward pass in V, each cell re-solved from its V-neighbour (all Fz of one V in
    lockstep) and kept if cheaper.  With under-relaxation (relax < 1) the forward pass
    stores ``relax x* + (1 - relax) x_prev`` (eq. 94) and the backward pass, which
    would undo that smoothing, is skipped."""
    model = get_model(cfg.model)
    g, st = cfg.grid, cfg.settings
    X, cost, conv = X.copy(), cost.copy(), conv.copy()
    evals = np.zeros(cost.shape, dtype=np.int64)
    nv, nfz = len(g.V), len(g.Fz)
    plain = st.relax == 1.0 and cfg.weights.distance == 0
    passes = [(range(1, nv), -1)] + ([(range(nv - 2, -1, -1), +1)] if st.relax == 1.0 else [])
    for order, step in passes:
        for k in order:
            # a V-neighbour this close is on the same branch: a re-solve would land here again
            todo = [j for j in range(nfz) if not (plain and np.max(np.abs(X[j, k + step] - X[j, k])) < st.branch_tol)]
            jobs = [partial(_resolve_from, cfg, model, g.Fx[ifx], g.Fz[j], g.V[k], X[j, k + step].copy()) for j in todo]
            for j, (x_new, c_new, e, ok) in zip(todo, run_lockstep(model, cfg.bird, st.n_search, jobs)):
                prev = X[j, k + step]
                evals[j, k] += e
                if not plain:
                    prob = _problem(cfg, model, g.Fx[ifx], g.Fz[j], g.V[k], prev if cfg.weights.distance > 0 else None)
                    if st.relax < 1.0:
                        x_new = st.relax * x_new + (1.0 - st.relax) * prev
                        X[j, k], cost[j, k], conv[j, k] = x_new, float(prob.cost(x_new[None])[0]), ok
                        continue
                    current = float(prob.cost(X[j, k][None])[0])
                else:
                    current = cost[j, k]
                if c_new < current - 1e-12:
                    X[j, k], cost[j, k], conv[j, k] = canonical_params(model, x_new), c_new, ok
    return {"params": X, "cost": cost, "evaluations": evals, "converged": conv}


# ---- orchestration ---------------------------------------------------------------------


class _InlineExecutor(Executor):
    """Runs each task at submission (``jobs=1``): no processes, same code path."""

    def submit(self, fn: Callable[..., Any], /, *args: Any, **kwargs: Any) -> Future:  # type: ignore[override]
        fut: Future = Future()
        try:
            fut.set_result(fn(*args, **kwargs))
        except BaseException as exc:  # noqa: BLE001 - handed to the caller through the future
            fut.set_exception(exc)
        return fut


def _git_commit() -> str:
    here = Path(__file__).resolve().parent
    try:
        out = subprocess.run(["git", "rev-parse", "HEAD"], cwd=here, capture_output=True, text=True, timeout=10)
        commit = out.stdout.strip() or "unknown"
        dirty = subprocess.run(["git", "status", "--porcelain", "--", "."], cwd=here, capture_output=True, text=True, timeout=10)
        return commit + ("-dirty" if dirty.stdout.strip() else "")
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def _is_checkpoint_file(name: str) -> bool:
    """A name that :class:`Checkpoints` writes (write_atomic's temporaries included)."""
    return name == "config.sha" or any(fnmatch.fnmatchcase(name, p) for p in _CHECKPOINT_PATTERNS)


_CHECKPOINT_PATTERNS = ("slice_V*.npz", "line_Fx*.npz", ".slice_V*.npz.*.partial.npz", ".line_Fx*.npz.*.partial.npz")


class Checkpoints:
    """Finished tasks of one build, one ``.npz`` per task in a folder; a folder of a
    different configuration is cleared.  A folder holding anything but checkpoint files
    (``config.sha``, ``slice_V*.npz``, ``line_Fx*.npz`` and their temporaries), or a
    path that is a file, is refused, never cleared: the folder is removed at the end."""

    def __init__(self, folder: Path | None, digest: str) -> None:
        self.folder = folder
        if folder is None:
            return
        stamp = folder / "config.sha"
        if folder.exists() and not folder.is_dir():
            raise BirdsimError(f"checkpoint_dir {str(folder)!r} is a file; allowed: a folder used only for checkpoints")
        if folder.exists():
            foreign = sorted(p.name for p in folder.iterdir() if not _is_checkpoint_file(p.name))
            if foreign:
                raise BirdsimError(
                    f"checkpoint_dir {str(folder)!r} holds {foreign[0]!r}, not a checkpoint; allowed: a new or empty "
                    "folder, or one written by an earlier build (it is cleared and removed)"
                )
        if folder.exists() and (not stamp.is_file() or stamp.read_text().strip() != digest):
            shutil.rmtree(folder)
        folder.mkdir(parents=True, exist_ok=True)
        stamp.write_text(digest + "\n")

    def load(self, name: str) -> dict[str, np.ndarray] | None:
        if self.folder is None or not (self.folder / f"{name}.npz").is_file():
            return None
        try:
            with np.load(self.folder / f"{name}.npz") as z:
                data = {k: z[k] for k in z.files}
            return data if {"params", "cost", "evaluations", "converged"} <= set(data) else None
        except (OSError, ValueError, EOFError, zipfile.BadZipFile):
            return None  # a damaged checkpoint is recomputed

    def save(self, name: str, arrays: dict[str, np.ndarray]) -> None:
        if self.folder is None:
            return
        import io

        buf = io.BytesIO()
        np.savez(buf, **arrays)
        write_atomic(self.folder / f"{name}.npz", buf.getvalue())

    def remove(self) -> None:
        if self.folder is not None and self.folder.exists():
            shutil.rmtree(self.folder)


def _run(
    tasks: dict[str, tuple[Callable[..., dict[str, np.ndarray]], tuple[Any, ...]]],
    executor: Executor,
    checkpoints: Checkpoints,
    tick: Callable[[int], None],
    cells_per_task: int,
) -> dict[str, dict[str, np.ndarray]]:
    done: dict[str, dict[str, np.ndarray]] = {}
    futures = {}
    for name, (fn, args) in tasks.items():
        cached = checkpoints.load(name)
        if cached is not None:
            done[name] = cached
            tick(cells_per_task)
        else:
            futures[executor.submit(fn, *args)] = name
    try:
        for fut in as_completed(futures):
            name = futures[fut]
            done[name] = fut.result()
            checkpoints.save(name, done[name])
            tick(cells_per_task)
    except BaseException:
        # an interruption or a failed task: keep every other task that has finished
        for fut, name in futures.items():
            if name not in done and fut.done() and not fut.cancelled() and fut.exception() is None:
                checkpoints.save(name, fut.result())
        raise
    return done


def _ignore_sigint() -> None:
    """Worker initializer: Ctrl-C is the parent's to handle (it stops the workers)."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _stop_workers(executor: ProcessPoolExecutor) -> None:
    """Terminate a ProcessPoolExecutor's workers (running tasks are abandoned)."""
    import signal
    import threading

    main = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN) if main else None  # a second Ctrl-C cannot cut this short
    try:
        terminate = getattr(executor, "terminate_workers", None)  # Python >= 3.14
        if terminate is not None:
            terminate()
        else:
            for proc in list((getattr(executor, "_processes", None) or {}).values()):
                proc.terminate()
        executor.shutdown(wait=False, cancel_futures=True)
    finally:
        if main and previous is not None:
            signal.signal(signal.SIGINT, previous)


def build_table(
    cfg: BuildConfig,
    *,
    executor: Executor | None = None,
    jobs: int | None = None,
    checkpoint_dir: str | Path | None = None,
    progress: bool = False,
) -> LookupTable:
    """Build the table of ``cfg``.  ``executor`` (any concurrent.futures Executor) wins
    over ``jobs`` (processes; 1 = in this process; default: all cores)."""
    model = get_model(cfg.model)
    g = cfg.grid
    t0 = time.perf_counter()
    ckpt = Checkpoints(Path(checkpoint_dir) if checkpoint_dir else None, cfg.digest())
    ncells = int(np.prod(g.shape))
    passes = 2 if cfg.settings.v_passes else 1
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=passes * ncells, unit="cell", desc=f"tables {cfg.model}", leave=False)
    tick = (lambda k: bar.update(k)) if bar is not None else (lambda k: None)
    own = executor is None
    if own:
        jobs = jobs or os.cpu_count() or 1
        executor = _InlineExecutor() if jobs == 1 else ProcessPoolExecutor(max_workers=jobs, initializer=_ignore_sigint)
    assert executor is not None
    try:
        slices = _run(
            {f"slice_V{k:03d}": (solve_slice, (cfg, k)) for k in range(len(g.V))},
            executor, ckpt, tick, len(g.Fx) * len(g.Fz),
        )
        X = np.stack([slices[f"slice_V{k:03d}"]["params"] for k in range(len(g.V))], axis=2)
        cost = np.stack([slices[f"slice_V{k:03d}"]["cost"] for k in range(len(g.V))], axis=2)
        evals = np.stack([slices[f"slice_V{k:03d}"]["evaluations"] for k in range(len(g.V))], axis=2)
        conv = np.stack([slices[f"slice_V{k:03d}"]["converged"] for k in range(len(g.V))], axis=2)
        if cfg.settings.v_passes:
            lines = _run(
                {f"line_Fx{i:03d}": (solve_v_line, (cfg, i, X[i], cost[i], conv[i])) for i in range(len(g.Fx))},
                executor, ckpt, tick, len(g.Fz) * len(g.V),
            )
            X = np.stack([lines[f"line_Fx{i:03d}"]["params"] for i in range(len(g.Fx))], axis=0)
            evals = evals + np.stack([lines[f"line_Fx{i:03d}"]["evaluations"] for i in range(len(g.Fx))], axis=0)
            conv = np.stack([lines[f"line_Fx{i:03d}"]["converged"] for i in range(len(g.Fx))], axis=0)
    except BaseException:
        # Ctrl-C or a failed task: finished parts are saved; stop our workers now (a
        # second Ctrl-C inside shutdown(wait=True) used to leave them alive and the
        # process hanging at exit)
        if own and isinstance(executor, ProcessPoolExecutor):
            _stop_workers(executor)
        raise
    finally:
        if own:
            executor.shutdown(wait=True, cancel_futures=True)
        if bar is not None:
            bar.close()
    table = finish_table(cfg, model, X, evals, conv)
    seconds = time.perf_counter() - t0
    table.meta.update(build_seconds=round(seconds, 3), cells_per_second=round(ncells / seconds, 2), jobs=jobs if own else "executor")
    ckpt.remove()
    return table


def final_check(cfg: BuildConfig, model: KinematicModel, X: np.ndarray) -> dict[str, np.ndarray]:
    """Cost terms, achieved forces and status of parameters X (grid shape x d) at n_final."""
    g = cfg.grid
    D = np.stack(np.meshgrid(g.Fx, g.Fz, g.V, indexing="ij"), axis=-1)
    Fx, Fz, P = forces(model, X, D[..., 2], cfg.bird, cfg.settings.n_final)
    other = other_cost(model, X, D[..., 2], cfg.weights)
    b = breakdown_from_forces(Fx, Fz, P, D[..., 0], D[..., 1], cfg.weights, other)
    err = np.maximum(np.abs(Fx - D[..., 0]), np.abs(Fz - D[..., 1]))
    status = np.where(err > cfg.settings.reach_tol, STATUS_NAMES.index("unreachable"), STATUS_NAMES.index("ok"))
    bad = ~(np.isfinite(b.total) & np.all(np.isfinite(X), axis=-1))
    status = np.where(bad, STATUS_NAMES.index("failed"), status).astype(np.uint8)
    return {
        "cost": np.asarray(b.total, dtype=float),
        "cost_fractions": b.fractions,
        "achieved": np.stack([Fx, Fz, P], axis=-1),
        "status_code": status,
    }


def finish_table(
    cfg: BuildConfig, model: KinematicModel, X: np.ndarray, evals: np.ndarray, converged: np.ndarray | None = None
) -> LookupTable:
    from birdsim import __version__

    chk = final_check(cfg, model, X)
    meta = {
        "force": "right wing + body drag (the dissertation's flapcost force), seed earth axes, Fz < 0 is up",
        "package_version": __version__,
        "git_commit": _git_commit(),
        "built_at": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        "config_sha": cfg.digest(),
        **{k: v for k, v in cfg.to_dict().items() if k != "bird"},
        "counts": {s: int(np.sum(chk["status_code"] == i)) for i, s in enumerate(STATUS_NAMES)},
        "not_converged": int(np.sum(~converged)) if converged is not None else 0,
    }
    return LookupTable(
        model=cfg.model,
        bird=cfg.bird,
        param_names=model.param_names,
        axes={a: np.asarray(getattr(cfg.grid, a), dtype=float) for a in AXES},
        params=X,
        evaluations=evals,
        converged=np.ones(X.shape[:-1], dtype=bool) if converged is None else converged.astype(bool),
        meta=meta,
        **chk,
    )


def config_from_meta(table: LookupTable) -> BuildConfig:
    """The configuration a table was built with (to rebuild it, or part of it)."""
    m = table.meta
    return BuildConfig(
        model=table.model,
        grid=Grid(**{a: tuple(m["grid"][a]) for a in AXES}),
        bird=table.bird,
        weights=CostWeights(**m["cost_weights"]),
        settings=BuildSettings(**m["solver"]),
    )


def sub_grid(grid: Grid, Fx: Sequence[int], Fz: Sequence[int], V: Sequence[int]) -> Grid:
    """The grid restricted to the given indices (e.g. a corner for a rebuild check)."""
    return Grid(tuple(grid.Fx[i] for i in Fx), tuple(grid.Fz[i] for i in Fz), tuple(grid.V[i] for i in V))
