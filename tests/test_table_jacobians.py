"""Per-cell moments and Jacobians of a lookup table (issue 22, item 4)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from birdsim.cli import main
from birdsim.physics.bird import Bird
from birdsim.physics.moments import wingbeat_moments
from birdsim.tables.jacobians import table_jacobians
from birdsim.tables.lookup import LookupTable, TableError, load_table


@pytest.fixture(scope="module")
def tiny() -> LookupTable:
    """A 2 x 2 x 3 corner of the shipped m3 table (hover to cruise)."""
    t = load_table("tables/m3")
    sl = (slice(4, 6), slice(7, 9), slice(0, 11, 5))
    axes = {a: t.axes[a][s] for a, s in zip(t.axis_names, sl)}
    return LookupTable(
        t.model,
        t.bird,
        t.param_names,
        axes,
        t.params[sl],
        t.cost[sl],
        t.cost_fractions[sl],
        t.achieved[sl],
        t.status_code[sl],
        t.evaluations[sl],
        meta={},
    )


def test_cells_are_wingbeat_moments_of_their_wingbeat(tiny):
    jac = table_jacobians(tiny)
    assert jac.moment_du.shape == tiny.shape + (3, 4)
    assert jac.moment_drate.shape == tiny.shape + (3, 3)
    for idx in [(0, 0, 0), (1, 1, 2), (0, 1, 1)]:
        p = dict(zip(tiny.param_names, map(float, tiny.params[idx])))
        r = wingbeat_moments(tiny.model, p, float(tiny.axes["V"][idx[2]]), jacobians=True)
        np.testing.assert_allclose(jac.moment_du[idx], r.moment_du, rtol=0, atol=1e-12)
        np.testing.assert_allclose(jac.moment_drate[idx], r.moment_drate, rtol=0, atol=1e-12)
        np.testing.assert_allclose(jac.force_body[idx], r.force_body, rtol=0, atol=1e-12)
    # symmetric stored wingbeats: no roll or yaw moment anywhere; roll damping < 0
    assert np.max(np.abs(jac.moment_body[..., [0, 2]])) < 1e-14
    assert np.all(jac.moment_drate[..., 0, 0] < 0)


def test_lookup_interpolates_and_is_exact_at_nodes(tiny):
    jac = tiny.moment_jacobians()
    a = tiny.axes
    at = tiny.lookup_jacobians(a["Fx"][1], a["Fz"][0], a["V"][2])
    np.testing.assert_allclose(at["moment_du"], jac.moment_du[1, 0, 2], rtol=0, atol=1e-15)
    mid = tiny.lookup_jacobians(a["Fx"][0], a["Fz"][0], 0.5 * (a["V"][0] + a["V"][1]))
    want = 0.5 * (jac.moment_drate[0, 0, 0] + jac.moment_drate[0, 0, 1])
    np.testing.assert_allclose(mid["moment_drate"], want, rtol=0, atol=1e-15)


def test_saved_jacobians_load_back_and_another_bird_is_refused(tiny, tmp_path):
    jac = table_jacobians(tiny)
    t = replace(tiny, jacobians=jac)
    t.save(tmp_path / "t")
    back = load_table(tmp_path / "t")
    assert back.jacobians is not None
    np.testing.assert_array_equal(back.jacobians.moment_du, jac.moment_du)
    other = replace(jac, bird=Bird(semispan=1.0, chord=0.5, name="narrow"))
    with pytest.raises(TableError) as exc:
        replace(tiny, jacobians=other)
    assert "reduced bird differs" in str(exc.value) and "\n" not in str(exc.value)
    with pytest.raises(TableError):
        table_jacobians(tiny, Bird(chord=0.5))


def test_old_tables_keep_working_and_get_jacobians_on_first_use(tiny):
    assert tiny.jacobians is None or tiny.jacobians.moment_du.shape[:3] == tiny.shape
    assert tiny.lookup(tiny.axes["Fx"][0], tiny.axes["Fz"][0], 0.0)  # plain lookup unchanged


def test_command_adds_them(tiny, tmp_path, capsys):
    tiny.save(tmp_path / "t")
    assert main(["tables", "jacobians", str(tmp_path / "t.npz"), "--out", str(tmp_path / "j")]) == 0
    assert load_table(tmp_path / "j").jacobians is not None
    assert "moments and Jacobians of 12 cells" in capsys.readouterr().out
    assert main(["tables", "jacobians", str(tmp_path / "t.npz")]) == 2
    assert "needs --force" in capsys.readouterr().err
    assert main(["tables", "jacobians", str(tmp_path / "t.npz"), "--force"]) == 0
    assert load_table(tmp_path / "t").jacobians is not None


def test_a_file_whose_jacobians_belong_to_another_bird_is_refused(tiny, tmp_path, capsys):
    import json

    t = replace(tiny, jacobians=table_jacobians(tiny))
    _, js = t.save(tmp_path / "t")
    meta = json.loads(js.read_text())
    meta["jacobians"]["bird"]["chord"] = 0.5  # another reduced bird (the npz checksum holds)
    js.write_text(json.dumps(meta))
    with pytest.raises(TableError) as exc:
        load_table(tmp_path / "t")
    assert "reduced bird differs" in str(exc.value) and "\n" not in str(exc.value)
    assert main(["tables", "info", str(tmp_path / "t.npz")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "reduced bird differs" in err
