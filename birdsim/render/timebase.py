"""One time base for ``birdsim render`` and ``birdsim export``: real time for an SI bird
(its wingbeat frequency in wingbeats per second of video), 2 wingbeats per second for the
non-dimensional seed bird; ``--slow-motion F`` divides that rate by F, ``--beat-rate HZ``
sets it outright. Each command prints the line :func:`describe` writes."""

from __future__ import annotations

import math

from birdsim.errors import MIN_POSITIVE, BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.units import scales

#: Wingbeats per second of video for a bird without SI units (the seed bird).
NONDIM_BEAT_RATE = 2.0


def is_si(bird: Bird) -> bool:
    sc = scales(bird)
    return not (sc.length == 1.0 and sc.time == 1.0)


def _positive(arg: str, raw: str | float | None, upper: float = 100.0) -> float | None:
    """A rate or factor in (0, upper], at least MIN_POSITIVE (one line naming the flag
    otherwise)."""
    if raw is None:
        return None
    try:
        v = float(raw)
    except (TypeError, ValueError):
        raise BirdsimError(
            f"{arg} {raw!r} is not a number; allowed: a number in (0, {upper:g}]"
        ) from None
    if not (math.isfinite(v) and MIN_POSITIVE <= v <= upper):
        raise BirdsimError(
            f"{arg} {raw} is invalid; allowed: a number in (0, {upper:g}], at least {MIN_POSITIVE:g}"
        )
    return v


def check_time_flags(beat_rate: str | None, slow_motion: str | None) -> None:
    """The flags alone, before any work (one line for a bad value or both at once)."""
    _positive("--beat-rate", beat_rate)
    _positive("--slow-motion", slow_motion, 1000.0)
    if beat_rate is not None and slow_motion is not None:
        raise BirdsimError(
            "--beat-rate and --slow-motion both set the time base; allowed: one of them"
        )


def beat_rate_for(
    bird: Bird, beat_rate: str | float | None, slow_motion: str | float | None
) -> tuple[float, str]:
    """Wingbeats per second of video, and what it is in words.

    Raises:
        BirdsimError: a non-positive value, or both flags.
    """
    check_time_flags(beat_rate, slow_motion)
    rate = _positive("--beat-rate", beat_rate)
    if rate is not None:
        return rate, f"{rate:g} wingbeats per second (--beat-rate)"
    factor = _positive("--slow-motion", slow_motion, 1000.0) or 1.0
    if is_si(bird):
        base = 1.0 / bird.period  # wingbeats per second of real time
        words = "real time" if factor == 1.0 else f"{factor:g}x slow motion"
    else:
        base = NONDIM_BEAT_RATE
        words = f"{base:g} wingbeats per second (a bird without SI units)"
        if factor != 1.0:
            words += f", {factor:g}x slower"
    return base / factor, words


def describe(rate: float, words: str, fps: float) -> str:
    """``time base: real time = 8.6 wingbeats per second of video, 3.5 frames per wingbeat``."""
    hint = "" if "slow" in words or "beat-rate" in words else "; --slow-motion F for slow motion"
    return (
        f"time base: {words} = {rate:.3g} wingbeats per second of video, "
        f"{fps / rate:.1f} frames per wingbeat at {fps:g} fps{hint}"
    )


__all__ = ["NONDIM_BEAT_RATE", "beat_rate_for", "check_time_flags", "describe", "is_si"]
