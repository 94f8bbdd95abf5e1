"""The straight path integral's band includes the side offset
(``path_integral.within_band``'s ``side``; docs/free-body.md, "the side offset in the
band"): the path loop's position error has no lateral part, so during the pigeon's 30 %
side gust the integral ran the whole time and wound its height part up (0.13 -> 1.21),
which held the path out of 0.05 semispan by height (wingbeat-mean +0.030 in wingbeat 12)
after the side offset had come back: back in 10 wingbeats instead of 8."""

from __future__ import annotations

import math

import numpy as np
from test_flown_lateral import _side_gust

from birdsim.flight.path_integral import within_band
from birdsim.physics.bird import Bird


def test_within_band_tests_the_newest_side_offset():
    e = np.array([0.01, -0.02])
    assert within_band(e, 0.1) and within_band(e, 0.1, np.empty((0, 2)))
    assert within_band(e, 0.1, np.array([[0.5, 0.0], [0.09, 1.0]]))  # the newest row only
    assert not within_band(e, 0.1, np.array([[0.0, 0.0], [-0.12, 0.0]]))
    assert not within_band(e, 0.1, np.array([[float("nan"), 0.0]]))


def test_pigeon_side_gust_back_within_eight_wingbeats(monkeypatch):
    bird = Bird.from_toml("models/pigeon.toml")
    err, roll, yaw, _, a = _side_gust(bird, monkeypatch)
    n = int(round(len(a["t"]) / (a["t"][-1] / (2 * math.pi))))
    dz = a["z"] - a["z_ref"]
    z = np.array([dz[b * n : (b + 1) * n].mean() for b in range(len(a["t"]) // n)])
    # the height no longer holds the path out after the side offset is back: wingbeat-mean
    # within 0.02 semispan in wingbeats 12-13 (before: +0.030, +0.016)
    assert np.all(np.abs(z[12:14]) < 0.02), z
    # back (0.05 semispan, 2 degrees) by 8 wingbeats after the gust's end (before: 10)
    back = (err <= 0.05) & (roll <= 2.0) & (yaw <= 2.0)
    assert back[12:].all(), (err, roll, yaw)
