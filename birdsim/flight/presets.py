"""The four preset manoeuvres as flight paths (issue 9, item 3).

Reduced units (semispans, wingbeats, ``omega s``), so one preset means the same for every
bird with the same reduced bird, mass ratio and reduced gravity: the seed bird of
``models/seed-bird.toml`` and the pigeon of ``models/pigeon.toml`` fly the same presets.
They were laid out inside the envelope of the demo table (docs/flight.md, "Manoeuvres as
paths"): ``tests/test_presets.py`` checks that every sample's feed-forward demand lies in
table cells whose corners are all reachable.

* ``hover``: in place, 6 semispans up, for 8 wingbeats.
* ``cruise``: straight and level at :data:`CRUISE_SPEED`, 6 semispans up, 10 wingbeats.
* ``take-off``: from rest on the perch, forward and up to cruise speed and height.
* ``landing``: from cruise, down and slower, to rest on the perch.
"""

from __future__ import annotations

from birdsim.flight.path import PERCH_Z, FlightPath, PathKeyframe

#: Height of hover and cruise (semispans above the floor).
CRUISE_HEIGHT = 6.0
#: Cruise speed (omega s): inside every demo bird's level-flight range, near its
#: minimum-power speed (docs/flight.md, "Envelope of each model").
CRUISE_SPEED = 0.5

_K = PathKeyframe


def _presets() -> dict[str, FlightPath]:
    vc, zc = CRUISE_SPEED, CRUISE_HEIGHT
    hover = FlightPath(
        "hover", 8.0, False, False,
        (_K(0.0, zc, x=0.0, regime="hover"),),
        "hover in place 6 semispans up",
    )
    cruise = FlightPath(
        "cruise", 10.0, False, False,
        (_K(0.0, zc, V=vc, regime="cruise"),),
        f"straight and level at V = {vc:g} omega s, 6 semispans up",
        x0=-0.5 * vc * 10.0 * 6.283185307179586,
    )
    take_off = FlightPath(
        "take-off", 18.0, True, False,
        (
            _K(0.0, PERCH_Z, V=0.0, regime="take-off"),
            _K(6.0, PERCH_Z + 0.6, V=0.25),
            _K(12.0, zc - 0.6, V=0.42, regime="climb-out"),
            _K(16.0, zc, V=vc, regime="cruise"),
        ),
        "from rest on the perch, forward and up to cruise",
    )
    landing = FlightPath(
        "landing", 18.0, False, True,
        (
            _K(0.0, zc, V=vc, regime="cruise"),
            _K(2.0, zc, V=vc),
            _K(8.0, zc - 2.0, V=0.35, regime="approach"),
            _K(13.0, PERCH_Z + 0.5, V=0.15, regime="flare"),
            _K(17.0, PERCH_Z, V=0.0, regime="perched"),
        ),
        "from cruise, down and slower, to rest on the perch",
    )
    return {p.name: p for p in (hover, cruise, take_off, landing)}


#: The presets by name (same names as the force-keyframe presets of manoeuvre.py).
PATH_PRESETS: dict[str, FlightPath] = _presets()

__all__ = ["CRUISE_HEIGHT", "CRUISE_SPEED", "PATH_PRESETS"]
