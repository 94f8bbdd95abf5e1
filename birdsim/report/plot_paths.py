"""Figures of the control points' paths and chord lines over a wingbeat (sec. 7 of the
report)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from birdsim.report.plot_base import add_footnote, closed, pyplot, wrap

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from birdsim.report.figdata import ControlPointPaths


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
                closed(coord(p, cx), 0),
                closed(coord(p, cy), 0),
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
            closed(p[:, 0], 0), closed(p[:, 1], 0), closed(-p[:, 2], 0), color=colours[k], lw=2
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
    add_footnote(fig, "body at rest, pitched; paths relative to the shoulder, earth-oriented axes")
    return fig
