"""The reachability bounds of issue 23's gust target (`scripts/turn_gust_bound.py`,
docs/turning.md "Gust stage, seventh pass"): the least bang-bang time to rest within a
band, and the turn's lateral loop on a double integrator behind a dead time."""

from __future__ import annotations

import math

import pytest
from script_module import load_script


@pytest.fixture(scope="module")
def bound():
    return load_script("turn_gust_bound")


def test_min_rest_time_is_the_bang_bang_time(bound):
    a = 4e-3
    # at rest 0.1 beyond the band: accelerate half way, brake half way
    assert bound.min_rest_time(0.15, 0.0, a, a, 0.05) == pytest.approx(2 * math.sqrt(0.1 / a))
    # on the path moving at v: braking alone ends exactly at the band's edge
    assert bound.min_rest_time(0.0, 0.02, a, a, 0.05) == pytest.approx(0.02 / a)
    # already at rest inside the band
    assert bound.min_rest_time(0.03, 0.0, a, a, 0.05) == 0.0
    # unequal authorities: towards +y at a, braking at 2a, 0.15 to go
    v = math.sqrt(0.15 / (1 / (2 * a) + 1 / (4 * a)))
    assert bound.min_rest_time(-0.2, 0.0, a, 2 * a, 0.05) == pytest.approx(v / a + v / (2 * a))
    # the mirror image takes the same time with the authorities swapped
    assert bound.min_rest_time(0.2, 0.0, 2 * a, a, 0.05) == pytest.approx(v / a + v / (2 * a))


def test_the_turns_lateral_loop_is_slow_even_without_delay(bound):
    """The turn's triple pole of 6 wingbeats answers a side velocity ``v0`` with
    ``v0 (t - w t^2 / 2) exp(-w t)``, ``w = 1 / (6 x 2 pi)``: its undershoot
    ``0.080 v0 / w`` leaves the band of 0.05 for a long time once ``v0`` exceeds 0.0166;
    4 wingbeats settle within 8; behind a dead time of 2 wingbeats the 4-wingbeat loop
    does not settle at all (the fifth gust pass's model)."""
    big = 1.0  # authority not binding
    t6 = bound.loop_settle_time(0.0, 0.017, 6.0, 0.0, big, big)
    t4 = bound.loop_settle_time(0.0, 0.017, 4.0, 0.0, big, big)
    assert t6 is not None and t6 > 8.0
    assert t4 is not None and t4 < 8.0
    assert bound.loop_settle_time(0.0, 0.017, 4.0, 2.0, big, big) is None
    # a small velocity stays inside: settled from the start
    assert bound.loop_settle_time(0.0, 0.001, 6.0, 0.0, big, big) == 0.0
