"""The flight-log reader on a log synthesised in the documented format (issue 9 item 6):
the cruise playback sampled 64 times per wingbeat, as `birdsim fly --out` will write it."""

import numpy as np
import pytest
import tomli_w

from birdsim.errors import BirdsimError
from birdsim.export.flightlog import frames_from_log, read_flight_log
from birdsim.physics.bird import Bird

from export_helpers import BEAT_RATE, FPS, cruise_frames


def synth_log(path, *, beats=4.0, drop=None, extra=None):
    from birdsim.flight.manoeuvre import get_manoeuvre
    from birdsim.flight.playback import play
    from birdsim.tables.lookup import load_table

    bird = Bird()
    t_beats = np.arange(int(beats * 64) + 1) / 64
    pb = play(get_manoeuvre("cruise"), load_table("tables/m4.npz"), t_beats, bird=bird, model="m4")
    x, z = pb.position_seed[:, 0], -pb.position_seed[:, 2]
    data = {
        "t": pb.time, "x": x, "z": z, "vx": pb.velocity_seed[:, 0], "vz": -pb.velocity_seed[:, 2],
        "x_ref": x, "z_ref": z, "pitch": pb.pitch, **pb.params,
        "Fx_demand": pb.demand["Fx"], "Fz_demand": pb.demand["Fz"], "V_air": pb.demand_used["V"],
        "saturated": np.zeros(len(x), dtype=bool), "pitch_moment": np.zeros(len(x)),
        "mass": np.float64(bird.mass), "gravity": np.float64(9.81), "model": np.str_("m4"),
        "bird": np.str_(tomli_w.dumps(bird.to_dict())), "omega": np.float64(bird.omega),
    }
    for k in drop or ():
        data.pop(k)
    data.update(extra or {})
    np.savez(path, **data)
    return path


def test_log_frames_equal_the_playback_frames(tmp_path):
    """Constant cruise: the log, resampled at the export's frames, reproduces the
    playback's qpos (the same body path and the same phase omega t)."""
    log = read_flight_log(synth_log(tmp_path / "cruise.npz"))
    fr = frames_from_log(log, fps=FPS, beat_rate=BEAT_RATE)
    ref = cruise_frames()
    n = fr.frames
    assert n == 61  # 4 wingbeats at 15 frames each, both ends
    assert np.allclose(fr.time, ref.time[:n], atol=1e-12)
    # x of the playback is centred on the manoeuvre, the log starts where the playback does
    assert np.allclose(fr.qpos[:, 0] - fr.qpos[0, 0], ref.qpos[:n, 0] - ref.qpos[0, 0], atol=1e-9)
    assert np.allclose(fr.qpos[:, 1:], ref.qpos[:n, 1:], atol=1e-9)
    assert np.allclose(fr.forces["Fz_achieved"], fr.forces["Fz_demand"], atol=2e-3)


@pytest.mark.parametrize(
    "drop, extra, why",
    [
        (["x"], None, "no 'x'"),
        (["flap_amp"], None, "flap_amp"),
        (["bird"], None, "no 'bird'"),
        (None, {"model": np.str_("m9")}, "m9"),
        (None, {"bird": np.str_("not = [toml")}, "bird TOML"),
        (None, {"z": np.full(3, 1.0)}, "shape"),
        (None, {"omega": np.float64(2.0)}, "omega"),
    ],
)
def test_a_log_from_another_program_is_one_line(tmp_path, drop, extra, why):
    with pytest.raises(BirdsimError, match="not a birdsim flight log") as exc:
        read_flight_log(synth_log(tmp_path / "bad.npz", beats=0.5, drop=drop, extra=extra))
    assert why in str(exc.value)
    assert "\n" not in str(exc.value)


def test_not_an_npz(tmp_path):
    p = tmp_path / "x.npz"
    p.write_text("hello")
    with pytest.raises(BirdsimError, match="not a birdsim flight log"):
        read_flight_log(p)
    with pytest.raises(BirdsimError, match="does not exist"):
        read_flight_log(tmp_path / "missing.npz")
