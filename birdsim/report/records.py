"""Records of the report: grid sizes (:class:`Resolution`), one figure's
:class:`Entry` with its :class:`Claim` checks, and the :class:`Context` a figure family
draws into; a figure :class:`Family` and the :class:`Section` it fills on the page."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from birdsim.physics.bird import Bird
from birdsim.report import plots


@dataclass(frozen=True)
class Resolution:
    """Grid sizes of the report.  ``quick`` keeps every figure but on coarse grids."""

    samples: int = 64  # per wingbeat for histories and paths
    landscape_samples: int = 32  # per wingbeat on the big grids
    cfx: int = 181  # advance angle points (twist gets half)
    wrist_map: int = 31  # lag x bias points
    wrist_amp: int = 16  # amplitude points of Fig 27
    wrist_opt: int = 19  # lag/bias points of Fig 27
    landscape: int = 41  # plotted axes of the cost landscapes
    profile: int = 31  # profiled (minimised-over) axes
    m4_landscape: int = 21
    m4_profile: int = 11
    sweep_speeds: int = 21
    optimiser_nodes: int = 12
    build_grid: int = 3  # demand grid per axis of the build-time study
    table_grid: int = 7  # Fx and Fz nodes of tables built here when none is committed
    table_screen: int = 1024  # screen candidates per V slice of tables built here
    quick: bool = False

    def build_settings(self):
        """Table-build settings of the report's own builds (coarser in quick mode)."""
        from birdsim.tables.build import BuildSettings

        if not self.quick:
            return BuildSettings(screen=self.table_screen)
        return BuildSettings(screen=self.table_screen, n_search=12, n_final=16, v_passes=False)


FULL = Resolution()
QUICK = Resolution(
    samples=16,
    landscape_samples=12,
    cfx=31,
    wrist_map=7,
    wrist_amp=4,
    wrist_opt=5,
    landscape=9,
    profile=5,
    m4_landscape=5,
    m4_profile=3,
    sweep_speeds=4,
    optimiser_nodes=12,
    build_grid=2,
    table_grid=2,
    table_screen=64,
    quick=True,
)

#: "Small Fx and Fz requirements" of secs 4.1.1 and 4.1.4 (the text does not print them).
SMALL_DEMAND = (0.1, -0.1)


@dataclass(frozen=True)
class Claim:
    """One statement of the dissertation and whether our numbers bear it out."""

    statement: str
    holds: bool
    ours: str

    def __post_init__(self) -> None:
        object.__setattr__(self, "holds", bool(self.holds))  # numpy bools print as np.True_


@dataclass(frozen=True)
class Entry:
    """One figure of the report."""

    file: str
    title: str
    shows: str
    dissertation: str  # what the dissertation printed here ("" if nothing comparable)
    claims: tuple[Claim, ...] = ()
    note: str = ""

    @property
    def verdict(self) -> str:
        if not self.claims:
            return "no printed counterpart" if not self.dissertation else "not checked"
        held = sum(c.holds for c in self.claims)
        if held == len(self.claims):
            return "agrees"
        if held == 0:
            return "disagrees"
        return f"agrees in part ({held} of {len(self.claims)})"


@dataclass(frozen=True)
class Context:
    out: Path
    res: Resolution
    bird: Bird

    def save(self, fig, name: str) -> str:
        plots.save_png(fig, self.out / f"{name}.png")
        return f"{name}.png"


@dataclass(frozen=True)
class Family:
    """One family of figures: its key (``--only``), its heading on the page and the
    function that draws its entries."""

    key: str
    heading: str
    build: Callable[[Context], list[Entry]]


@dataclass
class Section:
    """A family's part of the page: its entries, the time they took, an error if any."""

    family: Family
    entries: list[Entry] = field(default_factory=list)
    seconds: float = 0.0
    error: str = ""
