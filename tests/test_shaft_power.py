"""The positive-power cost option (issue 24; birdsim/physics/shaft_power.py)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from vacuum_wing import OMEGA, PHI, vacuum_bird, wing_inertia

from birdsim.errors import BirdConfigError, BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.kinematics import get_model
from birdsim.physics.shaft_power import inertial_power, positive_power
from birdsim.tables.cost import forces, forces_and_gradients


def _vacuum_flap(n: int) -> tuple[Bird, object, float]:
    """An m1 wing flapping Phi sin(wt) in (nearly) no air, the mass a point at half span:
    kinetic energy 1/2 I (Phi w cos wt)^2, I = m (s/2)^2, so dK/dt = -1/2 I Phi^2 w^3 sin 2wt."""
    bird = vacuum_bird()
    cyc = evaluate_cycle(
        "m1",
        {"pitch": 0.0, "flap_amp": PHI, "twist_amp": 0.0},
        0.0,
        bird=bird,
        n=n,
        backend="numpy",
    )
    return bird, cyc, wing_inertia()


def test_sinusoidal_flap_in_vacuum_has_zero_net_and_the_half_cycle_positive_power() -> None:
    bird, cyc, inertia = _vacuum_flap(256)
    amp = 0.5 * inertia * PHI**2 * OMEGA**3
    p = inertial_power(cyc, bird)
    exact = -amp * np.sin(2.0 * OMEGA * cyc.time)
    assert np.max(np.abs(p - exact)) < 1e-9 * amp
    assert abs(p.mean()) < 1e-12 * amp  # no net inertial power over a wingbeat
    # positive part: the half-cycle integral, mean of max(A sin, 0) = A / pi (the aerodynamic
    # power is ~1e-10 of it); N = n/2 samples per period of sin 2wt, zeros on samples: the
    # sample mean is exactly A cot(pi/N) / N = A/pi (1 - pi^2 / (3 N^2) + ...)
    per_period = 128
    discrete = amp / math.tan(math.pi / per_period) / per_period
    assert positive_power(cyc, bird) == pytest.approx(discrete, rel=1e-9)
    assert positive_power(cyc, bird) == pytest.approx(amp / math.pi, rel=3e-4)


def test_massless_positive_power_is_the_positive_part_of_the_aerodynamic_power() -> None:
    bird = Bird(power_cost="positive")
    params = {"pitch": 0.1, "flap_amp": 0.9, "twist_amp": 0.3, "stroke_plane": 0.2}
    cyc = evaluate_cycle("m3", params, 0.6, bird=bird, n=128, backend="numpy")
    p = np.asarray(cyc.power)
    assert np.any(p < 0)  # the air works on the wing in part of the beat
    assert positive_power(cyc, bird) == pytest.approx(np.maximum(p, 0).mean(), rel=1e-14)
    negative = np.maximum(-p, 0).mean()  # the work the net cost credits
    assert negative > 1e-4
    assert positive_power(cyc, bird) - cyc.mean.P == pytest.approx(negative, rel=1e-9)


def test_the_cost_reads_the_positive_power_and_its_gradient_agrees() -> None:
    model = get_model("m5")
    x = np.array([[0.1, 0.8, 0.3, 0.4, 0.2, 0.1, 0.5, 0.6, -0.3, 0.2]])
    bird = Bird(power_cost="positive", wing_mass_fraction=0.06, mass=30.0)
    fx, fz, p = forces(model, x, 0.5, bird, 64)
    net = forces(model, x, 0.5, dataclasses.replace(bird, power_cost="net"), 64)
    assert fx == pytest.approx(net[0], abs=1e-12) and fz == pytest.approx(net[1], abs=1e-12)
    cyc = evaluate_cycle(model, dict(zip(model.param_names, x[0])), 0.5, bird=bird, n=64)
    assert p[0] == pytest.approx(float(positive_power(cyc, bird)), rel=1e-12)
    assert p[0] > net[2][0]
    (_, _, p2), (_, _, gp) = forces_and_gradients(model, x, 0.5, bird, 64)
    assert p2[0] == pytest.approx(p[0], rel=1e-12)
    h = 1e-5
    for i in range(x.shape[1]):
        e = np.zeros_like(x)
        e[0, i] = h
        fd = (forces(model, x + e, 0.5, bird, 64)[2] - forces(model, x - e, 0.5, bird, 64)[2]) / (
            2 * h
        )
        assert gp[0, i] == pytest.approx(fd[0], abs=1e-6)


def test_defaults_leave_bird_files_unchanged_and_bad_values_are_refused() -> None:
    d = Bird().to_dict()
    assert "power_cost" not in d and "wing_mass_fraction" not in d
    b = Bird(power_cost="positive", wing_mass_fraction=0.06)
    assert Bird.from_dict(b.to_dict()) == b
    with pytest.raises(BirdConfigError, match="power_cost='gross' is invalid; allowed: net or"):
        Bird(power_cost="gross")
    with pytest.raises(BirdConfigError, match=r"wing_mass_fraction=-0.1 is invalid"):
        Bird(wing_mass_fraction=-0.1)
    with pytest.raises(BirdConfigError, match="overrides: power_cost='up' is invalid"):
        Bird().with_overrides({"power_cost": "up"})
    cyc = evaluate_cycle("m1", {"pitch": 0.0, "flap_amp": 0.5, "twist_amp": 0.0}, 0.0, n=8)
    with pytest.raises(BirdsimError, match="strips=4 is invalid with wing_mass_fraction"):
        inertial_power(cyc, Bird(strips=4, wing_mass_fraction=0.1))


def test_a_table_for_one_power_cost_does_not_serve_another() -> None:
    from birdsim.physics.units import same_reduced_bird

    net, pos = Bird(), Bird(power_cost="positive")
    assert same_reduced_bird(net, Bird()) and same_reduced_bird(pos, Bird(power_cost="positive"))
    assert not same_reduced_bird(net, pos) and not same_reduced_bird(pos, net)
    heavy = Bird(power_cost="positive", wing_mass_fraction=0.06)
    assert not same_reduced_bird(pos, heavy)
    # the wing's reduced mass is what counts: half the fraction of twice the mass serves
    assert same_reduced_bird(heavy, Bird(power_cost="positive", wing_mass_fraction=0.03, mass=2.0))


def test_a_positive_cost_trim_reports_the_net_aerodynamic_power() -> None:
    from birdsim.tables.optimize import slsqp
    from birdsim.validation.run import load_flying_bird
    from birdsim.validation.trim import TrimProblem, _point

    pigeon = load_flying_bird(None)
    bird = dataclasses.replace(pigeon, power_cost="positive", wing_mass_fraction=0.06)
    model = get_model("m5")
    x0 = np.array([0.0, 0.49, 0.27, 0.37, 0.07, 0.05, 1.57, 0.41, -0.89, 0.0])
    problem = TrimProblem(model, bird, 9.0)
    point = _point(problem, slsqp(problem, x0))
    cyc = evaluate_cycle(model, point.params, 9.0, bird=pigeon, n=64, check_bounds=False)
    assert point.trimmed
    assert point.power == pytest.approx(2.0 * float(cyc.mean.P), rel=1e-9)
    positive = 2.0 * float(positive_power(cyc, bird))
    assert positive > point.power * 1.02  # the cost's power is not what is reported
