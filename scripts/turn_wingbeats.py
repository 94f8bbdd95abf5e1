"""A turning flight's log wingbeat by wingbeat (docs/turning.md, "The pigeon's slow turns,
episode by episode"; a study, not the flight code).

Reads a flight log (``birdsim fly P --attitude free --out LOG.npz``) and prints per
wingbeat (the log's units: SI for a bird file, m and degrees here for SI logs):

* ``along``, ``lat``, ``up``: the wingbeat-mean path error (bird minus reference) along
  the reference's horizontal heading, to its left and up; ``err`` the RMS distance;
* ``psat``: samples where the path loop's force demand left the table (the log's
  ``saturated``: what ``rms``'s "no saturated sample" counts), ``asat``: samples where
  the attitude loop's inputs met their bounds (``attitude_saturated``, not counted there);
* ``Fz``: the wingbeat's most negative (largest upward) force demand (table units);
* ``pmax``: the wingbeat's largest body pitch measured from the reference's heading
  (:func:`pitch_from_heading`, degrees: past 90 the body is pitched over the vertical,
  which the log's Z-Y-X ``pitch`` (an arcsine) reads as 180 minus it);
* ``bank``, ``cmd``: the wingbeat-mean bank about the horizontal heading
  (:func:`birdsim.flight.bank.bank_of`, right wing down > 0) and its command (degrees);
* ``plan`` (with ``--preset``): the path's planned bank at the wingbeat's middle
  (:meth:`birdsim.flight.track.TrackFrame.bank_plan`, the command without the lateral
  loop's correction), and ``rate`` / ``acc`` its rate and acceleration (degrees per
  wingbeat, per wingbeat squared).

    PYTHONPATH=$PWD python scripts/turn_wingbeats.py LOG.npz [--preset turn-90]
"""

from __future__ import annotations

import argparse
import math
from typing import Any

import numpy as np

from birdsim.flight.bank import bank_of
from birdsim.flight.flightlog import LogError, load_log

TWO_PI = 2.0 * math.pi


def reference_heading(log: Any) -> np.ndarray:
    """Per sample: the reference's horizontal heading (rad, counter-clockwise from world
    x), held where the reference is at rest (its speed below a thousandth of its top)."""
    t = np.asarray(log["t"], dtype=float)
    ref = np.stack([log["x_ref"], log["y_ref"]], axis=1).astype(float)
    v = np.gradient(ref, t, axis=0)
    speed = np.hypot(v[:, 0], v[:, 1])
    psi = np.arctan2(v[:, 1], v[:, 0])
    moving = speed > 1e-3 * max(float(speed.max()), 1e-12)
    idx = np.maximum.accumulate(np.where(moving, np.arange(len(t)), 0))
    return psi[idx]


def pitch_from_heading(quat: np.ndarray, psi: np.ndarray) -> np.ndarray:
    """The elevation (degrees) of the body's x axis (MuJoCo quaternions (n, 4), w x y z)
    above the horizontal heading ``psi`` (n,), measured through the vertical: 90 with the
    body upright, 120 when pitched 30 degrees past it (nose leaning back)."""
    w, x, y, z = np.moveaxis(np.asarray(quat, dtype=float), -1, 0)
    bx = np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)])
    forward = np.cos(psi) * bx[0] + np.sin(psi) * bx[1]
    return np.degrees(np.arctan2(bx[2], forward))


def path_errors(log: Any) -> dict[str, np.ndarray]:
    """Per sample: the path error (bird minus reference, the log's length unit) ``along``
    the reference's horizontal heading (:func:`reference_heading`), ``lateral`` (to its
    left) and ``up``."""
    ref = np.stack([log["x_ref"], log["y_ref"]], axis=1).astype(float)
    psi = reference_heading(log)
    ex = np.asarray(log["x"], dtype=float) - ref[:, 0]
    ey = np.asarray(log["y"], dtype=float) - ref[:, 1]
    return {
        "along": np.cos(psi) * ex + np.sin(psi) * ey,
        "lateral": -np.sin(psi) * ex + np.cos(psi) * ey,
        "up": np.asarray(log["z"], dtype=float) - np.asarray(log["z_ref"], dtype=float),
    }


def wingbeat_rows(log: Any) -> list[dict[str, float]]:
    """One row per wingbeat (the last one partial) of :func:`path_errors`' wingbeat
    means, the saturated samples' counts, the largest upward force demand and the bank
    against its command (degrees)."""
    t_beats = np.asarray(log["t"], dtype=float) * float(log["omega"]) / TWO_PI
    err = path_errors(log)
    bank = np.degrees(bank_of(np.asarray(log["quat"], dtype=float)))
    pitch = pitch_from_heading(log["quat"], reference_heading(log))
    cmd = np.degrees(np.asarray(log["bank_command"], dtype=float))
    beat = np.floor(t_beats + 1e-9).astype(int)
    rows = []
    for k in range(int(beat.max()) + 1):
        m = beat == k
        if not m.any():
            continue
        dist = np.sqrt(err["along"][m] ** 2 + err["lateral"][m] ** 2 + err["up"][m] ** 2)
        rows.append(
            {
                "wingbeat": float(k),
                "along": float(err["along"][m].mean()),
                "lateral": float(err["lateral"][m].mean()),
                "up": float(err["up"][m].mean()),
                "err": float(np.sqrt(np.mean(dist**2))),
                "psat": float(np.sum(log["saturated"][m])),
                "asat": float(np.sum(log["attitude_saturated"][m])),
                "fz_min": float(np.min(log["Fz_demand"][m])),
                "pitch_max": float(pitch[m].max()),
                "bank": float(bank[m].mean()),
                "cmd": float(cmd[m].mean()),
            }
        )
    return rows


def planned_bank(log: Any, preset: str, beats: np.ndarray) -> np.ndarray:
    """The turning preset's planned bank at ``beats`` (wingbeats): (n, 3) value, rate and
    acceleration in degrees, per wingbeat and per wingbeat squared (the log's bird file
    gives the reduced gravity and time)."""
    from birdsim.flight.track import TrackFrame
    from birdsim.flight.turn_presets import TURN_PRESETS
    from birdsim.physics.units import reduced_bird, scales

    bird = log["bird_obj"]
    t_end = float(log["t"][-1]) / scales(bird).time
    track = TrackFrame(TURN_PRESETS[preset], t_end, reduced_bird(bird).gravity)
    out = []
    for b in beats:
        phi = track.bank_plan(float(b) * TWO_PI)[1]
        out.append([phi[0], phi[1] * TWO_PI, phi[2] * TWO_PI**2])
    return np.degrees(np.array(out))


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("log", help="a turning flight's log (.npz)")
    ap.add_argument("--preset", help="the turning preset flown (adds the planned bank)")
    args = ap.parse_args(argv)
    from birdsim.flight.turn_presets import TURN_PRESETS

    if args.preset is not None and args.preset not in TURN_PRESETS:
        ap.error(f"--preset {args.preset!r}; allowed: {', '.join(sorted(TURN_PRESETS))}")
    try:
        log = load_log(args.log)
    except LogError as e:
        ap.error(str(e))
    if "bank_command" not in log:
        ap.error(f"LOG {args.log!r} is not a turning flight's (no bank_command)")
    rows = wingbeat_rows(log)
    plan = None
    if args.preset:
        plan = planned_bank(log, args.preset, np.array([r["wingbeat"] + 0.5 for r in rows]))
    print(
        " wb  along    lat     up    err psat asat    Fz   pmax   bank    cmd"
        + ("   plan   rate    acc" if plan is not None else "")
    )
    for i, r in enumerate(rows):
        line = (
            f"{r['wingbeat']:3.0f} {r['along']:+.3f} {r['lateral']:+.3f} {r['up']:+.3f}"
            f" {r['err']:.3f} {r['psat']:4.0f} {r['asat']:4.0f} {r['fz_min']:+.3f}"
            f" {r['pitch_max']:6.1f} {r['bank']:+6.1f} {r['cmd']:+6.1f}"
        )
        if plan is not None:
            line += f" {plan[i, 0]:+6.1f} {plan[i, 1]:+6.1f} {plan[i, 2]:+6.1f}"
        print(line)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
