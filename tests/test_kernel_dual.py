"""Exact gradients of the cycle means (forward-mode dual numbers, kernel_dual.py)
against central differences, on random parameter sets of every model and option, near
flow reversal too."""

from __future__ import annotations

import numpy as np
import pytest
from test_kernel import OPTIONS, _random

import birdsim
from birdsim import Bird, evaluate_cycle, get_model
from birdsim.physics import kernel
from birdsim.physics.cycle import sample_phases


def _fd(m, X, V, climb, bird, h=1e-6):
    n = sample_phases(64, False)
    out = np.zeros((X.shape[0], 4, X.shape[1]))
    for i in range(X.shape[1]):
        Xp, Xm = X.copy(), X.copy()
        Xp[:, i] += h
        Xm[:, i] -= h
        fp = kernel.means_and_gradients(
            m, {k: Xp[:, j] for j, k in enumerate(m.param_names)}, V, climb, bird, n
        )[0]
        fm = kernel.means_and_gradients(
            m, {k: Xm[:, j] for j, k in enumerate(m.param_names)}, V, climb, bird, n
        )[0]
        out[..., i] = (fp - fm) / (2 * h)
    return out


@pytest.mark.parametrize("option", ["plain", "strips", "robofly", "climb", "other-bird"])
@pytest.mark.parametrize("model", list(birdsim.MODELS))
def test_gradients_equal_central_differences(model, option):
    # Central differences with h = 1e-6: truncation ~h^2 f''' ~1e-12, round-off ~1e-16/h
    # = 1e-10, so 1e-6 relative (per row, against the row's norm) is a real check: a
    # wrong term in the chain rule errs by O(1).  P itself, not |P|, so no kink.
    # Random sets include hover (V = 0: flow reversal at every stroke reversal).
    bird, climb = OPTIONS[option]
    m, X, V = _random(model, 12, seed=7, speed_scale=bird.omega * bird.semispan)
    C = np.full(len(V), climb * bird.omega * bird.semispan)
    flat = {k: X[:, j] for j, k in enumerate(m.param_names)}
    vals, grads = kernel.means_and_gradients(m, flat, V, C, bird, sample_phases(64, False))
    ref = evaluate_cycle(model, flat, V, climb=C, bird=bird, n=64, backend="numpy")
    np.testing.assert_allclose(
        vals[:, 2], ref.force_earth[..., 2].mean(-1), rtol=0, atol=1e-12 * np.abs(vals).max()
    )
    fd = _fd(m, X, V, C, bird)
    for r in (0, 2, 3):
        err = np.linalg.norm(grads[:, r] - fd[:, r], axis=-1)
        norm = np.linalg.norm(fd[:, r], axis=-1)
        assert np.all(err <= 1e-6 * norm + 1e-9 * np.abs(vals).max()), (r, (err / norm).max())


def test_gradients_near_flow_reversal():
    # m1 hover with the twist that makes the element's flow reverse direction: the
    # velocity passes close to zero; the gradient of P (not |P|) still matches.
    m = get_model("m1")
    X = np.array([[1.4, 1.5, 0.7], [np.pi / 2, 1.2, 0.0], [1.2, 0.4, 0.05]])
    V = np.array([0.0, 0.0, 1e-3])
    C = np.zeros(3)
    vals, grads = kernel.means_and_gradients(
        m, {k: X[:, j] for j, k in enumerate(m.param_names)}, V, C, Bird(), sample_phases(64, False)
    )
    fd = _fd(m, X, V, C, Bird())
    for r in (0, 2, 3):
        err = np.linalg.norm(grads[:, r] - fd[:, r], axis=-1)
        assert np.all(err <= 1e-6 * np.linalg.norm(fd[:, r], axis=-1) + 1e-10), r
