"""``birdsim tables build|info|lookup``: optimal-wingbeat lookup tables over (Fx, Fz, V).

Forces are the dissertation's: right wing + body drag, seed earth axes, Fz < 0 is up.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from birdsim.tables.build import BuildConfig, BuildSettings, Grid, build_table
from birdsim.tables.cost import FRACTION_NAMES, CostWeights
from birdsim.errors import BirdsimError, check_finite
from birdsim.io import check_output
from birdsim.physics.kinematics import get_model
from birdsim.physics.units import reduced_bird
from birdsim.tables.lookup import AXES, STATUS_NAMES, load_table, table_paths
from birdsim.commands.common import add_bird_arguments, bird_from_args

FORCE_NOTE = "right wing + body drag (the dissertation's flapcost force), Fz < 0 is up"


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("tables", help="build, inspect and query optimal-wingbeat lookup tables", description=__doc__)
    tsub = p.add_subparsers(dest="tables_command", metavar="{build,info,lookup}", required=True, parser_class=type(p))

    b = tsub.add_parser("build", help="optimise every cell of a (Fx, Fz, V) grid for one model")
    b.add_argument("--model", required=True, help="base, m1, m2, m3 or m4")
    b.add_argument("--grid", default="", help='e.g. "Fx=-0.5:0.5:11,Fz=-0.5:0:11,V=0:1:11" or "V=0|0.5|1"; '
                   "axes left out take the default range (Fx=-0.5:0.5, Fz=-0.5:0, V=0:1)")
    b.add_argument("--size", type=int, default=11, help="nodes per axis for axes not given in --grid (default 11)")
    b.add_argument("--out", help="output table (default tables/<model>.npz; a .json is written beside it)")
    b.add_argument("--force", action="store_true", help="overwrite an existing table")
    b.add_argument("--jobs", type=int, default=None, help="worker processes (default: all cores; 1 = no processes)")
    b.add_argument("--restart", action="store_true", help="discard checkpoints of an interrupted build")
    b.add_argument("--screen", type=int, default=BuildSettings.screen, help="screen candidates per V slice")
    b.add_argument("--starts", type=int, default=BuildSettings.starts, help="screen starts polished where the warm start is poor")
    b.add_argument("--relax", type=float, default=1.0, help="under-relaxation delta along V (eq. 94; 1 = off)")
    b.add_argument("--distance", type=float, default=0.0, help="distance-cost weight nu (eq. 93; 0 = off)")
    b.add_argument("--power-weight", type=float, default=CostWeights.power, help="weight of |P| in the cost (default 0.5)")
    b.add_argument("--reach-tol", type=float, default=BuildSettings.reach_tol, help="force error above which a cell is unreachable")
    b.add_argument("--no-v-passes", action="store_true", help="skip the forward/backward passes in V")
    b.add_argument("--quiet", action="store_true", help="no progress bar")
    add_bird_arguments(b)
    b.set_defaults(func=run_build)

    i = tsub.add_parser("info", help="grid, coverage, unreachable cells, cost statistics of a table")
    i.add_argument("file", help="table .npz or .json")
    i.add_argument("--json", action="store_true", help="print JSON")
    i.set_defaults(func=run_info)

    q = tsub.add_parser("lookup", help="interpolated optimal wingbeat for one demand")
    q.add_argument("file", help="table .npz or .json")
    q.add_argument("--Fx", required=True, help="demanded mean Fx (dissertation force)")
    q.add_argument("--Fz", required=True, help="demanded mean Fz (< 0 is up)")
    q.add_argument("--V", required=True, help="flight speed")
    q.add_argument("--clip", action="store_true", help="clip demands outside the grid to its edge")
    q.add_argument("--json", action="store_true", help="print JSON")
    q.set_defaults(func=run_lookup)


def _positive_int(name: str, value: int | None) -> None:
    if value is not None and value < 1:
        raise BirdsimError(f"{name} {value} is invalid; allowed: an integer >= 1")


def run_build(args: argparse.Namespace) -> int:
    model = get_model(args.model)
    _positive_int("--jobs", args.jobs)
    grid = Grid.parse(args.grid, args.size)
    # tables are non-dimensional: a bird in any units is built as its reduced bird (the
    # seed bird is its own), so forces are in rho omega^2 s^3 c and the table records it
    bird = reduced_bird(bird_from_args(args))
    for name in ("relax", "distance", "power_weight", "reach_tol"):
        check_finite(f"--{name.replace('_', '-')}", getattr(args, name))
    weights = CostWeights(power=args.power_weight, distance=args.distance)
    settings = BuildSettings(
        screen=args.screen, starts=args.starts, relax=args.relax, reach_tol=args.reach_tol, v_passes=not args.no_v_passes
    )
    out = Path(args.out) if args.out else Path("tables") / f"{model.name}.npz"
    npz_path, json_path = table_paths(out)
    check_output(npz_path, args.force)
    check_output(json_path, args.force, arg="--out (json)")
    ckpt = npz_path.with_name(f".{npz_path.stem}.build")
    if args.restart and ckpt.exists():
        import shutil

        shutil.rmtree(ckpt)
    cfg = BuildConfig(model.name, grid, bird, weights, settings)
    try:
        table = build_table(cfg, jobs=args.jobs, checkpoint_dir=ckpt, progress=not args.quiet)
    except KeyboardInterrupt:
        import sys

        print(f"birdsim tables: finished parts kept in {ckpt}; run the same command again to resume", file=sys.stderr)
        raise
    table.save(npz_path, force=True)  # existence was checked before the build
    m = table.meta
    print(
        f"wrote {npz_path} and {json_path.name}: model {model.name}, grid {'x'.join(map(str, table.shape))}, "
        f"{m['counts']['ok']} ok, {m['counts']['unreachable']} unreachable, {m['counts']['failed']} failed, "
        f"{m['build_seconds']:.1f} s ({m['cells_per_second']:.0f} cells/s)"
    )
    return 0


def table_summary(path: str) -> dict:
    t = load_table(path)
    m = t.meta
    status = t.status
    unreachable = np.argwhere(status == "unreachable")
    cells = int(np.prod(t.shape))
    per_v = {f"{v:g}": int(np.sum(status[:, :, k] == "unreachable")) for k, v in enumerate(t.axes["V"])}
    frac = t.cost_fractions.reshape(-1, len(FRACTION_NAMES)).mean(axis=0)
    return {
        "file": str(table_paths(path)[0]),
        "model": t.model,
        "bird": t.bird.name,
        "force": FORCE_NOTE,
        "param_names": list(t.param_names),
        "grid": {a: {"min": float(t.axes[a][0]), "max": float(t.axes[a][-1]), "count": len(t.axes[a])} for a in AXES},
        "cells": cells,
        "status": {s: int(np.sum(status == s)) for s in STATUS_NAMES},
        "coverage": float(np.mean(status == "ok")),
        "solver_not_converged": int(np.sum(~np.asarray(t.converged, dtype=bool))),
        "unreachable_per_V": per_v,
        "unreachable_examples": [
            {a: float(t.axes[a][idx[k]]) for k, a in enumerate(AXES)}
            | {"achieved_Fx": float(t.achieved[tuple(idx)][0]), "achieved_Fz": float(t.achieved[tuple(idx)][1])}
            for idx in unreachable[:: max(1, len(unreachable) // 5)][:5]
        ],
        "max_force_error_ok": float(t.force_error[status == "ok"].max()) if np.any(status == "ok") else None,
        "smoothness": smoothness(t),
        "cost": {"min": float(t.cost.min()), "median": float(np.median(t.cost)), "max": float(t.cost.max())},
        "mean_cost_fractions": dict(zip(FRACTION_NAMES, map(float, frac))),
        "evaluations": int(t.evaluations.sum()),
        "provenance": {k: m.get(k) for k in ("package_version", "git_commit", "built_at", "build_seconds", "cells_per_second", "cost_weights", "solver")},
    }


def smoothness(t) -> dict[str, dict[str, float]]:
    """Parameter steps (rad) between neighbouring ok cells along each axis: the 95th
    percentile and the largest (a jump flags a branch switch or a flat optimum)."""
    ok = t.status == "ok"
    out = {}
    for k, a in enumerate(AXES):
        step = np.abs(np.diff(t.params, axis=k)).max(axis=-1)
        both = np.logical_and(np.delete(ok, -1, axis=k), np.delete(ok, 0, axis=k))
        vals = step[both]
        out[a] = {"p95": float(np.percentile(vals, 95)) if vals.size else 0.0, "max": float(vals.max()) if vals.size else 0.0}
    return out


def run_info(args: argparse.Namespace) -> int:
    s = table_summary(args.file)
    if args.json:
        print(json.dumps(s, indent=2))
        return 0
    print(f"{s['file']}: model {s['model']}, bird {s['bird']}; force: {s['force']}")
    print("grid: " + ", ".join(f"{a} [{g['min']:g}, {g['max']:g}] x {g['count']}" for a, g in s["grid"].items()))
    print(f"parameters: {', '.join(s['param_names'])}")
    st = s["status"]
    print(f"cells: {s['cells']}; ok {st['ok']} ({100 * s['coverage']:.1f} %), unreachable {st['unreachable']}, failed {st['failed']}")
    print(f"cells whose kept SLSQP answer stopped without converging (e.g. iteration limit): {s['solver_not_converged']}")
    print("unreachable per V: " + ", ".join(f"{v}: {n}" for v, n in s["unreachable_per_V"].items()))
    for ex in s["unreachable_examples"]:
        print(
            f"  e.g. demand Fx={ex['Fx']:+.3f} Fz={ex['Fz']:+.3f} V={ex['V']:.3f} -> achieved Fx={ex['achieved_Fx']:+.3f} Fz={ex['achieved_Fz']:+.3f}"
        )
    if s["max_force_error_ok"] is not None:
        print(f"largest force error of an ok cell: {s['max_force_error_ok']:.2e}")
    print("parameter steps between neighbouring ok cells (rad): " + ", ".join(
        f"along {a} p95 {v['p95']:.3f} max {v['max']:.3f}" for a, v in s["smoothness"].items()))
    c = s["cost"]
    print(f"cost: min {c['min']:.4f}, median {c['median']:.4f}, max {c['max']:.4f}; mean fractions " +
          ", ".join(f"{k} {100 * v:.0f} %" for k, v in s["mean_cost_fractions"].items()))
    p = s["provenance"]
    print(f"built {p['built_at']} by birdsim {p['package_version']} (commit {p['git_commit']}) in {p['build_seconds']} s "
          f"({p['cells_per_second']} cells/s), {s['evaluations']} cycle evaluations")
    print(f"cost weights: {p['cost_weights']}")
    return 0


def _demand(name: str, raw: str) -> float:
    return check_finite(f"--{name}", raw, "a finite number inside the table grid")


def run_lookup(args: argparse.Namespace) -> int:
    t = load_table(args.file)
    fx, fz, v = _demand("Fx", args.Fx), _demand("Fz", args.Fz), _demand("V", args.V)
    out = t.lookup_many(fx, fz, v, clip=args.clip)
    params = {n: float(out[n]) for n in t.param_names}
    result = {
        "model": t.model,
        "demand": {"Fx": fx, "Fz": fz, "V": v},
        "clipped": bool(args.clip),
        "params": params,
        "achieved_interpolated": {k: float(out[f"achieved_{k}"]) for k in ("Fx", "Fz", "P")},
        "status": t.status_at(fx, fz, v, clip=args.clip),
        "force": FORCE_NOTE,
    }
    if args.json:
        print(json.dumps(result, indent=2))
        return 0
    print(f"model {t.model}, demand Fx={fx:g} Fz={fz:g} V={v:g} ({FORCE_NOTE}); cell status: {result['status']}")
    for n, val in params.items():
        print(f"  {n:14s} {val:+.4f} rad")
    a = result["achieved_interpolated"]
    print(f"  achieved (interpolated): Fx={a['Fx']:+.4f} Fz={a['Fz']:+.4f} P={a['P']:+.4f}")
    return 0
