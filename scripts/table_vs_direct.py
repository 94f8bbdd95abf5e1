"""The shipped table's level-flight power against the direct trim solve, speed by speed
(docs/validation.md, "The table check"): how far multilinear interpolation of the table
is from the optimum, and where the bracketing V nodes sit on different branches.

    PYTHONPATH=$PWD python scripts/table_vs_direct.py [--bird models/pigeon.toml]
        [--table tables/pigeon-m3.npz] [--step 0.25] [--json OUT.json]
"""

from __future__ import annotations

import argparse
import json

import numpy as np

from birdsim.physics.units import scales
from birdsim.tables.lookup import load_table
from birdsim.validation.run import load_flying_bird
from birdsim.validation.tablecheck import level_flight_from_table
from birdsim.validation.trim import trim_sweep


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bird", default=None)
    ap.add_argument("--table", default="tables/pigeon-m3.npz")
    ap.add_argument("--model", default="m3")
    ap.add_argument("--step", type=float, default=0.25)
    ap.add_argument("--json", default=None)
    a = ap.parse_args()
    bird = load_flying_bird(a.bird)
    table = load_table(a.table)
    sc = scales(bird)
    vmax = float(table.axes["V"][-1]) * sc.speed
    speeds = [float(v) for v in np.arange(0.0, vmax + 1e-9, a.step)]
    tab = level_flight_from_table(table, bird, speeds)
    sweep = trim_sweep(a.model, bird, speeds, extra_starts=tab.starts)
    axes = [np.asarray(table.axes[a]) for a in ("Fx", "Fz", "V")]
    rows = []
    for v, p, tp, dem in zip(speeds, sweep.points, tab.power, tab.demands):
        if tp is None:
            continue
        # the 8 cells the lookup interpolates between: the largest parameter spread
        # among them (rad; a branch change shows as a spread of several tenths)
        lo = [
            min(int(np.searchsorted(ax, d, side="right")) - 1, len(ax) - 2)
            for ax, d in zip(axes, dem)
        ]
        box = table.params[lo[0] : lo[0] + 2, lo[1] : lo[1] + 2, lo[2] : lo[2] + 2].reshape(
            -1, len(table.param_names)
        )
        spread = float(np.max(box.max(axis=0) - box.min(axis=0)))
        rel = (tp - p.power) / p.power
        rows.append(
            dict(speed=v, direct=p.power, table=tp, rel=rel, trimmed=p.trimmed, spread_rad=spread)
        )
        V = axes[2]
        print(
            f"{v:6.2f} m/s  direct {p.power:8.4f} W  table {tp:8.4f} W  {100 * rel:+6.2f} %"
            f"  V nodes {V[lo[2]] * sc.speed:5.2f}-{V[lo[2] + 1] * sc.speed:5.2f}"
            f"  corner spread {spread:.3f} rad" + ("" if p.trimmed else "  (not trimmed)")
        )
    rels = np.array([r["rel"] for r in rows if r["trimmed"]])
    print(
        f"max |rel| {np.max(np.abs(rels)) * 100:.2f} %, table above by at most "
        f"{rels.max() * 100:+.2f} %, below by at most {rels.min() * 100:+.2f} %, {len(rels)} speeds"
    )
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
