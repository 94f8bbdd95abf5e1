"""Reference scales and the reduced bird: a table built for the reduced bird serves the real one."""

import math

import numpy as np
import pytest

from birdsim import Bird, evaluate_cycle
from birdsim.physics.units import (
    mass_ratio,
    reduced_bird,
    same_reduced_bird,
    scales,
    weight_in_table_units,
)

PIGEONISH = Bird(
    name="p",
    semispan=0.33,
    chord=0.1,
    hand_chord=0.08,
    rho=1.225,
    omega=2 * math.pi * 7,
    body_drag_area=0.003,
    disc_area=math.pi * 0.33**2,
    mass=0.45,
    gravity=9.81,
)


@pytest.mark.parametrize("model", ["base", "m1", "m3", "m4"])
def test_forces_scale_exactly_with_the_reduced_bird(model):
    # The same wingbeat at the same reduced speed: SI forces / force scale == reduced forces.
    # Tolerance 1e-12 relative: the two evaluations differ only by rounding of the scales.
    rng = np.random.default_rng(1)
    from birdsim import get_model

    m = get_model(model)
    lo, hi = m.bounds
    params = {n: rng.uniform(a, b, 5) for n, a, b in zip(m.param_names, lo, hi)}
    sc = scales(PIGEONISH)
    v_red = 0.4
    si = evaluate_cycle(model, params, speed=v_red * sc.speed, bird=PIGEONISH).mean
    red = evaluate_cycle(model, params, speed=v_red, bird=reduced_bird(PIGEONISH)).mean
    for k in ("Fx", "Fz"):
        np.testing.assert_allclose(
            getattr(si, k) / sc.force, getattr(red, k), rtol=1e-12, atol=1e-14
        )
    np.testing.assert_allclose(si.P / sc.power, red.P, rtol=1e-12, atol=1e-14)


def test_pigeon_numbers_are_those_of_a_pigeon():
    assert 25 < mass_ratio(PIGEONISH) < 45
    assert 0.3 < weight_in_table_units(PIGEONISH) < 0.7


def test_seed_bird_is_its_own_reduced_bird():
    b = Bird()
    assert scales(b).force == 1.0 and mass_ratio(b) == 1.0
    assert same_reduced_bird(b, reduced_bird(b))
    assert not same_reduced_bird(b, PIGEONISH)
    assert same_reduced_bird(PIGEONISH, reduced_bird(PIGEONISH))
