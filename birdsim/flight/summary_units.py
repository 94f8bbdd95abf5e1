"""The units of a flight summary's errors, said in the summary itself: the bird's length
unit (metres for an SI bird, semispans for the non-dimensional seed bird) and, for an SI
bird, the same errors in semispans too (comparable across birds)."""

from __future__ import annotations

from typing import Any

from birdsim.physics.bird import Bird
from birdsim.physics.units import scales

#: The summary's error figures (distances in the bird's length unit).
ERROR_KEYS = (
    "rms_error",
    "max_error",
    "rms_error_after_start",
    "max_error_after_start",
    "rms_altitude_error_after_start",
)


def length_unit(bird: Bird) -> str:
    """ "m" for an SI bird, "semispans" for a non-dimensional one."""
    sc = scales(bird)
    return "semispans" if (sc.length == 1.0 and sc.time == 1.0) else "m"


def with_units(info: dict[str, Any], bird: Bird) -> dict[str, Any]:
    """``info`` plus ``error_unit`` and, for an SI bird, ``errors_semispans`` (each error
    divided by the semispan); the figures themselves are unchanged."""
    out = dict(info)
    unit = length_unit(bird)
    out["error_unit"] = unit
    if unit == "m":
        s = float(bird.semispan)
        out["errors_semispans"] = {k: float(info[k]) / s for k in ERROR_KEYS if k in info}
    return out


__all__ = ["ERROR_KEYS", "length_unit", "with_units"]
