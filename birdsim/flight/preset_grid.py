"""The table grid a bird needs to fly the four presets (issue 28, item 2).

``birdsim tables build --bird FILE`` builds this grid by default, and the table finder
(:func:`birdsim.tables.shipped.shipped_table`) prefers a table whose grid covers it.

The presets are laid out in reduced units (semispans, wingbeats, ``omega s``), so their
demands in table force units ``rho omega^2 s^3 c`` depend on the bird: on its mass ratio
``mu`` (the force per unit of acceleration) and its reduced gravity (the weight
``w = mu g``). The zebra finch of ``examples/zebra-finch.toml`` weighs 0.18 table units
(the seed bird 0.36) with a mass ratio of 43 (the seed's 30): braking and descending
cost it more force while its weight helps less, so its landing asks for a downward
table force (Fz up to +0.019), beyond the fixed flight grid's ``Fz <= 0``.

:func:`preset_demands` computes the feed-forward demands of every preset sample
(:func:`birdsim.flight.demand.path_demands` in earth axes and
:func:`birdsim.flight.demand.air_path_demand`, what the controller looks up), with the
body drag at both ends of the pitch range ``[0, pi/2]`` (the table's pitch is not known
before the table is built; the drag is monotonic in ``sin(pitch)``, so the two ends bound
it). :func:`preset_grid` covers their hull with :data:`FORCE_MARGIN` and
:data:`SPEED_MARGIN` for the feedback, rounded outwards to the flight grid's node spacing
(:data:`FORCE_STEP`, :data:`SPEED_STEP`), and V from 0.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.flight.demand import air_path_angle, air_path_demand, path_demands
from birdsim.flight.presets import PATH_PRESETS
from birdsim.physics.bird import Bird

#: Room for the closed loop around the feed-forward hull, table force units. Measured on
#: the seed bird's flight-grid table: the closed-loop demands of take-off and landing
#: leave the feed-forward hull by up to 0.036 in Fx and 0.065 in Fz (``fly --out``,
#: ``Fx_demand``, ``Fz_demand``); 0.075 is three node spacings.
FORCE_MARGIN = 0.075
#: Room above the presets' fastest airspeed (omega s): the controller's V clip tolerance.
SPEED_MARGIN = 0.05
#: Node spacing of the derived grid: the flight grid's (``FLIGHT_GRID``), 0.025 in Fx and
#: Fz (table units), 0.05 in V (omega s).
FORCE_STEP = 0.025
SPEED_STEP = 0.05
#: The ends of the body pitch range of every model (kinematics ``_PARAMS``: 0 .. pi/2).
PITCH_ENDS = (0.0, math.pi / 2)
#: Samples per wingbeat of :func:`preset_demands` (as ``envelope.path_reach``).
SAMPLES_PER_BEAT = 32


class _FixedPitch:
    """A stand-in for a table in :func:`path_demands`: every demand gets one pitch."""

    def __init__(self, pitch: float):
        self.pitch = pitch

    def lookup_many(self, Fx: Any, Fz: Any, V: Any, clip: bool = True) -> dict[str, Any]:
        return {"pitch": np.full(np.shape(V), self.pitch)}


def preset_demands(
    bird: Bird, presets: Any = None, samples_per_beat: int = SAMPLES_PER_BEAT
) -> dict[str, dict[str, np.ndarray]]:
    """The feed-forward table demands of each preset for ``bird``.

    Args:
        bird: the bird (its own units or reduced; reduced internally).
        presets: flight paths by name (default the four presets, ``PATH_PRESETS``).
        samples_per_beat: samples per wingbeat over each path's duration.

    Returns:
        ``{name: {"Fx", "Fz", "V"}}``: every sample in both readings (earth axes and the
        air-path frame) at both pitch ends, concatenated (table force units, omega s).
    """
    presets = PATH_PRESETS if presets is None else presets
    out = {}
    for name, path in presets.items():
        n = int(math.ceil(path.duration_beats * samples_per_beat)) + 1
        t = np.linspace(0.0, path.duration_beats, n) * 2.0 * math.pi
        parts = []
        for pitch in PITCH_ENDS:
            d = path_demands(path, bird, _FixedPitch(pitch), t)
            parts.append((d["Fx"], d["Fz"], d["V"]))
            # the air-path reading takes the turn off the pitch for the drag: add it back,
            # so that the drag is read at the table's pitch end, as the controller does
            turn = air_path_angle(d["vx"], d["vz"])
            fx, fz, v, _ = air_path_demand(d["ax"], d["az"], d["vx"], d["vz"], bird, pitch + turn)
            parts.append((fx, fz, v))
        out[name] = {
            k: np.concatenate([p[i] for p in parts]) for i, k in enumerate(("Fx", "Fz", "V"))
        }
    return out


def demand_box(bird: Bird, presets: Any = None) -> dict[str, tuple[float, float]]:
    """The hull of :func:`preset_demands` over all presets: ``{axis: (lo, hi)}``."""
    d = preset_demands(bird, presets)
    return {
        k: (
            float(min(np.min(p[k]) for p in d.values())),
            float(max(np.max(p[k]) for p in d.values())),
        )
        for k in ("Fx", "Fz", "V")
    }


def _outward(lo: float, hi: float, step: float) -> tuple[float, float, int]:
    """``[lo, hi]`` widened to multiples of ``step``: (lo, hi, node count)."""
    a = math.floor(lo / step + 1e-9)
    b = math.ceil(hi / step - 1e-9)
    b = max(b, a + 1)
    return a * step, b * step, b - a + 1


def preset_grid(
    bird: Bird,
    presets: Any = None,
    *,
    force_margin: float = FORCE_MARGIN,
    speed_margin: float = SPEED_MARGIN,
) -> str:
    """The grid spec (``Grid.parse`` syntax) that covers the presets' demands for ``bird``
    with room for the feedback: ``"Fx=LO:HI:N,Fz=LO:HI:N,V=0:HI:N"``.

    Fx and Fz: the demand hull widened by ``force_margin`` each side, then outwards to
    multiples of :data:`FORCE_STEP`; V: from 0 to the fastest demand plus
    ``speed_margin``, outwards to a multiple of :data:`SPEED_STEP`.
    """
    box = demand_box(bird, presets)
    parts = []
    for axis, margin, step in (
        ("Fx", force_margin, FORCE_STEP),
        ("Fz", force_margin, FORCE_STEP),
        ("V", speed_margin, SPEED_STEP),
    ):
        lo, hi = box[axis]
        lo = 0.0 if axis == "V" else lo - margin
        a, b, n = _outward(lo, hi + margin, step)
        parts.append(f"{axis}={_num(a)}:{_num(b)}:{n}")
    return ",".join(parts)


def _num(x: float) -> str:
    """A node value without float noise (multiples of 0.025 print exactly)."""
    return f"{round(x, 6):g}"


__all__ = [
    "FORCE_MARGIN",
    "FORCE_STEP",
    "PITCH_ENDS",
    "SPEED_MARGIN",
    "SPEED_STEP",
    "demand_box",
    "preset_demands",
    "preset_grid",
]
