"""A new user's second hour: the frictions met trying the README's and the docs' commands
and their mistakes (each test fails on the code before its fix).

* ``render``'s non-numbers say what is allowed (``--seconds``, ``--fps``, ``--at``);
* a refused ``render`` prints its one error line and nothing else (the time base was
  printed on stdout before the refusal);
* ``fly flock --attitude posed`` is refused in one line before any bird flies (it printed
  twelve progress lines first);
* ``view`` of a flock preset or file draws every bird (it flew the flock, then stopped on
  a traceback);
* the help texts name every shipped preset and that ``--bird`` takes a shipped bird's name;
* ``view`` says so when the flight it flew saturated, as ``fly`` and ``render`` do;
* an unknown model names ``--model`` in fly, export, envelope and view (as in render);
* a batch (``fly``, ``render``) with a misspelt preset is refused before any flight;
* a missing manoeuvre file lists the turning presets too (as an unknown name does);
* ``tables --help`` names its four subcommands (it said three and named a module);
* ``render LOG.npz`` refuses --model (another), --bird, --table, --kinematic as export does;
* ``--gust -3:1:0:0`` gets the gust's own message (argparse said "expected one argument").
* ``validate --out DIR`` writes its page (a KeyError at the span-ratio trend row);
* ``--legs``/``--strict`` with a flight log (render, export), and every free-flight option
  with ``--kinematic`` (render, export), are refused in one line (they were ignored);
* an unknown model names ``--model`` in validate and ``MODEL`` in params; validate's
  ``--bird`` takes a shipped bird's name; an unknown option names the subcommand and its
  ``--help`` (it said "birdsim: error: unrecognized arguments");
* an option's value of the wrong type (``--jobs abc``) says what is allowed;
* a flight log given as a table is named as given (it named a ``.json`` never typed);
* a refused ``export`` prints only its error (the time base came first), and BVH of the
  base model is refused before the flight (it was refused after flying it);
* Ctrl-C while the commands load is one line and exit 130 (it was a traceback);
* a flock flight shorter than two wingbeats prints no "nan" (it said "RMS nan").
"""

from __future__ import annotations

import argparse
import json
import re

import pytest

from birdsim.cli import build_parser, main
from birdsim.commands.common import FLOCK_LIST, PRESET_LIST
from birdsim.flight.flock import preset_names
from birdsim.flight.presets import PATH_PRESETS
from birdsim.flight.turn_presets import TURN_PRESETS


def _run(argv: list[str], capsys: pytest.CaptureFixture) -> tuple[int, str, list[str]]:
    capsys.readouterr()
    try:
        code = main(argv)
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else 1
    captured = capsys.readouterr()
    return code, captured.out, captured.err.splitlines()


@pytest.mark.parametrize(
    "flags, text",
    [
        (["--seconds", "abc"], "--seconds 'abc' is not a number; allowed: a number in (0, 3600]"),
        (["--fps", "x"], "--fps 'x' is not an integer; allowed: an integer in [1, 240]"),
        (["--still", "s.png", "--at", "abc"], "--at 'abc' is not a number; allowed: a time"),
    ],
)
def test_render_says_what_a_non_number_should_be(flags, text, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    code, _, err = _run(["render", "cruise", "--quiet", *flags], capsys)
    assert code == 2 and len(err) == 1, err
    assert text in err[0], err[0]


@pytest.mark.parametrize(
    "flags", [["--out", "exists.mp4"], ["--camera", "sky"], ["--sheet", "exists.png"]]
)
def test_a_refused_render_prints_only_its_error(flags, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "exists.mp4").write_bytes(b"old")
    (tmp_path / "exists.png").write_bytes(b"old")
    code, out, err = _run(["render", "cruise", "--quiet", *flags], capsys)
    assert code == 2 and len(err) == 1 and err[0].startswith("birdsim render: error:"), err
    assert out == "", out  # before: "birdsim render: time base: ..." and then the refusal
    assert (tmp_path / "exists.mp4").read_bytes() == b"old"


def test_a_posed_flock_on_a_turning_path_is_refused_before_any_bird_flies(capsys):
    code, out, err = _run(["fly", "flock", "--attitude", "posed"], capsys)
    assert code == 2 and len(err) == 1, err
    assert "--attitude posed cannot fly" in err[0] and "allowed: --attitude free" in err[0]
    assert out == ""


def test_view_of_a_flock_file_draws_every_bird(tmp_path, capsys):
    src = tmp_path / "two.toml"
    src.write_text(
        'path = "cruise"\nseconds = 2.0\n'
        "[[bird]]\noffset = [0.0, 0.0, 0.0]\n[[bird]]\noffset = [0.0, 2.0, 0.0]\n"
    )
    page = tmp_path / "two.html"
    code, out, err = _run(["view", str(src), "--out", str(page)], capsys)
    assert code == 0, err
    assert "2 birds" in out and "flown in MuJoCo" in out, out
    html = page.read_text()
    m = re.search(r'<script[^>]*id="birdsim-scene"[^>]*>(.*?)</script>', html, re.S)
    assert m and json.loads(m.group(1))["n_birds"] == 2


def _parsers() -> dict[str, argparse.ArgumentParser]:
    for action in build_parser()._actions:
        if isinstance(action, argparse._SubParsersAction):
            return dict(action.choices)
    raise AssertionError("no subcommands")


def _help_of(parser: argparse.ArgumentParser, dest: str) -> str:
    return next(a.help for a in parser._actions if a.dest == dest) or ""


def test_the_help_names_every_shipped_preset():
    assert PRESET_LIST.split(", ") == [*PATH_PRESETS, *TURN_PRESETS]
    assert FLOCK_LIST.split(", ") == preset_names()
    parsers = _parsers()
    for command, dest in (
        ("fly", "manoeuvre"),
        ("render", "manoeuvre"),
        ("export", "source"),
        ("view", "source"),
    ):
        assert PRESET_LIST in _help_of(parsers[command], dest), command
    for command in ("fly", "view"):  # they fly a flock by its name
        assert FLOCK_LIST in _help_of(parsers[command], {"fly": "manoeuvre"}.get(command, "source"))


def test_every_bird_option_says_it_takes_a_shipped_birds_name():
    for name, parser in _parsers().items():
        helps = [a.help or "" for a in parser._actions if "--bird" in a.option_strings]
        for text in helps:  # validate's names the pigeon as its default
            assert "pigeon" in text, (name, text)


def test_view_says_so_when_the_flight_it_flew_saturated(tmp_path, capsys):
    """A strong updraft the table cannot answer (4 saturated wingbeats, as `birdsim fly
    cruise --gust 3:2:0:0.4` says): the page is written, with the warning fly prints."""
    page = tmp_path / "sat.html"
    code, out, err = _run(["view", "cruise", "--gust", "3:2:0:0.4", "--out", str(page)], capsys)
    assert code == 0 and page.is_file(), err
    assert len(err) == 1 and err[0].startswith("birdsim view: warning: saturated in"), err


@pytest.mark.parametrize(
    "argv",
    [
        ["fly", "cruise"],
        ["envelope"],
        ["export", "cruise", "--format", "csv", "--out", "x.csv"],
        ["view", "cruise", "--out", "x.html"],
    ],
)
def test_an_unknown_model_names_the_flag(argv, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    code, out, err = _run([*argv, "--model", "m9"], capsys)
    assert code == 2 and len(err) == 1, err
    assert ": error: --model 'm9' is unknown; allowed: base, m1" in err[0], err[0]
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("command", ["fly", "render"])
def test_a_misspelt_batch_entry_is_refused_before_any_flight(
    command, tmp_path, monkeypatch, capsys
):
    """Before: entry 0 was flown (and written) and then entry 1 failed."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "batch.txt").write_text("cruise\ncruse\n")
    argv = [command, "--batch", "batch.txt", "--out", "logs", "--quiet", "--jobs", "1"]
    code, out, err = _run(argv, capsys)
    assert code == 2 and len(err) == 1, err
    assert err[0].startswith(f"birdsim {command}: error: entry 1 (cruse): manoeuvre 'cruse'"), err
    assert out == "" and not list(tmp_path.glob("logs*")), out


def test_a_missing_manoeuvre_file_lists_every_preset_it_could_have_been(capsys):
    code, _, err = _run(["fly", "nothing.toml"], capsys)
    assert code == 2 and len(err) == 1, err
    assert f"'nothing.toml' does not exist; allowed: {PRESET_LIST} or a readable" in err[0]


def test_tables_help_names_its_four_subcommands_not_its_modules():
    parser = _parsers()["tables"]
    text = parser.description or ""
    subs = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    assert "build|info|lookup|jacobians" in text and ":mod:" not in text
    assert set(subs.choices) == {"build", "info", "lookup", "jacobians"}


@pytest.fixture(scope="module")
def cruise_log(tmp_path_factory) -> str:
    out = tmp_path_factory.mktemp("log") / "c.npz"
    assert main(["fly", "cruise", "--quiet", "--seconds", "3", "--out", str(out)]) == 0
    return str(out)


@pytest.mark.parametrize(
    "flags, text",
    [
        (["--model", "m4"], "--model 'm4' differs from the log's model 'm3'"),
        (["--bird", "pigeon"], "--bird does not apply to a flight log"),
        (["--table", "t.npz"], "--table does not apply to a flight log"),
        (["--kinematic"], "--kinematic does not apply to a flight log"),
    ],
)
def test_render_of_a_log_refuses_what_the_log_already_says(
    flags, text, cruise_log, tmp_path, monkeypatch, capsys
):
    """As export does; before, render drew the log and ignored them."""
    monkeypatch.chdir(tmp_path)
    code, out, err = _run(["render", cruise_log, "--still", "s.png", *flags], capsys)
    assert code == 2 and len(err) == 1, err
    assert text in err[0] and out == "" and not list(tmp_path.iterdir()), err[0]


def test_a_value_starting_with_a_minus_sign_reaches_its_option(capsys) -> None:
    """``--gust -3:1:0:0`` (space, not ``=``) is checked by the gust's own parser, which
    names the value and what is allowed; plain negative numbers and the other tokens pass
    through unchanged."""
    from birdsim.cli import joined_minus_values

    code, _out, err = _run(["fly", "cruise", "--gust", "-3:1:0:0"], capsys)
    assert code == 2
    assert len(err) == 1 and "--gust '-3:1:0:0'" in err[0] and "allowed" in err[0], err
    assert joined_minus_values(["fly", "--gust", "-3:1", "--seconds", "-3", "-x"]) == [
        "fly",
        "--gust=-3:1",
        "--seconds",
        "-3",
        "-x",
    ]
    assert joined_minus_values(["--gust=-3:1", "-.5:1"]) == ["--gust=-3:1", "-.5:1"]


def test_validate_writes_its_page_with_the_span_ratio_trend(tmp_path, capsys):
    """``birdsim validate --out DIR`` (the README's command): the span-ratio trend row is
    scored in the table; the kinematics figure draws only the trends it has a curve for
    (before: KeyError 'span_ratio_slope', a traceback and no page)."""
    from birdsim.validation.measurements import default_path

    src = default_path().read_text().splitlines()
    keep = [src[0]] + [
        line for line in src[1:] if line.startswith(("TD96_speed_max", "TD96_span_ratio_trend"))
    ]
    data = tmp_path / "trend.csv"
    data.write_text("\n".join(keep) + "\n")
    out = tmp_path / "page"
    code, _, err = _run(["validate", "--data", str(data), "--out", str(out)], capsys)
    assert code == 0, err
    assert (out / "kinematics.png").is_file() and "TD96_span_ratio_trend" in (
        out / "scorecard.json"
    ).read_text()


@pytest.mark.parametrize(
    "argv, text",
    [
        (["export", "LOG", "--format", "csv", "--out", "x.csv", "--legs"], "--legs does not apply"),
        (["export", "LOG", "--format", "csv", "--out", "x.csv", "--strict"], "--strict does not"),
        (["render", "LOG", "--still", "s.png", "--legs"], "--legs does not apply to a flight log"),
        (["render", "LOG", "--still", "s.png", "--strict"], "--strict does not apply"),
        (
            ["export", "cruise", "--kinematic", "--format", "csv", "--out", "x.csv", "--legs"],
            "--legs needs free flight; allowed: omit --legs with --kinematic",
        ),
        (
            ["export", "cruise", "--kinematic", "--format", "csv", "--out", "x.csv", "--strict"],
            "--strict needs free flight",
        ),
        (
            ["render", "cruise", "--kinematic", "--still", "s.png", "--gust", "3:1:0:0.1"],
            "--gust needs free flight",
        ),
        (["render", "take-off", "--kinematic", "--still", "s.png", "--legs"], "--legs needs free"),
    ],
)
def test_a_free_flight_option_is_refused_where_nothing_is_flown(
    argv, text, cruise_log, tmp_path, monkeypatch, capsys
):
    """A flight log was flown already, ``--kinematic`` flies nothing: ``--legs``,
    ``--strict`` (and, for render's playback, ``--gust``...) were silently ignored."""
    monkeypatch.chdir(tmp_path)
    argv = [cruise_log if a == "LOG" else a for a in argv]
    code, out, err = _run(argv, capsys)
    assert code == 2 and len(err) == 1, err
    assert text in err[0] and out == "" and not list(tmp_path.iterdir()), err[0]


@pytest.mark.parametrize(
    "argv, text",
    [
        (["validate", "--model", "M3"], "birdsim validate: error: --model 'M3' is unknown;"),
        (["params", "M4"], "birdsim params: error: MODEL 'M4' is unknown; allowed: base, m1"),
        (
            ["validate", "--bird", "Pigeon"],
            "--bird 'Pigeon' does not exist; allowed: a readable TOML file or a shipped bird (pigeon",
        ),
        (
            ["examples", "--json"],
            "birdsim examples: error: unrecognized arguments: --json; allowed: the options "
            "`birdsim examples --help` lists",
        ),
        (["fly", "cruise", "--log", "c.npz"], "birdsim fly: error: unrecognized arguments: --log"),
        (["tables", "info", "t.npz", "--x"], "birdsim tables info: error: unrecognized arguments"),
    ],
)
def test_a_mistake_names_the_command_and_the_argument(argv, text, tmp_path, monkeypatch, capsys):
    """Before: "model 'M3' is unknown" (no flag), validate's --bird took no shipped name
    (every other --bird does), and an unknown option said "birdsim: error: ..." without
    the subcommand or where to look."""
    monkeypatch.chdir(tmp_path)
    code, out, err = _run(argv, capsys)
    assert code == 2 and len(err) == 1 and out == "", err
    assert text in err[0], err[0]


def test_validate_takes_a_shipped_birds_name(tmp_path, capsys):
    """``--bird pigeon`` from any folder, as every other command's --bird (the refusal
    that follows is the data file's, checked after the bird)."""
    code, _, err = _run(["validate", "--bird", "pigeon", "--data", str(tmp_path / "m.csv")], capsys)
    assert code == 2 and len(err) == 1 and "--data" in err[0], err


@pytest.mark.parametrize(
    "argv, text",
    [
        (["tables", "build", "--model", "m3", "--jobs", "abc"], "--jobs 'abc' is not an integer"),
        (["crosscheck", "--samples", "1.5"], "--samples '1.5' is not an integer; allowed: an"),
        (["tables", "build", "--model", "m3", "--relax", "x"], "--relax 'x' is not a number;"),
    ],
)
def test_an_option_of_the_wrong_type_says_what_is_allowed(argv, text, capsys):
    """Before: argparse's "argument --jobs: invalid int value: 'abc'" (no 'allowed')."""
    code, out, err = _run(argv, capsys)
    assert code == 2 and len(err) == 1 and text in err[0] and "allowed" in err[0], err


def test_a_flight_log_given_as_a_table_is_named(cruise_log, capsys):
    """``tables info LOG.npz``: the line names the file given and says a log is not a
    table (before: "table file 'c.json' does not exist", a file the user never named)."""
    code, out, err = _run(["tables", "info", cruise_log], capsys)
    assert code == 2 and len(err) == 1, err
    assert f"table file {cruise_log!r} has no 'c.json' beside it" in err[0], err[0]
    assert "a flight log is not a table" in err[0]


@pytest.mark.parametrize(
    "flags, text",
    [
        (["--format", "bvh", "--out", "b.bvh", "--model", "base"], "--format bvh cannot carry"),
        (["--format", "bvh", "--out", "b.bvh", "--kinematic", "--model", "base"], "heave slide"),
        (["--format", "csv", "--out", "x.csv", "--seconds", "5000"], "wingbeats of flight"),
        (["--format", "csv", "--out", "x.csv", "--kinematic", "--seconds", "5000"], "(0, 3600]"),
    ],
)
def test_a_refused_export_prints_only_its_error(flags, text, tmp_path, monkeypatch, capsys):
    """As render (above): before, the time base was printed on stdout before the refusal,
    and the base model's BVH was refused only after its whole flight was flown."""
    monkeypatch.chdir(tmp_path)
    code, out, err = _run(["export", "cruise", *flags], capsys)
    assert code == 2 and len(err) == 1 and text in err[0], err
    assert out == "" and not list(tmp_path.iterdir()), out


def test_ctrl_c_while_the_commands_load_is_one_line(monkeypatch, capsys):
    """Ctrl-C in the first seconds (building the parser imports the presets, compiled by
    numba) printed a 60-line traceback; now one line and exit 130, as during the work."""
    import birdsim.cli as cli

    def interrupted() -> argparse.ArgumentParser:
        raise KeyboardInterrupt

    monkeypatch.setattr(cli, "build_parser", interrupted)
    code, out, err = _run(["tables", "build", "--model", "m3"], capsys)
    assert code == 130 and err == ["birdsim: interrupted"] and out == "", err


def test_a_short_flock_flight_prints_no_nan(tmp_path, capsys):
    """A flock file of 2 s (0.3 wingbeats of the seed bird) printed "worst path RMS nan
    semispan"; the JSON says null, the line now says why there is no figure."""
    src = tmp_path / "two.toml"
    src.write_text(
        'path = "cruise"\nseconds = 2.0\n'
        "[[bird]]\noffset = [0.0, 0.0, 0.0]\n[[bird]]\noffset = [0.0, 2.0, 0.0]\n"
    )
    code, out, err = _run(["fly", str(src)], capsys)
    assert code == 0, err
    assert "nan" not in out and "no path RMS (the flight ends within its first 2" in out, out
