"""The default samples per wingbeat (``DEFAULT_SAMPLES``) meets its accuracy claim: the
mean force within 1e-7 of the converged mean (n -> infinity) for 99.9 % of random
parameter sets of every model (docs/performance.md "Samples per wingbeat")."""

from __future__ import annotations

import numpy as np
import pytest

import birdsim
from birdsim.physics.cycle import DEFAULT_SAMPLES, evaluate_cycle

#: Random sets per model, and the reference n (its own error is ~1e-9: the slow sets
#: converge as n^-3, (238 / 1024)^3 * 1e-7 ~ 1.3e-9, far below the 1e-7 tested).
COUNT, REFERENCE = 2000, 1024


def _errors(model: str, n: int, seed: int = 5) -> np.ndarray:
    """max(|dFx|, |dFz|) of the mean at n samples against n = REFERENCE, per random set
    (uniform in the model's box, V uniform in [0, 1])."""
    m = birdsim.get_model(model)
    rng = np.random.default_rng(seed)
    lo, hi = m.bounds
    X = lo + (hi - lo) * rng.random((COUNT, len(lo)))
    V = rng.random(COUNT)
    p = {k: X[:, i] for i, k in enumerate(m.param_names)}
    ref = evaluate_cycle(model, p, V, n=REFERENCE).mean
    a = evaluate_cycle(model, p, V, n=n).mean
    return np.maximum(np.abs(a.Fx - ref.Fx), np.abs(a.Fz - ref.Fz))


@pytest.mark.parametrize("model", list(birdsim.MODELS))
def test_default_samples_put_the_mean_force_within_1e7(model):
    # The claim is 99.9 % of the population (measured on 262 144 sets per model: >= 99.94 %,
    # m3 the slowest).  Of 2000 sets, at a miss rate of 0.06 % about 1.2 miss, at 0.1 %
    # two: at most 4 misses (99.8 %) holds at the measured rate (P(>= 5 | mean 1.2) ~ 1 %;
    # the seed is fixed anyway: 0-1 misses here) but fails at n = 192 for base, m1 and m3
    # (0.4-0.8 % miss: 7-14 of 2000) and at the old n = 64 (~10 %).  The worst set (of
    # the slow, n^-3 kind) is at most 2e-7 off (measured: 1.4e-7 over 262 144 sets).
    err = _errors(model, DEFAULT_SAMPLES)
    assert np.sum(err > 1e-7) <= 4, (model, np.sum(err > 1e-7), float(err.max()))
    assert err.max() < 2e-7


def test_the_bound_fails_at_fewer_samples():
    # The same check at n = 192 misses for the slowest model (m3): the test can fail.
    assert np.sum(_errors("m3", 192) > 1e-7) > 4
