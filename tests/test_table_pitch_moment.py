"""`scripts/table_pitch_moment.py` (docs/turning.md, 2026-12-03, p24f): the demand grid,
the slopes between neighbours, and the map is the attitude loop's ``M_0``."""

from __future__ import annotations

import numpy as np
import pytest
from script_module import load_script


@pytest.fixture(scope="module")
def tpm():
    return load_script("table_pitch_moment")


def test_the_grid_includes_both_ends(tpm):
    assert tpm.grid((-0.1, 0.1, 0.025)) == pytest.approx(np.linspace(-0.1, 0.1, 9))


def test_slopes_of_a_plane_are_its_gradient(tpm):
    fx, fz = np.meshgrid([0.0, 0.025, 0.05], [-0.2, -0.15])
    s = tpm.slopes(0.1 * fx - 0.04 * fz, 0.025, 0.05)
    assert s["median_dFx"] == pytest.approx(0.1) and s["max_dFx"] == pytest.approx(0.1)
    assert s["median_dFz"] == pytest.approx(0.04) and s["max_dFz"] == pytest.approx(0.04)


def test_the_map_is_the_attitude_loop_s_m0(tpm):
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.attitude_jacobians import measured_jacobian
    from birdsim.flight.simulate import FreeBird, SimConfig

    bird = load_bird("models/seed-bird.toml")
    table = load_table_for(bird, "m3", None)
    row = table.lookup(Fx=0.05, Fz=-0.2, V=0.5)
    params = np.array(list(row.values()))
    with FreeBird("m3", bird, params, config=SimConfig(attitude="free")) as fb:
        moment, pitch = tpm.held_moment_map(fb, table, np.array([0.05]), np.array([-0.2]), 0.5)
        m0, _ = measured_jacobian(fb, params, row["pitch"], 0.5)
    assert pitch[0, 0] == row["pitch"]
    assert moment[0, 0] == pytest.approx(m0[1], rel=1e-9, abs=1e-12)
