"""`birdsim export`: the happy path per format and every bad input as one line, exit 2,
nothing written."""

import sys

import numpy as np
import pytest

from birdsim.cli import main


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("fmt, suffix", [("csv", ".csv"), ("bvh", ".bvh"), ("usd", ".usda")])
def test_export_each_format(tmp_path, capsys, fmt, suffix):
    out = tmp_path / f"cruise{suffix}"
    code, text, err = run(
        capsys, "export", "cruise", "--format", fmt, "--out", str(out), "--seconds", "1"
    )
    assert code == 0, err
    assert out.is_file() and "wrote" in text and "31 frames" in text
    code, _, err = run(
        capsys, "export", "cruise", "--format", fmt, "--out", str(out), "--seconds", "1"
    )
    assert code == 2 and "--force" in err and err.count("\n") == 1


@pytest.mark.parametrize("kinematic", [[], ["--kinematic"]])
def test_seconds_include_both_ends(tmp_path, capsys, kinematic):
    """Free flight (the default, as `birdsim render`) and the prescribed playback alike."""
    out = tmp_path / "c.csv"
    code, text, err = run(
        capsys,
        "export",
        "cruise",
        *kinematic,
        "--format",
        "csv",
        "--out",
        str(out),
        "--seconds",
        "0.5",
    )
    assert code == 0, err
    assert "16 frames" in text and ("model m4" in text) == bool(kinematic)  # m3 in free flight


def test_export_a_flight_log(tmp_path, capsys):
    log = tmp_path / "f.npz"
    assert main(["fly", "hover", "--seconds", "6.3", "--out", str(log), "--quiet"]) == 0
    out = tmp_path / "f.csv"
    code, text, err = run(capsys, "export", str(log), "--format", "csv", "--out", str(out))
    assert code == 0, err
    assert "16 frames" in text  # 6.3 time units = 1.003 wingbeats: 0.5 s at 2 per second, 30 fps
    code, _, err = run(
        capsys,
        "export",
        str(log),
        "--format",
        "csv",
        "--out",
        str(tmp_path / "g.csv"),
        "--kinematic",
    )
    assert code == 2 and "--kinematic does not apply to a flight log" in err


def _bad(tmp_path, capsys, *argv, match):
    code, out, err = run(capsys, "export", *argv)
    assert code == 2, err
    assert match in err and err.count("\n") == 1 and "Traceback" not in err
    assert not [
        p
        for p in tmp_path.rglob("*")
        if p.suffix in (".usd", ".usda", ".bvh", ".csv") or ".partial" in p.name
    ]


def test_bad_inputs(tmp_path, capsys, monkeypatch):
    o = str(tmp_path / "x.usd")
    _bad(
        tmp_path, capsys, "cruise", "--format", "fbx", "--out", o, match="--format 'fbx' is unknown"
    )
    _bad(tmp_path, capsys, "cruise", "--format", "usd", "--out", o, "--fps", "0", match="--fps '0'")
    _bad(tmp_path, capsys, "cruise", "--format", "bvh", "--out", o, match="does not end in .bvh")
    (tmp_path / "ro").mkdir(mode=0o500)
    if not __import__("os").access(tmp_path / "ro", __import__("os").W_OK):  # root writes anywhere
        _bad(
            tmp_path,
            capsys,
            "cruise",
            "--format",
            "usd",
            "--out",
            str(tmp_path / "ro" / "x.usd"),
            match="not writable",
        )
    (tmp_path / "file").write_text("")
    _bad(
        tmp_path,
        capsys,
        "cruise",
        "--format",
        "csv",
        "--out",
        str(tmp_path / "file" / "x.csv"),
        match="cannot be created",
    )
    np.savez(tmp_path / "other.npz", a=np.arange(3))
    _bad(
        tmp_path,
        capsys,
        str(tmp_path / "other.npz"),
        "--format",
        "csv",
        "--out",
        str(tmp_path / "o.csv"),
        match="not a birdsim flight log",
    )
    _bad(
        tmp_path,
        capsys,
        "cruise",
        "--kinematic",
        "--bird",
        "models/pigeon.toml",
        "--format",
        "csv",
        "--out",
        str(tmp_path / "p.csv"),
        match="--table 'tables/m4.npz': table for model m4 was built for bird 'seed', whose reduced bird differs from bird 'pigeon''s",
    )
    _bad(
        tmp_path,
        capsys,
        "cruise",
        "--bird",
        "models/pigeon.toml",
        "--table",
        "tables/seed-m3.npz",
        "--format",
        "csv",
        "--out",
        str(tmp_path / "p.csv"),
        match="reduced bird differs",
    )
    monkeypatch.setitem(sys.modules, "pxr", None)  # usd-core not installed
    _bad(tmp_path, capsys, "cruise", "--format", "usd", "--out", o, match="birdsim[usd]")
