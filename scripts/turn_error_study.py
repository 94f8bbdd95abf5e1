"""Decompose a turning preset's path error (issue 23): per whole wingbeat the error along
the track, to the left of it and in height (m for a bird in metres, else semispans), the
bank about the heading against its command and against ``atan(a_c / g)`` of the flown
path (``turn_summary.turn_series``), the body's angle of attack and sideslip (the air
velocity in body axes, calm air), its mean pitch rate and the stroke plane (degrees);
then the RMS after two wingbeats per component, split into the turn's steady part and
the rest.

    PYTHONPATH=$PWD python scripts/turn_error_study.py circle --bird models/pigeon.toml
    PYTHONPATH=$PWD python scripts/turn_error_study.py s-turn --mirror --bird models/pigeon.toml

``--mirror`` (s-turn only): the s-turn to the right first, then to the left.
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from birdsim.commands.fly import load_table_for
from birdsim.export.bvh import quat_to_matrix
from birdsim.flight.flightlog import log_arrays
from birdsim.flight.freeflight import fly
from birdsim.flight.presets import CRUISE_SPEED, DEMO_MODEL, demo_bird
from birdsim.flight.simulate import SimConfig
from birdsim.flight.turn_presets import (
    CIRCLE_RADIUS,
    CRUISE_RAMP_BEATS,
    TURN_PRESETS,
    level_turns,
)
from birdsim.flight.turn_summary import turn_series
from birdsim.physics.bird import Bird


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("preset", choices=sorted(TURN_PRESETS))
    ap.add_argument("--bird", default=None)
    ap.add_argument("--model", default=DEMO_MODEL)
    ap.add_argument("--mirror", action="store_true", help="s-turn only: right first")
    args = ap.parse_args()
    if args.mirror and args.preset != "s-turn":
        ap.error(f"--mirror: preset {args.preset!r}; allowed: s-turn")
    path = TURN_PRESETS[args.preset]
    if args.mirror:  # the s-turn's shape (turn_presets) with the turns' signs swapped
        q = 0.25 * math.pi
        path = level_turns("s-turn", [-q, q], CRUISE_SPEED, CIRCLE_RADIUS, CRUISE_RAMP_BEATS, "")
    bird = Bird.from_toml(args.bird) if args.bird else demo_bird()
    table = load_table_for(bird, args.model, None)
    r = fly(path, table, bird, args.model, config=SimConfig(attitude="free"))
    a = {k: np.asarray(v) for k, v in r.arrays.items()}
    unit = bird.semispan  # the log is in semispans
    beats = a["t"] / (2.0 * np.pi)
    e = np.stack([a["x"] - a["x_ref"], a["y"] - a["y_ref"], a["z"] - a["z_ref"]], 1) * unit
    series = turn_series(log_arrays(r, args.preset))  # the bird's own units
    n = len(series["psi_ref"])
    idx = np.floor(beats + 1e-9).astype(int)
    psi = series["psi_ref"][np.clip(idx, 0, n - 1)]  # the reference's wingbeat heading
    along = np.cos(psi) * e[:, 0] + np.sin(psi) * e[:, 1]
    left = -np.sin(psi) * e[:, 0] + np.cos(psi) * e[:, 1]
    rot = quat_to_matrix(a["qpos"][:, 3:7])
    v_body = np.einsum("nji,nj->ni", rot, a["qvel"][:, :3])
    aoa = np.degrees(np.arctan2(-v_body[:, 2], v_body[:, 0]))
    slip = np.degrees(np.arctan2(v_body[:, 1], v_body[:, 0]))
    deg = np.degrees
    flap = a["flap_amp"] - 0.5 * a["u_flap_amp"] if "u_flap_amp" in a else a["flap_amp"]
    print(
        " wb   along    left  height | bank  cmd  coord | aoa  slip  pitch  cmd | q     sp  |  Fx    flap"
    )
    for b in range(n):
        s = idx == b
        print(
            f"{b:3d} {along[s].mean():7.4f} {left[s].mean():7.4f} {e[s, 2].mean():7.4f} |"
            f" {deg(series['bank'][b]):5.1f} {deg(a['bank_command'][s].mean()):5.1f}"
            f" {deg(series['coordinated'][b]):5.1f} | {aoa[s].mean():5.1f} {slip[s].mean():5.1f}"
            f" {deg(a['pitch'][s].mean()):5.1f} {deg(a['pitch_command'][s].mean()):5.1f} |"
            f" {a['omega_body'][s, 1].mean():6.3f} {deg(a['stroke_plane'][s].mean()):5.1f} |"
            f" {a['Fx_demand'][s].mean():6.3f} {flap[s].mean():5.2f}"
        )
    after = beats >= 2.0
    steady = np.zeros(len(beats), dtype=bool)
    steady[after] = series["steady"][np.clip(idx[after], 0, n - 1)]
    for name, m in (("after two", after), ("steady", after & steady), ("rest", after & ~steady)):
        if not m.any():
            continue
        parts = [np.sqrt(np.mean(c[m] ** 2)) for c in (np.linalg.norm(e, axis=1), along, left)]
        parts.append(np.sqrt(np.mean(e[m, 2] ** 2)))
        means = [c[m].mean() for c in (along, left, e[:, 2])]
        print(
            f"{name:9s} samples {int(m.sum()):5d}  RMS 3-D {parts[0]:.4f} along {parts[1]:.4f}"
            f" left {parts[2]:.4f} height {parts[3]:.4f};  mean along {means[0]:+.4f}"
            f" left {means[1]:+.4f} height {means[2]:+.4f}"
        )


if __name__ == "__main__":
    main()
