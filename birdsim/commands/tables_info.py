"""``birdsim tables info|lookup``: what a table holds (grid, coverage, unreachable
cells, smoothness, cost, provenance) and its interpolated wingbeat for one demand.

Forces are the dissertation's: right wing + body drag, seed earth axes, Fz < 0 is up.
"""

from __future__ import annotations

import argparse
import json

import numpy as np

from birdsim.commands.common import REDUCED_UNITS
from birdsim.errors import check_finite
from birdsim.tables.cost import FRACTION_NAMES
from birdsim.tables.lookup import STATUS_NAMES, load_table, table_paths
from birdsim.tables.smoothness import table_smoothness

FORCE_NOTE = "right wing + body drag (the dissertation's flapcost force), Fz < 0 is up"
#: Tables are non-dimensional whatever bird they were built for (docs/flight.md).
TABLE_UNITS = {
    **REDUCED_UNITS,
    "cost": "reduced units: |dFx| + |dFz| + 0.5 |P| (+ the small terms of docs/tables.md)",
}


def table_summary(path: str) -> dict:
    t = load_table(path)
    m = t.meta
    status = t.status
    unreachable = np.argwhere(status == "unreachable")
    cells = int(np.prod(t.shape))
    per_v = {
        f"{v:g}": int(np.sum(status[:, :, k] == "unreachable")) for k, v in enumerate(t.axes["V"])
    }
    frac = t.cost_fractions.reshape(-1, len(FRACTION_NAMES)).mean(axis=0)
    return {
        "file": str(table_paths(path)[0]),
        "model": t.model,
        "bird": t.bird.name,
        "force": FORCE_NOTE,
        "units": TABLE_UNITS,
        "param_names": list(t.param_names),
        "grid": {
            a: {"min": float(t.axes[a][0]), "max": float(t.axes[a][-1]), "count": len(t.axes[a])}
            for a in t.axis_names
        },
        "climb_axis": t.has_climb,
        "cells": cells,
        "status": {s: int(np.sum(status == s)) for s in STATUS_NAMES},
        "coverage": float(np.mean(status == "ok")),
        "solver_not_converged": int(np.sum(~np.asarray(t.converged, dtype=bool))),
        "unreachable_per_V": per_v,
        "unreachable_examples": [
            {a: float(t.axes[a][idx[k]]) for k, a in enumerate(t.axis_names)}
            | {
                "achieved_Fx": float(t.achieved[tuple(idx)][0]),
                "achieved_Fz": float(t.achieved[tuple(idx)][1]),
            }
            for idx in unreachable[:: max(1, len(unreachable) // 5)][:5]
        ],
        "max_force_error_ok": float(t.force_error[status == "ok"].max())
        if np.any(status == "ok")
        else None,
        "smoothness": smoothness(t),
        "cost": {
            "min": float(t.cost.min()),
            "median": float(np.median(t.cost)),
            "max": float(t.cost.max()),
        },
        "mean_cost_fractions": dict(zip(FRACTION_NAMES, map(float, frac))),
        "evaluations": int(t.evaluations.sum()),
        "provenance": {
            k: m.get(k)
            for k in (
                "package_version",
                "git_commit",
                "built_at",
                "build_seconds",
                "cells_per_second",
                "cost_weights",
                "solver",
                "regularising_pass",
            )
        },
    }


def smoothness(t) -> dict:
    """The library's smoothness measure (:mod:`birdsim.tables.smoothness`) as a dict."""
    return table_smoothness(t).to_dict()


def run_info(args: argparse.Namespace) -> int:
    s = table_summary(args.file)
    if args.json:
        print(json.dumps(s, indent=2))
        return 0
    print(f"{s['file']}: model {s['model']}, bird {s['bird']}; force: {s['force']}")
    u = s["units"]
    print(
        f"units (tables are non-dimensional): Fx, Fz in {u['force']}, P in {u['power']}, "
        f"V in {u['speed']}, wingbeat parameters in {u['angle']}; cost in {u['cost']}"
    )
    print(
        "grid: "
        + ", ".join(
            f"{a} [{g['min']:g}, {g['max']:g}] x {g['count']}" for a, g in s["grid"].items()
        )
        + ("" if s["climb_axis"] else "; no climb axis (level flight: lookups answer climb = 0)")
    )
    print(f"parameters: {', '.join(s['param_names'])}")
    st = s["status"]
    print(
        f"cells: {s['cells']}; ok {st['ok']} ({100 * s['coverage']:.1f} %), unreachable {st['unreachable']}, failed {st['failed']}"
    )
    print(
        f"cells whose kept SLSQP answer stopped without converging (e.g. iteration limit): {s['solver_not_converged']}"
    )
    print("unreachable per V: " + ", ".join(f"{v}: {n}" for v, n in s["unreachable_per_V"].items()))
    for ex in s["unreachable_examples"]:
        print(
            f"  e.g. demand Fx={ex['Fx']:+.3f} Fz={ex['Fz']:+.3f} V={ex['V']:.3f} -> achieved Fx={ex['achieved_Fx']:+.3f} Fz={ex['achieved_Fz']:+.3f}"
        )
    if s["max_force_error_ok"] is not None:
        print(f"largest force error of an ok cell: {s['max_force_error_ok']:.2e}")
    sm = s["smoothness"]
    print(
        f"smoothness: zig-zag share {100 * sm['zigzag_share']:.1f} % ({sm['zigzag_triples']} of {sm['triples']} reachable "
        f"triples go out and back by > {sm['zigzag_rad']} rad; "
        + ", ".join(f"along {a} {100 * v:.1f} %" for a, v in sm["per_axis"].items())
        + ")"
    )
    print(
        "largest step between reachable neighbours (rad): "
        + ", ".join(f"{n} {v:.3f}" for n, v in sm["largest_jump"].items())
    )
    for w in sm["worst"][:3]:
        where = " ".join(f"{a}={w[a]:+.3f}" for a in s["grid"])
        print(f"  zig-zag of {w['size_rad']:.3f} rad in {w['param']} along {w['axis']} at {where}")
    c = s["cost"]
    print(
        f"cost: min {c['min']:.4f}, median {c['median']:.4f}, max {c['max']:.4f}; mean fractions "
        + ", ".join(f"{k} {100 * v:.0f} %" for k, v in s["mean_cost_fractions"].items())
    )
    p = s["provenance"]
    print(
        f"built {p['built_at']} by birdsim {p['package_version']} (commit {p['git_commit']}) in {p['build_seconds']} s "
        f"({p['cells_per_second']} cells/s), {s['evaluations']} cycle evaluations"
    )
    print(f"cost weights: {p['cost_weights']}")
    rp = p.get("regularising_pass")
    if rp:
        print(
            f"regularising pass (tolerance {p['solver'].get('smooth_tol')}): {rp['rounds']} rounds, {rp['cells_resolved']} cells "
            f"re-solved, {rp['cells_changed']} changed, zig-zag cells per round {rp['zigzag_cells']}, {rp['seconds']} s"
        )
    else:
        print("regularising pass: none")
    return 0


def _demand(name: str, raw: str) -> float:
    return check_finite(f"--{name}", raw, "a finite number inside the table grid")


def run_lookup(args: argparse.Namespace) -> int:
    t = load_table(args.file)
    fx, fz, v = _demand("Fx", args.Fx), _demand("Fz", args.Fz), _demand("V", args.V)
    vc = _demand("climb", args.climb)
    out = t.lookup_many(fx, fz, v, clip=args.clip, climb=vc)
    params = {n: float(out[n]) for n in t.param_names}
    result = {
        "model": t.model,
        "demand": {"Fx": fx, "Fz": fz, "V": v, "climb": vc},
        "clipped": bool(args.clip),
        "params": params,
        "achieved_interpolated": {k: float(out[f"achieved_{k}"]) for k in ("Fx", "Fz", "P")},
        "status": t.status_at(fx, fz, v, clip=args.clip, climb=vc),
        "force": FORCE_NOTE,
        "units": TABLE_UNITS,
    }
    if args.json:
        print(json.dumps(result, indent=2))
        return 0
    print(
        f"model {t.model}, demand Fx={fx:g} Fz={fz:g} ({TABLE_UNITS['force']}) V={v:g} climb={vc:g} "
        f"({TABLE_UNITS['speed']}; {FORCE_NOTE}); cell status: {result['status']}"
    )
    for n, val in params.items():
        print(f"  {n:14s} {val:+.4f} rad")
    a = result["achieved_interpolated"]
    print(
        f"  achieved (interpolated): Fx={a['Fx']:+.4f} Fz={a['Fz']:+.4f} {TABLE_UNITS['force']}, "
        f"P={a['P']:+.4f} {TABLE_UNITS['power']}"
    )
    return 0
