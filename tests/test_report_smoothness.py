"""The report's smoothness figure (birdsim/report/smoothness.py) on a tiny table."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.physics.bird import Bird
from birdsim.tables.lookup import AXES, LookupTable


def tiny(zig: bool) -> LookupTable:
    shape = (4, 3, 3)
    axes = {a: np.linspace(0, 1, n) for a, n in zip(AXES, shape)}
    params = np.full(shape + (3,), 0.5)
    if zig:
        params[1, 1, 1, 2] = 0.7  # twist out and back along Fx, Fz and V
    z = np.zeros(shape)
    return LookupTable(
        "base",
        Bird(),
        ("pitch", "flap_amp", "twist_amp"),
        axes,
        params,
        z,
        np.zeros(shape + (4,)),
        np.zeros(shape + (3,)),
        np.zeros(shape, np.uint8),
        np.zeros(shape, np.int64),
    )


def test_zigzags_per_param_and_the_figure(tmp_path):
    pytest.importorskip("matplotlib")
    from birdsim.report.plots import save_png
    from birdsim.report.smoothness import smoothness_figure, zigzags_per_param

    assert zigzags_per_param(tiny(False)) == {"pitch": 0, "flap_amp": 0, "twist_amp": 0}
    assert zigzags_per_param(tiny(True)) == {
        "pitch": 0,
        "flap_amp": 0,
        "twist_amp": 3,
    }  # one triple per axis
    fig = smoothness_figure({"base": tiny(True), "m1": tiny(False)})
    bars = [p.get_height() for p in fig.axes[0].patches]
    # per axis (each axis: base, m1), then all axes: 3 of 18 + 12 + 12 triples for base, none for m1
    assert (
        bars[0:6:2] == pytest.approx([100 / 18, 100 / 12, 100 / 12])
        and bars[1:6:2] == [0, 0, 0]
        and bars[6:] == pytest.approx([100 * 3 / 42, 0.0])
    )
    png = save_png(fig, tmp_path / "s.png")
    assert png.stat().st_size > 1000
