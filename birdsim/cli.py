"""The ``birdsim`` command.  Each subcommand lives in ``birdsim/commands/<name>.py`` and
exposes ``register(subparsers)``; a user's mistake prints one line and exits 2."""

from __future__ import annotations

import argparse
import importlib
import re
import sys

from birdsim.commands.common import StoreOnce, forget_given, translate
from birdsim.errors import BirdsimError

#: Subcommand modules, in the order ``birdsim --help`` lists them.
COMMAND_MODULES = (
    "birdsim.commands.forces",
    "birdsim.commands.examples",
    "birdsim.commands.tables",
    "birdsim.commands.report",
    "birdsim.commands.render",
    "birdsim.commands.fly",
    "birdsim.commands.crosscheck",
    "birdsim.commands.export",
    "birdsim.commands.bird",
    "birdsim.commands.params",
    "birdsim.commands.envelope",
    "birdsim.commands.validate",
    "birdsim.commands.view",
    "birdsim.commands.studio",
)


#: The library names Python arguments at the start of its messages; per subcommand, the
#: flag each one is on the command line (see ``commands.common.translate``).
FLAG_NAMES: dict[str, dict[str, str]] = {
    "forces": {
        "model ": "--model ",
        "parameter ": "--param ",
        "speed=": "--speed=",
        "n=": "--samples ",
    },
    "tables": {
        "model ": "--model ",
        "screen=": "--screen ",
        "starts=": "--starts ",
        "relax=": "--relax ",
        "reach_tol=": "--reach-tol ",
        "cost weight power=": "--power-weight ",
        "cost weight distance=": "--distance ",
        "grid ": "--grid ",
        "Fx=": "--Fx=",
        "Fz=": "--Fz=",
        "V=": "--V=",
        "path (json) ": "--out (json) ",
        "path ": "--out ",
    },
    "render": {"model ": "--model ", "path ": "--out "},
    "report": {"out=": "--out ", "only=": "--only "},
    "crosscheck": {"model ": "--model "},
    "fly": {"model ": "--model "},
    "export": {"model ": "--model "},
    "envelope": {"model ": "--model "},
    "view": {"model ": "--model "},
    "validate": {"model ": "--model "},
    "params": {"model ": "MODEL "},
}
#: Python hints inside a message and their flags.
FLAG_HINTS = {
    "force=True (--force on the command line)": "--force",
    "force=True": "--force",
    "clip=True": "--clip",
}

#: What ``birdsim --help`` says first (the module docstring is for developers).
DESCRIPTION = (
    "Flapping-bird flight after the dissertation: wingbeat forces, optimal-wingbeat tables, "
    "MuJoCo renders of manoeuvres and the analysis report."
)


class _Parser(argparse.ArgumentParser):
    """argparse, but a usage mistake is one line (no usage dump) and exit status 2, and a
    single-valued option given twice is refused (:class:`commands.common.StoreOnce`)."""

    def __init__(self, *args: object, **kwargs: object) -> None:
        super().__init__(*args, **kwargs)  # type: ignore[arg-type]
        self.register("action", None, StoreOnce)
        self.register("action", "store", StoreOnce)

    def error(self, message: str) -> None:  # type: ignore[override]
        self.exit(2, f"{self.prog}: error: {_with_allowed(message)}\n")


#: argparse's word for a value its ``type=`` refused, and what the value should be.
_BAD_TYPE = re.compile(r"^argument (\S+): invalid (int|float) value: (.*)$")
_TYPE_WORDS = {"int": "an integer", "float": "a number"}


def _with_allowed(message: str) -> str:
    """argparse's "argument --jobs: invalid int value: 'abc'" as the project's one line:
    the option, the value and what is allowed."""
    m = _BAD_TYPE.match(message)
    if not m:
        return message
    kind = _TYPE_WORDS[m.group(2)]
    return f"{m.group(1)} {m.group(3)} is not {kind}; allowed: {kind}"


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="birdsim", description=DESCRIPTION)
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    for name in COMMAND_MODULES:
        try:
            module = importlib.import_module(name)
        except ModuleNotFoundError as exc:  # an optional extra is missing
            if exc.name and exc.name.split(".")[0] == "birdsim":
                raise
            continue
        module.register(sub)
    sub.metavar = "{" + ",".join(sub.choices) + "}"  # "required: {forces,...}", not the dest name
    return parser


#: A value that starts like a negative number but is not one (``-3:1:0:0``).
_MINUS_VALUE = re.compile(r"^-(\d|\.\d)")
_NUMBER = re.compile(r"^-(\d+|\d*\.\d+)([eE][-+]?\d+)?$")


def joined_minus_values(argv: list[str]) -> list[str]:
    """``--opt -3:1:0:0`` as ``--opt=-3:1:0:0``: argparse takes a value starting with a
    minus sign for an option unless it is a plain number, and would say only "expected
    one argument"; joined, the option's own check names the value and what is allowed."""
    out: list[str] = []
    for tok in argv:
        prev = out[-1] if out else ""
        if (
            _MINUS_VALUE.match(tok)
            and not _NUMBER.match(tok)
            and prev.startswith("--")
            and "=" not in prev
        ):
            out[-1] = f"{prev}={tok}"
        else:
            out.append(tok)
    return out


def main(argv: list[str] | None = None) -> int:
    try:
        return _main(argv)
    except KeyboardInterrupt:  # Ctrl-C while the commands load (their imports take seconds)
        print("birdsim: interrupted", file=sys.stderr)
        return 130


def _main(argv: list[str] | None) -> int:
    argv = joined_minus_values(sys.argv[1:] if argv is None else list(argv))
    parser = build_parser()
    args, extras = parser.parse_known_args(argv)
    if extras:  # the subcommand's name and its help, not "birdsim: error: ..."
        sub = getattr(args, f"{args.command}_command", None)  # tables build, bird new
        command = f"{args.command} {sub}" if sub else args.command
        parser.exit(
            2,
            f"birdsim {command}: error: unrecognized arguments: {' '.join(extras)}; "
            f"allowed: the options `birdsim {command} --help` lists\n",
        )
    args = forget_given(args)
    try:
        return int(args.func(args) or 0)
    except BirdsimError as exc:
        message = translate(str(exc), FLAG_NAMES.get(args.command, {}), FLAG_HINTS)
        print(f"birdsim {args.command}: error: {message}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"birdsim {args.command}: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
