"""A new user's first hour, continued (tests/test_new_user.py is near its 400 lines): the
frictions met with export, tables and validate (each test fails on the code before its fix).

* ``validate --out`` into a folder that cannot be made is one line before the validation
  (it was a FileNotFoundError traceback after the whole 70 s run);
* every ``--model`` help lists the models (export, view and validate did not);
* a resumed ``tables build`` says that it reuses the finished parts.
"""

from __future__ import annotations

from test_new_user import (
    _parsers,
    _run,
)  # the subcommands' parsers; main(argv) -> (status, out, err)


def test_validate_into_a_folder_that_cannot_be_made_is_refused_first(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "a-file").write_text("x")
    code, out, err = _run(["validate", "--out", "a-file/page"], capsys)
    assert code == 2 and len(err) == 1, err
    assert "--out 'a-file/page/index.html' cannot be created: a parent is not a folder" in err[0]
    assert out == "", out  # before: the scorecard's progress, then a traceback


def test_every_model_option_lists_the_models():
    for name, parser in _parsers().items():
        for action in parser._actions:
            if "--model" in action.option_strings:
                assert "base, m1, m2, m3, m4" in (action.help or ""), (name, action.help)


def test_a_resumed_table_build_says_so(tmp_path, monkeypatch, capsys):
    """Run the same ``tables build`` again after Ctrl-C: it reused the finished parts and
    said nothing about it; now one stderr line. (The parts are kept here by making the
    first build leave its checkpoint folder, as an interrupted one does.)"""
    from birdsim.tables.checkpoints import Checkpoints

    monkeypatch.chdir(tmp_path)
    argv = ["tables", "build", "--model", "m3", "--size", "2", "--grid", "V=0.5|0.6"]
    argv += ["--out", "t.npz", "--jobs", "1", "--quiet"]
    with monkeypatch.context() as m:
        m.setattr(Checkpoints, "remove", lambda self: None)
        assert _run(argv, capsys)[0] == 0
    assert (tmp_path / ".t.build").is_dir()
    for name in ("t.npz", "t.json"):
        (tmp_path / name).unlink()
    code, out, err = _run(argv, capsys)
    assert code == 0 and out.startswith("wrote t.npz"), err
    assert len(err) == 1 and "resuming: " in err[0] and "'.t.build' are reused" in err[0], err
