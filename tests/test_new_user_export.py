"""A new user's first hour, continued (tests/test_new_user.py is near its 400 lines): the
frictions met with export, tables and validate (each test fails on the code before its fix).

* ``validate --out`` into a folder that cannot be made is one line before the validation
  (it was a FileNotFoundError traceback after the whole 70 s run);
* every ``--model`` help lists the models (export, view and validate did not).
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
