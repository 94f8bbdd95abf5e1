"""The ``birdsim`` command.  Each subcommand lives in ``birdsim/commands/<name>.py`` and
exposes ``register(subparsers)``; a user's mistake prints one line and exits 2."""

from __future__ import annotations

import argparse
import importlib
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
        self.exit(2, f"{self.prog}: error: {message}\n")


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


def main(argv: list[str] | None = None) -> int:
    args = forget_given(build_parser().parse_args(argv))
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
