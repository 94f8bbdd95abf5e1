"""Issue 22's figures of the four presets with the attitude free (and posed, for the
ratio): path RMS after two wingbeats (cruise: altitude), wingbeat-mean pitch RMS from
the command after two wingbeats, largest wingbeat-mean |roll| and |yaw|, attitude- and
table-saturated samples, median within-wingbeat pitch rocking (peak to peak).

    python scripts/free_targets.py [--bird FILE] [--model m3] [--presets cruise,hover]
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from birdsim.commands.fly import load_table_for
from birdsim.flight.attitude_summary import attitude_figures
from birdsim.flight.flightlog import log_arrays, summary
from birdsim.flight.freeflight import fly
from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS, demo_bird
from birdsim.flight.simulate import SimConfig
from birdsim.physics.bird import Bird


def figures(preset: str, bird, model: str, attitude: str, gusts=()) -> dict[str, float]:
    table = load_table_for(bird, model, None)
    r = fly(
        PATH_PRESETS[preset], table, bird, model, config=SimConfig(attitude=attitude), gusts=gusts
    )
    s = summary(log_arrays(r, preset))
    att = attitude_figures(r.arrays)
    key = "rms_altitude_error_after_start" if preset == "cruise" else "rms_error_after_start"
    return {
        "path_rms": s[key],
        "pitch_rms_deg": att["wingbeat_mean_pitch_rms_error_deg"],
        "roll_deg": att["wingbeat_mean_roll_max_deg"],
        "yaw_deg": att["wingbeat_mean_yaw_max_deg"],
        "att_sat": att["attitude_saturated_samples"],
        "table_sat_beats": s["wingbeats_saturated"],
        "rocking_deg": att["rocking_median_deg"],
    }


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--bird", default=None)
    ap.add_argument("--model", default=DEMO_MODEL)
    ap.add_argument("--presets", default="cruise,hover,take-off,landing")
    ap.add_argument("--posed", action="store_true")
    ap.add_argument("--gusts", action="store_true", help="cruise with 30 %% and 100 %% gusts")
    args = ap.parse_args()
    bird = Bird.from_toml(args.bird) if args.bird else demo_bird()
    if args.gusts:
        # the presets' cruise speed, 0.5 omega s, in the bird's velocity units (the gusts'
        # units: the seed bird's are reduced, the pigeon's m/s)
        v = 0.5 * bird.semispan * 2.0 * math.pi / bird.period
        for frac in (0.3, 1.0):
            for wind in ((0, v, 0), (0, 0, v), (v, 0, 0), (-v, 0, 0), (0, -v, 0), (0, 0, -v)):
                w = tuple(frac * c for c in wind)
                f = gust_figures(bird, args.model, w)
                print(f"gust {w}", "  ".join(f"{k} {x:.4g}" for k, x in f.items()), flush=True)
            if frac == 0.3:
                print("(100 % gusts: finite and no crash is the target)")
        return
    for p in args.presets.split(","):
        t0 = time.process_time()
        f = figures(p, bird, args.model, "posed" if args.posed else "free")
        f["cpu_s"] = time.process_time() - t0
        print(p.ljust(9), "  ".join(f"{k} {v:.4g}" for k, v in f.items()), flush=True)


def gust_figures(
    bird, model: str, wind: tuple[float, float, float], beats: float = 16.0, attitude: str = "free"
) -> dict[str, float]:
    """Cruise with a one-wingbeat gust ``wind`` (x fwd, y left, z up; bird velocity units)
    from wingbeat 3: the largest path error, wingbeat-mean roll and yaw (unfolded past the
    vertical), and the wingbeat after the gust's end by which the path is within 0.05
    semispan and roll and yaw within 2 degrees for good (nan: never). The flight log is in
    reduced units for every bird (time 2 pi per wingbeat, lengths in semispans)."""
    from birdsim.flight.attitude_summary import unfolded_euler
    from birdsim.flight.gust import parse_gust

    table = load_table_for(bird, model, None)
    g = parse_gust("3:1:" + ":".join(f"{w:g}" for w in wind))
    r = fly(
        PATH_PRESETS["cruise"],
        table,
        bird,
        model,
        beats=beats,
        gusts=[g],
        config=SimConfig(attitude=attitude),
    )
    a = r.arrays
    n = int(round(len(a["t"]) / (a["t"][-1] / (2 * math.pi))))
    nb = len(a["t"]) // n
    mean = lambda v: np.array([v[b * n : (b + 1) * n].mean() for b in range(nb)])  # noqa: E731
    err = np.sqrt((a["x_ref"] - a["x"]) ** 2 + a["y"] ** 2 + (a["z_ref"] - a["z"]) ** 2)
    e_beat = np.array([err[b * n : (b + 1) * n].max() for b in range(nb)])
    yaw_u, _, roll_u = unfolded_euler(a["yaw"], a["pitch"], a["roll"])  # past the vertical
    roll, yaw = np.degrees(mean(roll_u)), np.degrees(mean(yaw_u))
    ok = (e_beat <= 0.05) & (np.abs(roll) <= 2) & (np.abs(yaw) <= 2)
    back = float("nan")
    for b in range(4, nb):
        if ok[b:].all():
            back = b - 4
            break
    return {
        "max_err": float(err.max()),
        "roll_max_deg": float(np.abs(roll).max()),
        "yaw_max_deg": float(np.abs(yaw).max()),
        "err_end": float(e_beat[-1]),
        "beats_back": back,
        "finite": bool(np.all(np.isfinite(a["qpos"]))),
    }


if __name__ == "__main__":
    main()
