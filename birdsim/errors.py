"""Typed exceptions for user errors.

Every message is one line that names the argument, the value and what is allowed.
The library names its Python arguments and starts the message with the name
(``speed=nan is invalid; ...``, ``model 'm9' is unknown; ...``, ``path='b.toml' does
not exist; ...``); the command line maps that name to the flag the user typed
(``birdsim.cli.FLAG_NAMES``, ``birdsim.commands.common.flag_names``), prints the line
without a traceback and exits with status 2.
"""

from __future__ import annotations


class BirdsimError(ValueError):
    """A user's mistake: bad argument, bad file, bad value."""


class UnknownModelError(BirdsimError):
    """A kinematic model name that does not exist."""


class ParameterError(BirdsimError):
    """A wingbeat parameter that is unknown, missing, NaN or out of bounds."""


class BirdConfigError(BirdsimError):
    """A bird geometry or coefficient that is invalid."""


def check_finite(name: str, value: float, allowed: str = "a finite number") -> float:
    """Return ``float(value)`` or raise naming ``name`` when it is NaN or infinite."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise BirdsimError(f"{name}={value!r} is not a number; allowed: {allowed}") from None
    if v != v or v in (float("inf"), float("-inf")):
        raise BirdsimError(f"{name}={value!r} is not finite; allowed: {allowed}")
    return v
