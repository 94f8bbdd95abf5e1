"""Report figures: one batched evaluation of a parameter grid against one
``evaluate_cycle`` call per parameter set (the way a plain loop would fill the grid),
and the time of the quick report's grid-heavy families."""

from __future__ import annotations

import math
import tempfile
import time

import numpy as np

from birdsim import evaluate_cycle
from birdsim.report import figdata as fd


def _best(fn, repeats: int = 3) -> float:
    best = math.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    lag = np.linspace(0, math.pi / 2, 31)
    bias = np.linspace(0, math.pi / 2, 31)
    sets = lag.size * bias.size

    def batched() -> None:
        fd.wrist_upward_force(math.pi / 5, 2 * math.pi / 5, lag[:, None], bias[None, :], n=32)

    sub = [
        (a, b) for a in lag[::3] for b in bias[::3]
    ]  # a loop over every set takes long; time a tenth

    def looped() -> None:
        for a, b in sub:
            evaluate_cycle(
                "m4",
                dict(
                    pitch=0.0,
                    flap_amp=math.pi / 5,
                    twist_amp=0.0,
                    stroke_plane=0.0,
                    wrist_amp=2 * math.pi / 5,
                    wrist_bias=b,
                    wrist_lag=a,
                ),
                0.5,
                n=32,
                check_bounds=False,
            )

    tb = _best(batched)
    tl = _best(looped, 1) * sets / len(sub)
    print(
        f"report grid (Fig 26, m4, {sets} sets x 32 samples): batched {tb * 1e3:.1f} ms, "
        f"one call per set {tl * 1e3:.0f} ms (from {len(sub)} sets), ratio {tl / tb:.1f}x"
    )

    from birdsim.report.report import build_report

    with tempfile.TemporaryDirectory() as out:
        t0 = time.perf_counter()
        secs = build_report(
            out, quick=True, progress=False, only=["thrust", "wrist", "landscapes", "activity"]
        )
        total = time.perf_counter() - t0
    print(
        "report --quick grid families: "
        + ", ".join(f"{s.family.key} {s.seconds:.2f} s" for s in secs)
        + f"; total {total:.2f} s"
    )


if __name__ == "__main__":
    main()
