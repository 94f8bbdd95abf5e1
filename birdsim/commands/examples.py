"""``birdsim examples``: the dissertation's example wingbeats (eqs 57-88) as a table."""

from __future__ import annotations

import argparse

from birdsim.commands.common import REDUCED_UNITS
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.examples import EXAMPLES


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "examples", help="mean forces of the dissertation's example wingbeats", description=__doc__
    )
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    print(
        "Dissertation examples (sec. 3.5); force = right wing + body drag, seed axes (Fz < 0 is up)"
    )
    u = REDUCED_UNITS  # the seed bird
    print(f"units: V in {u['speed']}, Fx, Fy, Fz in {u['force']}, P in {u['power']}")
    print(
        f"{'eq':>3s} {'model':5s} {'regime':6s} {'V':>4s} {'Fx':>8s} {'Fy':>8s} {'Fz':>8s} {'P':>8s} {'Fz range':>17s}"
    )
    for ex in EXAMPLES:
        c = evaluate_cycle(ex.model, ex.params, ex.speed, check_bounds=False)
        m = c.mean
        print(
            f"{ex.equation:3d} {ex.model:5s} {ex.regime:6s} {ex.speed:4.1f} {float(m.Fx):+8.4f} {float(m.Fy):+8.4f} "
            f"{float(m.Fz):+8.4f} {float(m.P):+8.4f}   [{c.Fz.min():+.3f}, {c.Fz.max():+.3f}]"
        )
    return 0
