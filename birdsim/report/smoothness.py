"""Report figure: how smooth the committed lookup tables are (zig-zag share per axis
and per parameter, :mod:`birdsim.tables.smoothness`), against the 2 % target."""

from __future__ import annotations

from typing import Any

import numpy as np

#: The committed tables (repository root / tables).
from birdsim.report.fig_tables import TABLE_FOLDER  # the repository's tables/
from birdsim.tables.smoothness import ZIGZAG_RAD, table_smoothness, zigzags

MODELS = ("base", "m1", "m2", "m3", "m4")
TARGET = 0.02


def zigzags_per_param(table: Any) -> dict[str, int]:
    """Zig-zag triples (all axes) in which each parameter goes out and back."""
    ok = table.status == "ok"
    counts = np.zeros(len(table.param_names), dtype=int)
    for k in range(ok.ndim):
        _, _, size = zigzags(tuple(table.param_names), np.asarray(table.params), ok, k)
        counts += np.sum(size > ZIGZAG_RAD, axis=tuple(range(size.ndim - 1)))
    return dict(zip(table.param_names, (int(c) for c in counts)))


def smoothness_figure(tables: dict[str, Any]) -> Any:
    """Two panels: the zig-zag share of each table along each axis (bars, the 2 % target
    dashed), and the zig-zag triples per parameter.

    Args:
        tables: {model: LookupTable}.
    Returns:
        A matplotlib Figure.
    """
    from birdsim.report import plots

    plt = plots.pyplot()
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
    names = list(tables)
    x = np.arange(len(names))
    stats = {m: table_smoothness(t) for m, t in tables.items()}
    axes_names = list(next(iter(stats.values())).per_axis) if stats else []
    width = 0.8 / max(len(axes_names) + 1, 1)
    for k, ax_name in enumerate(axes_names):
        a.bar(
            x + k * width,
            [100 * stats[m].per_axis[ax_name] for m in names],
            width,
            label=f"along {ax_name}",
        )
    a.bar(
        x + len(axes_names) * width,
        [100 * stats[m].zigzag_share for m in names],
        width,
        color="k",
        label="all axes",
    )
    a.axhline(100 * TARGET, ls="--", color="r", lw=1, label="target 2 %")
    a.set_xticks(x + 0.4 - width / 2, names)
    a.set_ylabel("zig-zag share of reachable triples (%)")
    a.set_title(f"Zig-zags (> {ZIGZAG_RAD} rad out and back)")
    a.legend(fontsize=8)
    for i, m in enumerate(names):
        per = zigzags_per_param(tables[m])
        b.scatter([i] * len(per), list(per.values()), s=12)
        for p, c in per.items():
            if c:
                b.annotate(p, (i, c), fontsize=7, xytext=(3, 0), textcoords="offset points")
    b.set_xticks(x, names)
    b.set_ylabel("zig-zag triples involving the parameter")
    b.set_title("Which parameters zig-zag")
    fig.tight_layout()
    return fig


def fig_smoothness(ctx: Any) -> list[Any]:
    """Report family: the smoothness of the committed tables (one figure, one claim per
    model: zig-zag share at most 2 %).  ``ctx`` is the report's Context (``save``)."""
    from birdsim.report.records import Claim, Entry  # the report's record types
    from birdsim.tables.lookup import load_table

    tables = {
        m: load_table(TABLE_FOLDER / f"{m}.npz")
        for m in MODELS
        if (TABLE_FOLDER / f"{m}.npz").is_file()
    }
    if not tables:
        return []
    name = ctx.save(smoothness_figure(tables), "table_smoothness")
    claims = tuple(
        Claim(
            f"model {m}: neighbouring cells do not zig-zag (share <= 2 %)",
            (s := table_smoothness(t)).zigzag_share <= TARGET,
            f"{100 * s.zigzag_share:.1f} % of {s.triples} reachable triples",
        )
        for m, t in tables.items()
    )
    return [
        Entry(
            name,
            "Smoothness of the lookup tables",
            "Share of three consecutive reachable cells along an axis where a wingbeat "
            f"parameter goes out and back by more than {ZIGZAG_RAD} rad (idle-wrist lag "
            "skipped), per committed table.",
            "Sec. 4.1: results 'fit for animation purposes, which essentially suggests smooth "
            "results'.",
            claims,
        )
    ]
