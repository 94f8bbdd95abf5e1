"""Generic line figures of the report: sweeps over speed, cost fractions, lookup-table
slices and optimiser runs."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from birdsim.report.plot_base import ND, add_footnote, pyplot, wrap

if TYPE_CHECKING:
    from matplotlib.figure import Figure


# ---- generic line plots (sweeps, fractions, timing) ----------------------------------


def lines(
    x: np.ndarray,
    series: Mapping[str, Sequence[tuple[str, np.ndarray, Mapping[str, Any]]]],
    *,
    x_label: str,
    title: str,
    footnote: str | None = None,
    ncols: int = 2,
    logy: bool = False,
) -> "Figure":
    """One small panel per key of ``series`` (its y label), each with labelled lines
    ``(label, y, matplotlib kwargs)`` sharing the x axis."""
    plt = pyplot()
    n = len(series)
    cols = min(ncols, n)
    rows = math.ceil(n / cols)
    fig, axes = plt.subplots(
        rows,
        cols,
        figsize=(5.2 * cols + 0.5, 3.3 * rows + 0.6),
        layout="constrained",
        squeeze=False,
    )
    for ax, (ylab, items) in zip(axes.flat, series.items()):
        for label, y, kw in items:
            ax.plot(
                x if "x" not in kw else kw["x"],
                y,
                label=label,
                **{k: v for k, v in kw.items() if k != "x"},
            )
        ax.set_xlabel(x_label)
        ax.set_ylabel(ylab)
        if logy:
            ax.set_yscale("log")
        ax.grid(alpha=0.3)
        if len(items) > 1:
            ax.legend(fontsize=8)
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    fig.suptitle(wrap(title, int(fig.get_figwidth() * 11)))
    if footnote:
        add_footnote(fig, footnote)
    return fig


def fractions(
    speeds: np.ndarray,
    panels: Sequence[tuple[str, np.ndarray]],
    names: Sequence[str],
    title: str,
    footnote: str | None = None,
) -> "Figure":
    """Fig 36: cost fractions (percent of the total) stacked over speed, one panel per
    ``(label, fractions len(speeds) x len(names))``."""
    plt = pyplot()
    fig, axes = plt.subplots(
        1, len(panels), figsize=(5.5 * len(panels) + 1.5, 4.8), layout="constrained", squeeze=False
    )
    for ax, (label, fr) in zip(axes[0], panels):
        ax.stackplot(
            speeds, 100 * np.asarray(fr).T, labels=[n.replace("_", " ") for n in names], alpha=0.85
        )
        ax.set_xlabel(f"flight speed V ({ND})")
        ax.set_ylabel("share of the total cost (%)")
        ax.set_ylim(0, 100)
        ax.set_xlim(speeds.min(), speeds.max())
        ax.grid(alpha=0.3)
        ax.set_title(label, fontsize=10)
    axes[0, -1].legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
    fig.suptitle(wrap(title, int(fig.get_figwidth() * 11)))
    if footnote:
        add_footnote(fig, footnote)
    return fig


def table_slices(
    fx: np.ndarray,
    fz: np.ndarray,
    speeds: Sequence[float],
    names: Sequence[str],
    values: np.ndarray,
    ok: np.ndarray,
    bounds: Sequence[tuple[float, float]],
    title: str,
    footnote: str | None = None,
) -> "Figure":
    """Fig 40 / appendices 6-8: each parameter (columns) over (Fx, Fz) at several speeds
    (rows).  ``values`` is nFx x nFz x nV x d, ``ok`` nFx x nFz x nV; cells whose optimum
    misses the demand are crossed.  Each column shares its parameter's bounds as colour scale."""
    plt = pyplot()
    d, nv = len(names), len(speeds)
    fig, axes = plt.subplots(
        nv, d, figsize=(2.9 * d + 1.2, 2.6 * nv + 1.0), layout="constrained", squeeze=False
    )
    for j, name in enumerate(names):
        lo, hi = bounds[j]
        for i, v in enumerate(speeds):
            ax = axes[i, j]
            mesh = ax.pcolormesh(
                fx, fz, values[:, :, i, j].T, shading="nearest", cmap="viridis", vmin=lo, vmax=hi
            )
            bad = ~ok[:, :, i]
            if bad.any():
                gx, gz = np.meshgrid(fx, fz, indexing="ij")
                ax.plot(gx[bad], gz[bad], "wx", ms=5, mew=1.2)
            ax.set_title(f"{name}, V = {v:g}", fontsize=9)
            if i == nv - 1:
                ax.set_xlabel("Fx demand")
            if j == 0:
                ax.set_ylabel("Fz demand (< 0 up)")
        fig.colorbar(
            mesh,
            ax=list(axes[:, j]),
            location="bottom",
            label=f"{name} (rad)",
            shrink=0.9,
            ticks=plt.MaxNLocator(4),
        )
    fig.suptitle(wrap(title, 110))
    note = (
        f"x: cell where the optimum misses the demand by more than the reach tolerance; forces {ND}"
    )
    add_footnote(fig, note + ("; " + footnote if footnote else ""))
    return fig


def optimiser_runs(
    runs: Sequence[Sequence[Any]], grids: Sequence[np.ndarray], title: str
) -> "Figure":
    """Figs 28-30: per test function (rows) and solver (columns), the points each solver
    evaluated over the function's contours, its path, and its answer."""
    plt = pyplot()
    rows, cols = len(runs), max(len(r) for r in runs)
    fig, axes = plt.subplots(
        rows,
        cols,
        figsize=(4.3 * cols + 0.8, 4.0 * rows + 0.6),
        layout="constrained",
        squeeze=False,
    )
    u = np.linspace(0, 1, grids[0].shape[0])
    for i, (row, z) in enumerate(zip(runs, grids)):
        for j in range(cols):
            ax = axes[i, j]
            if j >= len(row):
                ax.set_visible(False)
                continue
            run = row[j]
            cs = ax.contourf(u, u, z.T, levels=20, cmap="Greys", alpha=0.7)
            ax.scatter(
                run.points[:, 0],
                run.points[:, 1],
                s=9,
                c=np.arange(len(run.points)),
                cmap="plasma",
                label=f"{run.evaluations} evaluations (colour: order)",
            )
            if run.method == "slsqp":
                ax.plot(
                    run.points[:, 0], run.points[:, 1], "-", color="tab:orange", lw=0.8, alpha=0.7
                )
            ax.plot(
                *run.x,
                "r*",
                ms=14,
                mec="w",
                label=f"answer {run.function}({run.x[0]:.3f}, {run.x[1]:.3f}) = {run.value:.4f}",
            )
            ax.set_xlim(-0.03, 1.03)
            ax.set_ylim(-0.03, 1.03)
            ax.set_aspect("equal")
            ax.set_xlabel("x (non-dimensional)")
            ax.set_ylabel("y (non-dimensional)")
            ax.set_title(f"{run.function}(x, y): {run.label}", fontsize=9)
            ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.18), fontsize=7)
        fig.colorbar(cs, ax=list(axes[i]), label=f"{row[0].function}(x, y)", shrink=0.8)
    fig.suptitle(wrap(title))
    return fig
