"""A flight log as the renderer's StateSequence (birdsim.flight.flightstates) and
``birdsim render`` of a log and of a free flight."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim.cli import main
from birdsim.flight.flightlog import load_log
from birdsim.flight.flightstates import flight_states, resample
from birdsim.render.options import RenderOptions


@pytest.fixture(scope="module")
def log(tmp_path_factory):
    path = tmp_path_factory.mktemp("log") / "c.npz"
    assert (
        main(["fly", "cruise", "--out", str(path), "--seconds", str(2 * 2 * math.pi), "--quiet"])
        == 0
    )
    return path


def test_states_resample_the_log(log):
    data = load_log(log)
    opts = RenderOptions(fps=30, beats_per_second=2.0, trail_substeps=4)
    st = flight_states(data, opts)
    assert st.instants_per_frame == 4 and st.frames == 30  # 2 wingbeats at 2 per second, 30 fps
    assert st.qpos.shape == (120, data["qpos"].shape[1])
    # instants on the log's own samples reproduce them; quaternions stay unit
    t_log = data["t"] * float(data["omega"]) / (2 * math.pi)
    k = 16  # instant 16 = 16 / 60 wingbeats: between samples 17 and 18 of 64 per wingbeat
    np.testing.assert_allclose(
        st.qpos[k, :3], resample(t_log, data["qpos"][:, :3], np.array([st.t_beats[k]]))[0]
    )
    np.testing.assert_allclose(np.linalg.norm(st.qpos[:, 3:7], axis=1), 1.0, atol=1e-12)
    assert st.reference_path.shape == (t_log.size, 3)
    lines = " ".join(str(x) for x in st.overlay_at(0))
    assert "position error" in lines and "closed loop" in lines and "saturated" not in lines


def test_render_a_log_and_a_free_flight(log, tmp_path, capsys):
    out = tmp_path / "log.mp4"
    args = ["--size", "64x48", "--fps", "10", "--seconds", "0.3", "--quiet", "--gl", "auto"]
    assert main(["render", str(log), "--out", str(out), *args]) == 0 and out.stat().st_size > 0
    out2 = tmp_path / "fly.mp4"
    assert main(["render", "hover", "--out", str(out2), *args]) == 0 and out2.stat().st_size > 0
    assert "free flight" in capsys.readouterr().out


def test_render_refuses_a_foreign_npz(tmp_path, capsys):
    other = tmp_path / "other.npz"
    np.savez(other, a=np.zeros(2))
    assert main(["render", str(other), "--out", str(tmp_path / "x.mp4")]) == 2
    err = capsys.readouterr().err
    assert "not a birdsim flight log" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "x.mp4").exists()
