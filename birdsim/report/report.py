"""``birdsim report``: the dissertation's analysis regenerated from our own numbers.

The report is a list of figure families (:data:`FAMILIES`, keys for ``--only``).  Each
family computes its data (:mod:`birdsim.report.figdata`, the optimisers, the tables),
draws it (:mod:`birdsim.report.plots`), writes the PNGs and returns
:class:`~birdsim.report.records.Entry` records: what the figure shows, what the
dissertation printed in the same place and a list of claims -- each a statement of the
dissertation tested against our numbers (:mod:`birdsim.report.claims`,
:mod:`birdsim.report.sweep_claims`; never a hard-coded verdict).
:func:`build_report` runs the families and writes ``index.html``
(:mod:`birdsim.report.page`).

Modules: ``records`` (Resolution, Claim, Entry, Context), ``claims`` and
``sweep_claims`` (the statements, registered per figure), ``fig_cycle``, ``fig_costs``,
``fig_sweeps``, ``fig_tables``, ``fig_turns`` (the families), ``page`` (HTML), this module (the list
of families and the run).
"""

from __future__ import annotations

import os
import shutil
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path

from birdsim.errors import BirdsimError
from birdsim.io import write_atomic
from birdsim.physics.bird import Bird
from birdsim.report import plots
from birdsim.report.fig_costs import fig_landscapes, fig_wrist_activity
from birdsim.report.fig_cycle import fig_histories, fig_paths, fig_thrust, fig_wrist
from birdsim.report.fig_sweeps import fig_sweeps
from birdsim.report.fig_tables import fig_optimisers, fig_tables
from birdsim.report.fig_turns import fig_turns
from birdsim.report.page import render_html
from birdsim.report.records import (
    FULL,
    QUICK,
    SMALL_DEMAND,
    Claim,
    Context,
    Entry,
    Family,
    Resolution,
    Section,
)
from birdsim.report.smoothness import fig_smoothness

__all__ = [
    "FAMILIES",
    "FULL",
    "QUICK",
    "SMALL_DEMAND",
    "Claim",
    "Context",
    "Entry",
    "Family",
    "Resolution",
    "Section",
    "build_report",
    "render_html",
]


FAMILIES: tuple[Family, ...] = (
    Family("histories", "1. Force and power over one wingbeat (Figs 12-25)", fig_histories),
    Family("thrust", "2. Thrust coefficient over advance angle and twist (Fig 9)", fig_thrust),
    Family("wrist", "3. Wrist lag and bias (Figs 26-27)", fig_wrist),
    Family("landscapes", "4a. Optimisation spaces of the base model (Figs 33-34)", fig_landscapes),
    Family("activity", "4b. Wrist activity coefficient K (Figs 49-51)", fig_wrist_activity),
    Family(
        "sweeps", "5. Solutions over speed and cost fractions (Figs 35-38, 44, 45, 52)", fig_sweeps
    ),
    Family(
        "tables", "6. Lookup-table slices at V = 0, 0.5, 0.9 (Fig 40, appendices 6-8)", fig_tables
    ),
    Family("paths", "7. Control-point paths and chord lines (Figs 41-43, 46-48, 53-55)", fig_paths),
    Family(
        "optimisers",
        "8. Optimiser comparison and table-build time (Figs 28-31, Table 3, Fig 63)",
        fig_optimisers,
    ),
    Family("smoothness", "9. Smoothness of the lookup tables (sec. 4.1)", fig_smoothness),
    Family("turns", "10. Turning flight: ground tracks and bank (issue 23)", fig_turns),
)


def build_report(
    out: Path | str,
    *,
    quick: bool = False,
    force: bool = False,
    bird: Bird | None = None,
    only: Sequence[str] | None = None,
    progress: bool | None = True,
) -> list[Section]:
    """Regenerate every figure into ``out`` (PNGs) and write ``out/index.html``.

    The figures are drawn into a temporary folder inside ``out`` and moved into place
    with the page at the end: an interrupted or failed run leaves ``out`` as it was.

    Args:
        out: the report folder (made if missing).
        quick: coarse grids (:data:`QUICK`) instead of :data:`FULL`.
        force: replace an existing report in ``out``.
        bird: the bird of every figure (default: the seed bird).
        only: family keys (:data:`FAMILIES`) to build; default all.
        progress: a tqdm bar per family (None: only on a terminal).

    Returns:
        One :class:`Section` per family built, with its entries and seconds.

    Raises:
        BirdsimError: one line for an existing report without ``force``, an ``out``
            that is a file or cannot be made, an unknown ``only`` key, or matplotlib
            missing.
    """
    if not str(out).strip():
        raise BirdsimError(f"out={str(out)!r} is empty; allowed: a folder path")
    out = Path(out)
    plots.pyplot()  # fail early with the install hint when matplotlib is missing
    index = out / "index.html"
    if index.exists() and not force:
        raise BirdsimError(
            f"out={str(out)!r} already holds a report; allowed: a new folder, or force=True "
            "(--force on the command line) to overwrite"
        )
    if out.exists() and not out.is_dir():
        raise BirdsimError(f"out={str(out)!r} is a file; allowed: a folder")
    keys = [f.key for f in FAMILIES]
    for k in only or ():
        if k not in keys:
            raise BirdsimError(f"only={k!r} is unknown; allowed: {', '.join(keys)}")
    created = not out.exists()
    try:
        out.mkdir(parents=True, exist_ok=True)
        staging = Path(tempfile.mkdtemp(prefix=".report-", dir=out))
    except OSError as exc:
        raise BirdsimError(f"out={str(out)!r} cannot be created: {exc.strerror}") from None
    try:
        ctx = Context(staging, QUICK if quick else FULL, bird or Bird())
        sections = _build_sections(
            ctx, [f for f in FAMILIES if not only or f.key in only], progress
        )
        page = render_html(sections, ctx).encode()
        for png in sorted(staging.iterdir()):
            os.replace(png, out / png.name)
        write_atomic(index, page)
    except BaseException:
        shutil.rmtree(out if created else staging, ignore_errors=True)
        raise
    shutil.rmtree(staging, ignore_errors=True)
    return sections


def _build_sections(ctx: Context, families: list[Family], progress: bool | None) -> list[Section]:
    from tqdm import tqdm

    sections = []
    bar = tqdm(
        families, desc="report", unit="family", disable=None if progress is None else not progress
    )
    for fam in bar:
        bar.set_postfix_str(fam.key)
        t0 = time.perf_counter()
        sec = Section(fam)
        try:
            sec.entries = fam.build(ctx)
        except ImportError as exc:  # a part of the project this family needs is missing
            sec.error = f"not built: needs {exc.name or exc} (not available in this checkout)"
        sec.seconds = time.perf_counter() - t0
        sections.append(sec)
    return sections
