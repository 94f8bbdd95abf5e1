"""Flight paths: through their keyframes, C2, monotone between monotone keyframes, refused
where they hit the floor or the perch."""

import math

import numpy as np
import pytest

from birdsim.flight.path import (
    FLOOR_CLEARANCE,
    PERCH_X,
    PERCH_Z,
    FlightPath,
    PathError,
    PathKeyframe,
    quintic_hermite,
)
from birdsim.flight.presets import PATH_PRESETS

TWO_PI = 2 * math.pi
K = PathKeyframe


def _zigzag(form="position"):
    if form == "position":
        kfs = (K(0, 5.0, x=0.0), K(2, 6.5, x=3.0), K(3.5, 5.5, x=9.0), K(6, 7.0, x=10.0))
    else:
        kfs = (K(0, 5.0, V=0.2), K(2, 6.5, V=0.6), K(3.5, 5.5, V=0.3), K(6, 7.0, V=0.5))
    return FlightPath("zig", 7.0, False, False, kfs)


@pytest.mark.parametrize("form", ["position", "speed"])
def test_passes_through_its_keyframes(form):
    p = _zigzag(form)
    for k in p.keyframes:
        s = p.state(k.t * TWO_PI)
        assert s.z == pytest.approx(k.z, abs=1e-12)
        if form == "position":
            assert s.x == pytest.approx(k.x, abs=1e-12)
        else:
            assert s.vx == pytest.approx(k.V, abs=1e-12)


@pytest.mark.parametrize("form", ["position", "speed"])
def test_is_c2_with_consistent_derivatives(form):
    # Continuity: across every keyframe (and the ends, where it continues at constant
    # velocity) the jumps of x, v, a over +-1e-7 are O(1e-7) (a C1-only spline would jump
    # in acceleration by O(1)). Consistency: v and a equal central differences of x, v
    # (step 1e-6: the jerk jumps at knots, so the difference of v errs by ~h * jump there).
    p = _zigzag(form)
    eps = 1e-7
    for k in p.keyframes:
        t = k.t * TWO_PI
        lo, hi = p.sample(t - eps), p.sample(t + eps)
        for name in ("x", "z", "vx", "vz", "ax", "az"):
            assert abs(float(hi[name] - lo[name])) < 1e-5, (k.t, name)
    t = np.linspace(-3.0, p.duration + 3.0, 997)
    s, h = p.sample(t), 1e-6
    sp, sm = p.sample(t + h), p.sample(t - h)
    for pos, vel, acc in (("x", "vx", "ax"), ("z", "vz", "az")):
        np.testing.assert_allclose((sp[pos] - sm[pos]) / (2 * h), s[vel], atol=1e-7)
        np.testing.assert_allclose((sp[vel] - sm[vel]) / (2 * h), s[acc], atol=1e-7)
    assert np.abs(s["ax"]).max() > 1e-3 and np.abs(s["az"]).max() > 1e-3  # not trivially zero


def test_quintic_hermite_keeps_monotone_data_monotone():
    # Harmonic-mean slopes are at most twice the smaller secant; with zero knot
    # accelerations that keeps each quintic segment monotone (random monotone data).
    from birdsim.flight.path import knot_slopes

    rng = np.random.default_rng(3)
    for _ in range(50):
        t = np.cumsum(rng.uniform(0.2, 3.0, 6))
        y = np.cumsum(rng.uniform(0.0, 2.0, 6))
        pp = quintic_hermite(t, y, knot_slopes(t, y, [None] * 6, ends="level"))
        d = pp(np.linspace(t[0], t[-1], 2001), 1)
        assert d.min() >= -1e-12


def test_hold_and_extrapolation():
    hover = PATH_PRESETS["hover"]
    s = hover.state(123.0)
    assert (s.vx, s.vz, s.ax, s.az) == (0.0, 0.0, 0.0, 0.0)
    cruise = PATH_PRESETS["cruise"]
    a, b = cruise.state(-5.0), cruise.state(cruise.duration + 5.0)
    assert a.vx == pytest.approx(cruise.keyframes[0].V) and b.vx == pytest.approx(
        cruise.keyframes[0].V
    )
    assert b.x - a.x == pytest.approx(cruise.keyframes[0].V * (cruise.duration + 10.0))


def test_perched_ends_are_on_the_perch_at_rest():
    for name, idx in (("take-off", 0), ("landing", -1)):
        p = PATH_PRESETS[name]
        s = p.state(p.keyframes[idx].t * TWO_PI)
        assert (s.x, s.z) == pytest.approx((PERCH_X, PERCH_Z), abs=1e-9)
        assert abs(s.vx) < 1e-12 and abs(s.vz) < 1e-12 and abs(s.ax) < 1e-12 and abs(s.az) < 1e-12


def test_perch_constants_match_the_scene():
    pytest.importorskip("mujoco")
    from birdsim.physics.bird import Bird
    from birdsim.render.renderer import perch_seed_position

    x, z_seed = perch_seed_position("m3", Bird())
    assert (x, -z_seed) == pytest.approx((PERCH_X, PERCH_Z), abs=1e-9)


def test_below_the_floor_is_refused_naming_the_keyframe():
    # keyframe 3 is itself below the floor: it is named, not keyframe 2 before the dip
    with pytest.raises(PathError, match=r"keyframe 3 \(t=6\) is below the floor"):
        FlightPath(
            "dive",
            8.0,
            False,
            False,
            (K(0, 6.0, x=-10.0), K(3, 3.0, x=-5.0), K(6, FLOOR_CLEARANCE - 0.5, x=0.0)),
        )


def test_through_the_perch_is_refused_naming_the_keyframe():
    with pytest.raises(
        PathError,
        match=r"segment from keyframe 1 \(t=0\) to keyframe 2 \(t=5\) goes through the perch",
    ):
        FlightPath("skim", 6.0, False, False, (K(0, 1.2, x=0.0), K(5, 1.2, x=12.0)))
    # the same height clear of the post is fine
    FlightPath("skim", 6.0, False, False, (K(0, 1.2, x=-12.0), K(5, 1.2, x=0.0)))


def test_perch_flags_need_the_perched_keyframe():
    with pytest.raises(PathError, match="perch_end but keyframe 2"):
        FlightPath("miss", 4.0, False, True, (K(0, 6.0, x=0.0), K(3, 4.0, x=PERCH_X)))


@pytest.mark.parametrize(
    "kfs, match",
    [
        ((K(0, 6.0, x=0.0), K(1, 6.0, V=0.5)), "mixes or lacks x and V"),
        ((K(0, 6.0, x=0.0), K(0, 6.0, x=1.0)), "not increasing"),
        ((K(0, 6.0, V=-0.1),), "negative"),
        ((K(0, float("nan"), x=0.0),), "not a finite number"),
    ],
)
def test_bad_keyframes_are_one_line(kfs, match):
    with pytest.raises(PathError, match=match) as exc:
        FlightPath("bad", 4.0, False, False, kfs)
    assert "\n" not in str(exc.value)
