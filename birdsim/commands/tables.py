"""``birdsim tables build|info|lookup``: optimal-wingbeat lookup tables over (Fx, Fz, V).
This module registers the three and builds; ``info`` and ``lookup`` are in
:mod:`birdsim.commands.tables_info`.

Forces are the dissertation's: right wing + body drag, seed earth axes, Fz < 0 is up.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from birdsim.commands import table_jacobians
from birdsim.commands.common import MODEL_LIST, add_bird_arguments, bird_from_args
from birdsim.commands.tables_info import FORCE_NOTE, run_info, run_lookup
from birdsim.errors import BirdsimError, check_finite
from birdsim.io import check_output
from birdsim.physics.kinematics import get_model
from birdsim.physics.units import reduced_bird
from birdsim.tables.build import BuildConfig, BuildSettings, Grid, build_table
from birdsim.tables.cost import INCIDENCE_PARAMS, CostWeights
from birdsim.tables.lookup import table_paths

#: The flight grid (``make flight-tables``, docs/flight.md): Fx, Fz in table force units,
#: V in omega s; 21 x 17 x 17 cells over what the presets ask of the seed bird and the
#: pigeon.  ``tables build --bird`` builds instead the grid of that bird's own preset
#: demands (:func:`birdsim.flight.preset_grid.preset_grid`) unless ``--grid`` or
#: ``--size`` says otherwise, so that the command the table finder suggests for a new
#: bird builds a table that flies the presets (issue 28, item 2).
FLIGHT_GRID = "Fx=-0.2:0.3:21,Fz=-0.4:0:17,V=0:0.8:17"
#: Nodes per axis of the general grid (Fx=-0.5:0.5, Fz=-0.5:0, V=0:1), as ``make tables``.
DEFAULT_SIZE = 11
#: What ``birdsim tables --help`` says (the module docstring is for developers).
DESCRIPTION = (
    "``birdsim tables build|info|lookup|jacobians``: optimal-wingbeat lookup tables over "
    "(Fx, Fz, V). Forces are the dissertation's: right wing + body drag, seed earth axes, "
    "Fz < 0 is up."
)


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "tables",
        help="build, inspect and query optimal-wingbeat lookup tables",
        description=DESCRIPTION,
    )
    tsub = p.add_subparsers(
        dest="tables_command",
        metavar="{build,info,lookup,jacobians}",
        required=True,
        parser_class=type(p),
    )

    b = tsub.add_parser("build", help="optimise every cell of a (Fx, Fz, V) grid for one model")
    b.add_argument("--model", required=True, help=MODEL_LIST)
    b.add_argument(
        "--grid",
        default="",
        help='e.g. "Fx=-0.5:0.5:11,Fz=-0.5:0:11,V=0:1:11" or "V=0|0.5|1"; '
        "axes left out take the default range (Fx=-0.5:0.5, Fz=-0.5:0, V=0:1); "
        "default with --bird: the grid of the four presets' demands for that bird, "
        "with room for the feedback (docs/your-bird.md)",
    )
    b.add_argument(
        "--size",
        type=int,
        default=None,
        help=f"nodes per axis for axes not given in --grid (default {DEFAULT_SIZE}; "
        "given with --bird: the general grid instead of the presets' grid)",
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
    b.add_argument(
        "--smooth-rounds",
        type=int,
        default=BuildSettings.smooth_rounds,
        help="regularising pass: at most this many red-black rounds (default 4; it stops "
        "earlier after a round that removes no zig-zag, with --smooth-fixed-point after one "
        "that changes nothing)",
    )
    b.add_argument(
        "--smooth-median",
        action="store_true",
        help="regularising pass: also start from the median of a cell's neighbours (the "
        "shipped m5 table's setting; docs/tables.md)",
    )
    b.add_argument(
        "--smooth-fixed-point",
        action="store_true",
        help="regularising pass: run rounds until one changes no cell (at most "
        "--smooth-rounds) instead of stopping after one that removes no zig-zag "
        "(the shipped m5 table's setting; docs/tables.md)",
    )
    b.add_argument(
        "--smooth-planes",
        action="store_true",
        help="after the regularising pass, move planes of zig-zag middles together "
        "(birdsim/tables/plane_moves.py; the shipped m5 table's setting)",
    )
    b.add_argument(
        "--incidence-weight",
        type=float,
        default=0.0,
        help="quadratic tie-break w_q * sum x_p^2 on the incidence-setting parameters "
        "(--incidence-params; 0 = off, recorded only when on; docs/tables.md)",
    )
    b.add_argument(
        "--incidence-params",
        default=None,
        help="comma-separated parameters of the incidence tie-break (default "
        f"{','.join(INCIDENCE_PARAMS)}, those the model has)",
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
    table_jacobians.register(tsub)


def _positive_int(name: str, value: int | None) -> None:
    if value is not None and value < 1:
        raise BirdsimError(f"{name} {value} is invalid; allowed: an integer >= 1")


def _check_build_options(args: argparse.Namespace) -> None:
    """Every build option checked here, so that a message names the flag the user typed
    (the settings' own checks name internal fields such as ``screen=0``)."""
    check_finite("--relax", args.relax)
    if not 0.0 < args.relax <= 1.0:
        raise BirdsimError(f"--relax {args.relax:g} is invalid; allowed: 0 < D <= 1 (1 = off)")
    for flag, value in (
        ("--distance", args.distance),
        ("--power-weight", args.power_weight),
        ("--incidence-weight", args.incidence_weight),
    ):
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
    for flag, on in (
        ("--smooth-fixed-point", args.smooth_fixed_point),
        ("--smooth-planes", args.smooth_planes),
    ):
        if on and not args.smooth_tol > 0:
            raise BirdsimError(
                f"{flag} with --smooth-tol {args.smooth_tol:g} is invalid; allowed: with a "
                "regularising pass (--smooth-tol > 0)"
            )
    if args.smooth_rounds < 1:
        raise BirdsimError(
            f"--smooth-rounds {args.smooth_rounds} is invalid; allowed: an integer >= 1"
        )
    if args.screen < 2:
        raise BirdsimError(f"--screen {args.screen} is invalid; allowed: an integer >= 2")
    if args.starts < 0:
        raise BirdsimError(f"--starts {args.starts} is invalid; allowed: an integer >= 0")


def _grid_spec(args: argparse.Namespace, bird) -> str:  # type: ignore[no-untyped-def]
    """``--grid``; with ``--bird`` and neither ``--grid`` nor ``--size``, the grid of the
    bird's preset demands (:func:`birdsim.flight.preset_grid.preset_grid`), or the flight
    grid for a bird that does not fly (no weight: its presets ask nothing of the wings)."""
    if not args.grid and args.bird is not None and args.size is None:
        if not (bird.mass > 0 and bird.gravity > 0):
            return FLIGHT_GRID
        from birdsim.flight.preset_grid import preset_grid

        return preset_grid(bird)
    return args.grid


def _size(args: argparse.Namespace) -> int:
    return DEFAULT_SIZE if args.size is None else args.size


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
    # an SI bird gets a table in table units: the table records the reduced bird
    bird = reduced_bird(bird_from_args(args))
    spec = _grid_spec(args, bird)
    grid = Grid.parse(spec, _size(args), climb=args.climb)
    if spec and not args.grid and not args.quiet:
        why = "the flight grid" if spec == FLIGHT_GRID else "the presets' demands for this bird"
        print(f"birdsim tables: grid {spec} ({why})", file=sys.stderr)
    if model.name == "m5":
        from birdsim.physics.m5 import fold_bird_error

        if (why := fold_bird_error(bird)) is not None:
            raise BirdsimError(f"--bird: {why}")
    _check_build_options(args)
    names = INCIDENCE_PARAMS
    if args.incidence_params is not None:
        names = tuple(n.strip() for n in args.incidence_params.split(",") if n.strip())
        if not names or any(n not in model.param_names for n in names):
            raise BirdsimError(
                f"--incidence-params {args.incidence_params!r} is invalid; allowed: "
                f"comma-separated parameters of {model.name}: {', '.join(model.param_names)}"
            )
    weights = CostWeights(
        power=args.power_weight,
        distance=args.distance,
        incidence=args.incidence_weight,
        incidence_params=names,
    )
    settings = BuildSettings(
        screen=args.screen,
        starts=args.starts,
        relax=args.relax,
        reach_tol=args.reach_tol,
        v_passes=not args.no_v_passes,
        smooth_tol=args.smooth_tol,
        smooth_rounds=args.smooth_rounds,
        smooth_median=args.smooth_median,
        smooth_fixed_point=args.smooth_fixed_point,
        smooth_planes=args.smooth_planes,
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


__all__ = [
    "DEFAULT_SIZE",
    "FLIGHT_GRID",
    "FORCE_NOTE",
    "register",
    "run_build",
    "run_info",
    "run_lookup",
]
