"""Polars, the element force and the analytic results of sec. 3.4."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim import Bird, evaluate_cycle
from birdsim.errors import BirdConfigError
from birdsim.physics.aero import Polar, RoboflyPolar, SeedPolar, induced_velocity, polar_from_dict


def test_seed_fast_path_equals_coefficient_path():
    # SeedPolar.force_panel is an algebraic rewrite of Polar.force_panel (atan2 and the
    # coefficients); the two must agree to round-off everywhere, including U = 0.
    rng = np.random.default_rng(0)
    vx, vz = rng.normal(size=(2, 5000)) * rng.choice([1e-6, 1.0, 30.0], size=(2, 5000))
    vx[:3], vz[:3] = 0.0, 0.0
    polar = SeedPolar()
    fast = polar.force_panel(vx, vz, 0.7, 1.3)
    slow = Polar.force_panel(polar, vx, vz, 0.7, 1.3)
    scale = 0.5 * 1.3 * 0.7 * (vx**2 + vz**2) * 3.0 + 1e-300
    for a, b in zip(fast, slow):
        assert np.all(np.abs(a - b) <= 1e-13 * scale)
    assert fast[0][0] == 0.0 and fast[1][0] == 0.0


def test_seed_coefficients_eqs_4_to_6():
    cl, cd = SeedPolar().coefficients(np.array([0.0, math.pi / 4, math.pi / 2]))
    np.testing.assert_allclose(cl, [0.0, 2.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(cd, [0.05, 0.55, 1.05], atol=1e-15)


def test_drag_opposes_motion_lift_is_perpendicular():
    polar = SeedPolar()
    vx, vz = np.array([1.0, 0.3]), np.array([0.2, -0.9])
    fx, fz = polar.force_panel(vx, vz, 1.0, 1.0)
    u = np.hypot(vx, vz)
    drag = -(fx * vx + fz * vz) / u
    _, cd = polar.coefficients(np.arctan2(vz, vx))
    np.testing.assert_allclose(drag, 0.5 * u**2 * cd)  # the along-motion part is the drag


def test_robofly_polar_degrees_done_right():
    # Dickinson et al. (1999): at 45 deg, CL = 0.225 + 1.58 sin(88.65 deg) = 1.8046,
    # CD = 1.92 - 1.55 cos(81.98 deg) = 1.7037
    cl, cd = RoboflyPolar().coefficients(np.radians([45.0, -45.0, 45.0 + 180.0]))
    np.testing.assert_allclose(cl, [1.8046, -1.8046, 1.8046], atol=1e-4)
    np.testing.assert_allclose(cd, [1.7037, 1.7037, 1.7037], atol=1e-4)
    c = evaluate_cycle(
        "m1", dict(pitch=1.5, flap_amp=1.5, twist_amp=0.7), 0.0, bird=Bird(polar=RoboflyPolar())
    )
    assert float(c.mean.Fz) < 0  # a hovering wing still lifts


def test_polar_from_dict_errors():
    assert polar_from_dict({"kind": "seed", "cl_max": 1.5}) == SeedPolar(cl_max=1.5)
    with pytest.raises(BirdConfigError, match="polar.kind='foo' is unknown"):
        polar_from_dict({"kind": "foo"})
    # a NaN or infinite coefficient would turn every force into NaN without a word
    for bad in (float("nan"), float("inf"), "2"):
        with pytest.raises(
            BirdConfigError, match="polar.cd0=.* is invalid; allowed: a finite number"
        ):
            polar_from_dict({"kind": "seed", "cd0": bad})
    with pytest.raises(BirdConfigError, match="polar.cl_max=nan"):
        Bird().with_overrides({"polar.cl_max": "nan"})


# ---- sec. 3.4: the advance ratio ----------------------------------------------------


def _instantaneous_cfx(zeta: np.ndarray, twist: np.ndarray) -> np.ndarray:
    """C_Fx of a translating wing at the middle of the downstroke, through the whole
    pipeline: base model, pitch 0, t = 0 (twist = -Theta_f, leading edge down), flight
    speed V chosen so that the advance angle is ``zeta``; Fx / (q S)."""
    w = 0.5  # CP speed at t = 0 with flap_amp = 1
    speed = np.where(zeta < math.pi / 2, w / np.tan(np.minimum(zeta, 1.5707963)), 0.0)
    c = evaluate_cycle(
        "base", dict(pitch=0.0, flap_amp=1.0, twist_amp=twist), speed, n=4, check_bounds=False
    )
    q = 0.5 * (speed**2 + w**2)
    return c.Fx[..., 0] / q


def test_translating_wing_thrust_sign_follows_eq15():
    # eq. 15 divides eq. 14 by cos(zeta): valid below pi/2 (at pi/2 the thrust is zero)
    zeta = np.linspace(0.02, math.pi / 2 - 0.01, 300)
    cfx = _instantaneous_cfx(zeta, np.zeros_like(zeta))
    criterion = np.sin(zeta) ** 2 * (2 * 2.0 - 1.0) - 0.05  # eq. 15
    keep = np.abs(criterion) > 1e-3
    assert np.all(np.sign(cfx[keep]) == np.sign(criterion[keep]))
    # eq. 14 in closed form
    cl = 2 * np.sin(2 * zeta)
    cd = 0.05 + np.sin(zeta) ** 2
    np.testing.assert_allclose(cfx, cl * np.sin(zeta) - cd * np.cos(zeta), atol=1e-12)


def test_rotating_wing_thrust_eq20_and_fig9_maximum():
    zeta, twist = np.meshgrid(
        np.linspace(0.05, math.pi / 2, 40), np.linspace(0, math.pi / 2, 91), indexing="ij"
    )
    cfx = _instantaneous_cfx(zeta, twist)
    alpha = zeta - twist  # eq. 23: incidence = advance angle - twist
    closed = 2 * np.sin(2 * alpha) * np.sin(zeta) - (0.05 + np.sin(alpha) ** 2) * np.cos(zeta)
    np.testing.assert_allclose(cfx, closed, atol=1e-12)
    # at advance angle pi/2 (hover) thrust is greatest at twist pi/4 (sec. 3.4.3)
    assert twist[-1, np.argmax(cfx[-1])] == pytest.approx(math.pi / 4)
    # positive thrust needs twist below the advance angle (eq. 17) away from the drag-bound edge
    assert np.all(cfx[twist > zeta + 0.05] < 0)


def test_induced_velocity_axial_flow_is_appendix_formula():
    thrust, area = np.array([0.3, 1.0, 2.0]), 2.0
    for v_inf in (0.0, 0.7):
        f = np.stack([thrust, 0 * thrust, 0 * thrust], -1)  # force along the flight path
        vi = induced_velocity(f, np.full(3, v_inf), 1.0, area)
        np.testing.assert_allclose(
            vi, -v_inf / 2 + np.sqrt(v_inf**2 / 4 + thrust / (2 * area)), rtol=1e-12
        )
