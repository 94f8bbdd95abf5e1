"""Arguments shared by several subcommands: model, bird, NAME=VALUE pairs."""

from __future__ import annotations

import argparse

from birdsim.physics.bird import Bird
from birdsim.errors import BirdsimError


def parse_pairs(pairs: list[str] | None, arg: str) -> dict[str, str]:
    """``["a=1", "b=2"]`` -> ``{"a": "1", "b": "2"}``; one clear line for a malformed pair."""
    out: dict[str, str] = {}
    for pair in pairs or []:
        name, sep, value = pair.partition("=")
        if not sep or not name.strip():
            raise BirdsimError(f"{arg} {pair!r} is malformed; allowed: NAME=VALUE")
        if name.strip() in out:
            raise BirdsimError(f"{arg} {name.strip()} is given twice ({out[name.strip()]!r}, {value.strip()!r}); allowed: once")
        out[name.strip()] = value.strip()
    return out


def add_bird_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--bird", metavar="FILE.toml", help="bird geometry and coefficients (default: the seed bird)")
    p.add_argument("--set", action="append", metavar="NAME=VALUE", help="override one bird field, e.g. strips=20")


def bird_from_args(args: argparse.Namespace) -> Bird:
    bird = Bird.from_toml(args.bird) if getattr(args, "bird", None) else Bird()
    overrides = parse_pairs(getattr(args, "set", None), "--set")
    return bird.with_overrides(overrides) if overrides else bird
