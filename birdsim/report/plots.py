"""Figures of the dissertation's analysis (matplotlib, Agg backend), one function per
figure family.  The numbers come from ``birdsim/report/figdata.py`` (and the tables and
optimisers); these functions only draw.  matplotlib is an optional extra: without it
every function raises one clear :class:`BirdsimError` naming ``pip install birdsim[plots]``.

Every figure labels its axes with units ("rad", or "non-dimensional"), has a legend
where several lines share axes, and a title naming the model and the case.  Forces are
the dissertation's: right wing + body drag in seed axes, where Fz < 0 is up.

The figures live in :mod:`plot_base` (shared helpers), :mod:`plot_cycle` (histories,
thrust, maps, wrist), :mod:`plot_paths` (control-point paths) and :mod:`plot_lines`
(sweeps, fractions, tables, optimisers); this module gathers them, and the figure
families call them as ``plots.NAME``.
"""

from __future__ import annotations

from birdsim.report.plot_base import FORCE_NOTE, ND, add_footnote, closed, pyplot, save_png, wrap
from birdsim.report.plot_cycle import histories, maps, thrust_coefficient, wrist_optimum
from birdsim.report.plot_lines import fractions, lines, optimiser_runs, table_slices
from birdsim.report.plot_paths import cp_paths

__all__ = [
    "FORCE_NOTE",
    "ND",
    "closed",
    "cp_paths",
    "add_footnote",
    "fractions",
    "histories",
    "lines",
    "maps",
    "optimiser_runs",
    "pyplot",
    "save_png",
    "table_slices",
    "thrust_coefficient",
    "wrap",
    "wrist_optimum",
]
