"""A turn's roll and yaw allocation weighed per unit inertia
(`birdsim.flight.attitude_reserve.per_inertia`; docs/turning.md, "Gust stage, ninth pass")."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.flight.attitude_reserve import per_inertia
from birdsim.flight.bounded_lsq import bounded_lsq

INERTIA = np.array([0.85, 3.8])  # the seed bird's roll and yaw principal moments


def test_rows_are_weighed_by_the_inertia_ratio_and_the_regularisation_kept():
    a = np.array([[1.0, 2.0], [3.0, 4.0], [0.1, 0.0], [0.0, 0.1]])
    b = np.array([1.0, 2.0, 0.0, 0.0])
    aw, bw = per_inertia(a, b, INERTIA)
    assert np.allclose(aw[0], a[0] * 3.8 / 0.85) and bw[0] == pytest.approx(3.8 / 0.85)
    assert np.array_equal(aw[1:], a[1:]) and np.array_equal(bw[1:], b[1:])  # yaw exactly


def test_a_saturated_allocation_leaves_roll_the_smaller_angular_acceleration_miss():
    """Two inputs at their bounds shared by roll and yaw: weighed as moments the roll
    axis (the lighter) is left a larger angular acceleration miss than weighed per unit
    inertia, which is what the loop's gains are placed in."""
    jac = np.array([[1.0, 0.6], [0.6, 1.0]])  # (roll, yaw) x (two inputs), bounds +-1
    demand = np.array([3.0, -3.0])  # far beyond what the bounds give
    lo, hi = -np.ones(2), np.ones(2)

    def roll_miss(a_aug, b_aug):
        x, _ = bounded_lsq(a_aug, b_aug, lo, hi)
        return abs(jac[0] @ x - demand[0]) / INERTIA[0]

    a_aug = np.vstack([jac, 1e-2 * np.eye(2)])
    b_aug = np.concatenate([demand, np.zeros(2)])
    assert roll_miss(*per_inertia(a_aug, b_aug, INERTIA)) < 0.9 * roll_miss(a_aug, b_aug)


@pytest.mark.slow
def test_the_circle_side_gust_is_nearer_the_calm_flight_eight_wingbeats_after():
    """`birdsim fly circle --attitude free --gust 25:1:0:0.15:0`: the distance from the
    calm flight (semispans, 3-D) over wingbeats 33-35, eight wingbeats after the gust.
    Allocated as moments 0.69 at wingbeat 33, per unit inertia 0.28 (the target, 0.05,
    is not met)."""
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.freeflight import fly, parse_gust
    from birdsim.flight.simulate import SimConfig
    from birdsim.flight.turn_presets import TURN_PRESETS

    bird = load_bird(None)
    table = load_table_for(bird, "m3", None)
    cfg = SimConfig(attitude="free")
    circle = TURN_PRESETS["circle"]
    calm = fly(circle, table, bird, "m3", config=cfg, beats=35).arrays
    gust = [parse_gust("25:1:0:0.15:0")]
    g = fly(circle, table, bird, "m3", config=cfg, beats=35, gusts=gust).arrays
    n = min(len(calm["t"]), len(g["t"]))
    d = np.sqrt(sum((g[k][:n] - calm[k][:n]) ** 2 for k in ("x", "y", "z")))
    late = calm["t"][:n] / (2 * np.pi) >= 33.0
    assert late.any() and np.all(np.isfinite(d))
    assert d[late].max() < 0.45
