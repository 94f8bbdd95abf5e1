"""Plumage: the colours and materials of the visual bird, chosen by the bird's name.

:data:`PLUMAGES` maps a bird name to a :class:`Plumage`; a name it does not know gets
:data:`NEUTRAL` (the seed bird's plain brown-grey).  The pigeon (``bird.name ==
"pigeon"``, models/pigeon.toml) is a rock dove: blue-grey body and wings, an
iridescent green-purple neck, two dark bars across the inner wing, dark primaries and
a dark band at the tail's end.  Colours only: nothing here touches the physics.
"""

from __future__ import annotations

from dataclasses import dataclass

RGBA = tuple[float, float, float, float]


@dataclass(frozen=True)
class Plumage:
    """RGBA per part of the visual bird; ``neck_specular``/``neck_shininess`` make an
    iridescent neck (a glossy material); ``wing_bars`` = how many dark bars cross the
    inner wing's coverts (0 = none)."""

    name: str
    body: RGBA
    belly: RGBA
    head: RGBA
    neck: RGBA
    beak: RGBA
    eye: RGBA
    eye_ring: RGBA
    coverts: RGBA
    bars: RGBA
    secondaries: RGBA
    primaries: RGBA
    tail: RGBA
    tail_band: RGBA
    feet: RGBA
    wing_bars: int = 0
    neck_specular: float = 0.3
    neck_shininess: float = 0.3


#: The seed bird (and any bird without its own entry): a neutral brown-grey plumage.
NEUTRAL = Plumage(
    name="neutral",
    body=(0.55, 0.50, 0.44, 1.0),
    belly=(0.78, 0.74, 0.66, 1.0),
    head=(0.50, 0.45, 0.40, 1.0),
    neck=(0.52, 0.47, 0.42, 1.0),
    beak=(0.85, 0.65, 0.25, 1.0),
    eye=(0.05, 0.05, 0.05, 1.0),
    eye_ring=(0.85, 0.80, 0.70, 1.0),
    coverts=(0.62, 0.56, 0.48, 1.0),
    bars=(0.45, 0.40, 0.34, 1.0),
    secondaries=(0.48, 0.43, 0.37, 1.0),
    primaries=(0.34, 0.30, 0.27, 1.0),
    tail=(0.46, 0.41, 0.36, 1.0),
    tail_band=(0.36, 0.32, 0.28, 1.0),
    feet=(0.75, 0.55, 0.35, 1.0),
    wing_bars=0,
)

#: Rock dove (Columba livia): blue-grey, iridescent neck, two black wing bars.
PIGEON = Plumage(
    name="pigeon",
    body=(0.52, 0.56, 0.62, 1.0),
    belly=(0.60, 0.63, 0.69, 1.0),
    head=(0.42, 0.45, 0.52, 1.0),
    neck=(0.28, 0.48, 0.40, 1.0),
    beak=(0.20, 0.18, 0.18, 1.0),
    eye=(0.85, 0.35, 0.05, 1.0),
    eye_ring=(0.75, 0.75, 0.78, 1.0),
    coverts=(0.66, 0.69, 0.74, 1.0),
    bars=(0.10, 0.10, 0.12, 1.0),
    secondaries=(0.50, 0.53, 0.59, 1.0),
    primaries=(0.22, 0.23, 0.27, 1.0),
    tail=(0.48, 0.51, 0.58, 1.0),
    tail_band=(0.12, 0.12, 0.14, 1.0),
    feet=(0.80, 0.30, 0.30, 1.0),
    wing_bars=2,
    neck_specular=0.9,
    neck_shininess=0.9,
)

#: Plumage by bird name (``Bird.name``).
PLUMAGES: dict[str, Plumage] = {"seed": NEUTRAL, "pigeon": PIGEON}


def plumage_for(bird_name: str) -> Plumage:
    """The plumage of the bird called ``bird_name`` (:data:`NEUTRAL` when unknown)."""
    return PLUMAGES.get(bird_name, NEUTRAL)


__all__ = ["NEUTRAL", "PIGEON", "PLUMAGES", "Plumage", "plumage_for"]
