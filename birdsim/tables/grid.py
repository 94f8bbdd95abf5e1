"""The configuration of a table build: the demand grid (:class:`Grid`), the solver
settings (:class:`BuildSettings`) and everything that determines a table
(:class:`BuildConfig`, hashed for the checkpoints)."""

from __future__ import annotations

import hashlib
import inspect
import json
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from birdsim.errors import BirdsimError, limits_text, magnitude_ok
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import DEFAULT_SAMPLES
from birdsim.tables.cost import CostWeights
from birdsim.tables.lookup import AXES, CLIMB

if TYPE_CHECKING:
    from birdsim.tables.lookup import LookupTable

#: Largest grid accepted: nodes per axis and cells in all (a count of 1e9 in --grid
#: used to exhaust memory before any check; a million cells is hours of building).
MAX_NODES = 1000
MAX_CELLS = 1_000_000


#: Default climb axis (``--climb``): 7 nodes from -0.5 to 0.5 (speed units, positive up).
CLIMB_DEFAULT = (-0.5, 0.5, 7)


@dataclass(frozen=True)
class Grid:
    """The demand grid: increasing values of Fx, Fz (dissertation force), V and,
    optionally, climb (vertical speed relative to the air, positive up; None = a
    level-flight table with three axes)."""

    Fx: tuple[float, ...]
    Fz: tuple[float, ...]
    V: tuple[float, ...]
    climb: tuple[float, ...] | None = None

    @property
    def axis_names(self) -> tuple[str, ...]:
        return AXES + ((CLIMB,) if self.climb is not None else ())

    def __post_init__(self) -> None:
        for a in self.axis_names:
            ax = getattr(self, a)
            if (
                len(ax) < 2
                or any(not (np.isfinite(x) and magnitude_ok(x)) for x in ax)
                or any(b <= a_ for a_, b in zip(ax, ax[1:]))
            ):
                raise BirdsimError(
                    f"grid {a}={[float(x) for x in ax]} is invalid; allowed: >= 2 finite increasing values, {limits_text()}"
                )
        if self.V[0] < 0:
            raise BirdsimError(f"grid V starts at {self.V[0]:g}; allowed: speeds >= 0")
        if int(np.prod(self.shape)) > MAX_CELLS:
            raise BirdsimError(
                f"grid {'x'.join(map(str, self.shape))} has too many cells; allowed: at most {MAX_CELLS} cells"
            )

    @classmethod
    def default(cls, size: int = 11) -> "Grid":
        """docs/design.md's default grid: Fx in [-0.5, 0.5], Fz in [-0.5, 0], V in [0, 1]."""
        return cls.parse("", size)

    @classmethod
    def parse(cls, spec: str, size: int = 11, climb: bool = False) -> "Grid":
        """``"Fx=-0.5:0.5:11,Fz=-0.5:0:11,V=0:1:11"`` (``lo:hi:count``) or explicit
        values ``"V=0|0.5|1"``; axes left out take the default range with ``size`` nodes.
        A ``climb=...`` part, or ``climb=True`` (:data:`CLIMB_DEFAULT`), adds the climb axis."""
        if not isinstance(size, int) or not 2 <= size <= MAX_NODES:
            raise BirdsimError(
                f"--size {size!r} is invalid; allowed: an integer in [2, {MAX_NODES}]"
            )
        defaults = {"Fx": (-0.5, 0.5), "Fz": (-0.5, 0.0), "V": (0.0, 1.0)}
        axes: dict[str, Any] = {
            a: tuple(float(x) for x in np.linspace(*defaults[a], size)) for a in AXES
        }
        if climb:
            axes[CLIMB] = tuple(float(x) for x in np.linspace(*CLIMB_DEFAULT))
        for part in filter(None, (s.strip() for s in spec.split(","))):
            name, sep, value = part.partition("=")
            name = name.strip()
            if not sep or name not in AXES + (CLIMB,):
                raise BirdsimError(
                    f"grid {part!r} is malformed; allowed: Fx=LO:HI:COUNT, Fz=..., V=..., climb=... or NAME=A|B|C"
                )
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
                raise BirdsimError(
                    f"grid {part!r} is malformed; allowed: {name}=LO:HI:COUNT (2 <= COUNT <= {MAX_NODES}) or {name}=A|B|C"
                ) from None
        return cls(**axes)

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(getattr(self, a)) for a in self.axis_names)

    def to_dict(self) -> dict[str, list[float]]:
        """The axes (climb only when present: a level-flight grid hashes as before)."""
        return {a: list(getattr(self, a)) for a in self.axis_names}


@dataclass(frozen=True)
class BuildSettings:
    """Solver settings of a table build (recorded in the table's provenance)."""

    n_search: int = 32  # samples per wingbeat during the search
    n_final: int = DEFAULT_SAMPLES  # samples per wingbeat of the final check (the stored values)
    screen: int = 1024  # space-filling candidates per V slice, shared by its cells
    starts: int = 2  # screen candidates polished where the warm start is poor
    screen_gap: float = (
        0.02  # multi-start unless the warm start beats the best screen candidate by this
    )
    always_polish: int = 1  # screen candidates polished even after a good warm start
    switch_margin: float = 1e-4  # another branch must beat the warm-start branch by this
    polish_rule: bool = True  # skip the polishes that cannot win (docs/performance.md); False: polish every candidate
    polish_near: float = (
        0.12  # ... a candidate this near the warm answer (fraction of every parameter's range)
    )
    polish_excess: float = 0.1  # ... and costing 0 to this fraction more than the warm answer
    reach_tol: float = 0.01  # |achieved - demanded| force above which a cell is unreachable
    v_passes: bool = True  # forward and backward passes in V after the slices
    branch_tol: float = 0.25  # rad; a neighbour this close is on the same branch (no re-solve)
    relax: float = 1.0  # under-relaxation delta of eq. 94 along V (1 = off)
    maxiter: int = 100
    seed: int = 0
    smooth_tol: float = 5e-3  # regularising pass: cost tolerance of a tie-break (0 = no pass)
    smooth_nu: float = 0.05  # its distance weight (per rad) towards the neighbours' wingbeat
    smooth_rounds: int = 4  # at most this many red-black rounds
    # ... also start from the parameter-wise median of a cell's neighbours (issue 24; the
    # m5 table's; off by default, so the other tables rebuild bit for bit: docs/tables.md)
    smooth_median: bool = False
    # ... run the pass to its fixed point: rounds until one changes no cell (at most
    # smooth_rounds) instead of stopping after a round that removes no zig-zag cell; then
    # the plane moves (birdsim/tables/plane_moves.py).  Both issue 24's m5 table's, off by
    # default and recorded only when on (docs/tables.md)
    smooth_fixed_point: bool = False
    smooth_planes: bool = False

    def __post_init__(self) -> None:
        if not (0.0 < self.relax <= 1.0):
            raise BirdsimError(f"relax={self.relax!r} is invalid; allowed: 0 < relax <= 1")
        for name in ("n_search", "n_final", "screen", "maxiter"):
            if int(getattr(self, name)) < 2:
                raise BirdsimError(
                    f"{name}={getattr(self, name)!r} is invalid; allowed: an integer >= 2"
                )
        for name in (
            "polish_rule",
            "v_passes",
            "smooth_median",
            "smooth_fixed_point",
            "smooth_planes",
        ):
            if not isinstance(getattr(self, name), bool):
                raise BirdsimError(
                    f"{name}={getattr(self, name)!r} is invalid; allowed: True or False"
                )
        # written as "not (ok)" so that NaN is refused too (every comparison with NaN is False)
        if not self.reach_tol > 0:
            raise BirdsimError(f"reach_tol={self.reach_tol!r} is invalid; allowed: a number > 0")
        for name in (
            "starts",
            "always_polish",
            "switch_margin",
            "screen_gap",
            "polish_near",
            "polish_excess",
            "branch_tol",
            "smooth_tol",
            "smooth_nu",
            "smooth_rounds",
        ):
            value = getattr(self, name)
            if not value >= 0:
                raise BirdsimError(f"{name}={value!r} is invalid; allowed: a number >= 0")


def _solver_dict(settings: BuildSettings) -> dict[str, Any]:
    """The settings as recorded; ``smooth_median``, ``smooth_fixed_point`` and
    ``smooth_planes`` only when on, so that every table built before they existed keeps
    its configuration digest (and its checkpoints)."""
    out = asdict(settings)
    for name in ("smooth_median", "smooth_fixed_point", "smooth_planes"):
        if not out[name]:
            del out[name]
    return out


@dataclass(frozen=True)
class BuildConfig:
    """Everything that determines a table (hashed for the checkpoints)."""

    model: str
    grid: Grid
    bird: Bird = field(default_factory=Bird)
    weights: CostWeights = field(default_factory=CostWeights)
    settings: BuildSettings = field(default_factory=BuildSettings)

    def __post_init__(self) -> None:
        from birdsim.physics.m5 import fold_bird_error

        if self.model == "m5" and (why := fold_bird_error(self.bird)) is not None:
            raise BirdsimError(f"bird: {why}")  # m5 needs an arm and a hand

    def to_dict(self) -> dict[str, Any]:
        return {
            "model": self.model,
            "grid": self.grid.to_dict(),
            "bird": self.bird.to_dict(),
            "cost_weights": self.weights.to_dict(),
            "solver": _solver_dict(self.settings),
        }

    def stamp(self) -> dict[str, Any]:
        """What a checkpoint must share with this build to be reused: the package
        version, a fingerprint of the numerical code (physics and optimiser sources),
        the optimiser's fixed settings and the digest of :meth:`to_dict` (grid, bird,
        cost weights, solver settings)."""
        from birdsim import __version__
        from birdsim.tables import optimize

        return {
            "package_version": __version__,
            "code": code_fingerprint(),
            "optimiser": {
                "fd_step": optimize.FD_STEP,
                "slsqp_ftol": inspect.signature(optimize.slsqp).parameters["ftol"].default,
            },
            "config": hashlib.sha256(
                json.dumps(self.to_dict(), sort_keys=True).encode()
            ).hexdigest()[:16],
        }

    def digest(self) -> str:
        """16 hex digits of :meth:`stamp`: equal digests, interchangeable checkpoints."""
        return hashlib.sha256(json.dumps(self.stamp(), sort_keys=True).encode()).hexdigest()[:16]


#: Source files whose change changes the numbers of a table (relative to birdsim/).
NUMERICAL_SOURCES = (
    "physics/*.py",
    "tables/cost.py",
    "tables/optimize.py",
    "tables/point.py",
    "tables/slsqp_driver.py",
    "tables/sweeps.py",
    "tables/regularise.py",
    "tables/finish.py",
)


def code_fingerprint() -> str:
    """SHA-256 (16 hex digits) of the numerical sources (:data:`NUMERICAL_SOURCES`), so
    that a build resumed after an upgrade or an edit of the physics does not mix the
    results of two codes."""
    root = Path(__file__).resolve().parent.parent
    h = hashlib.sha256()
    for pattern in NUMERICAL_SOURCES:
        for path in sorted(root.glob(pattern)):
            h.update(path.relative_to(root).as_posix().encode() + b"\0" + path.read_bytes())
    return h.hexdigest()[:16]


def config_from_meta(table: LookupTable) -> BuildConfig:
    """The configuration a table was built with (to rebuild it, or part of it)."""
    m = table.meta
    return BuildConfig(
        model=table.model,
        grid=Grid(**{a: tuple(m["grid"][a]) for a in AXES + (CLIMB,) if a in m["grid"]}),
        bird=table.bird,
        weights=CostWeights(**m["cost_weights"]),
        settings=BuildSettings(**m["solver"]),
    )


def sub_grid(
    grid: Grid,
    Fx: Sequence[int],
    Fz: Sequence[int],
    V: Sequence[int],
    climb: Sequence[int] | None = None,
) -> Grid:
    """The grid restricted to the given indices (e.g. a corner for a rebuild check)."""
    c = (
        None
        if grid.climb is None
        else tuple(grid.climb[i] for i in (climb if climb is not None else range(len(grid.climb))))
    )
    return Grid(
        tuple(grid.Fx[i] for i in Fx), tuple(grid.Fz[i] for i in Fz), tuple(grid.V[i] for i in V), c
    )
