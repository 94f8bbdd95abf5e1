"""LookupTable: interpolation, files, version and mismatch checks, bad input; the
``birdsim tables`` command on a tiny grid."""

from __future__ import annotations

import json

import numpy as np
import pytest

import birdsim
from birdsim.cli import main
from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird
from birdsim.tables.lookup import AXES, LookupTable, TableError, load_table, table_paths


def synthetic(model="base", shape=(3, 4, 5)) -> LookupTable:
    """A table whose parameters are affine in (Fx, Fz, V): multilinear interpolation
    must reproduce them exactly everywhere (an independent check of the lookup)."""
    axes = {
        "Fx": np.linspace(-0.5, 0.5, shape[0]),
        "Fz": np.linspace(-0.5, 0.0, shape[1]),
        "V": np.linspace(0, 1, shape[2]),
    }
    D = np.stack(np.meshgrid(*(axes[a] for a in AXES), indexing="ij"), axis=-1)
    names = birdsim.get_model(model).param_names
    coef = np.resize(
        np.array([[1.0, 0.2, -0.3], [0.5, -1.0, 0.1], [0.0, 0.3, 0.7]]), (len(names), 3)
    )
    params = D @ coef.T + np.resize(np.array([0.8, 0.9, 0.3]), len(names))
    status = np.zeros(shape, dtype=np.uint8)
    status[0, 0, 0] = 1
    return LookupTable(
        model=model,
        bird=Bird(),
        param_names=names,
        axes=axes,
        params=params,
        cost=D[..., 2] ** 2,
        cost_fractions=np.full(shape + (4,), 0.25),
        achieved=D.copy(),
        status_code=status,
        evaluations=np.ones(shape, dtype=np.int64),
        meta={"note": "synthetic"},
    ), coef


def test_lookup_reproduces_an_affine_table_exactly():
    t, coef = synthetic()
    rng = np.random.default_rng(0)
    Fx, Fz, V = rng.uniform(-0.5, 0.5, 200), rng.uniform(-0.5, 0, 200), rng.uniform(0, 1, 200)
    out = t.lookup_many(Fx, Fz, V)
    expect = np.stack([Fx, Fz, V], axis=-1) @ coef.T + np.array([0.8, 0.9, 0.3])
    for k, name in enumerate(t.param_names):
        # 1e-12: multilinear interpolation is exact for affine data up to round-off
        np.testing.assert_allclose(out[name], expect[:, k], atol=1e-12)
    one = t.lookup(0.1, -0.2, 0.3)
    assert set(one) == set(t.param_names) and all(isinstance(v, float) for v in one.values())
    assert one["pitch"] == pytest.approx(float(t.lookup_many(0.1, -0.2, 0.3)["pitch"]), abs=0)


def test_lookup_many_keeps_the_shape_of_its_inputs():
    t, _ = synthetic()
    out = t.lookup_many(np.zeros((4, 2)), -0.25, np.linspace(0, 1, 2))
    assert out["pitch"].shape == (4, 2) and out["achieved_Fz"].shape == (4, 2)
    np.testing.assert_allclose(
        out["achieved_Fz"], -0.25, atol=1e-15
    )  # achieved was the demand here


def test_nodes_are_reproduced():
    t, _ = synthetic()
    i, j, k = 1, 2, 3
    out = t.lookup(t.axes["Fx"][i], t.axes["Fz"][j], t.axes["V"][k])
    np.testing.assert_allclose(list(out.values()), t.params[i, j, k], atol=1e-14)


@pytest.mark.parametrize(
    "axis, kwargs",
    [
        ("Fx", dict(Fx=0.7, Fz=-0.1, V=0.5)),
        ("Fz", dict(Fx=0, Fz=0.1, V=0.5)),
        ("V", dict(Fx=0, Fz=-0.1, V=-0.2)),
    ],
)
def test_outside_the_grid_names_axis_value_and_range(axis, kwargs):
    t, _ = synthetic()
    with pytest.raises(BirdsimError, match=rf"^{axis}=.* is outside the table grid; allowed: \["):
        t.lookup(**kwargs)
    clipped = t.lookup(**kwargs, clip=True)  # clipping is asked for: edge values
    edge = {a: float(np.clip(kwargs[a], t.axes[a][0], t.axes[a][-1])) for a in AXES}
    assert clipped == t.lookup(**edge)


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), "abc"])
def test_non_finite_demand_raises(bad):
    t, _ = synthetic()
    with pytest.raises(BirdsimError, match="^Fz="):
        t.lookup(Fx=0.0, Fz=bad, V=0.5)
    with pytest.raises(BirdsimError):
        t.lookup_many(np.array([0.0, 0.1]), np.array([-0.1, np.nan]), 0.5)


def test_status_and_model_check():
    t, _ = synthetic()
    assert t.status[0, 0, 0] == "unreachable" and t.status[1, 1, 1] == "ok"
    assert t.status_at(t.axes["Fx"][0], t.axes["Fz"][0], 0.0) == "unreachable"
    assert t.status_at(0.0, -0.2, 0.6) == "ok"
    assert t.status_at(-0.4, -0.45, 0.1) == "unreachable"  # a corner of the surrounding cell
    t.require_model("base")
    with pytest.raises(BirdsimError, match="table is for model 'base', asked to drive model 'm4'"):
        t.require_model("m4")


def test_save_load_round_trip_and_no_silent_overwrite(tmp_path):
    t, _ = synthetic("m3")
    npz, js = t.save(tmp_path / "m3")
    assert (npz.name, js.name) == ("m3.npz", "m3.json")
    for path in (npz, js, tmp_path / "m3"):
        u = load_table(path)
        assert u.model == "m3" and u.param_names == t.param_names and u.bird == t.bird
        for name in ("params", "cost", "cost_fractions", "achieved", "status_code", "evaluations"):
            np.testing.assert_array_equal(getattr(u, name), getattr(t, name))
        assert u.meta["note"] == "synthetic"
    with pytest.raises(BirdsimError, match="exists; allowed: a new path, or force=True"):
        t.save(npz)
    t.save(npz, force=True)
    assert not list(tmp_path.glob(".*partial*"))  # atomic writes leave no temporaries
    assert birdsim.load_table is load_table


def test_mismatched_version_and_unreadable_files(tmp_path):
    t, _ = synthetic()
    npz, js = t.save(tmp_path / "a")
    other, _ = synthetic(shape=(2, 2, 2))
    other.save(tmp_path / "b")
    # swap the arrays of another table in: checksum mismatch
    (tmp_path / "b.npz").replace(npz)
    with pytest.raises(BirdsimError, match="do not belong together"):
        load_table(js)
    t.save(tmp_path / "a", force=True)
    meta = json.loads(js.read_text())
    meta["format_version"] = 99
    js.write_text(json.dumps(meta))
    with pytest.raises(BirdsimError, match="format version 99; this birdsim reads version 1"):
        load_table(npz)
    js.write_text("{not json")
    with pytest.raises(BirdsimError, match="is unreadable"):
        load_table(npz)
    with pytest.raises(BirdsimError, match="does not exist"):
        load_table(tmp_path / "missing.npz")
    assert table_paths("x/y.json") == table_paths("x/y.npz")


def test_inconsistent_arrays_are_refused():
    t, _ = synthetic()
    with pytest.raises(BirdsimError, match="table array cost has shape"):
        LookupTable(
            t.model,
            t.bird,
            t.param_names,
            t.axes,
            t.params,
            t.cost[:1],
            t.cost_fractions,
            t.achieved,
            t.status_code,
            t.evaluations,
        )
    with pytest.raises(
        BirdsimError, match="status_code holds uint8 values in .0, 7.; allowed: integers 0..2"
    ):
        LookupTable(
            t.model,
            t.bird,
            t.param_names,
            t.axes,
            t.params,
            t.cost,
            t.cost_fractions,
            t.achieved,
            t.status_code * 7,
            t.evaluations,
        )
    with pytest.raises(BirdsimError, match="param_names=.* do not match model base"):
        LookupTable(
            t.model,
            t.bird,
            ("a", "b", "c"),
            t.axes,
            t.params,
            t.cost,
            t.cost_fractions,
            t.achieved,
            t.status_code,
            t.evaluations,
        )
    with pytest.raises(BirdsimError, match="table model 'm9' is unknown"):
        LookupTable(
            "m9",
            t.bird,
            t.param_names,
            t.axes,
            t.params,
            t.cost,
            t.cost_fractions,
            t.achieved,
            t.status_code,
            t.evaluations,
        )


def _rewrite_npz(npz, js, edit):
    """Rewrite the .npz through ``edit(arrays)`` and give the .json the matching checksum,
    so that only the content check can catch it."""
    import hashlib
    import io

    with np.load(npz) as z:
        arrays = {k: z[k] for k in z.files}
    edit(arrays)
    buf = io.BytesIO()
    np.savez(buf, **arrays)
    npz.write_bytes(buf.getvalue())
    meta = json.loads(js.read_text())
    meta["npz_sha256"] = hashlib.sha256(buf.getvalue()).hexdigest()
    js.write_text(json.dumps(meta))


def test_consistent_but_corrupt_files_give_one_clear_error(tmp_path):
    t, _ = synthetic()
    npz, js = t.save(tmp_path / "a")
    _rewrite_npz(npz, js, lambda a: a.pop("format_version"))
    with pytest.raises(TableError, match="unreadable or incomplete: missing 'format_version'"):
        load_table(npz)
    t.save(tmp_path / "a", force=True)
    _rewrite_npz(npz, js, lambda a: a.update(status_code=a["status_code"] + 5))
    with pytest.raises(TableError, match="status_code holds"):
        load_table(npz)


# ---- the command ----------------------------------------------------------------------------

GRID = "Fx=0|0.2,Fz=-0.5|-0.2,V=0|0.9"


def test_cli_build_info_lookup(tmp_path, capsys):
    out = tmp_path / "t" / "base.npz"
    assert (
        main(
            [
                "tables",
                "build",
                "--model",
                "base",
                "--grid",
                GRID,
                "--out",
                str(out),
                "--jobs",
                "1",
                "--quiet",
            ]
        )
        == 0
    )
    assert "2x2x2" in capsys.readouterr().out
    assert out.is_file() and out.with_suffix(".json").is_file()
    assert not (tmp_path / "t" / ".base.build").exists()  # checkpoints removed after success
    assert main(["tables", "info", str(out), "--json"]) == 0
    info = json.loads(capsys.readouterr().out)
    assert info["cells"] == 8 and info["model"] == "base"
    # hover at Fz = -0.5 is beyond the base wing (eq. 57: about -0.29): flagged, not hidden
    assert info["status"]["unreachable"] >= 2 and info["unreachable_per_V"]["0"] >= 2
    assert (
        main(["tables", "lookup", str(out), "--Fx", "0", "--Fz", "-0.2", "--V", "0.9", "--json"])
        == 0
    )
    res = json.loads(capsys.readouterr().out)
    assert res["status"] == "ok" and abs(res["achieved_interpolated"]["Fz"] + 0.2) < 1e-6
    assert main(["tables", "info", str(out)]) == 0
    assert "unreachable" in capsys.readouterr().out


@pytest.mark.parametrize(
    "argv, message",
    [
        (["tables", "build", "--model", "m9"], "model 'm9' is unknown"),
        (
            ["tables", "build", "--model", "base", "--grid", "Fx=0:1"],
            "--grid 'Fx=0:1' is malformed",
        ),
        (
            ["tables", "build", "--model", "base", "--grid", "V=1|0"],
            "--grid V=[1.0, 0.0] is invalid",
        ),
        (["tables", "build", "--model", "base", "--grid", "Q=1"], "--grid 'Q=1' is malformed"),
        (["tables", "build", "--model", "base", "--jobs", "0"], "--jobs 0 is invalid"),
        # a count of 1e9 used to exhaust memory (the process was killed) before any check
        (
            ["tables", "build", "--model", "base", "--grid", "Fx=0:1:1000000000"],
            "(2 <= COUNT <= 1000)",
        ),
        (
            ["tables", "build", "--model", "base", "--size", "100000000"],
            "--size 100000000 is invalid",
        ),
        (
            ["tables", "build", "--model", "base", "--grid", "Fx=0:1:1000,Fz=-1:0:1000"],
            "--grid 1000x1000x11 has too many cells",
        ),
        (["tables", "info", "nowhere.npz"], "does not exist"),
    ],
)
def test_cli_bad_input_is_one_line(argv, message, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1 and "Traceback" not in err


def test_cli_lookup_bad_demands(tmp_path, capsys):
    t, _ = synthetic()
    t.save(tmp_path / "s")
    for argv, message in (
        (
            ["--Fx", "0", "--Fz", "-0.1", "--V", "3"],
            "V=3 is outside the table grid; allowed: [0, 1]",
        ),
        (["--Fx", "nan", "--Fz", "-0.1", "--V", "0.5"], "--Fx='nan' is not finite"),
    ):
        assert main(["tables", "lookup", str(tmp_path / "s.npz"), *argv]) == 2
        err = capsys.readouterr().err
        assert message in err and err.count("\n") == 1
    assert (
        main(
            [
                "tables",
                "lookup",
                str(tmp_path / "s.npz"),
                "--Fx",
                "0",
                "--Fz",
                "-0.1",
                "--V",
                "3",
                "--clip",
            ]
        )
        == 0
    )
    (tmp_path / "s.json").write_text("[]")
    assert main(["tables", "info", str(tmp_path / "s.npz")]) == 2
    assert "is unreadable" in capsys.readouterr().err


def test_cli_refuses_to_overwrite(tmp_path, capsys):
    t, _ = synthetic()
    t.save(tmp_path / "base")
    assert main(["tables", "build", "--model", "base", "--out", str(tmp_path / "base.npz")]) == 2
    assert "exists; allowed: a new path, or --force" in capsys.readouterr().err


# ---- the optional climb axis (issue 11) ------------------------------------------------------


def synthetic_climb(shape=(3, 3, 3, 4)) -> tuple[LookupTable, np.ndarray]:
    """A 4-axis table affine in (Fx, Fz, V, climb): reproduced exactly by the lookup."""
    axes = {
        "Fx": np.linspace(-0.5, 0.5, shape[0]),
        "Fz": np.linspace(-0.5, 0.0, shape[1]),
        "V": np.linspace(0, 1, shape[2]),
        "climb": np.linspace(-0.5, 0.5, shape[3]),
    }
    D = np.stack(np.meshgrid(*axes.values(), indexing="ij"), axis=-1)
    coef = np.array([[1.0, 0.2, -0.3, 0.4], [0.5, -1.0, 0.1, -0.2], [0.0, 0.3, 0.7, 0.1]])
    params = D @ coef.T + np.array([0.8, 0.9, 0.3])
    return LookupTable(
        "base",
        Bird(),
        birdsim.get_model("base").param_names,
        axes,
        params,
        D[..., 2] ** 2,
        np.full(shape + (4,), 0.25),
        D[..., :3].copy(),
        np.zeros(shape, np.uint8),
        np.ones(shape, np.int64),
    ), coef


def test_a_climb_axis_is_interpolated_saved_and_loaded(tmp_path):
    t, coef = synthetic_climb()
    assert t.axis_names == ("Fx", "Fz", "V", "climb") and t.has_climb and t.shape == (3, 3, 3, 4)
    rng = np.random.default_rng(1)
    for _ in range(20):
        d = np.array(
            [
                rng.uniform(-0.5, 0.5),
                rng.uniform(-0.5, 0),
                rng.uniform(0, 1),
                rng.uniform(-0.5, 0.5),
            ]
        )
        out = t.lookup(Fx=d[0], Fz=d[1], V=d[2], climb=d[3])
        np.testing.assert_allclose(list(out.values()), coef @ d + [0.8, 0.9, 0.3], atol=1e-12)
    with pytest.raises(
        TableError, match=r"climb=0.7 is outside the table grid; allowed: \[-0.5, 0.5\]"
    ):
        t.lookup(Fx=0, Fz=-0.2, V=0.5, climb=0.7)
    with pytest.raises(TableError, match="climb=nan is not finite"):
        t.lookup(Fx=0, Fz=-0.2, V=0.5, climb=float("nan"))
    npz, js = t.save(tmp_path / "c.npz")
    back = load_table(npz)
    assert back.axis_names == t.axis_names
    np.testing.assert_allclose(
        json.loads(js.read_text())["axes"]["climb"], [-0.5, -1 / 6, 1 / 6, 0.5], atol=1e-15
    )
    np.testing.assert_array_equal(back.params, t.params)
    assert t.status_at(0, -0.25, 0.5, climb=0.1) == "ok"


def test_a_level_flight_table_answers_climb_zero_only():
    t, _ = synthetic()
    assert not t.has_climb and t.axis_names == AXES
    assert t.lookup(Fx=0.1, Fz=-0.2, V=0.3, climb=0.0) == t.lookup(0.1, -0.2, 0.3)
    with pytest.raises(
        TableError,
        match=r"climb=0.1 is outside the table grid; allowed: 0 \(a table without a climb axis",
    ):
        t.lookup(Fx=0.1, Fz=-0.2, V=0.3, climb=0.1)
    assert t.lookup(Fx=0.1, Fz=-0.2, V=0.3, climb=0.1, clip=True) == t.lookup(0.1, -0.2, 0.3)
    with pytest.raises(TableError, match="climb=inf is not finite"):
        t.lookup_many(0.1, -0.2, 0.3, climb=np.inf)
