"""``birdsim tables jacobians TABLE [--out NEW | --force]``: add every cell's moments and
Jacobians (issue 22; :mod:`birdsim.tables.jacobians`) to a table file."""

from __future__ import annotations

import argparse
import time

from birdsim.errors import BirdsimError
from birdsim.io import check_output
from birdsim.tables.jacobians import table_jacobians
from birdsim.tables.lookup import load_table, table_paths


def register(tsub: argparse._SubParsersAction) -> None:
    """Add the ``jacobians`` subcommand to ``birdsim tables``."""
    j = tsub.add_parser(
        "jacobians",
        help="add every cell's wingbeat-mean moments and their Jacobians to a table",
        description=__doc__,
    )
    j.add_argument("file", help="table .npz or .json")
    j.add_argument("--out", help="write the table with Jacobians here (default: in place)")
    j.add_argument("--force", action="store_true", help="overwrite an existing output")
    j.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    out = args.out if args.out is not None else args.file
    npz, js = table_paths(out)
    if args.out is None and not args.force:
        raise BirdsimError(
            f"--out is missing: writing into {str(npz)!r} needs --force; allowed: --out NEW or --force"
        )
    check_output(npz, args.force, arg="--out")
    check_output(js, args.force, arg="--out (json)")
    table = load_table(args.file)
    t0 = time.perf_counter()
    jac = table_jacobians(table)
    object.__setattr__(table, "jacobians", jac)
    table.save(out, force=True)
    cells = table.params.size // len(table.param_names)
    print(
        f"{npz}: moments and Jacobians of {cells} cells for inputs "
        f"{', '.join(f'{n} ({k})' for n, k in jac.inputs)} in {time.perf_counter() - t0:.1f} s"
    )
    return 0
