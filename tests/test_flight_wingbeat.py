"""The incremental wingbeat schedule (birdsim.flight.wingbeat): exact cascaded filters and
joint accelerations that are the time derivatives of the joint rates."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.flight.wingbeat import CascadeFilter, WingbeatSchedule
from birdsim.mujoco.model import build_model
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model


def test_cascade_filter_is_exact_and_continuous():
    f = CascadeFilter(2.0, np.array([0.0, 1.0]))
    u = np.array([1.0, -1.0])
    t = np.linspace(0.0, 3.0, 3001)
    p, dp, ddp = f.advance(u, t, 3.0)
    # derivatives are the exact derivatives of p (central differences agree to O(h^2))
    h = t[1] - t[0]
    np.testing.assert_allclose(np.gradient(p, h, axis=0)[1:-1], dp[1:-1], atol=1e-6)
    np.testing.assert_allclose(np.gradient(dp, h, axis=0)[1:-1], ddp[1:-1], atol=1e-6)
    # the state carried on is the output at the end: the next piece starts where this ended
    p2, dp2, _ = f.advance(u, np.array([0.0]), 1.0)
    np.testing.assert_allclose(p2[0], p[-1], atol=1e-15)
    np.testing.assert_allclose(dp2[0], dp[-1], atol=1e-15)
    # the step response never overshoots (critically damped cascade): stays in [start, u]
    assert np.all(p[:, 0] <= 1.0 + 1e-15) and np.all(p[:, 0] >= -1e-15)
    # starts with zero slope (C1 at the step) and a jump only in the second derivative
    assert dp[0, 0] == 0.0 and ddp[0, 0] > 0.0


def test_cascade_filter_without_smoothing_passes_through():
    f = CascadeFilter(0.0, np.array([0.3]))
    p, dp, ddp = f.advance(np.array([0.7]), np.array([0.0, 0.5]), 1.0)
    assert np.all(p == 0.7) and np.all(dp == 0.0) and np.all(ddp == 0.0)
    with pytest.raises(ValueError):
        CascadeFilter(float("nan"), np.zeros(1))


@pytest.mark.parametrize("model", ["m4", "base", "m2"])
def test_prescribed_accelerations_are_derivatives_of_rates(model):
    """qacc of the prescription = d/dt qvel while the parameters change (finite
    differences, O(h^2))."""
    kin = get_model(model)
    bird = Bird()
    m = build_model(model, bird, scene=False)
    start = np.array([kin.guess("cruise")[n] for n in kin.param_names])
    target = np.array([kin.guess("hover")[n] for n in kin.param_names])
    sched = WingbeatSchedule(m, kin, bird, start, smoothing=1.5)
    t = np.linspace(0.0, 2.0, 2001)
    pres = sched.advance(target, t, 0.0, 2.0)
    h = t[1] - t[0]
    fd = np.gradient(pres.qvel, h, axis=0)[1:-1]
    np.testing.assert_allclose(fd, pres.qacc[1:-1], atol=2e-5 * max(1.0, np.abs(pres.qacc).max()))
    # the root: pitch from the table's parameter, roll and yaw zero
    assert np.all(pres.qvel[:, 3] == 0.0) and np.all(pres.qvel[:, 5] == 0.0)
    np.testing.assert_allclose(pres.pitch, pres.params[:, kin.param_names.index("pitch")])
