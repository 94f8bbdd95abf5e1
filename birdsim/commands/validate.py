"""``birdsim validate``: the model against published measurements of real pigeons -- a
scorecard of rows (measured value and source, birdsim's value from the trimmed
level-flight wingbeat, ratio, verdict), optionally as JSON or as an HTML page."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from birdsim.commands.common import MODEL_LIST


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "validate",
        help="score the model against measured pigeons (power curve, kinematics)",
        description=__doc__,
    )
    p.add_argument(
        "--model",
        default="m3",
        help=f"kinematic model: {MODEL_LIST} (default m3: its flap reaches the pigeon's amplitudes)",
    )
    p.add_argument(
        "--bird",
        metavar="FILE.toml",
        help="bird file with mass and gravity, or a shipped bird's name (pigeon; default: models/pigeon.toml)",
    )
    p.add_argument(
        "--polar",
        choices=("seed", "robofly"),
        help="replace the bird's polar (default: the bird file's)",
    )
    p.add_argument(
        "--data",
        metavar="FILE.csv",
        help="measurements CSV (default: the shipped pigeon measurements)",
    )
    p.add_argument(
        "--json",
        action="store_true",
        help="print one JSON object (model, rows, power_curve, min_power_speed)",
    )
    p.add_argument(
        "--out", metavar="DIR", help="write index.html, figures and scorecard.json into DIR"
    )
    p.add_argument("--force", action="store_true", help="overwrite a page already in DIR")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from birdsim.commands.common import bird_file, flag_names
    from birdsim.physics.kinematics import get_model
    from birdsim.validation.measurements import load_measurements
    from birdsim.validation.page import check_page_folder, write_page
    from birdsim.validation.run import load_flying_bird, scorecard_text, validate

    get_model(args.model)  # unknown model: one line before any work
    with flag_names({"path=": "--bird "}):  # a shipped bird's name, as every --bird takes
        path = bird_file(args.bird) if args.bird else None
    bird = load_flying_bird(path, args.polar)
    ms = load_measurements(args.data)
    if args.out:
        check_page_folder(Path(args.out), args.force)
    v = validate(
        bird,
        args.model,
        ms,
        bird_file=str(args.bird or "models/pigeon.toml"),
        progress=not args.json,
    )
    if args.out:
        index = write_page(Path(args.out), v.obj, v.rows, v.sweep, v.variants, force=args.force)
    if args.json:
        print(json.dumps(v.obj, indent=1))
    else:
        print(scorecard_text(v))
        if args.out:
            print(f"page: {index}")
    return 0
