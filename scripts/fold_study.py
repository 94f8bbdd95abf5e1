"""Why the pigeon's optimal m5 wingbeat folds more the faster it flies (issue 24): trimmed
level flight (``validation.trim``) at each speed with m5's bounds, and again with the fold
and supination locked at 0 (the same model with those bounds at 0), both re-optimised.

Per speed it prints the span ratio, the power folded and locked (and the saving), the
positive-only power (negative work not credited) of both, and the upstroke's share of
the weight (cos(wt) < 0: the wing rising).  ``--fold-upper`` widens the fold bound.

    python scripts/fold_study.py [--speeds 4.46,6,8,10,12,14,16] [--fold-upper 1.571]
"""

from __future__ import annotations

import argparse
import dataclasses
import math

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.kinematics import KinematicModel, get_model
from birdsim.physics.span import span_ratio
from birdsim.validation.trim import TrimPoint, trim_sweep

N = 256  # samples per wingbeat of the reported histories


def with_upper(upper: dict[str, float]) -> KinematicModel:
    """m5 with some upper bounds replaced (the optimiser reads the bounds from the model)."""
    m = get_model("m5")
    params = tuple(
        dataclasses.replace(p, upper=upper[p.name]) if p.name in upper else p for p in m.params
    )
    return dataclasses.replace(m, params=params)


def histories(model: KinematicModel, bird: Bird, p: TrimPoint) -> dict[str, float]:
    """Positive-only power [W] and the upstroke's share of the weight of a trimmed beat."""
    c = evaluate_cycle(model, p.params, p.speed, bird=bird, n=N, check_bounds=False)
    power = 2.0 * np.asarray(c.power).ravel()
    fz = 2.0 * np.asarray(c.force_earth)[..., 2].ravel()
    up = np.cos(np.arange(N) * 2.0 * math.pi / N) < 0.0
    weight = bird.mass * bird.gravity
    return {"positive": float(np.maximum(power, 0.0).mean()), "up": -fz[up].sum() / N / weight}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--speeds", default="4.46,6,8,10,12,14,16")
    ap.add_argument("--bird", default="models/pigeon.toml")
    ap.add_argument("--fold-upper", type=float, default=None)
    a = ap.parse_args()
    bird = Bird.from_toml(a.bird)
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
