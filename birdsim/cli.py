"""The ``birdsim`` command.  Each subcommand lives in ``birdsim/commands/<name>.py`` and
exposes ``register(subparsers)``; a user's mistake prints one line and exits 2."""

from __future__ import annotations

import argparse
import importlib
import sys

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
    "birdsim.commands.envelope",
)


#: What ``birdsim --help`` says first (the module docstring is for developers).
DESCRIPTION = (
    "Flapping-bird flight after the dissertation: wingbeat forces, optimal-wingbeat tables, "
    "MuJoCo renders of manoeuvres and the analysis report."
)


class _Parser(argparse.ArgumentParser):
    """argparse, but a usage mistake is one line (no usage dump) and exit status 2."""

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
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except BirdsimError as exc:
        print(f"birdsim {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"birdsim {args.command}: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
