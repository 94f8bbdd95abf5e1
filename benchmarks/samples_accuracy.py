"""Samples per wingbeat chosen by accuracy (docs/performance.md): the error of the cycle
mean at n samples against a converged reference (n = 4096) on random parameter sets of
every model (uniform in the model's box, V uniform in [0, 1]).

Prints, per model and n, the fraction of sets whose mean force (max of |dFx|, |dFz|)
is within 1e-7 of the reference, the 99.9th percentile and the maximum of that error,
and the same for the power.  ``python benchmarks/samples_accuracy.py [COUNT]``.
"""

from __future__ import annotations

import sys

import numpy as np

import birdsim
from birdsim.physics.cycle import evaluate_cycle

NS = (32, 48, 64, 80, 96, 128, 192, 224, 230, 234, 236, 238, 240, 244, 248, 256)
REFERENCE = 4096


def main(argv: list[str] | None = None) -> None:
    count = int((argv or sys.argv[1:] or ["4000"])[0])
    print(
        f"{count} random parameter sets per model; reference n = {REFERENCE}; force error = max(|dFx|, |dFz|)"
    )
    print(
        f"{'model':6s} {'n':>5s} {'within 1e-7':>12s} {'p99.9 force':>12s} {'max force':>10s} {'p99.9 P':>10s}"
    )
    for model in birdsim.MODELS:
        m = birdsim.get_model(model)
        rng = np.random.default_rng(11)
        lo, hi = m.bounds
        X = lo + (hi - lo) * rng.random((count, len(lo)))
        V = rng.random(count)
        p = {k: X[:, i] for i, k in enumerate(m.param_names)}
        ref = evaluate_cycle(model, p, V, n=REFERENCE).mean
        for n in NS:
            a = evaluate_cycle(model, p, V, n=n).mean
            ef = np.maximum(np.abs(a.Fx - ref.Fx), np.abs(a.Fz - ref.Fz))
            ep = np.abs(a.P - ref.P)
            print(
                f"{model:6s} {n:5d} {np.mean(ef <= 1e-7):12.4%} {np.quantile(ef, 0.999):12.1e} {ef.max():10.1e} {np.quantile(ep, 0.999):10.1e}"
            )


if __name__ == "__main__":
    main()
