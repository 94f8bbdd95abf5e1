"""The scorecard's angle-of-attack station (issue 24): the same point of the wing for
every model, ``cp_span_fraction`` of the extended semispan from the shoulder."""

from __future__ import annotations

import dataclasses
import math

import pytest

from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.validation.trim import TrimPoint, angle_of_attack_deg, mid_span_station

BIRD = Bird(semispan=0.33, chord=0.12, hand_chord=0.1, omega=50.0, gravity=9.81)
SHOULDER = {"pitch": 0.2, "flap_amp": 0.9, "twist_amp": 0.3, "stroke_plane": 0.4}
RIGID_HAND = {"wrist_amp": 0.0, "wrist_bias": 0.0, "wrist_lag": 0.0}
NO_FOLD = {"fold_amp": 0.0, "fold_phase": 0.0, "supination_amp": 0.0}


def _point(params: dict[str, float]) -> TrimPoint:
    return TrimPoint(5.0, 0.0, params, True, 0.0, 0.0, 0.0, 1.0)


def test_station_is_mid_semispan_on_the_arm_or_the_hand() -> None:
    # m3: its one panel's control point; m4/m5: half the semispan lies on the arm (2/3)
    assert mid_span_station(get_model("m3"), BIRD) == (0, pytest.approx(0.165, abs=1e-15))
    assert mid_span_station(get_model("m5"), BIRD) == (0, pytest.approx(0.165, abs=1e-15))
    # a hand longer than half the semispan carries the station: 0.5 - 0.4 = 0.1 semispan in
    long_hand = dataclasses.replace(BIRD, hand_span_fraction=0.6)
    panel, r = mid_span_station(get_model("m4"), long_hand)
    assert panel == 1 and r == pytest.approx(0.1 * 0.33, abs=1e-12)


@pytest.mark.parametrize("model, extra", [("m4", RIGID_HAND), ("m5", RIGID_HAND | NO_FOLD)])
def test_rigid_two_panel_wing_reads_the_one_panel_wings_angle(model: str, extra: dict) -> None:
    """With the wrist idle (and m5's fold and supination at 0) the arm and the hand are one
    rigid wing, so m4/m5 must give m3's angle at the same station to round-off (1e-9 deg).
    The first panel's own control point (1/3 semispan, the reading until issue 24's second
    stage) differs from it by degrees here: this test fails on it."""
    bird = dataclasses.replace(BIRD, wrist_twist_ratio=1.0)
    for phase in (0.0, 0.5 * math.pi, math.pi):
        ref = angle_of_attack_deg("m3", bird, _point(dict(SHOULDER)), phase)
        got = angle_of_attack_deg(model, bird, _point(SHOULDER | extra), phase)
        assert got == pytest.approx(ref, abs=1e-9)
