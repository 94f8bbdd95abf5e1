"""``birdsim crosscheck``: MuJoCo's mean force on the held bird against the analytic mean.

Per model, the dissertation's example wingbeats (and optionally seeded random parameter
sets): the analytic whole-bird mean (two wings + body drag, seed axes), the mean force
the body must be held with in MuJoCo (``mj_inverse``, and a welded forward simulation)
and their relative errors.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from birdsim.commands.common import add_bird_arguments, bird_from_args, units_of
from birdsim.errors import BirdsimError
from birdsim.io import check_output, temporary_sibling
from birdsim.physics.examples import EXAMPLES
from birdsim.physics.kinematics import MODELS, get_model

FORCE_NOTE = "whole bird (2 wings + body drag), seed earth axes (Fz < 0 is up)"
FIGURE_SUFFIXES = (".png", ".pdf", ".svg")
#: Largest ``--samples`` (MuJoCo steps per wingbeat) and ``--random`` (cases per model).
MAX_SAMPLES = 10_000
MAX_RANDOM = 10_000
#: Seeded random sets checked at least for a model with no dissertation example (m5).
NO_EXAMPLE_RANDOM = 2


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "crosscheck",
        help="MuJoCo's mean force on the held bird vs the analytic mean",
        description=__doc__,
    )
    p.add_argument("--model", default="all", help="base, m1, m2, m3, m4, m5 or all (default)")
    p.add_argument("--samples", type=int, default=64, help="samples per wingbeat (default 64)")
    p.add_argument(
        "--forward",
        choices=("held", "free", "none"),
        default="held",
        help="forward measurement: torso re-set each step (held, default), free under the weld, or none",
    )
    p.add_argument(
        "--random",
        type=int,
        default=0,
        metavar="K",
        help="also K seeded random parameter sets per model (at least 2 for m5, "
        "which has no dissertation example)",
    )
    p.add_argument(
        "--seed", type=int, default=0, help="seed of the random parameter sets (default 0)"
    )
    p.add_argument("--json", action="store_true", help="print JSON")
    p.add_argument("--figure", metavar="PATH", help="write a force-history figure (PNG/PDF/SVG)")
    p.add_argument("--force", action="store_true", help="overwrite an existing --figure")
    add_bird_arguments(p)
    p.set_defaults(func=run)


def _cases(models: list[str], k: int, seed: int) -> list[tuple[str, str, dict, float]]:
    cases = [
        (ex.model, f"eq{ex.equation}", dict(ex.params), ex.speed)
        for ex in EXAMPLES
        if ex.model in models
    ]
    rng = np.random.default_rng(seed)
    for name in models:
        km = get_model(name)
        lo, hi = km.bounds
        # a model without a dissertation example (m5) is checked on seeded random sets
        has_example = any(ex.model == name for ex in EXAMPLES)
        for i in range(k if has_example else max(k, NO_EXAMPLE_RANDOM)):
            cases.append(
                (
                    name,
                    f"random{i}",
                    dict(zip(km.param_names, map(float, rng.uniform(lo, hi)))),
                    float(rng.uniform(0, 1)),
                )
            )
    return sorted(cases, key=lambda c: models.index(c[0]))


def run(args: argparse.Namespace) -> int:
    from tqdm import tqdm

    from birdsim.mujoco.crosscheck import crosscheck

    models = list(MODELS) if args.model == "all" else [get_model(args.model).name]
    if not 2 <= args.samples <= MAX_SAMPLES:
        raise BirdsimError(
            f"--samples {args.samples} is invalid; allowed: an integer in [2, {MAX_SAMPLES}]"
        )
    if not 0 <= args.random <= MAX_RANDOM:
        raise BirdsimError(
            f"--random {args.random} is invalid; allowed: an integer in [0, {MAX_RANDOM}]"
        )
    if args.seed < 0:
        raise BirdsimError(f"--seed {args.seed} is invalid; allowed: an integer >= 0")
    if args.figure and Path(args.figure).suffix.lower() not in FIGURE_SUFFIXES:
        raise BirdsimError(
            f"--figure {args.figure!r} has an unknown suffix; allowed: a path ending in {', '.join(FIGURE_SUFFIXES)}"
        )
    figure = check_output(Path(args.figure), args.force, "--figure") if args.figure else None
    bird = bird_from_args(args)
    forward = None if args.forward == "none" else args.forward
    results = []
    for name, case, params, speed in tqdm(
        _cases(models, args.random, args.seed),
        desc="crosscheck",
        unit="case",
        disable=None,
        leave=False,
    ):
        r = crosscheck(name, params, speed, bird, samples=args.samples, forward=forward)
        results.append((case, r))
    if figure is not None:
        _figure(results, figure)
    if args.json:
        print(
            json.dumps(
                {
                    "force": FORCE_NOTE,
                    "units": units_of(bird),
                    "results": [{"case": c, **r.as_dict()} for c, r in results],
                },
                indent=2,
            )
        )
        return 0
    u = units_of(bird)
    print(f"force: {FORCE_NOTE}; MuJoCo: mean force the held body transmits")
    print(f"units: forces in {u['force']}, V in {u['speed']}; relative errors have none")
    head = f"{'model':5s} {'case':8s} {'V':>5s} {'analytic Fx':>11s} {'Fz':>9s} {'inverse Fx':>11s} {'Fz':>9s} {'rel.err':>8s}"
    if forward:
        head += f" {'forward Fx':>11s} {'Fz':>9s} {'rel.err':>8s}"
    print(head)
    for case, r in results:
        line = (
            f"{r.model:5s} {case:8s} {r.speed:5.2f} {r.analytic_seed[0]:+11.6f} {r.analytic_seed[2]:+9.6f} "
            f"{r.inverse_seed[0]:+11.6f} {r.inverse_seed[2]:+9.6f} {r.inverse_rel_error:8.1e}"
        )
        if forward:
            line += (
                f" {r.forward_seed[0]:+11.6f} {r.forward_seed[2]:+9.6f} {r.forward_rel_error:8.1e}"
            )
        print(line)
    worst_inv = max(r.inverse_rel_error for _, r in results)
    summary = f"worst relative error: inverse {worst_inv:.1e} (required 1e-6)"
    if forward:
        summary += f", forward {max(r.forward_rel_error for _, r in results):.1e} (required 1e-3)"
    print(summary)
    if figure is not None:
        print(f"figure: {figure}")
    return 0


def _figure(results, path: Path) -> None:
    """Whole-bird force histories, analytic (lines) and mj_inverse (dots), first case per model."""
    import os

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    firsts = {}
    for case, r in results:
        firsts.setdefault(r.model, (case, r))
    fig, axes = plt.subplots(
        len(firsts), 1, figsize=(7, 2.2 * len(firsts)), squeeze=False, sharex=True
    )
    for ax, (model, (case, r)) in zip(axes[:, 0], firsts.items()):
        phase = r.time / r.time[-1] * (1 - 1 / len(r.time))
        for k, (label, color) in enumerate((("Fx", "C0"), (None, None), ("Fz", "C3"))):
            if label is None:
                continue
            ax.plot(phase, r.analytic_history_seed[:, k], color=color, label=f"{label} analytic")
            ax.plot(
                phase, r.inverse_history_seed[:, k], ".", color=color, ms=4, label=f"{label} MuJoCo"
            )
        ax.set_ylabel("force")
        ax.set_title(
            f"{model} {case}, V = {r.speed:g}: rel. error of the mean {r.inverse_rel_error:.1e}",
            fontsize=9,
        )
        ax.legend(fontsize=7, ncol=4)
    axes[-1, 0].set_xlabel("t / T")
    fig.suptitle(
        "Whole-bird force (seed axes, Fz < 0 up): analytic vs MuJoCo mj_inverse", fontsize=10
    )
    fig.tight_layout()
    tmp = temporary_sibling(path)
    try:
        fig.savefig(tmp, format=path.suffix.lstrip(".") or "png")
        os.replace(tmp, path)
    finally:
        plt.close(fig)
        if tmp.exists():
            tmp.unlink()
