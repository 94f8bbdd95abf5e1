import numpy as np
import pytest
from export_helpers import CHECK_FRAMES, FPS, SECONDS, cruise_frames, reference_body_position

from birdsim.errors import BirdsimError
from birdsim.export.frames import FrameSequence, check_fps, is_non_dimensional, time_per_second
from birdsim.physics.bird import Bird


def test_playback_frames_follow_the_playback():
    fr = cruise_frames()
    assert fr.frames == int(SECONDS * FPS) + 1
    assert fr.model == "m4"
    # seed bird at 2 wingbeats per second: one time unit per frame is period * 2 / 30
    assert np.allclose(np.diff(fr.time), Bird().period * 2 / FPS)
    ref = reference_body_position()
    for k in CHECK_FRAMES:
        assert np.allclose(fr.body_position[k], ref[k], atol=1e-12)
    # cruise: the body moves forward at the table's V in bird units per bird time
    v = np.diff(fr.body_position[:, 0]) / np.diff(fr.time)
    assert np.allclose(v, 0.9, rtol=1e-6)
    assert set(fr.params) == {
        "pitch",
        "flap_amp",
        "twist_amp",
        "stroke_plane",
        "wrist_amp",
        "wrist_bias",
        "wrist_lag",
    }


def test_achieved_force_is_the_demand_in_cruise():
    """The table's wingbeat at the cruise demand delivers it (table tolerance 2e-3)."""
    fr = cruise_frames()
    assert np.allclose(fr.forces["Fz_achieved"], fr.forces["Fz_demand"], atol=2e-3)
    assert np.allclose(fr.forces["Fx_achieved"], fr.forces["Fx_demand"], atol=2e-3)


def test_time_per_second():
    assert time_per_second(Bird()) == pytest.approx(2 * Bird().period)
    pigeon = Bird(name="p", rho=1.225, omega=2 * np.pi * 7, semispan=0.33, chord=0.1)
    assert not is_non_dimensional(pigeon)
    assert time_per_second(pigeon) == 1.0  # real time
    assert time_per_second(pigeon, 1.0) == pytest.approx(pigeon.period)


@pytest.mark.parametrize("bad", ["0", "-3", "nan", "x", "1000"])
def test_bad_fps_is_one_line(bad):
    with pytest.raises(BirdsimError, match="--fps"):
        check_fps(bad)


def test_nan_state_is_refused():
    with pytest.raises(BirdsimError, match="NaN"):
        FrameSequence("m4", Bird(), 30.0, np.array([0.0]), np.full((1, 21), np.nan))
