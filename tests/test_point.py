"""The optimiser's one-row path (birdsim.tables.point) against the batched path."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim import Bird, get_model
from birdsim.physics import kernel
from birdsim.physics.aero import RoboflyPolar
from birdsim.tables import point
from birdsim.tables.cost import forces, forces_and_gradients
from birdsim.tables.optimize import ForceProblem, slsqp
from birdsim.tables.point import PointForces

BIRDS = {
    "seed": Bird(),
    "robofly, 3 strips": Bird(polar=RoboflyPolar(), strips=3),
    "another bird": Bird(body_drag_area=0.3, cp_span_fraction=0.6),
}


@pytest.mark.parametrize("bird_name", list(BIRDS))
@pytest.mark.parametrize("model", ["base", "m1", "m2", "m3", "m4"])
def test_one_row_equals_the_batched_path(model, bird_name):
    # The same compiled kernels on the same numbers: equal to round-off.  1e-15: the
    # body drag is computed with math.sin/cos here and numpy's (vectorised, an ulp
    # apart) there, and the climbing drag is written as |sin(pitch - gamma)| (kx, kz).
    m, bird = get_model(model), BIRDS[bird_name]
    lo, hi = m.bounds
    rng = np.random.default_rng(3)
    for speed, climb in ((0.0, 0.0), (0.7, 0.0), (0.4, 0.3), (0.5, -0.2), (0.0, 0.25)):
        pf = PointForces.create(m, bird, speed, climb, 32)
        assert pf is not None
        for x in rng.uniform(lo, hi, (4, len(lo))):
            ref = np.array([f[0] for f in forces(m, x[None], speed, bird, 32, climb)])
            (rv, rg) = forces_and_gradients(m, x[None], speed, bird, 32, climb)
            vals, jac = pf.gradients(x)
            tol = 1e-15
            np.testing.assert_allclose(pf.values(x), ref, rtol=0, atol=tol)
            np.testing.assert_allclose(vals, [v[0] for v in rv], rtol=0, atol=tol)
            np.testing.assert_allclose(jac, np.stack([g[0] for g in rg]), rtol=0, atol=tol)


def test_nan_in_gives_nan_out():
    m = get_model("m4")
    pf = PointForces.create(m, Bird(), 0.5, 0.0, 32)
    x = np.mean(m.bounds, axis=0)
    x[2] = np.nan
    assert all(np.isnan(pf.values(x)))
    assert np.all(np.isnan(pf.gradients(x)[0]))


def test_refused_where_it_cannot_serve(monkeypatch):
    m = get_model("m3")
    assert PointForces.create(m, Bird(induced_velocity=True), 0.5, 0.0, 32) is None
    # joint motions that are not affine in the parameters (here: wrong derivatives)
    damp, dphase, dbias = kernel.joint_derivatives(m, Bird())
    monkeypatch.setattr(kernel, "joint_derivatives", lambda *a: (1.5 * damp + 0.1, dphase, dbias))
    point._joint_map.cache_clear()
    point._affine.cache_clear()
    try:
        assert PointForces.create(m, Bird(), 0.5, 0.0, 32) is None
    finally:
        point._joint_map.cache_clear()
        point._affine.cache_clear()


def test_slsqp_takes_the_same_path_with_and_without_it(monkeypatch):
    # values and gradients equal to round-off: SLSQP makes the same steps (1e-9 in x
    # allows round-off amplified by the solver; another path would differ by ~1e-2)
    x0 = list(get_model("m4").guess("cruise").values())
    lean = slsqp(ForceProblem("m4", 0.05, -0.2, 0.6), x0)
    monkeypatch.setattr(PointForces, "create", classmethod(lambda cls, *a: None))
    plain = slsqp(ForceProblem("m4", 0.05, -0.2, 0.6), x0)
    assert lean.iterations == plain.iterations
    np.testing.assert_allclose(lean.x, plain.x, rtol=0, atol=1e-9)
    assert lean.cost == pytest.approx(plain.cost, abs=1e-12)


@pytest.mark.parametrize("model", ["base", "m4", "m5"])
def test_the_one_row_distance_term_is_other_costs_bitwise(model):
    """The lean path's eq. 93 distance term and its gradient (the regularising pass's
    candidates) are :func:`other_cost`'s and :func:`other_cost_gradient`'s to the bit, at
    V = 0 (with the orientation term) and V > 0; and a problem given a PointForces made for
    its demand point (shared by a cell's candidates) takes bitwise the same SLSQP path."""
    from birdsim.tables.cost import CostWeights, other_cost, other_cost_gradient

    m = get_model(model)
    rng = np.random.default_rng(5)
    for speed in (0.0, 0.6):
        for _ in range(50):
            w = CostWeights(distance=float(rng.uniform(0.01, 1.0)))
            prev, x = rng.uniform(*m.bounds, size=(2, len(m.param_names)))
            prob = ForceProblem(m, 0.1, -0.2, speed, weights=w, previous=prev)
            h = other_cost(m, x[None], speed, w, prev)[0]
            g = other_cost_gradient(m, x[None], speed, w, prev)[0]
            _, _, h_lean, g_lean = prob._parts_and_jacobian(x)
            assert prob._other_point(x) == h and h_lean == h
            assert g_lean.tobytes() == g.tobytes()
    x0 = np.mean(m.bounds, axis=0)
    w = CostWeights(distance=0.05)
    own = slsqp(ForceProblem(m, 0.05, -0.2, 0.6, weights=w, previous=x0), x0)
    pf = PointForces.create(m, Bird(), 0.6, 0.0, 32)
    slsqp(ForceProblem(m, -0.1, -0.1, 0.6, point=pf), x0)  # the buffers used before
    shared = slsqp(ForceProblem(m, 0.05, -0.2, 0.6, weights=w, previous=x0, point=pf), x0)
    assert shared.x.tobytes() == own.x.tobytes() and shared.cost == own.cost
