"""Manoeuvre presets (sec. 4.1 regimes, sec. 4.2.3 landing) and user TOML files."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.errors import BirdsimError
from birdsim.flight.manoeuvre import (
    CRUISE_HEIGHT,
    PERCH_HEIGHT,
    PRESETS,
    ManoeuvreError,
    get_manoeuvre,
    load_manoeuvre,
)


def test_presets_are_the_four_regimes():
    assert set(PRESETS) == {"hover", "cruise", "take-off", "landing"}


@pytest.mark.parametrize(
    "name, Fx, Fz, V",
    [("hover", 0.0, -0.5, 0.0), ("cruise", 0.0, -0.2, 0.9)],
)
def test_steady_presets_hold_the_dissertation_demands(name, Fx, Fz, V):
    d = PRESETS[name].demands(np.linspace(0, PRESETS[name].duration, 50))
    # exact: a single keyframe is held
    assert np.all(d["Fx"] == Fx) and np.all(d["Fz"] == Fz) and np.all(d["V"] == V)


def test_take_off_starts_from_rest_with_full_forces_then_eases_to_cruise():
    m = PRESETS["take-off"]
    t = np.linspace(0, m.duration, 400)
    d = m.demands(t)
    assert d["V"][0] == 0 and d["Fx"][0] == 0.5 and d["Fz"][0] == -0.5
    assert np.all(np.diff(d["V"]) >= -1e-12)  # V only rises (PCHIP keeps monotone data monotone)
    assert (
        d["V"][-1] == pytest.approx(0.9)
        and d["Fx"][-1] == pytest.approx(0.0)
        and d["Fz"][-1] == pytest.approx(-0.2)
    )
    assert np.all(np.diff(d["z"]) >= -1e-12) and d["z"][0] == PERCH_HEIGHT and m.perch == "start"


def test_landing_has_rising_negative_forces_and_falling_speed():
    m = PRESETS["landing"]
    t = np.linspace(0, m.duration, 400)
    d = m.demands(t)
    assert d["V"][0] == pytest.approx(0.9) and d["V"][-1] == pytest.approx(0.0, abs=1e-12)
    assert np.all(np.diff(d["V"]) <= 1e-12)
    assert np.all(np.diff(d["Fx"]) <= 1e-12) and d["Fx"][-1] == -0.5  # more and more negative
    assert np.all(np.diff(d["Fz"]) <= 1e-12) and d["Fz"][-1] == -0.5
    assert (
        d["z"][0] == CRUISE_HEIGHT
        and d["z"][-1] == pytest.approx(PERCH_HEIGHT, abs=1e-12)
        and m.perch == "end"
    )
    assert m.regime(0.0) == "cruise" and m.regime(m.duration) == "perched"


def test_demands_are_c1_between_keyframes():
    m = PRESETS["landing"]
    dt = 1e-3
    t = np.arange(0, m.duration, dt)
    for k in ("Fx", "Fz", "V", "z"):
        v = m.demands(t)[k]
        slope = np.diff(v) / dt
        # C1: the slope changes by O(dt) per step; a kink (C0 only) would jump by O(1)
        assert np.max(np.abs(np.diff(slope))) < 50 * dt, k


KEYFRAMES = """
name = "climb"
duration = 6
[[keyframe]]
t = 0
Fx = 0.0
Fz = -0.2
V = 0.9
z = 5.0
regime = "cruise"
[[keyframe]]
t = 4
Fx = 0.1
Fz = -0.45
V = 0.7
"""

COLUMNS = """
name = "climb"
duration = 6
[demands]
t = [0, 4]
Fx = [0.0, 0.1]
Fz = [-0.2, -0.45]
V = [0.9, 0.7]
z = [5.0, 5.0]
"""


def test_user_file_both_forms_agree(tmp_path):
    a, b = tmp_path / "a.toml", tmp_path / "b.toml"
    a.write_text(KEYFRAMES)
    b.write_text(COLUMNS)
    ma, mb = get_manoeuvre(str(a)), load_manoeuvre(b)
    t = np.linspace(0, 6, 31)
    for k in ("Fx", "Fz", "V", "z"):
        np.testing.assert_allclose(ma.demands(t)[k], mb.demands(t)[k], rtol=0, atol=1e-15)
    assert ma.name == "climb" and ma.duration == 6 and ma.keyframes[1].z == 5.0  # z held
    assert ma.regime(5.0) == "cruise"


@pytest.mark.parametrize(
    "text, words",
    [
        ("[[keyframe]]\nt = 0\nFx = 0\nFz = -0.2\n", "V is missing"),
        ("[[keyframe]]\nt = 0\nFx = 0\nFz = -0.2\nV = -1\n", "negative"),
        (
            "[[keyframe]]\nt = 1\nFx = 0\nFz = 0\nV = 0\n[[keyframe]]\nt = 1\nFx = 0\nFz = 0\nV = 0\n",
            "not increasing",
        ),
        ("[[keyframe]]\nt = 0\nFx = 'a'\nFz = 0\nV = 0\n", "not a finite number"),
        ("speed = 3\n[[keyframe]]\nt = 0\nFx = 0\nFz = 0\nV = 0\n", "'speed' is unknown"),
        ("[[keyframe]]\nt = 0\nFx = 0\nFz = 0\nV = 0\nwing = 1\n", "'wing' is unknown"),
        ("name = 'x'\n", "no [[keyframe]] table and no [demands] table"),
        ("[demands]\nt = [0, 1]\nFx = [0]\nFz = [0, 0]\nV = [0, 0]\n", "one length"),
        # a scalar column used to be left out of the message, which listed only t, Fx, Fz
        (
            "[demands]\nt = [0, 1]\nFx = [0, 0]\nFz = [0, 0]\nV = 0.9\n",
            "[demands] V=0.9 is not an array",
        ),
        ("[[keyframe\n", "not valid TOML"),
        # ... and says what is allowed instead (a file of another kind: a .bvh, a log)
        ("[[keyframe\n", "allowed: hover, cruise"),
        # a huge time would make playback sample ~1e11 instants (MemoryError traceback before the fix)
        ("[[keyframe]]\nt = 1e9\nFx = 0\nFz = 0\nV = 0\n", "t <= 10000 wingbeats"),
        (
            "duration = 2e4\n[[keyframe]]\nt = 0\nFx = 0\nFz = 0\nV = 0\n",
            "duration=20000.0; allowed",
        ),
    ],
)
def test_bad_files_give_one_clear_line(tmp_path, text, words):
    p = tmp_path / "bad.toml"
    p.write_text(text)
    with pytest.raises(ManoeuvreError) as exc:
        load_manoeuvre(p)
    msg = str(exc.value)
    assert words in msg and "\n" not in msg and "bad.toml" in msg


def test_unknown_preset_and_missing_file():
    with pytest.raises(
        BirdsimError, match="'hovr' is unknown; allowed: hover, cruise, take-off, landing"
    ):
        get_manoeuvre("hovr")
    with pytest.raises(BirdsimError, match="does not exist"):
        get_manoeuvre("/nonexistent/x.toml")


def test_default_duration_stays_within_the_longest_manoeuvre(tmp_path):
    p = tmp_path / "long.toml"
    p.write_text("[[keyframe]]\nt = 10000\nFx = 0\nFz = 0\nV = 0\n")
    assert load_manoeuvre(p).duration == 10000
