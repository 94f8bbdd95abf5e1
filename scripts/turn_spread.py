"""How far a turning preset's path RMS moves under tiny changes of the loops' constants
(docs/turning.md, "The pigeon's cruise turns: the error's parts, and a circle on the
edge", 2026-12-03): the preset flown free (m3, or `--model`) once as it is and once per perturbation,
each a module constant nudged by a fraction of itself that no design would tell apart
(:data:`PERTURBATIONS`: the lateral loop's time constant 6 -> 5.99 / 6.01 wingbeats, the
cruise turn's pitch axis 2.5 -> 2.49 / 2.51).  Prints one line per flight (path RMS after
two wingbeats in the bird's length unit, saturated samples) and the median; a figure
that moves by more than its own target between these neighbours is not a measurement of
the change under study but of where the flight lands.

    PYTHONPATH=$PWD python scripts/turn_spread.py circle --bird models/pigeon.toml
    PYTHONPATH=$PWD python scripts/turn_spread.py s-turn --bird models/pigeon.toml --set MODULE.NAME=VALUE
    PYTHONPATH=$PWD python scripts/turn_spread.py circle --bird models/pigeon.toml --model m5
"""

from __future__ import annotations

import argparse
import importlib
from typing import Any

import numpy as np
from turn_coupling_study import TURN_NAMES, fly_preset, or_exit

from birdsim.physics.kinematics import MODELS

#: (module, constant, factor): each perturbed flight multiplies one constant (a scalar,
#: or a tuple's middle entry) by the factor.
PERTURBATIONS = (
    ("birdsim.flight.bank", "LATERAL_BEATS", 5.99 / 6.0),
    ("birdsim.flight.bank", "LATERAL_BEATS", 6.01 / 6.0),
    ("birdsim.flight.turning", "FOURTH_STAGE_TURN_AXIS_BEATS", 2.49 / 2.5),
    ("birdsim.flight.turning", "FOURTH_STAGE_TURN_AXIS_BEATS", 2.51 / 2.5),
)


def nudged(value: Any, factor: float) -> Any:
    """``value`` times ``factor``; for a tuple (an axis triple) its middle entry only."""
    if isinstance(value, tuple):
        mid = len(value) // 2
        return (*value[:mid], value[mid] * factor, *value[mid + 1 :])
    return value * factor


def fly_figures(preset: str, bird_file: str | None, model: str = "m3") -> tuple[float, int]:
    """``preset`` flown free with ``model`` by the bird of ``bird_file``: (path RMS after
    two wingbeats in the bird's length unit, saturated samples)."""
    from birdsim.flight.flightlog import log_arrays, summary

    s = summary(log_arrays(fly_preset(bird_file, preset, model), preset))
    return float(s["rms_error_after_start"]), int(s["saturated_samples"])


def spread(preset: str, bird_file: str | None, model: str = "m3") -> list[tuple[str, float, int]]:
    """The flight as it is, then one per :data:`PERTURBATIONS` (each restored after), every
    flight with ``model``."""
    rows = [("as is", *fly_figures(preset, bird_file, model))]
    for module, name, factor in PERTURBATIONS:
        mod = importlib.import_module(module)
        before = getattr(mod, name)
        setattr(mod, name, nudged(before, factor))
        try:
            value = np.round(getattr(mod, name), 4).tolist()
            rows.append((f"{name} {value}", *fly_figures(preset, bird_file, model)))
        finally:
            setattr(mod, name, before)
    return rows


def main() -> None:
    from turn_gust_study import apply_settings

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("preset", choices=TURN_NAMES, help="turning preset")
    parser.add_argument("--bird", default=None, help="bird file (default: the seed bird)")
    parser.add_argument(
        "--model", default="m3", choices=list(MODELS), help="kinematic model (default m3)"
    )
    parser.add_argument("--set", action="append", default=[], help="MODULE.NAME=VALUE")
    args = parser.parse_args()
    apply_settings(args.set)
    rows = or_exit(parser, lambda: spread(args.preset, args.bird, args.model))
    for label, rms, sat in rows:
        print(f"{label:48s} {rms:.5f} ({sat})")
    print(f"median {float(np.median([r[1] for r in rows])):.5f}")


if __name__ == "__main__":
    main()
