"""``birdsim envelope``: what a bird can do with the shipped table of a model -- the
largest lift at each speed, the heaviest bird that can hover, the speed range of level
flight, the minimum-power speed, the steepest climb (definitions: docs/flight.md)."""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

from birdsim.commands.common import (
    MODEL_LIST,
    REDUCED_UNITS,
    SI_UNITS,
    add_bird_arguments,
    bird_from_args,
)
from birdsim.flight.envelope import envelope
from birdsim.flight.presets import DEMO_MODEL, demo_bird
from birdsim.physics.kinematics import get_model
from birdsim.physics.units import scales
from birdsim.tables.lookup import load_table
from birdsim.tables.shipped import shipped_table

#: Whose force the envelope prints (docs/conventions.md, "Which force").
FORCE_NOTE = (
    "whole bird (2 wings + body drag) unless marked as the table's "
    "(right wing + body drag, the dissertation's flapcost force)"
)


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "envelope",
        help="what a bird can do with a table: lift, hover, speeds, power, climb",
        description=__doc__,
    )
    p.add_argument(
        "--model",
        default=DEMO_MODEL,
        help=f"{MODEL_LIST} (default {DEMO_MODEL}, the demo model)",
    )
    p.add_argument(
        "--table",
        metavar="FILE",
        help="lookup table (default: the shipped table built for this bird and model)",
    )
    p.add_argument(
        "--json",
        action="store_true",
        help="print JSON (reduced units; *_si in the bird file's units)",
    )
    add_bird_arguments(p)
    p.set_defaults(func=run)


def _fmt(x: float | None, spec: str = ".3f") -> str:
    return "-" if x is None or not math.isfinite(x) else format(x, spec)


def run(args: argparse.Namespace) -> int:
    model = get_model(args.model).name
    bird = bird_from_args(args, default=None if args.bird else demo_bird())
    path = Path(args.table) if args.table else shipped_table(bird, model)
    table = load_table(path)
    table.require_model(model)
    table.require_bird(bird)
    env = envelope(table, bird)
    if args.json:
        units = {
            "reduced": REDUCED_UNITS,
            "si": {k: v for k, v in SI_UNITS.items()},
            "note": "plain keys in reduced units (table units); *_si keys in the bird file's units",
        }
        print(
            json.dumps(
                {"table": str(path), "force": FORCE_NOTE, "units": units, **env.to_dict()},
                indent=2,
            )
        )
        return 0
    sc = scales(bird)
    si = bird.rho != 1.0 or bird.omega != 1.0 or bird.semispan != 1.0 or bird.chord != 1.0
    u_f, u_v, u_p = ("N", "m/s", "W") if si else ("", "", "")
    print(f"envelope of bird {bird.name!r} with model {model} (table {path})")
    print(f"force: {FORCE_NOTE}")
    print(
        f"units: force {sc.force:.4g} {u_f or '(rho omega^2 s^3 c)'}, speed {sc.speed:.4g} "
        f"{u_v or '(omega s)'}, power {sc.power:.4g} {u_p or '(rho omega^3 s^4 c)'}"
    )
    print(
        f"mass ratio m/(rho s^2 c) = {env.mass_ratio:.2f}; weight w = {env.weight:.4f} "
        f"(whole bird; level flight asks the table for Fz = {-env.weight / 2:+.4f})"
        + (f" = {env.weight_si:.3f} {u_f}" if si else "")
    )
    print(
        "per speed: largest trimmed lift (whole bird, reachable cells), level-flight "
        "acceleration limits (omega^2 s), steepest climb:"
    )
    print(
        f"  {'V':>5s} {'V ' + u_v:>9s} {'lift':>7s} {'lift ' + u_f:>9s} {'ax max':>8s} "
        f"{'ax min':>8s} {'climb deg':>9s}"
    )
    step = max(1, round(0.1 / (env.speeds[1] - env.speeds[0])))
    for i in range(0, len(env.speeds), step):
        v = env.speeds[i]
        print(
            f"  {v:5.2f} {v * sc.speed:9.3f} {_fmt(env.lift[i]):>7s} {_fmt(env.lift_si[i]):>9s} "
            f"{_fmt(env.accel_forward[i], '+.4f'):>8s} "
            f"{_fmt(env.accel_backward[i], '+.4f'):>8s} {_fmt(env.climb_angles_deg[i], '.1f'):>9s}"
        )
    print(
        "optimiser's best lift at Fx = 0 per table speed (whole bird): "
        + ", ".join(f"V={v:g}: {x:.3f}" for v, x in zip(env.best_lift_speeds, env.best_lift))
    )
    mass = f" ({env.hover_mass_si:.3g} kg)" if si and env.hover_mass_si is not None else ""
    print(
        f"heaviest bird that can hover: weight {env.hover_weight:.3f} (whole bird)"
        + (f" = {env.hover_weight_si:.3f} {u_f}{mass}" if si else "")
        + f"; this bird {'can' if env.can_hover else 'CANNOT'} hover"
    )
    if env.level_speeds:
        ranges = ", ".join(
            f"{a:.2f}-{b:.2f}" + (f" ({a * sc.speed:.2f}-{b * sc.speed:.2f} {u_v})" if si else "")
            for a, b in env.level_speeds
        )
        print(f"level flight at this weight: V in {ranges}")
        print(
            f"minimum-power speed: V = {env.min_power_speed:.2f}"
            + (f" ({env.min_power_speed_si:.2f} {u_v})" if si else "")
            + f", whole-bird power {env.min_power:.4f}"
            + (f" = {env.min_power_si:.3f} {u_p}" if si else "")
        )
    else:
        print("level flight at this weight: none (the table cannot carry this bird)")
    if env.climb_rate is not None:
        print(
            f"steepest climb: {env.climb_angle_deg:.1f} deg at V = {env.climb_speed:.2f}, "
            f"climb rate {env.climb_rate:.3f}"
            + (f" ({env.climb_rate_si:.2f} {u_v})" if si else "")
            + " (wind-axes reading of the table)"
        )
    else:
        print("steepest climb: none")
    return 0
