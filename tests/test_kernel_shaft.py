"""The positive shaft power in the fused kernels (issue 24; birdsim/physics/kernel_shaft.py):
values against the numpy reference (birdsim/physics/shaft_power.py), exact gradients
against central differences, and the lean one-row path the optimiser uses."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from vacuum_wing import OMEGA, PHI, vacuum_bird, wing_inertia

from birdsim.errors import BirdsimError
from birdsim.physics import kernel
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.kinematics import get_model
from birdsim.physics.shaft_power import positive_power, shaft_power
from birdsim.tables.cost import forces, forces_and_gradients
from birdsim.tables.point import PointForces
from birdsim.validation.run import load_flying_bird

pytestmark = pytest.mark.skipif(not kernel.available(), reason="no compiled kernel")

PIGEON = load_flying_bird(None)
CASES = [("m3", Bird()), ("m4", PIGEON), ("m5", PIGEON)]


def _rows(model: str, count: int, seed: int) -> np.ndarray:
    lo, hi = get_model(model).bounds
    return np.random.default_rng(seed).uniform(lo, hi, size=(count, lo.size))


def _reference(model, X, speed, bird, n):
    """The numpy path's P+ and shaft-power histories (B x N)."""
    m = get_model(model)
    params = {k: X[:, i] for i, k in enumerate(m.param_names)}
    cyc = evaluate_cycle(m, params, speed, bird=bird, n=n, check_bounds=False, backend="numpy")
    return positive_power(cyc, bird), shaft_power(cyc, bird)


@pytest.mark.parametrize("model,base", CASES)
@pytest.mark.parametrize("mass", [0.0, 0.06])
@pytest.mark.parametrize("n", [31, 32, 238])
def test_kernel_positive_power_equals_the_numpy_reference(model, base, mass, n) -> None:
    """1e-12 relative: the same sums in another order, and dK/dt by the differentiation
    matrix instead of the FFT (both exact on the grid's band; round-off ~1e-15)."""
    bird = dataclasses.replace(base, power_cost="positive", wing_mass_fraction=mass)
    X = _rows(model, 40, 1)
    v = np.random.default_rng(2).uniform(0.0, 1.0, 40)
    ref, hist = _reference(model, X, v, bird, n)
    assert np.all(hist.min(axis=-1) < 0) or mass == 0.0  # the rectifier is exercised
    _, _, p = forces(get_model(model), X, v, bird, n)
    (_, _, p2), _ = forces_and_gradients(get_model(model), X, v, bird, n)
    np.testing.assert_allclose(p, ref, rtol=1e-12, atol=0)
    np.testing.assert_allclose(p2, ref, rtol=1e-12, atol=0)
    pf = PointForces.create(get_model(model), bird, float(v[0]), 0.0, n)
    assert pf is not None  # the lean path serves a positive cost (it refused one before)
    assert pf.values(X[0])[2] == pytest.approx(ref[0], rel=1e-12)
    assert pf.gradients(X[0])[0][2] == pytest.approx(ref[0], rel=1e-12)
    # the forces are the net cost's, bit for bit
    net = forces(get_model(model), X, v, dataclasses.replace(bird, power_cost="net"), n)
    fx, fz, _ = forces(get_model(model), X, v, bird, n)
    assert np.array_equal(fx, net[0]) and np.array_equal(fz, net[1])


@pytest.mark.parametrize("model,base", CASES)
@pytest.mark.parametrize("mass", [0.0, 0.06])
def test_kernel_gradient_of_the_positive_power_agrees_with_central_differences(
    model, base, mass
) -> None:
    """d P+/dx against central differences (step 1e-6 rad) of the kernel's own P+, on
    rows where no sample's shaft power is within reach of zero for that step (the kinks
    of max(p, 0); m3's samples at the flap's reversal, where the control point stands
    still, are zero to round-off for every row and are not kinks): |error| <= 1e-8 x
    max_t |p_t| per radian (measured: ~1e-10, the round-off of the differences;
    truncation ~h^2 is below it)."""
    m = get_model(model)
    bird = dataclasses.replace(base, power_cost="positive", wing_mass_fraction=mass)
    X = _rows(model, 24, 7)
    v = np.full(24, 0.5)
    n, h = 32, 1e-6
    _, hist = _reference(model, X, v, bird, n)
    scale = np.abs(hist).max(axis=-1)
    rel = np.abs(hist) / scale[:, None]
    smooth = ~np.any((rel > 1e-12) & (rel < 1e-4), axis=-1)  # no kink within the step
    assert smooth.sum() >= 5
    X, v, scale = X[smooth], v[smooth], scale[smooth]
    (_, _, _), (_, _, grad) = forces_and_gradients(m, X, v, bird, n)
    d = X.shape[1]
    fd = np.zeros_like(grad)
    for i in range(d):
        e = np.zeros(d)
        e[i] = h
        fd[:, i] = (forces(m, X + e, v, bird, n)[2] - forces(m, X - e, v, bird, n)[2]) / (2 * h)
    assert np.all(np.abs(grad - fd).max(axis=1) <= 1e-8 * scale)
    pf = PointForces.create(m, bird, 0.5, 0.0, n)
    for r in range(3):
        assert np.array_equal(pf.gradients(X[r])[1][2], grad[r])  # one kernel, one row


def test_inertial_gradient_in_vacuum_is_twice_the_power_over_the_amplitude() -> None:
    """A massive m1 wing flapping Phi sin(wt) in (nearly) no air: P+ is the sampled mean
    of the positive half of dK/dt = -1/2 I Phi^2 w^3 sin 2wt, so P+ ~ Phi^2 and
    dP+/dPhi = 2 P+ / Phi (the air's share is ~1e-10 of it)."""
    phi, omega, n = PHI, OMEGA, 64
    bird = vacuum_bird()
    inertia = wing_inertia()
    amp = 0.5 * inertia * phi**2 * omega**3
    per_period = n // 2
    exact = amp / math.tan(math.pi / per_period) / per_period
    m = get_model("m1")
    x = np.zeros((1, len(m.param_names)))
    x[0, m.param_names.index("flap_amp")] = phi
    (_, _, p), (_, _, g) = forces_and_gradients(m, x, 0.0, bird, n)
    assert p[0] == pytest.approx(exact, rel=1e-9)
    assert g[0, m.param_names.index("flap_amp")] == pytest.approx(2.0 * exact / phi, rel=1e-8)


def test_nan_rows_and_a_massive_wing_on_strips() -> None:
    """A NaN row gives NaN (as np.maximum), not 0; a massive wing with strips is refused
    in one line, as the numpy reference refuses it."""
    m = get_model("m3")
    bird = Bird(power_cost="positive", wing_mass_fraction=0.06)
    X = np.array([[0.1, 0.8, 0.3, 0.2], [np.nan, 0.8, 0.3, 0.2]])
    _, _, p = forces(m, X, 0.5, bird, 32)
    assert np.isfinite(p[0]) and np.isnan(p[1])
    with pytest.raises(BirdsimError, match="strips=4 is invalid with wing_mass_fraction"):
        forces(m, X, 0.5, dataclasses.replace(bird, strips=4), 32)
