"""Typed exceptions for user errors.

Every message is one line that names the argument, the value and what is allowed.
The library names its Python arguments and starts the message with the name
(``speed=nan is invalid; ...``, ``model 'm9' is unknown; ...``, ``path='b.toml' does
not exist; ...``); the command line maps that name to the flag the user typed
(``birdsim.cli.FLAG_NAMES``, ``birdsim.commands.common.flag_names``), prints the line
without a traceback and exits with status 2.

Numbers are checked here, in one place: :func:`check_finite` (NaN and infinity) and
:func:`check_number` / :func:`check_numbers` (the same plus the magnitude limits below)
for one number or an array.  Every physical number a user gives (a speed, climb, force or
force demand, mass, length, area, density, frequency, gust wind, position or time, in the
bird's reduced units or in SI) must lie within :data:`MAX_MAGNITUDE` in magnitude, and a
quantity that must be positive (a length, a mass, a frequency) at or above
:data:`MIN_POSITIVE`.  The reason is overflow, not physics: the forces go as
``rho V^2 S``, the power as ``rho V^3 S``, MuJoCo's inertias as ``m l^2``; a product of up
to eight numbers inside [1e-6, 1e6] stays inside [1e-48, 1e48], far from float64's
1e+-308, so no warning and no NaN can come out, whereas ``--speed 1e300`` squared is
infinite.  No bird comes near the limits in any unit system (reduced units are of order
one; an SI bird's mass, span and wingbeat frequency are 1e-3..1e2).
"""

from __future__ import annotations

import numpy as np


class BirdsimError(ValueError):
    """A user's mistake: bad argument, bad file, bad value."""


class UnknownModelError(BirdsimError):
    """A kinematic model name that does not exist."""


class ParameterError(BirdsimError):
    """A wingbeat parameter that is unknown, missing, NaN or out of bounds."""


class BirdConfigError(BirdsimError):
    """A bird geometry or coefficient that is invalid."""


#: The largest magnitude any physical number may have (see the module docstring).
MAX_MAGNITUDE = 1e6
#: The smallest value a strictly positive physical number may have.
MIN_POSITIVE = 1e-6


def limits_text(*, positive: bool = False) -> str:
    """The limits as the end of an ``allowed:`` clause."""
    if positive:
        return f"at least {MIN_POSITIVE:g} and at most {MAX_MAGNITUDE:g}"
    return f"at most {MAX_MAGNITUDE:g} in magnitude"


def magnitude_ok(value: float, *, positive: bool = False) -> bool:
    """True when the finite ``value`` is inside the limits (``positive``: also >= MIN_POSITIVE)."""
    if positive and value < MIN_POSITIVE:
        return False
    return abs(value) <= MAX_MAGNITUDE


def check_number(
    name: str,
    value: object,
    allowed: str = "a finite number",
    *,
    positive: bool = False,
    minimum: float | None = None,
) -> float:
    """``float(value)``, or one line naming ``name`` when it is not a number, not finite or
    outside the magnitude limits (:data:`MAX_MAGNITUDE`; ``positive``: also at least
    :data:`MIN_POSITIVE`; ``minimum``: also at least that).  ``allowed`` says what the
    caller requires (``"a finite number >= 0"``); the limits are appended to it."""
    full = f"{allowed}, {limits_text(positive=positive)}"
    v = check_finite(name, value, full)
    if not magnitude_ok(v, positive=positive) or (minimum is not None and v < minimum):
        raise BirdsimError(f"{name}={v!r} is invalid; allowed: {full}")
    return v


def check_numbers(
    name: str,
    value: object,
    allowed: str = "a finite number",
    *,
    positive: bool = False,
    minimum: float | None = None,
) -> np.ndarray:
    """``value`` as a float array (any shape), or one line naming ``name`` and the first
    element that is not finite or is outside the magnitude limits (see
    :func:`check_number`)."""
    full = f"{allowed}, {limits_text(positive=positive)}"
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise BirdsimError(f"{name}={value!r} is not a number; allowed: {full}") from None
    finite = np.isfinite(a)
    good = finite & (np.abs(np.where(finite, a, 0.0)) <= MAX_MAGNITUDE)
    if positive:
        good &= np.where(finite, a, 0.0) >= MIN_POSITIVE
    if minimum is not None:
        good &= np.where(finite, a, minimum) >= minimum
    if not np.all(good):
        bad = float(a[~good].flat[0]) if a.ndim else float(a)
        raise BirdsimError(f"{name}={bad!r} is invalid; allowed: {full}")
    return a


def check_finite(name: str, value: float, allowed: str = "a finite number") -> float:
    """Return ``float(value)`` or raise naming ``name`` when it is NaN or infinite."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise BirdsimError(f"{name}={value!r} is not a number; allowed: {allowed}") from None
    if v != v or v in (float("inf"), float("-inf")):
        raise BirdsimError(f"{name}={value!r} is not finite; allowed: {allowed}")
    return v
