"""Arguments shared by several subcommands: model, bird, NAME=VALUE pairs; and the
translation of the library's Python argument names into the flags the user typed."""

from __future__ import annotations

import argparse
from collections.abc import Iterator, Mapping
from contextlib import contextmanager

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird


def parse_pairs(pairs: list[str] | None, arg: str) -> dict[str, str]:
    """``["a=1", "b=2"]`` -> ``{"a": "1", "b": "2"}``; one clear line for a malformed pair."""
    out: dict[str, str] = {}
    for pair in pairs or []:
        name, sep, value = pair.partition("=")
        if not sep or not name.strip():
            raise BirdsimError(f"{arg} {pair!r} is malformed; allowed: NAME=VALUE")
        if name.strip() in out:
            raise BirdsimError(
                f"{arg} {name.strip()} is given twice ({out[name.strip()]!r}, {value.strip()!r}); allowed: once"
            )
        out[name.strip()] = value.strip()
    return out


def add_bird_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--bird",
        metavar="FILE.toml",
        help="bird geometry and coefficients (default: the seed bird)",
    )
    p.add_argument(
        "--set",
        action="append",
        metavar="NAME=VALUE",
        help="override one bird field, e.g. strips=20",
    )


def translate(
    message: str, starts: Mapping[str, str], hints: Mapping[str, str] | None = None
) -> str:
    """The library's one-line ``message`` as the command line says it.

    The library names Python arguments and starts its messages with them
    (``speed=nan is invalid``, ``model 'm9' is unknown``).  ``starts`` maps such a
    start to the flag the user typed (``{"speed=": "--speed="}``), first match wins;
    ``hints`` replaces a Python hint anywhere in the message (``{"clip=True": "--clip"}``).
    """
    for python, flag in starts.items():
        if message.startswith(python):
            message = flag + message[len(python) :]
            break
    for python, flag in (hints or {}).items():
        message = message.replace(python, flag)
    return message


@contextmanager
def flag_names(starts: Mapping[str, str], hints: Mapping[str, str] | None = None) -> Iterator[None]:
    """Re-raise a :class:`BirdsimError` from the block with its message :func:`translate`-d."""
    try:
        yield
    except BirdsimError as exc:
        exc.args = (translate(str(exc), starts, hints),)
        raise


def bird_from_args(args: argparse.Namespace) -> Bird:
    """The bird of ``--bird FILE.toml`` (default: the seed bird) with ``--set`` applied."""
    with flag_names({"path=": "--bird "}):
        bird = Bird.from_toml(args.bird) if getattr(args, "bird", None) is not None else Bird()
    overrides = parse_pairs(getattr(args, "set", None), "--set")
    with flag_names({"overrides: ": "--set "}):
        return bird.with_overrides(overrides) if overrides else bird
