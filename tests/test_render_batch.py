"""``birdsim render`` batches (birdsim/commands/render_batch.py): each entry rendered by
the command itself in a fresh worker, the videos written by the submitting process to
``--out DIR/<index>-<name>.mp4``; a failed entry is one line naming it, the others are
written; a still or a sheet takes one manoeuvre."""

from __future__ import annotations

import pytest

from birdsim.cli import main
from birdsim.errors import BirdsimError
from birdsim.render import gl

try:
    BACKEND = gl.select_gl("auto")
except BirdsimError:
    BACKEND = None


@pytest.mark.skipif(BACKEND is None, reason="no headless OpenGL (libOSMesa or libEGL)")
@pytest.mark.render
@pytest.mark.slow  # a worker process starts and renders (~11 s at load 6)
def test_a_render_batch_writes_every_good_entry(tmp_path, capsys):
    out = tmp_path / "videos"
    argv = ["render", "cruise", "missing.toml", "--kinematic", "--size", "64x48", "--fps", "8"]
    code = main([*argv, "--seconds", "0.25", "--out", str(out), "--jobs", "1"])
    captured = capsys.readouterr()
    err = captured.err.strip().splitlines()
    assert code == 2
    assert len(err) == 1 and "entry 1 (missing.toml)" in err[0]
    assert [p.name for p in out.iterdir()] == ["000-cruise.mp4"]
    assert (out / "000-cruise.mp4").read_bytes()[4:8] == b"ftyp"  # an MP4
    assert "entry 0 cruise: wrote" in captured.out


@pytest.mark.parametrize(
    "argv, words",
    [
        (["cruise", "hover", "--still", "x.png"], "--still/--sheet with a batch"),
        (["cruise", "hover", "--out", "x.mp4"], "is a .mp4 file; allowed: a folder"),
        (["cruise", "--jobs", "x"], "--jobs 'x' is invalid"),
        ([], "no MANOEUVRE"),
    ],
)
def test_bad_render_batch_input_is_one_line(argv, words, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["render", *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0]
    assert not list(tmp_path.rglob("*.mp4"))
