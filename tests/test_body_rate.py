"""The body rate input of the core (issue 22): omega x r in every element's air velocity.

Bit for bit at zero: a rate of 1e-300 switches the rotating code path on while omega x r
(~1e-300) vanishes against velocities of O(0.1..1), so the rotating path must give
today's numbers exactly, in the numpy path and in the kernel.  Kernel against numpy with
a real rate: 1e-12, as for every other kernel mean (docs/performance.md).
"""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.kinematics import get_model

MODELS = ("base", "m1", "m2", "m3", "m4", "m5")  # m5: the hand's area fold too


def _means(c):
    m = c.mean
    return np.array([m.Fx, m.Fy, m.Fz, m.P], dtype=float)


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("backend", ["kernel", "numpy"])
def test_zero_body_rate_is_bit_for_bit(model, backend):
    p = get_model(model).guess("cruise")
    ref = evaluate_cycle(model, p, 0.5, backend=backend, climb=0.1)
    zero = evaluate_cycle(model, p, 0.5, backend=backend, climb=0.1, body_rate=(0.0, 0.0, 0.0))
    tiny = evaluate_cycle(model, p, 0.5, backend=backend, climb=0.1, body_rate=(1e-300,) * 3)
    assert np.array_equal(_means(ref), _means(zero))
    assert np.array_equal(_means(ref), _means(tiny))
    if backend == "numpy":
        assert np.array_equal(ref.panel_force_earth, tiny.panel_force_earth)


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("strips", [1, 3])
def test_kernel_equals_numpy_with_a_body_rate(model, strips):
    bird = Bird(strips=strips)
    p = get_model(model).guess("hover")
    rate = np.array([[0.3, -0.2, 0.1], [0.0, 0.4, -0.5]])
    k = evaluate_cycle(model, p, np.array([0.0, 0.7]), bird=bird, body_rate=rate)
    n = evaluate_cycle(model, p, np.array([0.0, 0.7]), bird=bird, body_rate=rate, backend="numpy")
    np.testing.assert_allclose(_means(k), _means(n), rtol=0, atol=1e-12)
    still = evaluate_cycle(model, p, np.array([0.0, 0.7]), bird=bird)
    assert np.max(np.abs(_means(k) - _means(still))) > 1e-3  # the rate matters


def test_rates_of_a_still_wing_give_the_expected_velocities():
    # a wing at rest along body y: omega x r with r = (0, y, 0) vanishes for a pure pitch
    # rate q, so the force is unchanged; a roll rate p > 0 moves the right wing down
    # (vz = p y > 0): it meets air from below and its force turns upward (Fz more negative)
    p = {"pitch": 0.0, "flap_amp": 0.0, "twist_amp": 0.0}
    base = evaluate_cycle("m1", p, 0.5, backend="numpy").mean
    q = evaluate_cycle("m1", p, 0.5, backend="numpy", body_rate=(0.0, 0.7, 0.0)).mean
    roll = evaluate_cycle("m1", p, 0.5, backend="numpy", body_rate=(0.7, 0.0, 0.0)).mean
    assert q.Fz == base.Fz and q.Fx == base.Fx
    assert roll.Fz < base.Fz - 0.1


def test_bad_body_rate_is_one_line():
    p = get_model("m1").guess("cruise")
    for rate, text in (
        ((1, 2), "body_rate has shape (2,)"),
        ((0, np.nan, 0), "body_rate=nan is invalid"),
    ):
        with pytest.raises(BirdsimError) as exc:
            evaluate_cycle("m1", p, 0.5, body_rate=rate)
        assert text in str(exc.value)
