"""Cycle evaluation speed: batched vs one-at-a-time vs a plain per-sample loop."""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

import birdsim

sys.path.insert(0, str(Path(__file__).parent.parent / "tests"))
from reference_flapcost import flapcost_histories  # noqa: E402  (the plain approach)


def _params(model: str, count: int, seed: int = 0) -> tuple[dict[str, np.ndarray], np.ndarray]:
    rng = np.random.default_rng(seed)
    m = birdsim.get_model(model)
    lo, hi = m.bounds
    x = lo + (hi - lo) * rng.random((count, len(lo)))
    return {n: x[:, i] for i, n in enumerate(m.param_names)}, rng.random(count)


def _rate(fn, count: int, min_seconds: float = 1.0) -> float:
    fn()  # warm up
    reps, start = 0, time.perf_counter()
    while True:
        fn()
        reps += 1
        elapsed = time.perf_counter() - start
        if elapsed >= min_seconds:
            return reps * count / elapsed


def main() -> None:
    n = 64
    print(f"wingbeat evaluations per second, {n} samples each (mean forces and power of one wing)")
    print(f"{'model':6s} {'batched':>12s} {'one-at-a-time':>14s} {'plain loop':>11s} {'batch/one':>10s} {'batch/plain':>12s}")
    for model in birdsim.MODELS:
        params, speed = _params(model, 4096)
        batched = _rate(lambda: birdsim.evaluate_cycle(model, params, speed, n=n).mean, 4096)
        single_p = {k: float(v[0]) for k, v in params.items()}
        one = _rate(lambda: birdsim.evaluate_cycle(model, single_p, float(speed[0]), n=n).mean, 1, 0.5)
        if model != "m4":  # the appendix transcription covers the single-panel models
            times = np.linspace(0, 2 * np.pi, n, endpoint=False)
            plain = _rate(lambda: flapcost_histories(model, single_p, float(speed[0]), times), 1, 0.5)
            plain_s, ratio_plain = f"{plain:11.0f}", f"{batched / plain:11.0f}x"
        else:
            plain_s, ratio_plain = f"{'-':>11s}", f"{'-':>12s}"
        print(f"{model:6s} {batched:12.0f} {one:14.0f} {plain_s} {batched / one:9.0f}x {ratio_plain}")
    print("target (issue 2): >= 1e5 batched evaluations per second for m3 on this 2-core machine")
