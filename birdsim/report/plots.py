"""Figures of the dissertation's analysis (matplotlib, Agg backend), one function per
figure family.  The numbers come from ``birdsim/report/figdata.py`` (and the tables and
optimisers); these functions only draw.  matplotlib is an optional extra: without it
every function raises one clear :class:`BirdsimError` naming ``pip install birdsim[plots]``.

Every figure labels its axes with units ("rad", or "non-dimensional"), has a legend
where several lines share axes, and a title naming the model and the case.  Forces are
the dissertation's: right wing + body drag in seed axes, where Fz < 0 is up.
"""

from __future__ import annotations

import io
import math
import textwrap
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.io import write_atomic

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from birdsim.physics.cycle import Cycle
    from birdsim.report.figdata import ControlPointPaths, WristOptimum

FORCE_NOTE = "force = right wing + body drag (dissertation force), seed axes, Fz < 0 is up"
ND = "non-dimensional"


def pyplot() -> Any:
    """``matplotlib.pyplot`` on the Agg backend, or one line saying how to install it."""
    try:
        import matplotlib
    except ImportError:
        raise BirdsimError(
            "matplotlib is not installed; the figures need the optional extra: pip install birdsim[plots]"
        ) from None
    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    return plt


def save_png(fig: "Figure", path: Path, dpi: int = 100) -> Path:
    """Render ``fig`` to PNG and write it atomically; the figure is closed."""
    plt = pyplot()
    buf = io.BytesIO()
    try:
        fig.savefig(buf, format="png", dpi=dpi)
    finally:
        plt.close(fig)
    write_atomic(Path(path), buf.getvalue())
    return Path(path)


def wrap(title: str, width: int = 100) -> str:
    """Wrap each line of a title at ``width`` characters."""
    return "\n".join(textwrap.fill(line, width) for line in title.split("\n"))


def _footnote(fig: "Figure", text: str) -> None:
    """A grey line under the axes; the constrained layout keeps a strip free for it."""
    height = fig.get_figheight()
    lines = len(wrap(text, int(fig.get_figwidth() * 15)).splitlines())
    strip = (0.1 + 0.15 * lines) / height  # inches kept free under the axes
    fig.text(
        0.5,
        0.004,
        wrap(text, int(fig.get_figwidth() * 15)),
        ha="center",
        va="bottom",
        fontsize=8,
        color="0.3",
    )
    fig.get_layout_engine().set(rect=(0.0, strip, 1.0, 1.0 - strip))


def _closed(x: np.ndarray, axis: int = -1) -> np.ndarray:
    """Append the first sample at the end (one periodic wingbeat drawn from 0 to T)."""
    first = np.take(x, [0], axis=axis)
    return np.concatenate([x, first], axis=axis)


# ---- 1. force and power histories ----------------------------------------------------


def histories(cycle: "Cycle", title: str) -> "Figure":
    """Fx, Fz and P over one wingbeat (Figs 12-25).  Several panels: one line each plus
    the total; the dashed line is the cycle mean of the total."""
    plt = pyplot()
    fig, axes = plt.subplots(3, 1, figsize=(10, 8), sharex=True, layout="constrained")
    phase = _closed(cycle.time / (cycle.time[1] - cycle.time[0]) / len(cycle.time))
    phase[-1] = 1.0
    drag = float(np.asarray(cycle.body_drag_x))
    total = {
        "Fx": cycle.Fx + drag,
        "Fz": cycle.Fz,
        "P": cycle.P,
    }
    means = {"Fx": float(cycle.mean.Fx), "Fz": float(cycle.mean.Fz), "P": float(cycle.mean.P)}
    labels = {
        "Fx": f"Fx ({ND})",
        "Fz": f"Fz ({ND}, < 0 is up)",
        "P": f"power P ({ND})",
    }
    several = len(cycle.panel_names) > 1
    for ax, key in zip(axes, ("Fx", "Fz", "P")):
        ax.plot(
            phase,
            _closed(total[key]),
            color="k",
            lw=2,
            label="whole wing" + (" + body drag" if key == "Fx" and drag else ""),
        )
        if several:
            for k, name in enumerate(cycle.panel_names):
                part = (
                    cycle.panel_power[k]
                    if key == "P"
                    else cycle.panel_force_earth[k, :, "xyz".index(key[1].lower())]
                )
                ax.plot(phase, _closed(part), lw=1.5, label=f"panel {k + 1} ({name})")
        ax.axhline(means[key], color="k", ls="--", lw=1, label=f"cycle mean = {means[key]:+.3f}")
        ax.axhline(0.0, color="0.7", lw=0.8)
        ax.axvspan(0.0, 0.25, color="0.93", zorder=0)
        ax.axvspan(0.75, 1.0, color="0.93", zorder=0)
        ax.set_ylabel(labels[key])
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("phase t/T (non-dimensional; shaded: downstroke, flap angle increasing)")
    axes[-1].set_xlim(0, 1)
    fig.suptitle(wrap(title))
    _footnote(fig, FORCE_NOTE)
    return fig


# ---- 2. thrust coefficient over advance angle and twist ------------------------------


def thrust_coefficient(
    zeta: np.ndarray, twist: np.ndarray, cfx: np.ndarray, title: str
) -> "Figure":
    """C_Fx (eq. 23) over advance angle (x) and twist (y), the zero contour and the
    line twist = advance angle (Fig 9)."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8, 5.5), layout="constrained")
    lim = float(np.max(np.abs(cfx)))
    cs = ax.contourf(zeta, twist, cfx.T, levels=np.linspace(-lim, lim, 25), cmap="RdBu_r")
    fig.colorbar(cs, ax=ax, label=f"thrust coefficient C_Fx ({ND})")
    ax.contour(zeta, twist, cfx.T, levels=[0.0], colors="k", linewidths=1.5)
    t_max = float(twist[-1])
    ax.plot([0, t_max], [0, t_max], "g--", lw=2, label="twist = advance angle (eq. 17/19)")
    ax.plot([], [], "k-", lw=1.5, label="C_Fx = 0 (positive / negative flight mode)")
    best = twist[np.argmax(cfx, axis=1)]
    ax.plot(zeta, best, "m:", lw=2, label="twist of largest C_Fx at each advance angle")
    ax.set_xlabel("advance angle zeta = atan(w_f / V) (rad)")
    ax.set_ylabel("wing twist theta_f (rad)")
    ax.set_xlim(zeta[0], zeta[-1])
    ax.set_ylim(twist[0], twist[-1])
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title(title)
    return fig


# ---- 3. wrist lag and bias -----------------------------------------------------------


def maps(
    x: np.ndarray,
    y: np.ndarray,
    panels: Sequence[tuple[str, np.ndarray]],
    *,
    x_label: str,
    y_label: str,
    value_label: str,
    title: str,
    mark: str = "max",
    footnote: str | None = None,
    shared_scale: bool = True,
    extra: Sequence[Sequence[tuple[float, float, str]]] | None = None,
) -> "Figure":
    """Side-by-side filled-contour maps of ``value[x, y]`` with the max (or min) marked.

    ``extra`` lists per panel further points ``(x, y, label)`` to mark (e.g. the
    dissertation's optimum)."""
    plt = pyplot()
    n = len(panels)
    fig, axes = plt.subplots(
        1, n, figsize=(4.6 * n + 1.0, 4.6), layout="constrained", squeeze=False
    )
    values = [np.asarray(v) for _, v in panels]
    lo = min(float(np.nanmin(v)) for v in values)
    hi = max(float(np.nanmax(v)) for v in values)
    for k, (ax, (label, v)) in enumerate(zip(axes[0], panels)):
        vlo, vhi = (lo, hi) if shared_scale else (float(np.nanmin(v)), float(np.nanmax(v)))
        levels = np.linspace(vlo, vhi if vhi > vlo else vlo + 1e-12, 21)
        cs = ax.contourf(x, y, v.T, levels=levels, cmap="viridis")
        ax.contour(x, y, v.T, levels=levels[::4], colors="w", linewidths=0.5, alpha=0.6)
        if not shared_scale or k == n - 1:
            fig.colorbar(
                cs,
                ax=ax if not shared_scale else list(axes[0]),
                label=value_label,
                ticks=plt.MaxNLocator(7),
            )
        i, j = np.unravel_index(np.nanargmax(v) if mark == "max" else np.nanargmin(v), v.shape)
        ax.plot(
            x[i],
            y[j],
            "r*",
            ms=14,
            mec="w",
            label=f"{mark} at ({x[i]:.2f}, {y[j]:.2f}) = {v[i, j]:.3g}",
        )
        for px, py, plabel in extra[k] if extra else ():
            ax.plot(px, py, "wo", ms=9, mfc="none", mew=2, label=plabel)
        pad_x, pad_y = 0.03 * np.ptp(x), 0.03 * np.ptp(y)
        ax.set_xlim(x[0] - pad_x, x[-1] + pad_x)  # markers on the edge stay visible
        ax.set_ylim(y[0] - pad_y, y[-1] + pad_y)
        ax.set_xlabel(x_label)
        ax.set_ylabel(y_label)
        ax.set_title(label, fontsize=10)
        ax.legend(loc="best", fontsize=7, framealpha=0.8)
    fig.suptitle(wrap(title))
    if footnote:
        _footnote(fig, footnote)
    return fig


def wrist_optimum(opt: "WristOptimum", title: str) -> "Figure":
    """Fig 27: the best lag and bias (and the upward force there) over the two amplitudes."""
    searched = (
        0.0,
        math.pi / 2,
    )  # colour scale = the searched range, so a constant map looks constant
    panels = [
        ("lag of largest upward force, Delta* (rad)", opt.lag_star, searched),
        ("bias of largest upward force, Psi* (rad)", opt.bias_star, searched),
        (f"largest upward force -Fz ({ND})", opt.upward_max, (None, None)),
    ]
    plt = pyplot()
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.8), layout="constrained")
    for ax, (label, v, (lo, hi)) in zip(axes, panels):
        mesh = ax.pcolormesh(
            opt.flap_amp, opt.wrist_amp, v.T, shading="nearest", cmap="viridis", vmin=lo, vmax=hi
        )
        fig.colorbar(mesh, ax=ax, label=label)
        ax.set_xlabel("shoulder flap amplitude Phi_f (rad)")
        ax.set_ylabel("wrist flap amplitude Phi_w (rad)")
        ax.set_title(label, fontsize=10)
    fig.suptitle(wrap(title))
    _footnote(fig, "lag and bias searched on [0, pi/2] (colour scale = that range); " + FORCE_NOTE)
    return fig


# ---- 7. control-point paths ----------------------------------------------------------


def cp_paths(
    paths: "ControlPointPaths", title: str, chords: int = 16, chord_scale: float = 0.3
) -> "Figure":
    """Figs 41-43, 46-48, 53-55: plan, rear, side and perspective views of every CP
    path with chord lines at ``chords`` instants, relative to the shoulder,
    earth-oriented (X forward, Y right, up = -Z).  Chord lines are drawn at
    ``chord_scale`` of their length (full-length chords hide the paths); the dot marks
    the leading edge."""
    plt = pyplot()
    fig = plt.figure(figsize=(11, 9.5), layout="constrained")
    views = [
        (
            "plan view (from above)",
            1,
            0,
            "Y, right (non-dimensional)",
            "X, forward (non-dimensional)",
        ),
        (
            "rear view (from behind)",
            1,
            2,
            "Y, right (non-dimensional)",
            "up = -Z (non-dimensional)",
        ),
        (
            "side view (from the right)",
            0,
            2,
            "X, forward (non-dimensional)",
            "up = -Z (non-dimensional)",
        ),
    ]
    n = paths.path.shape[1]
    pick = np.unique(np.linspace(0, n, chords, endpoint=False).astype(int))
    colours = ["tab:blue", "tab:orange", "tab:green"]
    centre = paths.path
    lead = centre + chord_scale * (paths.leading - centre)
    trail = centre + chord_scale * (paths.trailing - centre)

    def coord(a: np.ndarray, c: int) -> np.ndarray:
        return -a[..., 2] if c == 2 else a[..., c]

    for v, (name, cx, cy, xl, yl) in enumerate(views):
        ax = fig.add_subplot(2, 2, v + 1)
        for k, pname in enumerate(paths.panel_names):
            p, le, te = centre[k], lead[k], trail[k]
            ax.plot(
                _closed(coord(p, cx), 0),
                _closed(coord(p, cy), 0),
                color=colours[k],
                lw=2,
                label=f"CP path, panel {k + 1} ({pname})",
            )
            for i in pick:
                ax.plot(
                    [coord(te[i], cx), coord(le[i], cx)],
                    [coord(te[i], cy), coord(le[i], cy)],
                    color="0.25",
                    lw=1.0,
                )
                ax.plot(
                    coord(le[i], cx),
                    coord(le[i], cy),
                    "o",
                    color=colours[k],
                    ms=3.5,
                    mec="0.25",
                    mew=0.5,
                )
            ax.plot(
                coord(p[0], cx),
                coord(p[0], cy),
                "k^",
                ms=8,
                label="t = 0 (start of downstroke)" if k == 0 else None,
            )
        ax.plot(
            [],
            [],
            color="0.25",
            lw=1.0,
            marker="o",
            ms=3.5,
            label=f"chord line x {chord_scale:g}, dot = leading edge",
        )
        ax.plot(0, 0, "ks", ms=6, label="shoulder")
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel(xl)
        ax.set_ylabel(yl)
        ax.set_title(name, fontsize=10)
        ax.grid(alpha=0.3)
        if v == 0:
            ax.legend(loc="best", fontsize=7)
    ax3 = fig.add_subplot(2, 2, 4, projection="3d")
    for k in range(len(paths.panel_names)):
        p, le, te = centre[k], lead[k], trail[k]
        ax3.plot(
            _closed(p[:, 0], 0), _closed(p[:, 1], 0), _closed(-p[:, 2], 0), color=colours[k], lw=2
        )
        for i in pick:
            ax3.plot(
                [te[i, 0], le[i, 0]],
                [te[i, 1], le[i, 1]],
                [-te[i, 2], -le[i, 2]],
                color="0.25",
                lw=1.0,
            )
    ax3.plot([0], [0], [0], "ks")
    ax3.set_xlabel("X, forward")
    ax3.set_ylabel("Y, right")
    ax3.zaxis.set_rotate_label(False)
    ax3.set_zlabel("up\n(-Z)")
    for axis in (ax3.xaxis, ax3.yaxis, ax3.zaxis):
        axis.set_major_locator(plt.MaxNLocator(4))
    everything = np.concatenate(
        [a.reshape(-1, 3) for a in (centre, lead, trail)] + [np.zeros((1, 3))]
    )
    ax3.set_box_aspect(tuple(np.ptp(everything, axis=0) + 0.05))
    ax3.view_init(elev=20, azim=-125)
    ax3.set_title("perspective (non-dimensional)", fontsize=10)
    fig.suptitle(wrap(title))
    _footnote(fig, "body at rest, pitched; paths relative to the shoulder, earth-oriented axes")
    return fig


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
        _footnote(fig, footnote)
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
        _footnote(fig, footnote)
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
    _footnote(fig, note + ("; " + footnote if footnote else ""))
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
