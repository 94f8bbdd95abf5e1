"""Why the pigeon's optimal m5 wingbeat folds more the faster it flies (issue 24): trimmed
level flight (``validation.trim``) at each speed with m5's bounds, and again with the fold
and supination locked at 0 (the same model with those bounds at 0), both re-optimised.

Per speed it prints the span ratio, the power folded and locked (and the saving), the
positive-only power (negative work not credited) of both, and the upstroke's share of
the weight (cos(wt) < 0: the wing rising).  ``--fold-upper`` widens the fold bound.

``--profile V`` prints instead the cost of folding at one speed: the trim with
``fold_amp`` pinned at each of ``--folds`` (every other parameter re-optimised from the
optima of the speeds ``--from`` and four Sobol points; those optima are trimmed from the
shipped table's lookup, as ``validate`` starts), the free optimum, and the cost's slope
in ``fold_amp`` at the fold-0 optimum for several fold phases (is fold 0 a trap?).
``--set FIELD=VALUE`` replaces a number of the bird file (e.g. ``fold_coupling=1.5``).

    python scripts/fold_study.py [--speeds 4.46,6,8,10,12,14,16] [--fold-upper 1.571]
    python scripts/fold_study.py --profile 9 [--folds 0,0.2,0.4,0.6,0.8,1.047] [--from 7,8,9,10,11]
                                 [--set fold_coupling=1.5]
"""

from __future__ import annotations

import argparse
import dataclasses
import math

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.kinematics import KinematicModel, get_model
from birdsim.physics.shaft_power import positive_power
from birdsim.physics.span import span_ratio
from birdsim.validation.trim import TrimPoint, trim_sweep

N = 256  # samples per wingbeat of the reported histories


def with_bounds(bounds: dict[str, tuple[float | None, float]]) -> KinematicModel:
    """m5 with some (lower, upper) bounds replaced, lower None = kept (the optimiser reads
    the bounds from the model)."""
    m = get_model("m5")
    params = tuple(
        dataclasses.replace(
            p,
            lower=p.lower if bounds[p.name][0] is None else bounds[p.name][0],
            upper=bounds[p.name][1],
        )
        if p.name in bounds
        else p
        for p in m.params
    )
    return dataclasses.replace(m, params=params)


def with_upper(upper: dict[str, float]) -> KinematicModel:
    """m5 with some upper bounds replaced."""
    return with_bounds({k: (None, v) for k, v in upper.items()})


def histories(model: KinematicModel, bird: Bird, p: TrimPoint) -> dict[str, float]:
    """Positive-only power [W] and the upstroke's share of the weight of a trimmed beat."""
    c = evaluate_cycle(model, p.params, p.speed, bird=bird, n=N, check_bounds=False)
    fz = 2.0 * np.asarray(c.force_earth)[..., 2].ravel()
    up = np.cos(np.arange(N) * 2.0 * math.pi / N) < 0.0
    weight = bird.mass * bird.gravity
    positive = 2.0 * float(np.asarray(positive_power(c, bird)).ravel()[0])
    return {"positive": positive, "up": -fz[up].sum() / N / weight}


def _line(model: KinematicModel, bird: Bird, p: TrimPoint, cost: float) -> str:
    sr = float(span_ratio(model, p.params, bird=bird, check_bounds=False))
    return (
        f"cost {cost:.6f}  P {p.power:6.3f} W  trimmed {int(p.trimmed)}  span ratio {sr:.3f}  "
        f"fold {p.params['fold_amp']:.3f} at phase {p.params['fold_phase']:+.3f}  "
        f"supination {p.params['supination_amp']:.3f}"
    )


def profile(bird: Bird, speed: float, folds: list[float], neighbours: list[float]) -> None:
    """The cost of folding at ``speed`` (see the module docstring)."""
    from birdsim.tables.optimize import random_starts, slsqp
    from birdsim.validation.tablecheck import find_table, level_flight_from_table
    from birdsim.validation.trim import TrimProblem, _point

    m5 = get_model("m5")
    names = m5.param_names
    table = find_table(bird, "m5")
    starts = level_flight_from_table(table, bird, neighbours).starts if table else None
    sweep = trim_sweep(m5, bird, neighbours, extra_starts=starts)
    rows = [np.array([p.params[n] for n in names]) for p in sweep.points]
    i_fold = names.index("fold_amp")
    found = []
    for fold in folds:
        model = with_bounds({"fold_amp": (fold, fold)})
        prob = TrimProblem(model, bird, speed)
        x0 = [np.where(np.arange(len(names)) == i_fold, fold, r) for r in rows]
        sol = min(
            (slsqp(prob, x) for x in [*x0, *random_starts(prob, 4, seed=1)]),
            key=lambda s: s.cost,
        )
        found.append(sol)
        print(
            f"V {speed:g} m/s, fold pinned at {fold:.3f}: "
            + _line(m5, bird, _point(prob, sol), sol.cost)
        )
    prob = TrimProblem(m5, bird, speed)
    free = min((slsqp(prob, x) for x in [*rows, *(s.x for s in found)]), key=lambda s: s.cost)
    print(f"V {speed:g} m/s, free optimum: " + _line(m5, bird, _point(prob, free), free.cost))
    zero = found[folds.index(0.0)] if 0.0 in folds else None
    if zero is None:
        return
    for phase in (-1.5, -1.0, -0.5, 0.0, 0.5, 1.0):
        x = zero.x.copy()
        x[names.index("fold_phase")] = phase
        c0, c1 = prob.cost(np.vstack([x, np.where(np.arange(len(x)) == i_fold, 1e-3, x)]))
        print(
            f"V {speed:g} m/s, fold-0 optimum with fold phase {phase:+.1f}: "
            f"d cost / d fold_amp at 0 = {(c1 - c0) / 1e-3:+.6f}"
        )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--speeds", default="4.46,6,8,10,12,14,16")
    ap.add_argument("--bird", default="models/pigeon.toml")
    ap.add_argument("--fold-upper", type=float, default=None)
    ap.add_argument("--profile", type=float, default=None, metavar="V")
    ap.add_argument("--folds", default="0,0.2,0.4,0.6,0.8,1.047")
    ap.add_argument("--from", dest="neighbours", default="7,8,9,10,11")
    ap.add_argument("--set", action="append", default=[], metavar="FIELD=VALUE")
    a = ap.parse_args()
    bird = Bird.from_toml(a.bird)
    for item in a.set:  # e.g. fold_coupling=1.5: another estimate of the skeleton
        key, value = item.split("=", 1)
        bird = dataclasses.replace(bird, **{key: float(value)})
    if a.profile is not None:
        fl = [float(s) for s in a.folds.split(",")]
        profile(bird, a.profile, fl, [float(s) for s in a.neighbours.split(",")])
        return
    speeds = [float(s) for s in a.speeds.split(",")]
    free = with_upper({} if a.fold_upper is None else {"fold_amp": a.fold_upper})
    locked = with_upper({"fold_amp": 0.0, "supination_amp": 0.0})
    sf = trim_sweep(free, bird, speeds)
    sl = trim_sweep(locked, bird, speeds)
    print(
        f"{'V m/s':>6s} {'trim':>4s} {'span ratio':>10s} {'fold rad':>8s} {'P W':>6s} "
        f"{'locked':>6s} {'saving':>6s} | {'P+ W':>6s} {'locked':>6s} | {'upstroke weight':>15s}"
    )
    for pf, pl in zip(sf.points, sl.points):
        hf, hl = histories(free, bird, pf), histories(locked, bird, pl)
        sr = float(span_ratio(free, pf.params, bird=bird, check_bounds=False))
        save = 100.0 * (1.0 - pf.power / pl.power)
        print(
            f"{pf.speed:6.2f} {int(pf.trimmed and pl.trimmed):4d} {sr:10.3f} "
            f"{pf.params['fold_amp']:8.3f} {pf.power:6.2f} {pl.power:6.2f} {save:5.1f}% | "
            f"{hf['positive']:6.2f} {hl['positive']:6.2f} | {hf['up']:+7.3f} ({hl['up']:+.3f})"
        )


if __name__ == "__main__":
    main()
