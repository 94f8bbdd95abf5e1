"""Straight flight after a turn (issue 23): the roll and yaw integrals of the attitude
loop are bounded as in straight flight (``attitude.LATERAL_INTEGRAL_RAD``) where a
track's plan is straight, and keep the full bound in a turn; a bird on the fourth-stage
pitch loop (the pigeon) also takes straight flight's time constants there.

Tolerances: which parts of a path count as straight is exact (the plan's bank is 0 to
round-off there); the pigeon's flight is bounded near the measured figures
(docs/turning.md, "Straight flight after a turn"): 90 degrees on R = 50 then 40
wingbeats straight, path RMS after two wingbeats 0.0171 m = 0.052 semispan (bound: the issue
tracking target, 0.1; without the bound the flight diverged at wingbeat 47.8, RMS
7.9), no saturated sample; the same turn on R 55 started 1.91 wingbeats after wingbeat
20 (a flock's centreline place), straight to 81: 0.0122 m = 0.037 semispan (4.1 m RMS,
diverged, with the integrals' bound alone).
"""

from __future__ import annotations

import math

import pytest

from birdsim.flight.attitude import LATERAL_INTEGRAL_RAD
from birdsim.flight.path import FlightPath
from birdsim.flight.presets import CRUISE_SPEED
from birdsim.flight.track import TrackFrame
from birdsim.flight.turn_presets import level_turns
from birdsim.flight.turning import lateral_integral_bound

TWO_PI = 2.0 * math.pi
#: wingbeats of straight flight after the turn (the path ends 2 after the roll-out)
AFTER = 40.0


def _late_turn(delay_beats: float) -> FlightPath:
    from birdsim.flight.path import PathKeyframe
    from birdsim.flight.presets import CRUISE_HEIGHT
    from birdsim.flight.turn_presets import turns_keyframes

    t0 = 20.0 + delay_beats
    ks = turns_keyframes(t0, [0.5 * math.pi], CRUISE_SPEED, 55.0, 6.0, CRUISE_HEIGHT)
    first = PathKeyframe(0.0, CRUISE_HEIGHT, V=CRUISE_SPEED, heading=0.0, turn_rate=0.0)
    x0 = -CRUISE_SPEED * t0 * TWO_PI
    return FlightPath("late-turn", 81.0, False, False, (first, *ks), "", x0=x0)


def _turn_then_straight() -> FlightPath:
    p = level_turns("turn-then-straight", [0.5 * math.pi], CRUISE_SPEED, 50.0, 6.0, "test")
    return FlightPath(
        p.name, p.duration_beats + AFTER - 2.0, False, False, p.keyframes, "", x0=p.x0
    )


def test_the_lateral_integrals_are_bounded_only_where_the_plan_is_straight():
    path = _turn_then_straight()
    track = TrackFrame(path, path.duration_beats * TWO_PI, 1.0)
    turn_end = path.keyframes[-1].t  # the roll-out's end (wingbeats)
    start = path.keyframes[1].t  # the turn-rate ramp's start (wingbeats)
    assert lateral_integral_bound(track, (start - 1.0) * TWO_PI) == LATERAL_INTEGRAL_RAD
    assert lateral_integral_bound(track, (start - 0.4) * TWO_PI) is None  # 0.5 ahead: turning
    assert lateral_integral_bound(track, 0.5 * turn_end * TWO_PI) is None  # mid-turn
    assert lateral_integral_bound(track, (turn_end + 1.0) * TWO_PI) == LATERAL_INTEGRAL_RAD
    assert lateral_integral_bound(track, (turn_end + 30.0) * TWO_PI) == LATERAL_INTEGRAL_RAD


@pytest.mark.slow
@pytest.mark.parametrize("late", [False, True])
def test_the_pigeon_flies_straight_on_after_a_turn(late):
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import fly
    from birdsim.flight.simulate import SimConfig

    bird = load_bird("models/pigeon.toml")
    table = load_table_for(bird, "m3", None)
    path = _late_turn(12.0 / (CRUISE_SPEED * TWO_PI)) if late else _turn_then_straight()
    log = log_arrays(fly(path, table, bird, "m3", config=SimConfig(attitude="free")), "t")
    info = summary(log)
    assert info["saturated_samples"] == 0
    assert info["rms_error_after_start"] / bird.semispan <= 0.1
