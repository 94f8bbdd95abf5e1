"""The wingbeat-mean pitching moment of a lookup table's wingbeats across its force
demands (docs/turning.md and docs/free-body.md, "The pigeon's m5 falls in free landing
and circle", 2026-12-03): at one airspeed, for each demand (Fx, Fz) of a grid, the
table's wingbeat beaten by the held body at the table's pitch, not rotating, every
attitude input at zero -- the moment the attitude loop measures as its ``M_0``
(:func:`birdsim.flight.attitude_jacobians.held_mean_moments`; seed body axes about the
centre of mass, table units, > 0 nose up).  The optimiser's cost holds the force and the
power, not this moment; where it changes steeply or jumps between neighbouring demands,
every change of the path loop's demand is a pitching-moment step the attitude loop must
absorb.  Prints the map, the table's pitch there, the slopes between neighbours and the
pitch loop's proportional stiffness ``Kp I`` (straight flight's pitch axis) to compare.

    PYTHONPATH=$PWD python scripts/table_pitch_moment.py --bird models/pigeon.toml --model m5
"""

from __future__ import annotations

import argparse
from typing import Any

import numpy as np

from birdsim.physics.kinematics import MODELS

#: The default grid (table units): Fx and Fz around the pigeon's cruise and turns.
FX = (-0.1, 0.1, 0.025)
FZ = (-0.35, -0.1, 0.05)


def grid(spec: tuple[float, float, float]) -> np.ndarray:
    """``(first, last, step)`` -> the values first, first + step, ... up to last (included)."""
    first, last, step = spec
    n = int(round((last - first) / step)) + 1
    return first + step * np.arange(n)


def held_moment_map(
    fb: Any, table: Any, fxs: np.ndarray, fzs: np.ndarray, speed: float
) -> tuple[np.ndarray, np.ndarray]:
    """(M (len(fzs), len(fxs)), pitch (rad), the same shape): per demand the held body's
    wingbeat-mean pitching moment of the table's wingbeat at the table's pitch and
    ``speed`` (reduced units, the attitude loop's ``M_0``) and that pitch."""
    from birdsim.flight.attitude_jacobians import held_mean_moments

    names = fb.schedule.names
    moment = np.zeros((len(fzs), len(fxs)))
    pitch = np.zeros_like(moment)
    for i, fz in enumerate(fzs):
        for j, fx in enumerate(fxs):
            row = table.lookup(Fx=float(fx), Fz=float(fz), V=speed)
            params = np.array([row[n] for n in names], dtype=float)
            pitch[i, j] = row["pitch"]
            held = held_mean_moments(fb, params, row["pitch"], speed, [np.zeros(3)])
            moment[i, j] = held[0][1]
    return moment, pitch


def slopes(moment: np.ndarray, dfx: float, dfz: float) -> dict[str, float]:
    """The map's finite-difference slopes between neighbours (table units per table force
    unit): median and largest ``|dM/dFx|`` and ``|dM/dFz|``, and the map's range."""
    gx = np.abs(np.diff(moment, axis=1)) / dfx
    gz = np.abs(np.diff(moment, axis=0)) / dfz
    return {
        "median_dFx": float(np.median(gx)),
        "max_dFx": float(gx.max()),
        "median_dFz": float(np.median(gz)),
        "max_dFz": float(gz.max()),
        "min": float(moment.min()),
        "max": float(moment.max()),
    }


def main() -> None:
    from turn_coupling_study import or_exit

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bird", default="models/pigeon.toml", help="bird file (gravity)")
    parser.add_argument(
        "--model", default="m5", choices=list(MODELS), help="kinematic model (default m5)"
    )
    parser.add_argument("--speed", type=float, default=0.5, help="airspeed, semispan omega")
    args = parser.parse_args()
    or_exit(parser, lambda: report(args.bird, args.model, args.speed))


def report(bird_file: str, model: str, speed: float) -> None:
    """Print the map and its slopes for ``model``'s table of the bird of ``bird_file``."""
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.attitude import AttitudeLoop, attitude_gains
    from birdsim.flight.simulate import FreeBird, SimConfig

    bird = load_bird(bird_file)
    table = load_table_for(bird, model, None)
    fxs, fzs = grid(FX), grid(FZ)
    start = table.lookup(Fx=0.0, Fz=float(fzs[len(fzs) // 2]), V=speed)
    params = np.array(list(start.values()))
    with FreeBird(model, bird, params, config=SimConfig(attitude="free")) as fb:
        moment, pitch = held_moment_map(fb, table, fxs, fzs, speed)
        inertia = float(AttitudeLoop(fb).inertia[1])
        kp = float(attitude_gains(fb.red.omega).kp[1])
    print(f"{model}, V {speed:g}: held M_0 (table units, nose up > 0) | table pitch (deg)")
    print("Fx " + " ".join(f"{fx:+8.3f}" for fx in fxs))
    for i, fz in enumerate(fzs):
        cells = " ".join(f"{m:+8.4f}" for m in moment[i])
        print(f"Fz {fz:+.2f} {cells} | " + " ".join(f"{p:3.0f}" for p in np.degrees(pitch[i])))
    s = slopes(moment, FX[2], FZ[2])
    print(
        f"|dM/dFx| median {s['median_dFx']:.4f} max {s['max_dFx']:.4f}; |dM/dFz| median "
        f"{s['median_dFz']:.4f} max {s['max_dFz']:.4f}; range {s['min']:+.4f}..{s['max']:+.4f}"
    )
    print(f"pitch loop's Kp I (straight): {kp * inertia:.4f} per rad (inertia {inertia:.3f})")


if __name__ == "__main__":
    main()
