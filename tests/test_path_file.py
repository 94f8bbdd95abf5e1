"""Manoeuvre files: path files load as FlightPath, force-keyframe files still load as Manoeuvre."""

import math

import pytest

from birdsim.flight.manoeuvre import Manoeuvre, ManoeuvreError
from birdsim.flight.path import PERCH_X, PERCH_Z, FlightPath, PathError
from birdsim.flight.path_file import get_flight, load_flight
from birdsim.flight.presets import PATH_PRESETS


def _write(tmp_path, text, name="m.toml"):
    p = tmp_path / name
    p.write_text(text)
    return p


def test_presets_by_name_are_paths():
    for name in ("hover", "cruise", "take-off", "landing"):
        assert get_flight(name) is PATH_PRESETS[name]


def test_position_path_file(tmp_path):
    p = _write(
        tmp_path,
        """
name = "hop"
perch = "start"
duration = 9
[[keyframe]]
t = 0
x = 6.0
z = 1.67
regime = "take-off"
[[keyframe]]
t = 8
x = 14.0
z = 4.0
vx = 0.2
""",
    )
    path = load_flight(p)
    assert (
        isinstance(path, FlightPath)
        and path.name == "hop"
        and path.perch_start
        and not path.perch_end
    )
    assert path.duration_beats == 9 and path.regime(0.5) == "take-off"
    s = path.state(8 * 2 * math.pi)
    assert (s.x, s.z, s.vx) == pytest.approx((14.0, 4.0, 0.2), abs=1e-12)


def test_speed_path_file_ending_on_the_perch(tmp_path):
    p = _write(
        tmp_path,
        """
perch = "end"
[[keyframe]]
t = 0
V = 0.4
z = 5.0
[[keyframe]]
t = 10
V = 0.0
z = 1.67
""",
    )
    path = load_flight(p)
    assert path.name == "m" and path.duration_beats == 11 and path.form == "speed"
    s = path.state(10 * 2 * math.pi)
    assert (s.x, s.z, s.vx) == pytest.approx((PERCH_X, PERCH_Z, 0.0), abs=1e-9)


def test_force_keyframe_files_still_load_as_manoeuvres(tmp_path):
    kf = _write(
        tmp_path,
        """
[[keyframe]]
t = 0
Fx = 0.0
Fz = -0.2
V = 0.9
""",
        "old.toml",
    )
    cols = _write(
        tmp_path,
        """
[demands]
t = [0, 4]
Fx = [0, 0]
Fz = [-0.2, -0.3]
V = [0.9, 0.9]
""",
        "cols.toml",
    )
    for p in (kf, cols):
        m = get_flight(str(p))
        assert isinstance(m, Manoeuvre)


@pytest.mark.parametrize(
    "text, err, match",
    [
        ("[[keyframe]]\nt = 0\nz = 6\nq = 1\nx = 0\n", ManoeuvreError, "key 'q' is unknown"),
        ("[[keyframe]]\nt = 0\nx = 0\n", ManoeuvreError, "z is missing"),
        (
            "[[keyframe]]\nt = 0\nx = 0\nz = 'high'\n",
            ManoeuvreError,
            "z='high' is not a finite number",
        ),
        ("perch = 'top'\n[[keyframe]]\nt = 0\nx = 0\nz = 6\n", ManoeuvreError, "perch='top'"),
        (
            "[[keyframe]]\nt = 0\nx = 0\nz = 6\n[[keyframe]]\nt = 4\nx = 10\nz = 0.2\n",
            PathError,
            r"keyframe 2 \(t=4\) is below the floor",  # the keyframe that is itself below
        ),
        (
            "[[keyframe]]\nt = 0\nx = 0\nz = 1.0\n[[keyframe]]\nt = 4\nx = 12\nz = 1.0\n",
            PathError,
            "through the perch",
        ),
        ("nonsense = [", ManoeuvreError, "not valid TOML"),
    ],
)
def test_bad_files_are_one_line(tmp_path, text, err, match):
    p = _write(tmp_path, text)
    with pytest.raises(err, match=match) as exc:
        load_flight(p)
    assert "\n" not in str(exc.value) and str(p) in str(exc.value)


def test_unknown_name():
    with pytest.raises(
        ManoeuvreError, match="'loop' is unknown; allowed: hover, cruise, take-off, landing"
    ):
        get_flight("loop")
