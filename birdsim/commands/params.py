"""``birdsim params``: each model's wingbeat parameters with meaning, unit, bounds and the
dissertation's example values (sec. 3.5, eqs 57-88)."""

from __future__ import annotations

import argparse
import json
import math
from typing import Any


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "params",
        help="the wingbeat parameters of each model (meaning, unit, bounds, examples)",
        description=__doc__,
    )
    p.add_argument(
        "model", nargs="?", metavar="MODEL", help="base, m1, m2, m3, m4 or m5 (default: all)"
    )
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(func=run)


def reference(model_name: str | None = None) -> dict[str, Any]:
    """model -> description and its parameters (name, symbol, meaning, unit, bounds,
    the cruise and hover defaults, and the dissertation's examples by equation)."""
    from birdsim.physics.examples import EXAMPLES
    from birdsim.physics.kinematics import MODELS, get_model

    names = [get_model(model_name).name] if model_name else list(MODELS)
    out: dict[str, Any] = {}
    for name in names:
        km = MODELS[name]
        exs = [e for e in EXAMPLES if e.model == name]
        out[name] = {
            "description": km.description,
            "params": [
                {
                    "name": p.name,
                    "symbol": p.symbol,
                    "meaning": p.doc,
                    "unit": "rad",
                    "lower": p.lower,
                    "upper": p.upper,
                    "default_hover": km.guess("hover")[p.name],
                    "default_cruise": km.guess("cruise")[p.name],
                    "examples": {
                        f"eq{e.equation} {e.regime} (V={e.speed:g})": e.params.get(p.name)
                        for e in exs
                    },
                }
                for p in km.params
            ],
        }
        if name == "m5":
            from birdsim.physics import m5

            for p in out[name]["params"]:
                p["bounds_source"] = m5.BOUND_SOURCES[p["name"]]
            out[name]["skeleton"] = dict(m5.SKELETON_SOURCES)
    return out


def _fmt(v: float | None) -> str:
    if v is None:
        return "-"
    for k, text in ((1, "pi"), (2, "pi/2"), (4, "pi/4"), (8, "pi/8"), (16, "pi/16")):
        if abs(v - math.pi / k) < 1e-12:
            return text
    return f"{v:.4g}"


def run(args: argparse.Namespace) -> int:
    ref = reference(args.model)
    if args.json:
        print(json.dumps(ref, indent=2))
        return 0
    for name, entry in ref.items():
        print(f"{name}: {entry['description']}")
        examples = list(entry["params"][0]["examples"])
        head = f"  {'name':13s}{'symbol':9s}{'unit':5s}{'bounds':18s}" + "".join(
            f"{e.split()[0]:>8s}" for e in examples
        )
        print(head + "   meaning")
        for p in entry["params"]:
            bounds = f"[{_fmt(p['lower'])}, {_fmt(p['upper'])}]"
            ex = "".join(f"{_fmt(v):>8s}" for v in p["examples"].values())
            print(
                f"  {p['name']:13s}{p['symbol']:9s}{p['unit']:5s}{bounds:18s}{ex}   {p['meaning']}"
            )
        print("  examples: " + ("; ".join(examples) or "none (beyond the dissertation)"))
        for p in entry["params"]:
            if "bounds_source" in p:
                print(f"  bounds of {p['name']}: {p['bounds_source']}")
        for field, text in entry.get("skeleton", {}).items():
            print(f"  bird.{field}: {text}")
    return 0
