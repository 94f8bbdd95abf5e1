"""Paths in three dimensions (issue 23 item 1): y and the heading, minimum-jerk in 3-D,
the perch and floor in 3-D, and today's 2-D paths unchanged (bit for bit on one machine, to an ULP across CPUs)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from birdsim.flight.path import (
    PERCH_X,
    PERCH_Z,
    FlightPath,
    PathError,
    PathKeyframe,
)
from birdsim.flight.path_file import load_flight
from birdsim.flight.presets import PATH_PRESETS

TWO_PI = 2 * math.pi
K = PathKeyframe
ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "data" / "paths2d_samples.npz"


def _golden_paths() -> dict[str, FlightPath]:
    """The paths of tests/data/paths2d_samples.npz, written by the code before issue 23
    (the presets, the example path file, and paths with given slopes, dV, x0, a perched
    end in the speed form)."""
    out = dict(PATH_PRESETS)
    out["example:perch-climb-level"] = load_flight(ROOT / "examples" / "perch-climb-level.toml")
    out["zig-position"] = FlightPath(
        "zig",
        7.0,
        False,
        False,
        (K(0, 5.0, x=0.0), K(2, 6.5, x=3.0), K(3.5, 5.5, x=9.0), K(6, 7.0, x=10.0)),
    )
    out["zig-speed"] = FlightPath(
        "zig",
        7.0,
        False,
        False,
        (K(0, 5.0, V=0.2), K(2, 6.5, V=0.6), K(3.5, 5.5, V=0.3), K(6, 7.0, V=0.5)),
    )
    span = 8 * TWO_PI
    out["slopes"] = FlightPath(
        "sl",
        9.0,
        False,
        False,
        (K(0, 4.0, x=0.0, vx=0.5, vz=0.05), K(8, 4.0 + 0.05 * span, x=0.5 * span, vx=0.5, vz=0.05)),
    )
    out["speed-dV"] = FlightPath(
        "dv",
        12.0,
        False,
        True,
        (K(0, 5.0, V=0.4, regime="a"), K(4, 3.0, V=0.3, dV=-0.004), K(11, 1.67, V=0.0)),
        x0=3.0,
    )
    out["x0"] = FlightPath("x0", 5.0, False, False, (K(0, 6.0, V=0.5),), x0=-7.5)
    return out


def test_todays_paths_give_the_same_samples_bit_for_bit():
    ref = np.load(GOLDEN)
    paths = _golden_paths()
    names = {k.split("|")[0] for k in ref.files}
    assert names == set(paths)
    for name, p in paths.items():
        t = ref[f"{name}|t"]
        s = p.sample(t)
        for key in ("x", "z", "vx", "vz", "ax", "az"):
            # bitwise on the machine that stored them; across CPUs numpy's vectorised
            # sin/cos/exp may round differently (seen: 1 ULP in 4 of 405 take-off samples on
            # an AVX-512 Xeon against the AMD machine that wrote the file, and up to 7e-15
            # where a speed-form path integrates them), so 1e-13: a few tens of ULPs of paths
            # tens of semispans long, far below the 1e-9 of the flight's own checks
            np.testing.assert_allclose(
                s[key], ref[f"{name}|{key}"], rtol=0, atol=1e-13, err_msg=f"{name} {key}"
            )
        for key in ("y", "vy", "ay"):
            assert np.all(s[key] == 0.0), (name, key)
        assert list(s)[:6] == ["x", "vx", "ax", "z", "vz", "az"]  # the old keys, first
        st = p.state(float(t[7]))
        assert (st.y, st.vy, st.ay) == (0.0, 0.0, 0.0) and st.x == s["x"][7]


def _sway():
    """A position-form path with a sideways S (y out and back)."""
    return FlightPath(
        "sway",
        9.0,
        False,
        False,
        (
            K(0, 5.0, x=0.0),
            K(3, 5.5, x=6.0, y=2.0),
            K(5, 6.0, x=10.0, y=-1.0, vy=-0.2),
            K(8, 6.0, x=14.0),
        ),
    )


def _bend():
    """A speed-form path that turns: heading 0 -> 1 rad -> -0.5 rad with a given turn rate."""
    return FlightPath(
        "bend",
        13.0,
        False,
        False,
        (
            K(0, 5.0, V=0.3),
            K(3, 5.5, V=0.4, heading=1.0),
            K(6, 6.0, V=0.25, heading=0.2, turn_rate=-0.05),
            K(9, 6.0, V=0.3, heading=-0.5),
            K(12, 6.0, V=0.3),
        ),
        x0=-3.0,
        y0=1.5,
    )


@pytest.mark.parametrize("make", [_sway, _bend])
def test_3d_path_is_c2_with_consistent_derivatives(make):
    # Continuity to 1e-9 across every keyframe (+-1e-10 reduced time: a continuous value
    # moves by |derivative| x 2e-10 < 1e-9, a jump in acceleration of a C1 spline is O(1e-3)).
    # Consistency: velocities and accelerations are central differences of the positions
    # and velocities (step 1e-6, error ~ h^2 x jerk < 1e-8; 1e-7 allowed).
    p = make()
    for k in p.keyframes:
        t = k.t * TWO_PI
        lo, hi = p.sample(t - 1e-10), p.sample(t + 1e-10)
        for name in ("x", "y", "z", "vx", "vy", "vz", "ax", "ay", "az"):
            assert abs(float(hi[name] - lo[name])) < 1e-9, (k.t, name)
    t = np.linspace(-3.0, p.duration + 3.0, 997)
    s, h = p.sample(t), 1e-6
    sp, sm = p.sample(t + h), p.sample(t - h)
    for pos, vel, acc in (("x", "vx", "ax"), ("y", "vy", "ay"), ("z", "vz", "az")):
        np.testing.assert_allclose((sp[pos] - sm[pos]) / (2 * h), s[vel], atol=1e-7)
        np.testing.assert_allclose((sp[vel] - sm[vel]) / (2 * h), s[acc], atol=1e-7)
    assert np.abs(s["ay"]).max() > 1e-3 and np.abs(s["y"]).max() > 0.5  # it does leave the plane


def test_keyframes_are_passed_in_3d():
    p = _sway()
    for k in p.keyframes:
        s = p.state(k.t * TWO_PI)
        assert (s.x, s.y, s.z) == pytest.approx((k.x, k.y or 0.0, k.z), abs=1e-12)
    assert p.state(5 * TWO_PI).vy == pytest.approx(-0.2, abs=1e-15)
    b = _bend()
    assert (b.state(0.0).x, b.state(0.0).y) == (-3.0, 1.5)
    for k, psi in zip(b.keyframes, (0.0, 1.0, 0.2, -0.5, -0.5)):  # a missing heading holds
        s = b.state(k.t * TWO_PI)
        assert math.hypot(s.vx, s.vy) == pytest.approx(k.V, abs=1e-14)
        assert math.atan2(s.vy, s.vx) == pytest.approx(psi, abs=1e-13)
    s6 = b.sample(np.array([6 * TWO_PI - 1e-6, 6 * TWO_PI + 1e-6]))
    rate = np.diff(np.arctan2(s6["vy"], s6["vx"]))[0] / 2e-6
    assert rate == pytest.approx(-0.05, abs=1e-6)


def test_speed_form_track_is_exact_on_a_steady_arc():
    # constant speed and turn rate: the quadrature's track lies on a circle of radius V/w
    # (every sample's centre, p + R n with n the left normal, is the same to 1e-10)
    v, w = 0.4, 0.05
    ks = (
        K(0, 5.0, V=v, heading=0.0),
        K(2, 5.0, V=v, heading=0.5 * w * 2 * TWO_PI, turn_rate=w),
        K(10, 5.0, V=v, heading=0.5 * w * 2 * TWO_PI + w * 8 * TWO_PI, turn_rate=w),
        K(12, 5.0, V=v, heading=w * 10 * TWO_PI),
    )
    p = FlightPath("arc", 12.0, False, False, ks)
    s = p.sample(np.linspace(2 * TWO_PI, 10 * TWO_PI, 301))
    r = v / w
    cx, cy = s["x"] - r * s["vy"] / v, s["y"] + r * s["vx"] / v
    assert np.ptp(cx) < 1e-10 and np.ptp(cy) < 1e-10
    np.testing.assert_allclose(np.hypot(s["ax"], s["ay"]), v * w, rtol=1e-12)


def test_perch_is_an_obstacle_in_3d():
    # beside the perch (y = 1, outside the keep-out) a low pass is allowed; over it, not
    ok = FlightPath(
        "beside", 6.0, False, False, (K(0, 1.2, x=2.0, y=1.0), K(5, 1.2, x=10.0, y=1.0))
    )
    assert ok.state(0.0).y == 1.0
    with pytest.raises(PathError, match=r"through the perch \(within 0.55 of x = 6, y = 0"):
        FlightPath("over", 6.0, False, False, (K(0, 1.2, x=2.0, y=0.3), K(5, 1.2, x=10.0, y=0.3)))
    # a perched end must be at y = 0 too
    with pytest.raises(PathError, match=r"perch_end but keyframe 2 is at x=6, y=0.5"):
        FlightPath(
            "off-perch", 6.0, False, True, (K(0, 4.0, x=0.0), K(5, PERCH_Z, x=PERCH_X, y=0.5))
        )


def test_below_the_floor_in_3d_names_the_keyframe_itself():
    # issue 28 item 3: keyframe 3 is itself below the floor (z = 0.3, clearance 1): it is
    # named, not keyframe 2 before the dip; in the speed form with a heading as well
    with pytest.raises(PathError, match=r"keyframe 3 \(t=4\) is below the floor"):
        FlightPath(
            "low",
            6.0,
            False,
            False,
            (K(0, 4.0, V=0.3), K(2, 3.0, V=0.3, heading=0.5), K(4, 0.3, V=0.3)),
        )
    with pytest.raises(PathError, match=r"segment from keyframe 1 \(t=0\) to keyframe 2"):
        FlightPath(
            "dip", 6.0, False, False, (K(0, 1.2, x=0.0, y=1.0, vz=-0.2), K(5, 1.2, x=10.0, y=1.0))
        )


@pytest.mark.parametrize(
    "kfs, words",
    [
        ((K(0, 4.0, x=0.0, heading=1.0),), ["keyframe 1 gives heading", "position form"]),
        ((K(0, 4.0, V=0.2, y=1.0),), ["keyframe 1 gives y", "speed form"]),
        ((K(0, 4.0, V=0.2, vy=1.0),), ["keyframe 1 gives vy", "speed form"]),
        ((K(0, 4.0, V=0.2), K(3, 4.0, V=0.2, heading=math.nan)), ["keyframe 2 heading=nan"]),
        ((K(0, 4.0, x=0.0, y=math.inf),), ["keyframe 1 y=inf", "allowed: a finite number"]),
        ((K(0, 4.0, V=0.2, turn_rate=0.1), K(3, 4.0, V=0.2)), ["keyframe 1 turn_rate=0.1"]),
    ],
)
def test_bad_3d_keyframes_are_one_line(kfs, words):
    with pytest.raises(PathError) as e:
        FlightPath("bad", 5.0, False, False, kfs)
    text = str(e.value)
    assert "\n" not in text and "allowed" in text
    for w in words:
        assert w in text, text


# ---- files and the command line ---------------------------------------------------------

TURN_FILE = """
name = "bend"
perch = ""
x0 = -3.0
y0 = 1.5
[[keyframe]]
t = 0
V = 0.3
z = 5.0
[[keyframe]]
t = 3
V = 0.4
heading = 1.0
z = 5.5
[[keyframe]]
t = 6
V = 0.25
heading = 0.2
turn_rate = -0.05
z = 6.0
[[keyframe]]
t = 9
V = 0.3
heading = -0.5
z = 6.0
[[keyframe]]
t = 12
V = 0.3
z = 6.0
"""


def test_a_3d_path_file_reads_as_the_same_path(tmp_path):
    f = tmp_path / "bend.toml"
    f.write_text(TURN_FILE)
    p = load_flight(f)
    ref = _bend()
    assert p.keyframes == ref.keyframes and (p.x0, p.y0) == (ref.x0, ref.y0) and p.is_3d
    t = np.linspace(0, ref.duration, 200)
    a, b = p.sample(t), ref.sample(t)
    for key in a:
        np.testing.assert_array_equal(a[key], b[key])
    g = tmp_path / "sway.toml"
    g.write_text(
        "[[keyframe]]\nt = 0\nx = 0\nz = 5\n[[keyframe]]\nt = 3\nx = 6\ny = 2\nvy = 0.1\nz = 5\n"
    )
    assert load_flight(g).state(3 * TWO_PI).y == 2.0


@pytest.mark.parametrize(
    "change, words",
    [
        (
            ("heading = 1.0", 'heading = "north"'),
            ["keyframe 2: heading='north'", "allowed: a finite number of radians"],
        ),
        (("heading = 1.0", "heading = nan"), ["keyframe 2: heading=nan", "radians"]),
        (
            ("heading = 1.0", "bank = 1.0"),
            ["keyframe 2: key 'bank' is unknown", "heading", "turn_rate"],
        ),
        (("turn_rate = -0.05", "turn_rate = true"), ["keyframe 3: turn_rate=True", "allowed"]),
        (
            ("heading = 1.0", "heading = 1.0\ny = 2.0"),
            ["keyframe 2 gives y", "speed form", "allowed"],
        ),
        (("y0 = 1.5", "y0 = inf"), ["y0=inf", "allowed"]),
        (("z = 5.5", "z = 0.4"), ["keyframe 2 (t=3) is below the floor", "allowed"]),
    ],
)
def test_bad_3d_path_files_are_one_line(tmp_path, change, words):
    from birdsim.errors import BirdsimError

    f = tmp_path / "bad.toml"
    f.write_text(TURN_FILE.replace(*change))
    with pytest.raises(BirdsimError) as e:
        load_flight(f)
    text = str(e.value)
    assert "\n" not in text and "bad.toml" in text, text
    for w in words:
        assert w in text, text


def test_the_cli_refuses_a_3d_path_in_one_line_and_writes_nothing(tmp_path, capsys):
    # a posed body cannot bank: fly, render and export refuse a turning path with
    # --attitude posed rather than fly it in the x-z plane (exit 2, one line naming what
    # is allowed); without --attitude they fly it free (tests/test_turning.py,
    # tests/test_render_export_turning.py)
    from birdsim.cli import main
    from birdsim.flight.path_file import get_flight

    f = tmp_path / "bend.toml"
    f.write_text(TURN_FILE)
    out = tmp_path / "log.npz"
    for argv, words in (
        (["fly", str(f), "--attitude", "posed", "--out", str(out)], "cannot bank"),
        (
            ["render", str(f), "--attitude", "posed", "--out", str(tmp_path / "a.mp4")],
            "cannot bank",
        ),
        (
            [
                "export",
                "circle",
                "--format",
                "csv",
                "--out",
                str(tmp_path / "a.csv"),
                "--attitude",
                "posed",
            ],
            "cannot bank",
        ),
    ):
        rc = main(argv)
        err = capsys.readouterr().err.strip()
        assert rc == 2 and len(err.splitlines()) == 1, err
        assert words in err and "allowed" in err, err
    assert sorted(x.name for x in tmp_path.iterdir()) == ["bend.toml"]
    assert get_flight(str(f), turning=True).is_3d  # the controller's way in
