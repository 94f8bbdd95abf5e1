"""The wingtip's stroke-plane angle (issue 24): Tobalske & Dial 1996 measure "the
stroke-plane angles of the wingtip ... relative to the horizontal", so the scorecard reads
the tip's own path, not the shoulder's flap plane (the two differ once the tip leaves that
plane: m4's wrist, m5's fold)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.physics.span import tip_span
from birdsim.physics.tip_path import tip_positions, tip_stroke_plane_deg
from birdsim.tables.problem import Solution
from birdsim.validation.trim import TrimPoint, TrimProblem, _point

BIRD = Bird(semispan=0.33, chord=0.12, hand_chord=0.1, omega=50.0, gravity=9.81)
RIGID_HAND = {"wrist_amp": 0.0, "wrist_bias": 0.0, "wrist_lag": 0.0}
NO_FOLD = {"fold_amp": 0.0, "fold_phase": 0.0, "supination_amp": 0.0}


@pytest.mark.parametrize(
    "pitch, stroke_plane", [(0.0, 0.0), (0.2, 0.3), (0.3, 1.0), (1.2, 0.5), (1.5, 1.0)]
)
def test_rigid_wing_tip_path_is_the_flap_plane(pitch: float, stroke_plane: float) -> None:
    """A rigid wing's tip moves in the flap's plane: the angle is 90 - (pitch + stroke
    plane) by hand, to 1e-9 deg, also past the vertical (pitch + stroke plane > 90 deg reads
    as a negative angle, the line tilted the other way) and with the twist on (the tip lies
    on the twist axis)."""
    params = {"pitch": pitch, "flap_amp": 0.8, "twist_amp": 0.4, "stroke_plane": stroke_plane}
    want = 90.0 - math.degrees(pitch + stroke_plane)
    assert tip_stroke_plane_deg("m3", params, bird=BIRD, check_bounds=False) == pytest.approx(
        want, abs=1e-9
    )
    point = TrimPoint(5.0, 0.0, params, True, 0.0, 0.0, 0.0, 1.0)
    assert point.flap_plane_deg == pytest.approx(want, abs=1e-12)  # the formula it replaces
    m5 = params | RIGID_HAND | NO_FOLD
    assert tip_stroke_plane_deg("m5", m5, bird=BIRD, check_bounds=False) == pytest.approx(
        want, abs=1e-9
    )


@pytest.mark.parametrize("pitch", [0.1, 0.25, 0.6])
def test_a_folding_tip_is_read_off_its_own_path(pitch: float) -> None:
    """m5 without a flap, folding only: the elbow and the wrist turn about the wing-plane
    normal (body z with no flap, twist or stroke plane), so the tip moves fore and aft in
    the body's x-y plane, and its side view is a segment along the body axis, pitched up
    by ``pitch``: the rearmost (folded) point is the lowest, so the angle is -pitch (hand
    computed).  The shoulder's flap plane (the formula 90 - pitch) is 90 deg off."""
    params = {"pitch": pitch, "flap_amp": 0.0, "twist_amp": 0.0, "stroke_plane": 0.0}
    params |= RIGID_HAND | {"fold_amp": 0.8, "fold_phase": 0.3, "supination_amp": 0.0}
    x, _, z = tip_positions("m5", params, np.linspace(0, 2 * math.pi, 9), bird=BIRD)
    assert np.ptp(x) > 0.05 * BIRD.semispan and np.max(np.abs(z)) < 1e-14  # moves in x only
    got = tip_stroke_plane_deg("m5", params, bird=BIRD)
    assert got == pytest.approx(-math.degrees(pitch), abs=1e-9)
    formula = TrimPoint(5.0, 0.0, params, True, 0.0, 0.0, 0.0, 1.0).flap_plane_deg
    assert abs(formula - got) > 80.0


def test_the_scorecard_reads_the_tip_of_a_folding_wing() -> None:
    """The trimmed point the scorecard scores (``trim._point``) carries the tip's angle,
    not the flap plane: for a folding m5 wingbeat (the pigeon, 9 m/s) the two differ by
    degrees; before issue 24's tip reading the row read the flap plane (this fails)."""
    pigeon = Bird.from_toml(Path(__file__).resolve().parents[1] / "models" / "pigeon.toml")
    m5 = get_model("m5")
    params = {"pitch": 0.05, "flap_amp": 0.5, "twist_amp": 0.2, "stroke_plane": 0.35}
    params |= {"wrist_amp": 0.1, "wrist_bias": 0.05, "wrist_lag": 0.3}
    params |= {"fold_amp": 1.0, "fold_phase": -0.9, "supination_amp": 0.0}
    x = np.array([params[n] for n in m5.param_names])
    sol = Solution(x, 0.0, "test", True, "", 0, 0)
    point = _point(TrimProblem(m5, pigeon, 9.0), sol)
    want = tip_stroke_plane_deg(m5, params, bird=pigeon)
    assert point.tip_stroke_plane == want and point.stroke_plane_deg == want
    assert abs(point.flap_plane_deg - want) > 1.0


def test_tip_span_is_twice_the_tip_y() -> None:
    params = {"pitch": 0.2, "flap_amp": 0.9, "twist_amp": 0.3, "stroke_plane": 0.4}
    params |= RIGID_HAND | {"fold_amp": 0.7, "fold_phase": -0.5, "supination_amp": 0.2}
    phases = np.linspace(0.0, 2.0 * math.pi, 7)
    _, y, _ = tip_positions("m5", params, phases, bird=BIRD)
    np.testing.assert_array_equal(tip_span("m5", params, phases, bird=BIRD), 2.0 * y)
