"""The side gust in the circle: the height's recovery (the path loop's integral held
nearer the path in a cruise turn, ``birdsim.flight.turning.integral_band``;
docs/turning.md, "Gust stage, tenth pass")."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from birdsim.flight.path_integral import INTEGRAL_BAND, TURN_INTEGRAL_BAND, within_band
from birdsim.flight.turning import integral_band


def test_a_cruise_turn_holds_its_path_integral_nearer_the_path_than_straight_flight():
    e = np.array([0.0, 0.05])  # 0.05 semispan below the path
    assert within_band(e, INTEGRAL_BAND)
    assert not within_band(e, TURN_INTEGRAL_BAND)
    cruise, slow = SimpleNamespace(slow_turn=False), SimpleNamespace(slow_turn=True)
    second, fourth = SimpleNamespace(straight=False), SimpleNamespace(straight=True)
    assert integral_band(cruise, second) == TURN_INTEGRAL_BAND < INTEGRAL_BAND
    # straight flight, a slow turn, a rocking bird's turn (the pigeon): straight's band
    for track, att in ((None, fourth), (None, second), (slow, second), (cruise, fourth)):
        assert integral_band(track, att) == INTEGRAL_BAND


@pytest.mark.slow
def test_the_circle_side_gust_leaves_the_height_nearer_the_calm_flight():
    """`birdsim fly circle --attitude free --gust 25.25:1:0:0.15:0` and from 25.5: the
    height difference from the calm flight (semispans) from 8 wingbeats after the gust
    to wingbeat 45.  With straight flight's band (0.1) the integral wound up while the
    lateral transient moved the height and overshot it afterwards: 0.076 / 0.086; held
    within 0.03 of the path: 0.046 / 0.049 (the target, 0.05 in 3-D, is not met: the
    lateral part is 0.17)."""
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.freeflight import fly, parse_gust
    from birdsim.flight.simulate import SimConfig
    from birdsim.flight.turn_presets import TURN_PRESETS

    bird = load_bird(None)
    table = load_table_for(bird, "m3", None)
    cfg = SimConfig(attitude="free")
    circle, beats = TURN_PRESETS["circle"], 45.0
    calm = fly(circle, table, bird, "m3", config=cfg, beats=beats).arrays
    for start in (25.25, 25.5):
        gust = [parse_gust(f"{start}:1:0:0.15:0")]
        g = fly(circle, table, bird, "m3", config=cfg, beats=beats, gusts=gust).arrays
        n = min(len(calm["t"]), len(g["t"]))
        late = calm["t"][:n] / (2 * np.pi) >= start + 8.0
        dz = np.abs(g["z"][:n] - calm["z"][:n])[late]
        assert late.any() and np.all(np.isfinite(dz))
        assert dz.max() < 0.065, (start, float(dz.max()))
