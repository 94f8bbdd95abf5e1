"""Does the optimiser's power measure decide where the pigeon's m5 wing folds? (issue 24)

Trims the pigeon's level flight (``validation.trim.trim_sweep``: multi-start SLSQP at each
speed, warm-started along speed, a backward pass) with the bird's ``power_cost`` set to

* ``net``: today's cost, the cycle-mean aerodynamic power (negative work credited);
* ``positive``: the mean positive part of aerodynamic + inertial power
  (:mod:`birdsim.physics.shaft_power`), for each ``--wing-mass`` (one wing's share of the
  bird's mass; 0 = massless wings).

The net sweep starts as ``validate`` does (the shipped table's lookup is one more start);
each positive sweep gets the net optimum at its speed as one more start.  Per speed it
prints the span ratio, the fold, the mid-upstroke angle of attack (the scorecard's
station), the stroke-plane angle to the horizontal, the body angle, the whole bird's net
aerodynamic power and its positive-only power (W), and the slopes over the speeds >= 6.

    python scripts/power_cost_study.py [--speeds 0,4,6,8,10] [--wing-mass 0,0.06]
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import time

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.kinematics import get_model
from birdsim.physics.shaft_power import positive_power
from birdsim.physics.span import span_ratio
from birdsim.validation.run import load_flying_bird
from birdsim.validation.tablecheck import find_table, level_flight_from_table
from birdsim.validation.trim import TrimSweep, angle_of_attack_deg, trim_sweep

N = 64  # samples per wingbeat of the reported figures (the trims' check)


def report(label: str, bird: Bird, sweep: TrimSweep) -> list[dict[str, float]]:
    """Print one line per speed; return the rows."""
    rows = []
    print(f"\n{label}: {sweep.seconds:.0f} s")
    print(" V m/s  span   fold  AoA_up  stroke  body   P_net W  P+ W  trimmed")
    for p in sweep.points:
        c = evaluate_cycle("m5", p.params, p.speed, bird=bird, n=N, check_bounds=False)
        massless = dataclasses.replace(bird, wing_mass_fraction=0.0)
        row = {
            "V": p.speed,
            "span": float(span_ratio("m5", p.params, bird=bird, check_bounds=False)),
            "fold": p.params["fold_amp"],
            "aoa_up": abs(angle_of_attack_deg("m5", bird, p, math.pi)),
            "stroke": p.stroke_plane_deg,
            "body": p.body_angle_deg,
            "p_net": 2.0 * float(np.asarray(c.mean.P)),
            "p_plus": 2.0 * float(positive_power(c, bird).ravel()[0]),
            "p_plus_aero": 2.0 * float(positive_power(c, massless).ravel()[0]),
        }
        rows.append(row)
        print(
            f"{p.speed:6.2f} {row['span']:.3f} {row['fold']:6.3f} {row['aoa_up']:6.1f} "
            f"{row['stroke']:7.1f} {row['body']:5.1f} {row['p_net']:8.3f} {row['p_plus']:6.3f}"
            f"  {int(p.trimmed)}   (aero-only P+ {row['p_plus_aero']:.3f})"
        )
    fast = [r for r in rows if r["V"] >= 6.0]
    if len(fast) >= 2:
        v = np.array([r["V"] for r in fast])
        for key in ("span", "stroke", "body"):
            slope = np.polyfit(v, np.array([r[key] for r in fast]), 1)[0]
            print(f"  slope of {key} over {v.min():g}-{v.max():g} m/s: {slope:+.4f} per m/s")
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--speeds", default="0,4,6,8,10")
    ap.add_argument("--wing-mass", default="0,0.06", help="one wing's mass / the bird's")
    ap.add_argument("--starts", type=int, default=4, help="Sobol starts of a positive sweep")
    args = ap.parse_args()
    speeds = [float(s) for s in args.speeds.split(",")]
    bird = load_flying_bird(None)
    table = find_table(bird, "m5")
    tab = level_flight_from_table(table, bird, speeds) if table is not None else None
    t0 = time.perf_counter()
    net = trim_sweep("m5", bird, speeds, extra_starts=tab.starts if tab else None)
    report("net aerodynamic power (today's cost)", bird, net)
    names = get_model("m5").param_names
    starts = [np.array([p.params[n] for n in names]) for p in net.points]
    for mass in (float(m) for m in args.wing_mass.split(",")):
        b = dataclasses.replace(bird, power_cost="positive", wing_mass_fraction=mass)
        sweep = trim_sweep(
            "m5", b, speeds, first_starts=args.starts, corners=False, extra_starts=starts
        )
        report(f"positive power, wing mass {mass:g} of the bird's", b, sweep)
    print(f"\ntotal {time.perf_counter() - t0:.0f} s")


if __name__ == "__main__":
    main()
