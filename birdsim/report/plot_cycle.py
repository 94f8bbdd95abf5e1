"""Figures of one wingbeat and of the wingbeat parameters: force and power histories
(sec. 1 of the report), the thrust coefficient (2), and the wrist's lag and bias maps
(3; :func:`maps` draws every 2-D map of the report)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from birdsim.report.plot_base import FORCE_NOTE, ND, add_footnote, closed, pyplot, wrap

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from birdsim.physics.cycle import Cycle
    from birdsim.report.figdata import WristOptimum


# ---- 1. force and power histories ----------------------------------------------------


def histories(cycle: "Cycle", title: str) -> "Figure":
    """Fx, Fz and P over one wingbeat (Figs 12-25).  Several panels: one line each plus
    the total; the dashed line is the cycle mean of the total."""
    plt = pyplot()
    fig, axes = plt.subplots(3, 1, figsize=(10, 8), sharex=True, layout="constrained")
    phase = closed(cycle.time / (cycle.time[1] - cycle.time[0]) / len(cycle.time))
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
            closed(total[key]),
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
                ax.plot(phase, closed(part), lw=1.5, label=f"panel {k + 1} ({name})")
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
    add_footnote(fig, FORCE_NOTE)
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
        add_footnote(fig, footnote)
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
    add_footnote(
        fig, "lag and bias searched on [0, pi/2] (colour scale = that range); " + FORCE_NOTE
    )
    return fig
