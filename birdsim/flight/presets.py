"""The four preset manoeuvres as flight paths (issue 9, item 3).

Reduced units (semispans, wingbeats, ``omega s``), so one preset means the same for every
bird with the same reduced bird, mass ratio and reduced gravity: the seed bird of
``models/seed-bird.toml`` and the pigeon of ``models/pigeon.toml`` fly the same presets.
They were laid out inside the envelope of the demo table (docs/flight.md, "Manoeuvres as
paths"): ``tests/test_presets.py`` checks that every sample's feed-forward demand lies in
table cells whose corners are all reachable, read in earth axes and in the air-path frame
(:func:`birdsim.flight.demand.air_path_demand`), with room for the controller.

* ``hover``: in place, 6 semispans up, for 8 wingbeats.
* ``cruise``: straight and level at :data:`CRUISE_SPEED`, 6 semispans up, 10 wingbeats.
* ``take-off``: from rest on the perch, forward and up to cruise speed and height
  (26 wingbeats).
* ``landing``: from cruise, down at cruise speed, then braking nearly level, to rest on
  the perch (40 wingbeats: below V = 0.2 the demo table brakes the bird by at most
  about 0.003-0.006 omega^2 s, 0.3-0.5 g for the pigeon; docs/flight.md).
"""

from __future__ import annotations

from pathlib import Path

from birdsim.flight.path import PERCH_Z, FlightPath, PathKeyframe
from birdsim.physics.bird import Bird

#: The demo model: it hovers with the demo bird (m4 cannot: its flap is bounded to pi/4)
#: and its table reaches every preset (docs/flight.md, "Envelope of each model").
DEMO_MODEL = "m3"
#: The shipped bird files (repository ``models/``).
MODELS_FOLDER = Path(__file__).resolve().parents[2] / "models"
SEED_BIRD_FILE = MODELS_FOLDER / "seed-bird.toml"
PIGEON_FILE = MODELS_FOLDER / "pigeon.toml"

#: Height of hover and cruise (semispans above the floor).
CRUISE_HEIGHT = 6.0
#: Cruise speed (omega s): inside every demo bird's level-flight range, near its
#: minimum-power speed (docs/flight.md, "Envelope of each model").
CRUISE_SPEED = 0.5

_K = PathKeyframe


def _presets() -> dict[str, FlightPath]:
    vc, zc = CRUISE_SPEED, CRUISE_HEIGHT
    hover = FlightPath(
        "hover",
        8.0,
        False,
        False,
        (_K(0.0, zc, x=0.0, regime="hover"),),
        "hover in place 6 semispans up",
    )
    cruise = FlightPath(
        "cruise",
        10.0,
        False,
        False,
        (_K(0.0, zc, V=vc, regime="cruise"),),
        f"straight and level at V = {vc:g} omega s, 6 semispans up",
        x0=-0.5 * vc * 10.0 * 6.283185307179586,
    )
    take_off = FlightPath(
        "take-off",
        26.0,
        True,
        False,
        (
            _K(0.0, PERCH_Z, V=0.0, regime="take-off"),
            _K(9.0, 2.0, V=0.3, regime="climb-out"),
            _K(21.0, zc - 0.4, V=0.47),
            _K(25.0, zc, V=vc, regime="cruise"),
        ),
        "from rest on the perch, forward and up to cruise: speed first, then height",
    )
    landing = FlightPath(
        "landing",
        40.0,
        False,
        True,
        (
            _K(0.0, zc, V=vc, regime="cruise"),
            _K(1.0, zc, V=vc, regime="descent"),
            _K(11.0, 2.4, V=vc),
            _K(16.0, 2.15, V=0.42, regime="braking"),
            _K(22.0, 2.0, V=0.26),
            _K(28.0, 1.8, V=0.12, regime="approach"),
            _K(33.0, 1.7, V=0.04),
            _K(39.0, PERCH_Z, V=0.0, regime="perched"),
        ),
        "from cruise: down at cruise speed, then brake nearly level, to rest on the perch",
    )
    return {p.name: p for p in (hover, cruise, take_off, landing)}


def demo_bird() -> Bird:
    """The seed bird that flies: ``models/seed-bird.toml`` (mass ratio 30, reduced gravity
    0.012, weight 0.36 table units); the same values when the file is not installed."""
    if SEED_BIRD_FILE.is_file():
        return Bird.from_toml(SEED_BIRD_FILE)
    return Bird(mass=30.0, gravity=0.012)


#: The presets by name (same names as the force-keyframe presets of manoeuvre.py).
PATH_PRESETS: dict[str, FlightPath] = _presets()

__all__ = [
    "CRUISE_HEIGHT",
    "CRUISE_SPEED",
    "DEMO_MODEL",
    "PATH_PRESETS",
    "PIGEON_FILE",
    "SEED_BIRD_FILE",
    "demo_bird",
]
