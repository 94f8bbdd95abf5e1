"""The scorecard's stroke-plane and mid-upstroke rows of the pigeon, per speed (issue 24).

Runs the scorecard's sweep (``validation.trim.trim_sweep`` over the card's speeds, the
shipped table's lookup one more start, as ``birdsim validate`` does, without the
other-physics variants and the flights) and prints per speed: body pitch and stroke plane
(deg), the shoulder's flap plane ``90 - (pitch + stroke_plane)`` and the wingtip's own
stroke-plane angle (``physics/tip_path.py``, the row's reading), the mid-upstroke and
mid-downstroke angles of attack at the rows' station and the upstroke's ratio to Crandell &
Tobalske's 66 deg, the fold and the supination (rad), and the pitch the shipped table looks
up at the level-flight demand; then the slopes over 6-20 m/s and the two angle rows as the
scorecard reads them (the mean over the sweep's speeds of the rows' window, 0 to <3 m/s).
About 90 CPU s for m5.

    python scripts/slow_rows_study.py [--model m5]
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from birdsim.validation.measurements import load_measurements
from birdsim.validation.run import load_flying_bird
from birdsim.validation.scorecard import model_value, sweep_speeds
from birdsim.validation.tablecheck import find_table, level_flight_from_table
from birdsim.validation.trim import angle_of_attack_deg, trim_sweep

MEASURED_AOA_UP = 66.0  # deg, Crandell & Tobalske 2011 (the data file's CT11_aoa_up)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--model", default="m5")
    args = ap.parse_args()
    bird = load_flying_bird(None)
    ms = load_measurements()
    speeds = sweep_speeds(ms)
    table = find_table(bird, args.model)
    tab = level_flight_from_table(table, bird, speeds) if table is not None else None
    sweep = trim_sweep(args.model, bird, speeds, extra_starts=tab.starts if tab else None)
    print(f"{args.model}: {sweep.seconds:.0f} s")
    print(
        " V m/s  pitch  sp   flap_plane  wingtip  |AoA_up| ratio |AoA_down|  fold  sup  table_pitch trimmed"
    )
    for i, p in enumerate(sweep.points):
        aoa = abs(angle_of_attack_deg(sweep.model, bird, p, math.pi))
        down = abs(angle_of_attack_deg(sweep.model, bird, p, 0.0))
        row = tab.starts[i] if tab is not None else None
        tp = "" if row is None else f"{math.degrees(row[table.param_names.index('pitch')]):6.2f}"
        print(
            f"{p.speed:6.2f} {p.body_angle_deg:6.2f} {math.degrees(p.params.get('stroke_plane', 0.0)):6.2f}"
            f" {p.flap_plane_deg:8.2f} {p.stroke_plane_deg:8.2f} {aoa:8.2f} {aoa / MEASURED_AOA_UP:5.2f}"
            f" {down:8.2f} {p.params.get('fold_amp', 0.0):5.2f} {p.params.get('supination_amp', 0.0):5.2f}"
            f"  {tp:>6} {p.trimmed}"
        )
    pts = [p for p in sweep.points if p.trimmed and 6.0 - 1e-9 <= p.speed <= 20.0 + 1e-9]
    v = np.array([p.speed for p in pts])
    for name, attr in (
        ("flap plane", "flap_plane_deg"),
        ("wingtip (the row)", "stroke_plane_deg"),
        ("body angle", "body_angle_deg"),
    ):
        slope = np.polyfit(v, [getattr(p, attr) for p in pts], 1)[0]
        print(f"slope 6-20 m/s, {name}: {slope:+.3f} deg per m/s")
    for m in ms:
        if m.id in ("CT11_aoa_up", "CT11_aoa_down"):
            v = model_value(m, sweep, bird)
            ratio = "-" if v is None else f"{v / m.value:.3f}"
            print(f"{m.id} ({m.measured_text()}): birdsim {v}, ratio {ratio}")


if __name__ == "__main__":
    main()
