"""``birdsim report``: regenerate the dissertation's analysis as figures (PNGs) and one
HTML page with a line of explanation per figure and the dissertation's statements
checked against our numbers.  Needs the optional extra ``pip install birdsim[plots]``."""

from __future__ import annotations

import argparse

from birdsim.commands.common import add_bird_arguments, bird_from_args


def register(sub: argparse._SubParsersAction) -> None:
    from birdsim.report.report import FAMILIES

    p = sub.add_parser(
        "report", help="figures of the dissertation's analysis + index.html", description=__doc__
    )
    p.add_argument(
        "--out", default="report", metavar="DIR", help="output folder (default: report/)"
    )
    p.add_argument(
        "--quick", action="store_true", help="coarse grids and few samples (about a minute)"
    )
    p.add_argument("--force", action="store_true", help="overwrite an existing report in DIR")
    p.add_argument(
        "--only",
        action="append",
        metavar="FAMILY",
        help="build only these figure families (repeatable; the page then lists only them): "
        + ", ".join(f.key for f in FAMILIES),
    )
    add_bird_arguments(p)
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from birdsim.report.report import build_report

    sections = build_report(
        args.out,
        quick=args.quick,
        force=args.force,
        bird=bird_from_args(args),
        only=args.only,
        progress=None,
    )
    figures = sum(len(s.entries) for s in sections)
    print(f"report: {figures} figures in {args.out}/ (open {args.out}/index.html)")
    for s in sections:
        verdicts = ", ".join(f"{e.file.removesuffix('.png')}: {e.verdict}" for e in s.entries)
        print(f"  {s.family.key:11s} {s.seconds:6.1f} s  {s.error or verdicts}")
    return 0
