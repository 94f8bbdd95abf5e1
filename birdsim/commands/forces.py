"""``birdsim forces``: the mean force and power of one wingbeat."""

from __future__ import annotations

import argparse
import json
import math

from birdsim.commands.common import (
    MODEL_LIST,
    add_bird_arguments,
    bird_from_args,
    parse_pairs,
    units_of,
)
from birdsim.errors import BirdsimError, check_number
from birdsim.physics.cycle import DEFAULT_SAMPLES, evaluate_cycle
from birdsim.physics.kinematics import get_model
from birdsim.physics.span import span_ratio

#: Most samples per wingbeat ``--samples`` accepts (the histories are N long per strip).
MAX_SAMPLES = 100_000
FORCE_NOTE = "mean: right wing + body drag (the dissertation's flapcost force); whole bird: 2 wings + body drag"


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("forces", help="mean Fx, Fy, Fz and P of one wingbeat", description=__doc__)
    p.add_argument("--model", required=True, help=MODEL_LIST)
    p.add_argument("--speed", required=True, help="flight speed V >= 0 (non-dimensional)")
    p.add_argument(
        "--climb", default="0", help="vertical speed relative to the air, positive up (default 0)"
    )
    p.add_argument(
        "--param",
        action="append",
        metavar="NAME=VALUE",
        help="a wingbeat parameter (radians); any not given is filled from the model's defaults (birdsim params)",
    )
    p.add_argument(
        "--samples",
        type=int,
        default=DEFAULT_SAMPLES,
        help=f"samples per wingbeat (default {DEFAULT_SAMPLES}: the mean within 1e-7 of the converged mean)",
    )
    p.add_argument(
        "--appendix-grid",
        action="store_true",
        help="the dissertation's grid: 11 samples, t=0 and t=T",
    )
    p.add_argument(
        "--json", action="store_true", help="print JSON (keys mean.Fx, mean.Fy, mean.Fz, mean.P)"
    )
    add_bird_arguments(p)
    p.set_defaults(func=run)


def _float(arg: str, raw: str) -> float:
    try:
        return float(raw)
    except ValueError:
        raise BirdsimError(
            f"{arg}={raw!r} is not a number; allowed: a number (radians for angles)"
        ) from None


def run(args: argparse.Namespace) -> int:
    model = get_model(args.model)
    bird = bird_from_args(args)
    raw = parse_pairs(args.param, "--param")
    params = {}
    for name, value in raw.items():
        model.spec(name)  # unknown name -> one clear line
        params[name] = _float(f"--param {name}", value)
    speed = _float("--speed", args.speed)
    # a parameter not given is filled from the model's defaults (hover at V = 0, else cruise)
    regime = "hover" if speed == 0 else "cruise"
    filled = {n: v for n, v in model.guess(regime).items() if n not in params}
    params.update(filled)
    climb = _float("--climb", args.climb)
    if not math.isfinite(climb):
        raise BirdsimError(
            f"--climb {args.climb} is invalid; allowed: a finite number (positive up)"
        )
    check_number("--climb", climb, "a finite number (positive up)")
    if not args.appendix_grid and not 2 <= args.samples <= MAX_SAMPLES:
        raise BirdsimError(
            f"--samples {args.samples} is invalid; allowed: an integer >= 2 and <= {MAX_SAMPLES}"
        )
    n, endpoint = (11, True) if args.appendix_grid else (args.samples, False)
    cyc = evaluate_cycle(model, params, speed, climb=climb, bird=bird, n=n, endpoint=endpoint)
    out = {
        "model": model.name,
        "speed": speed,
        "climb": climb,
        "params": params,
        "samples": n,
        "filled": filled,
        "force": FORCE_NOTE,
        "mean": cyc.mean.as_dict(),
        "whole_bird": cyc.whole_bird_mean.as_dict(),
        "panels": {k: v.as_dict() for k, v in cyc.panel_mean.items()},
        "body_drag_x": float(cyc.body_drag_x),
        "body_drag_z": float(cyc.body_drag_z),
        "span_ratio": float(span_ratio(model, params, bird=bird)),
        "units": units_of(bird),
    }
    if len(cyc.joint_power_mean) > 1:
        out["joint_power"] = {g: float(v) for g, v in cyc.joint_power_mean.items()}
    if args.json:
        print(json.dumps(out, indent=2))
        return 0
    print(
        f"model {model.name}, V = {speed:g}, climb = {climb:g}, "
        + ", ".join(f"{k} = {v:g}" for k, v in params.items())
    )
    if filled:
        print(
            f"filled from the model's {regime} defaults (not given): "
            + ", ".join(f"{k} = {v:g}" for k, v in filled.items())
        )
    print(f"force: {FORCE_NOTE}")
    u = out["units"]
    print(f"units: Fx, Fy, Fz in {u['force']}, P in {u['power']}, V and climb in {u['speed']}")
    print(f"{'':12s}{'Fx':>10s}{'Fy':>10s}{'Fz':>10s}{'P':>10s}")
    rows = [("mean", out["mean"]), ("whole bird", out["whole_bird"])]
    rows += [(f"panel {k}", v) for k, v in out["panels"].items()] if len(out["panels"]) > 1 else []
    for label, row in rows:
        print(f"{label:12s}" + "".join(f"{row[k]:+10.4f}" for k in ("Fx", "Fy", "Fz", "P")))
    print(f"span ratio (mid-upstroke / mid-downstroke tip-to-tip span): {out['span_ratio']:.4f}")
    return 0
