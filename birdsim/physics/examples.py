"""The dissertation's example wingbeats (sec. 3.5), by equation number.

Some examples use values outside the default optimisation bounds (m3's stroke plane
pi/4, m4 flap amplitudes): evaluate them with ``check_bounds=False``.
"""

from __future__ import annotations

from dataclasses import dataclass
from math import pi


@dataclass(frozen=True)
class Example:
    equation: int
    model: str
    regime: str  # "hover" or "cruise"
    speed: float
    params: dict[str, float]
    figure: int


_HOVER = dict(pitch=pi / 2, flap_amp=pi / 2, twist_amp=pi / 4)
_CRUISE = dict(pitch=pi / 16, flap_amp=pi / 4, twist_amp=pi / 16)

EXAMPLES: tuple[Example, ...] = (
    Example(57, "base", "hover", 0.0, _HOVER, 12),
    Example(58, "base", "cruise", 0.5, _CRUISE, 13),
    Example(61, "m1", "hover", 0.0, _HOVER, 15),
    Example(62, "m1", "cruise", 0.5, _CRUISE, 16),
    Example(68, "m2", "hover", 0.0, {**_HOVER, "sweep": pi / 4}, 18),
    Example(69, "m2", "cruise", 0.5, {**_CRUISE, "sweep": pi / 4}, 19),
    Example(75, "m3", "hover", 0.0, {**_HOVER, "stroke_plane": pi / 4}, 21),
    Example(76, "m3", "cruise", 0.5, {**_CRUISE, "stroke_plane": pi / 4}, 22),
    Example(
        87,
        "m4",
        "hover",
        0.0,
        dict(
            pitch=pi / 2,
            flap_amp=pi / 4,
            twist_amp=pi / 4,
            stroke_plane=0.0,
            wrist_amp=pi / 8,
            wrist_bias=0.0,
            wrist_lag=0.0,
        ),
        24,
    ),
    Example(
        88,
        "m4",
        "cruise",
        0.5,
        dict(
            pitch=0.0,
            flap_amp=pi / 4,
            twist_amp=pi / 16,
            stroke_plane=0.0,
            wrist_amp=pi / 8,
            wrist_bias=pi / 8,
            wrist_lag=pi / 2,
        ),
        25,
    ),
)


def example(equation: int) -> Example:
    for ex in EXAMPLES:
        if ex.equation == equation:
            return ex
    raise KeyError(equation)
