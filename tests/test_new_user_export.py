"""A new user's first hour, continued (tests/test_new_user.py is near its 400 lines): the
frictions met with export, tables and validate (each test fails on the code before its fix).

* ``validate --out`` into a folder that cannot be made is one line before the validation
  (it was a FileNotFoundError traceback after the whole 70 s run).
"""

from __future__ import annotations

from test_new_user import _run  # main(argv) -> (exit status, stdout, stderr lines)


def test_validate_into_a_folder_that_cannot_be_made_is_refused_first(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "a-file").write_text("x")
    code, out, err = _run(["validate", "--out", "a-file/page"], capsys)
    assert code == 2 and len(err) == 1, err
    assert "--out 'a-file/page/index.html' cannot be created: a parent is not a folder" in err[0]
    assert out == "", out  # before: the scorecard's progress, then a traceback
