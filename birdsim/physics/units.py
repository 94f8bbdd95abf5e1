"""Reference scales of a bird, and the reduced bird that tables are built for.

The core is unit-agnostic: a :class:`Bird` carries ``rho``, ``omega``, ``semispan`` (s) and
``chord`` (c) in any consistent unit system (the seed bird: all 1; the pigeon: SI). Every
control point lies on its panel's twist axis, so CP kinematics scale with the span only and
forces with ``q S``: in the units below, a wingbeat's forces depend only on the *reduced
bird* (spanwise lengths / s, chordwise lengths / c, body drag area / (s c), disc area / s^2,
rho = omega = 1). The scaling is exact without induced velocity; with it, the induced speed
also depends on c / s, so two birds share a table only when their c / s agree as well.

Scales (docs/conventions.md, "Units"):

==========  ==============================
length      s
time        1 / omega
speed       omega s
force       rho omega^2 s^3 c
power       rho omega^3 s^4 c
mass        rho s^2 c
==========  ==============================
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from birdsim.physics.bird import Bird


@dataclass(frozen=True)
class Scales:
    """Reference scales of one bird, in the bird file's own units."""

    length: float
    time: float
    speed: float
    force: float
    power: float
    mass: float


def scales(bird: Bird) -> Scales:
    """The reference scales of ``bird`` (all 1 for the seed bird)."""
    s, c = bird.semispan, bird.chord
    return Scales(
        length=s,
        time=1.0 / bird.omega,
        speed=bird.omega * s,
        force=bird.rho * bird.omega**2 * s**3 * c,
        power=bird.rho * bird.omega**3 * s**4 * c,
        mass=bird.rho * s**2 * c,
    )


#: the last reduced birds, by the identity of their (frozen) bird: a free flight's
#: controller reduces the same bird at every control update
_REDUCED: dict[int, tuple[Bird, Bird]] = {}


def reduced_bird(bird: Bird) -> Bird:
    """The non-dimensional bird whose table serves ``bird`` (rho = omega = s = c = 1).

    Mass and gravity are reduced too (mass ratio, and gravity in s omega^2) so that the
    reduced bird flies exactly like the original in reduced units.  Made once per bird
    object (a frozen dataclass) and kept: the same numbers.
    """
    hit = _REDUCED.get(id(bird))
    if hit is not None and hit[0] is bird:
        return hit[1]
    red = _reduce(bird)
    if len(_REDUCED) > 64:
        _REDUCED.clear()
    _REDUCED[id(bird)] = (bird, red)
    return red


def _reduce(bird: Bird) -> Bird:
    s, c = bird.semispan, bird.chord
    return replace(
        bird,
        semispan=1.0,
        chord=1.0,
        hand_chord=bird.hand_chord / c,
        rho=1.0,
        omega=1.0,
        body_drag_area=bird.body_drag_area / (s * c),
        disc_area=bird.disc_area / s**2,
        mass=mass_ratio(bird),
        gravity=bird.gravity / (bird.omega**2 * s),
        tail_length=bird.tail_length / s,
        tail_span=bird.tail_span / s,
        tail_root=bird.tail_root / s,
        leg_length=bird.leg_length / s,
        toe_span=bird.toe_span / s,
        body_inertia=tuple(i / (bird.rho * s**4 * c) for i in bird.body_inertia),
    )


def mass_ratio(bird: Bird) -> float:
    """``m / (rho s^2 c)``: about 30 for a pigeon; 1 for the seed bird's default mass."""
    return bird.mass / scales(bird).mass


def weight_in_table_units(bird: Bird) -> float:
    """The whole bird's weight ``m g / (rho omega^2 s^3 c)``.

    Level flight needs the table force (one wing + body drag) ``Fz = -weight / 2``.
    """
    return bird.mass * bird.gravity / scales(bird).force


def same_reduced_bird(a: Bird, b: Bird, *, rel_tol: float = 1e-9) -> bool:
    """Whether a table built for ``a`` serves ``b`` exactly (aerodynamic fields only)."""
    ra, rb = reduced_bird(a), reduced_bird(b)
    da, db = ra.to_dict(), rb.to_dict()
    from birdsim.physics.bird import FLIGHT_FIELDS

    for key in ("name", "mass", "gravity", *FLIGHT_FIELDS):  # not the wings' business
        da.pop(key), db.pop(key)
    for key in ("power_cost", "wing_mass_fraction"):  # left out of to_dict at their defaults
        da.pop(key, None), db.pop(key, None)
    if ra.power_cost != rb.power_cost or not math.isclose(  # the optimiser's power measure
        ra.wing_mass_fraction * ra.mass,
        rb.wing_mass_fraction * rb.mass,
        rel_tol=rel_tol,
        abs_tol=1e-12,
    ):
        return False
    if ra.induced_velocity or rb.induced_velocity:
        da["c_over_s"], db["c_over_s"] = a.chord / a.semispan, b.chord / b.semispan
    for key, va in da.items():
        vb = db[key]
        if isinstance(va, float) and isinstance(vb, (int, float)):
            if not math.isclose(va, vb, rel_tol=rel_tol, abs_tol=1e-12):
                return False
        elif va != vb:
            return False
    return True


__all__ = [
    "Scales",
    "mass_ratio",
    "reduced_bird",
    "same_reduced_bird",
    "scales",
    "weight_in_table_units",
]
