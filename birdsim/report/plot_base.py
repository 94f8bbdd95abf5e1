"""What every figure of the report shares: matplotlib on the Agg backend (or one line
saying how to install it), atomic PNG writing, wrapped titles, footnotes, closed
periodic curves, and the notes on forces and units."""

from __future__ import annotations

import io
import textwrap
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.io import write_atomic

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure


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


def add_footnote(fig: "Figure", text: str) -> None:
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


def closed(x: np.ndarray, axis: int = -1) -> np.ndarray:
    """Append the first sample at the end (one periodic wingbeat drawn from 0 to T)."""
    first = np.take(x, [0], axis=axis)
    return np.concatenate([x, first], axis=axis)
