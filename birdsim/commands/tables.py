"""``birdsim tables build|info|lookup``: optimal-wingbeat lookup tables over (Fx, Fz, V).

Forces are the dissertation's: right wing + body drag, seed earth axes, Fz < 0 is up.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from birdsim.commands.common import add_bird_arguments, bird_from_args
from birdsim.errors import BirdsimError, check_finite
from birdsim.io import check_output
from birdsim.physics.kinematics import get_model
from birdsim.physics.units import reduced_bird
from birdsim.tables.build import BuildConfig, BuildSettings, Grid, build_table
from birdsim.tables.cost import FRACTION_NAMES, CostWeights
from birdsim.tables.lookup import STATUS_NAMES, load_table, table_paths
from birdsim.tables.smoothness import table_smoothness

FORCE_NOTE = "right wing + body drag (the dissertation's flapcost force), Fz < 0 is up"


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "tables",
        help="build, inspect and query optimal-wingbeat lookup tables",
        description=__doc__,
    )
    tsub = p.add_subparsers(
        dest="tables_command", metavar="{build,info,lookup}", required=True, parser_class=type(p)
    )

    b = tsub.add_parser("build", help="optimise every cell of a (Fx, Fz, V) grid for one model")
    b.add_argument("--model", required=True, help="base, m1, m2, m3 or m4")
    b.add_argument(
        "--grid",
        default="",
        help='e.g. "Fx=-0.5:0.5:11,Fz=-0.5:0:11,V=0:1:11" or "V=0|0.5|1"; '
        "axes left out take the default range (Fx=-0.5:0.5, Fz=-0.5:0, V=0:1)",
    )
    b.add_argument(
        "--size",
        type=int,
        default=11,
        help="nodes per axis for axes not given in --grid (default 11)",
    )
    b.add_argument(
        "--climb",
        action="store_true",
        help="add the climb axis (vertical speed relative to the air, up): "
        "7 nodes in [-0.5, 0.5] unless --grid gives climb=LO:HI:COUNT",
    )
    b.add_argument(
        "--out", help="output table (default tables/<model>.npz; a .json is written beside it)"
    )
    b.add_argument("--force", action="store_true", help="overwrite an existing table")
    b.add_argument(
        "--jobs",
        type=int,
        default=None,
        help="worker processes (default: all cores; 1 = no processes)",
    )
    b.add_argument(
        "--dask",
        metavar="SCHEDULER",
        help="run the tasks on a Dask cluster: tcp://HOST:PORT (a running "
        "`dask scheduler`) or local:N (N worker processes started here); needs birdsim[cluster]",
    )
    b.add_argument(
        "--restart", action="store_true", help="discard checkpoints of an interrupted build"
    )
    b.add_argument(
        "--screen", type=int, default=BuildSettings.screen, help="screen candidates per V slice"
    )
    b.add_argument(
        "--starts",
        type=int,
        default=BuildSettings.starts,
        help="screen starts polished where the warm start is poor",
    )
    b.add_argument(
        "--relax", type=float, default=1.0, help="under-relaxation delta along V (eq. 94; 1 = off)"
    )
    b.add_argument(
        "--distance", type=float, default=0.0, help="distance-cost weight nu (eq. 93; 0 = off)"
    )
    b.add_argument(
        "--power-weight",
        type=float,
        default=CostWeights.power,
        help="weight of |P| in the cost (default 0.5)",
    )
    b.add_argument(
        "--reach-tol",
        type=float,
        default=BuildSettings.reach_tol,
        help="force error above which a cell is unreachable",
    )
    b.add_argument(
        "--no-v-passes", action="store_true", help="skip the forward/backward passes in V"
    )
    b.add_argument(
        "--smooth-tol",
        type=float,
        default=BuildSettings.smooth_tol,
        help="regularising pass: keep the wingbeat that continues its neighbours among those within this "
        "cost of the best found (default 5e-3; 0 = no pass)",
    )
    b.add_argument("--quiet", action="store_true", help="no progress bar")
    add_bird_arguments(b)
    b.set_defaults(func=run_build)

    i = tsub.add_parser(
        "info", help="grid, coverage, unreachable cells, cost statistics of a table"
    )
    i.add_argument("file", help="table .npz or .json")
    i.add_argument("--json", action="store_true", help="print JSON")
    i.set_defaults(func=run_info)

    q = tsub.add_parser("lookup", help="interpolated optimal wingbeat for one demand")
    q.add_argument("file", help="table .npz or .json")
    q.add_argument("--Fx", required=True, help="demanded mean Fx (dissertation force)")
    q.add_argument("--Fz", required=True, help="demanded mean Fz (< 0 is up)")
    q.add_argument("--V", required=True, help="flight speed")
    q.add_argument(
        "--climb",
        default="0",
        help="vertical speed relative to the air, positive up (default 0; "
        "other values need a table with a climb axis)",
    )
    q.add_argument("--clip", action="store_true", help="clip demands outside the grid to its edge")
    q.add_argument("--json", action="store_true", help="print JSON")
    q.set_defaults(func=run_lookup)


def _positive_int(name: str, value: int | None) -> None:
    if value is not None and value < 1:
        raise BirdsimError(f"{name} {value} is invalid; allowed: an integer >= 1")


def _check_build_options(args: argparse.Namespace) -> None:
    """Every build option checked here, so that a message names the flag the user typed
    (the settings' own checks name internal fields such as ``screen=0``)."""
    check_finite("--relax", args.relax)
    if not 0.0 < args.relax <= 1.0:
        raise BirdsimError(f"--relax {args.relax:g} is invalid; allowed: 0 < D <= 1 (1 = off)")
    for flag, value in (("--distance", args.distance), ("--power-weight", args.power_weight)):
        check_finite(flag, value)
        if value < 0:
            raise BirdsimError(f"{flag} {value:g} is invalid; allowed: a finite number >= 0")
    check_finite("--reach-tol", args.reach_tol)
    if not args.reach_tol > 0:
        raise BirdsimError(f"--reach-tol {args.reach_tol:g} is invalid; allowed: a number > 0")
    check_finite("--smooth-tol", args.smooth_tol)
    if args.smooth_tol < 0:
        raise BirdsimError(
            f"--smooth-tol {args.smooth_tol:g} is invalid; allowed: a number >= 0 (0 = no regularising pass)"
        )
    if args.screen < 2:
        raise BirdsimError(f"--screen {args.screen} is invalid; allowed: an integer >= 2")
    if args.starts < 0:
        raise BirdsimError(f"--starts {args.starts} is invalid; allowed: an integer >= 0")


def run_build(args: argparse.Namespace) -> int:
    import sys

    model = get_model(args.model)
    _positive_int("--jobs", args.jobs)
    if args.dask is not None:
        from birdsim.tables.cluster import parse_scheduler

        parse_scheduler(args.dask)
        if args.jobs is not None:
            raise BirdsimError(
                f"--jobs {args.jobs} with --dask {args.dask!r}; allowed: one of them (the cluster has its own workers)"
            )
    grid = Grid.parse(args.grid, args.size, climb=args.climb)
    # an SI bird gets a table in table units: the table records the reduced bird
    bird = reduced_bird(bird_from_args(args))
    if model.name == "m5":
        from birdsim.physics.m5 import fold_bird_error

        if (why := fold_bird_error(bird)) is not None:
            raise BirdsimError(f"--bird: {why}")
    _check_build_options(args)
    weights = CostWeights(power=args.power_weight, distance=args.distance)
    settings = BuildSettings(
        screen=args.screen,
        starts=args.starts,
        relax=args.relax,
        reach_tol=args.reach_tol,
        v_passes=not args.no_v_passes,
        smooth_tol=args.smooth_tol,
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

    def build(executor=None, name="executor"):  # type: ignore[no-untyped-def]
        # the table is written (existence checked above) before the checkpoints go
        return build_table(
            cfg,
            executor=executor,
            jobs=args.jobs,
            checkpoint_dir=ckpt,
            progress=not args.quiet,
            out=npz_path,
            force=True,
            notify=lambda line: print(f"birdsim tables: {line}", file=sys.stderr),
            executor_name=name,
        )

    try:
        if args.dask is None:
            table = build()
        else:
            from birdsim.tables.cluster import dask_executor

            with dask_executor(args.dask) as executor:
                table = build(executor, f"dask {args.dask}")
    except KeyboardInterrupt:  # one line, as every interrupted command (cli.main's exit status 130)
        print(
            f"birdsim tables: interrupted; finished parts kept in {ckpt}; run the same command again to resume",
            file=sys.stderr,
        )
        return 130
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
    per_v = {
        f"{v:g}": int(np.sum(status[:, :, k] == "unreachable")) for k, v in enumerate(t.axes["V"])
    }
    frac = t.cost_fractions.reshape(-1, len(FRACTION_NAMES)).mean(axis=0)
    return {
        "file": str(table_paths(path)[0]),
        "model": t.model,
        "bird": t.bird.name,
        "force": FORCE_NOTE,
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
    }
    if args.json:
        print(json.dumps(result, indent=2))
        return 0
    print(
        f"model {t.model}, demand Fx={fx:g} Fz={fz:g} V={v:g} climb={vc:g} ({FORCE_NOTE}); cell status: {result['status']}"
    )
    for n, val in params.items():
        print(f"  {n:14s} {val:+.4f} rad")
    a = result["achieved_interpolated"]
    print(f"  achieved (interpolated): Fx={a['Fx']:+.4f} Fz={a['Fz']:+.4f} P={a['P']:+.4f}")
    return 0
