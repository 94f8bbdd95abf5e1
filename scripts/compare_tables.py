"""Compare two lookup tables cell by cell by cost (not bitwise): usage
``python scripts/compare_tables.py OLD.npz NEW.npz [--samples N]``.

Both tables' stored wingbeats are re-costed with the same evaluator (N samples per
wingbeat, default 256: converged), so a change of the build's sample count cannot
pass for a change of quality.  Prints the cost difference per cell, the cells where the
new table costs more than 1e-6 more, and reachable cells lost (ok -> not ok).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.tables.cost import CostWeights, evaluate_cost


def _load(path: str) -> tuple[dict, dict]:
    z = np.load(path, allow_pickle=False)
    meta = json.loads(Path(path).with_suffix(".json").read_text())
    return {k: z[k] for k in z.files}, meta


def recost(
    t: dict, meta: dict, samples: int, weights: CostWeights | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """(cost, max force miss) of every cell's stored wingbeat (with the table's own cost
    weights unless ``weights`` are given)."""
    model = get_model(meta["model"])
    bird = Bird.from_dict(meta["bird"]) if "bird" in meta else Bird()
    if weights is None:
        weights = CostWeights(**meta["cost_weights"]) if "cost_weights" in meta else CostWeights()
    axes = [t["axis_Fx"], t["axis_Fz"], t["axis_V"]] + (
        [t["axis_climb"]] if "axis_climb" in t else []
    )
    Fx, Fz, V, *climb = np.meshgrid(*axes, indexing="ij")
    X = t["params"].reshape(-1, t["params"].shape[-1])
    vc = climb[0].ravel() if climb else 0.0
    b = evaluate_cost(
        model, X, Fx.ravel(), Fz.ravel(), V.ravel(), weights=weights, bird=bird, n=samples, climb=vc
    )
    miss = np.maximum(np.abs(b.Fx - Fx.ravel()), np.abs(b.Fz - Fz.ravel()))
    return b.total.reshape(Fx.shape), miss.reshape(Fx.shape)


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--samples", type=int, default=256)
    ap.add_argument("--reach-tol", type=float, default=0.01)
    ap.add_argument(
        "--old-weights",
        action="store_true",
        help="cost NEW with OLD's cost weights too (e.g. a table built with a token cost, "
        "compared on the cost without it)",
    )
    a = ap.parse_args(argv)
    (t0, m0), (t1, m1) = _load(a.old), _load(a.new)
    c0, miss0 = recost(t0, m0, a.samples)
    same = CostWeights(**m0.get("cost_weights", {})) if a.old_weights else None
    c1, miss1 = recost(t1, m1, a.samples, same)
    diff = c1 - c0
    ok0, ok1 = miss0 <= a.reach_tol, miss1 <= a.reach_tol
    worse = diff > 1e-6
    print(f"cells {diff.size}; cost re-evaluated at {a.samples} samples per wingbeat")
    print(
        f"mean cost old {c0.mean():.6f} new {c1.mean():.6f}; new - old: mean {diff.mean():+.2e}, "
        f"max {diff.max():+.2e}, min {diff.min():+.2e}"
    )
    both = (miss0 <= a.reach_tol) & (miss1 <= a.reach_tol)
    print(
        f"over the {int(both.sum())} cells reachable in both: mean old {c0[both].mean():.6f} "
        f"new {c1[both].mean():.6f} ({diff[both].mean():+.2e}), largest increase "
        f"{diff[both].max():+.2e}"
    )
    print(
        f"cells costing more than 1e-6 more: {int(worse.sum())}; cheaper by more than 1e-6: {int((diff < -1e-6).sum())}"
    )
    print(
        f"reachable cells old {int(ok0.sum())} new {int(ok1.sum())}; lost {int((ok0 & ~ok1).sum())}, gained {int((ok1 & ~ok0).sum())}"
    )
    if "evaluations" in t0 and "evaluations" in t1:
        print(
            f"wingbeat evaluations per cell: old {t0['evaluations'].mean():.0f}, new {t1['evaluations'].mean():.0f}"
        )
    for idx in np.argwhere(worse)[:10]:
        i = tuple(idx)
        at_climb = f" climb={t0['axis_climb'][i[3]]:+.2f}" if len(i) > 3 else ""
        print(
            f"  worse at Fx={t0['axis_Fx'][i[0]]:+.2f} Fz={t0['axis_Fz'][i[1]]:+.2f} V={t0['axis_V'][i[2]]:.1f}{at_climb}: {diff[i]:+.2e}"
        )
    return 0 if not worse.any() and not (ok0 & ~ok1).any() else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
