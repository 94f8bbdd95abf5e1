"""``birdsim bird new``: a bird TOML in SI units from its measurements (docs/your-bird.md)."""

from __future__ import annotations

import argparse
import re
from pathlib import Path

from birdsim.errors import BirdsimError


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "bird", help="make a bird file from measurements (bird new NAME ...)", description=__doc__
    )
    bsub = p.add_subparsers(dest="bird_command", required=True, metavar="{new}")
    n = bsub.add_parser(
        "new",
        help="write a bird TOML in SI units from mass, span, chord and wingbeat frequency",
        description=__doc__,
    )
    n.add_argument("name", metavar="NAME", help="the bird's name (also the default file name)")
    n.add_argument("--mass", required=True, metavar="KG", help="whole-bird mass (kg)")
    n.add_argument("--span", required=True, metavar="M", help="wingspan, tip to tip (m)")
    n.add_argument("--mean-chord", required=True, metavar="M", help="mean wing chord (m)")
    n.add_argument("--frequency", required=True, metavar="HZ", help="wingbeat frequency (Hz)")
    n.add_argument(
        "--body-drag-area",
        metavar="M2",
        help="body drag area (m^2; default semispan x chord, the seed bird's ratio)",
    )
    n.add_argument(
        "--source", default="", help="where the measurements come from (written into the file)"
    )
    n.add_argument("--out", metavar="FILE.toml", help="output file (default NAME.toml)")
    n.add_argument("--force", action="store_true", help="overwrite an existing file")
    n.set_defaults(func=run_new)


def _number(arg: str, raw: str | None) -> float | None:
    if raw is None:
        return None
    try:
        return float(raw)
    except ValueError:
        raise BirdsimError(f"{arg} {raw!r} is not a number") from None


def run_new(args: argparse.Namespace) -> int:
    from birdsim.commands.common import check_writable
    from birdsim.io import write_atomic
    from birdsim.physics.measured import bird_from_measurements, bird_toml, derived

    bird = bird_from_measurements(
        args.name,
        mass=_number("--mass", args.mass),  # type: ignore[arg-type]
        span=_number("--span", args.span),  # type: ignore[arg-type]
        mean_chord=_number("--mean-chord", args.mean_chord),  # type: ignore[arg-type]
        frequency=_number("--frequency", args.frequency),  # type: ignore[arg-type]
        body_drag_area=_number("--body-drag-area", args.body_drag_area),
    )
    slug = re.sub(r"[^A-Za-z0-9_.-]+", "_", args.name).strip("_") or "bird"
    out = Path(args.out) if args.out else Path(f"{slug}.toml")
    if out.suffix.lower() != ".toml":
        raise BirdsimError(f"--out {str(out)!r} does not end in .toml; allowed: a .toml path")
    check_writable(out, args.force)
    write_atomic(out, bird_toml(bird, source=args.source).encode())
    print(
        f"wrote {out} ({bird.name}: semispan {bird.semispan:g} m, chord {bird.chord:g} m, omega {bird.omega:.4g} rad/s, mass {bird.mass:g} kg)"
    )
    for line in derived(bird).lines():
        print(line)
    return 0
