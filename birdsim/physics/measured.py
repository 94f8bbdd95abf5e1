"""A bird from measurements in SI units: mass, wingspan, mean chord, wingbeat frequency.

``bird_from_measurements`` fills a :class:`Bird` with rho = 1.225 kg/m^3 (sea-level air),
omega = 2 pi f, semispan = span / 2, chord = hand chord = the mean chord and gravity
9.81 m/s^2.  Everything else keeps the seed bird's *reduced* values (hand span fraction,
CP position, polar, body drag area s c, disc area pi s^2), so that without
``body_drag_area`` the new bird's reduced bird is the seed bird's and the shipped seed
tables serve it exactly (docs/your-bird.md).  Derived figures (mass ratio, weight in table
units, the tables' speed range in m/s) come from :mod:`birdsim.physics.units`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from birdsim.errors import BirdConfigError, limits_text, magnitude_ok
from birdsim.physics.bird import Bird
from birdsim.physics.units import mass_ratio, scales, weight_in_table_units

RHO_SEA_LEVEL = 1.225  # kg/m^3
GRAVITY = 9.81  # m/s^2
#: The tables' speed axis (docs/tables.md default grid), in omega s.
TABLE_SPEED_RANGE = (0.0, 1.0)


def _positive(arg: str, value: float, unit: str) -> float:
    if not (
        isinstance(value, (int, float))
        and math.isfinite(value)
        and magnitude_ok(value, positive=True)
    ):
        raise BirdConfigError(
            f"{arg} {value!r} is invalid; allowed: a number > 0 ({unit}), {limits_text(positive=True)}"
        )
    return float(value)


def bird_from_measurements(
    name: str,
    *,
    mass: float,
    span: float,
    mean_chord: float,
    frequency: float,
    body_drag_area: float | None = None,
) -> Bird:
    """An SI bird from its measurements.

    Args:
        name: the bird's name.
        mass: whole-bird mass [kg].
        span: wingspan, tip to tip [m].
        mean_chord: mean wing chord [m].
        frequency: wingbeat frequency [Hz].
        body_drag_area: body drag area A_b [m^2] (default: semispan x chord, the seed
            bird's reduced value).

    Returns:
        The bird (SI units).

    Raises:
        BirdConfigError: a value that is not a positive finite number, a chord longer
            than the span, a negative drag area.
    """
    mass = _positive("--mass", mass, "kg")
    span = _positive("--span", span, "m, tip to tip")
    chord = _positive("--mean-chord", mean_chord, "m")
    frequency = _positive("--frequency", frequency, "Hz")
    if chord > span:
        raise BirdConfigError(
            f"--mean-chord {chord:g} is longer than --span {span:g}; allowed: a mean chord shorter than the span (m)"
        )
    s = span / 2.0
    if body_drag_area is None:
        body_drag_area = s * chord
    elif not (
        isinstance(body_drag_area, (int, float))
        and math.isfinite(body_drag_area)
        and body_drag_area >= 0
        and magnitude_ok(body_drag_area)
    ):
        raise BirdConfigError(
            f"--body-drag-area {body_drag_area!r} is invalid; allowed: a number >= 0 (m^2), {limits_text()}"
        )
    return Bird(
        name=name,
        semispan=s,
        chord=chord,
        hand_chord=chord,
        rho=RHO_SEA_LEVEL,
        omega=2.0 * math.pi * frequency,
        body_drag_area=float(body_drag_area),
        disc_area=math.pi * s * s,
        mass=mass,
        gravity=GRAVITY,
    )


@dataclass(frozen=True)
class Derived:
    """Figures derived from a bird (see :mod:`birdsim.physics.units`)."""

    mass_ratio: float  # m / (rho s^2 c)
    weight_table: float  # whole bird m g / (rho omega^2 s^3 c)
    speed_unit: float  # omega s [m/s]
    speed_range_si: tuple[float, float]  # the tables' V range in m/s

    def lines(self) -> list[str]:
        lo, hi = TABLE_SPEED_RANGE
        return [
            f"mass ratio m / (rho s^2 c) = {self.mass_ratio:.4g}",
            f"weight in table units m g / (rho omega^2 s^3 c) = {self.weight_table:.4g} (whole bird; level flight needs the table's Fz = {-self.weight_table / 2:.4g}, right wing + body drag)",
            f"reduced speed range: the tables' V in [{lo:g}, {hi:g}] omega s = [{self.speed_range_si[0]:.3g}, {self.speed_range_si[1]:.3g}] m/s (omega s = {self.speed_unit:.4g} m/s)",
        ]


def derived(bird: Bird) -> Derived:
    """Mass ratio, weight in table units and the tables' speed range for ``bird``."""
    v = scales(bird).speed
    lo, hi = TABLE_SPEED_RANGE
    return Derived(mass_ratio(bird), weight_in_table_units(bird), v, (lo * v, hi * v))


def bird_toml(bird: Bird, *, source: str = "") -> str:
    """The bird as TOML text with the derived figures (and ``source``) as comments."""
    import tomli_w

    head = [f"# {bird.name}: a bird in SI units (kg, m, s), written by `birdsim bird new`"]
    if source:
        head.append(f"# measurements: {source}")
    head += [f"# {line}" for line in derived(bird).lines()]
    return "\n".join(head) + "\n\n" + tomli_w.dumps(bird.to_dict())


__all__ = ["Derived", "GRAVITY", "RHO_SEA_LEVEL", "bird_from_measurements", "bird_toml", "derived"]
