"""Whole-bird wingbeat moments, control inputs and body-rate damping (issue 22).

Tolerances: symmetry results are exact up to round-off of sums of O(0.1) terms over 238
samples (1e-14 absolute); central differences of step 1e-5 are good to ~1e-9 (truncation
h^2 times third derivatives of O(1), round-off 1e-16/h); analytic damping of a wing that
does not flap is exact in the quasi-steady model, so only the difference step limits it.
"""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.frames import earth_to_body
from birdsim.physics.kinematics import get_model
from birdsim.physics.moments import CONTROL_INPUTS, input_model, wing_params, wingbeat_moments

MODELS = ("base", "m1", "m2", "m3", "m4", "m5")  # m5: the hand's area fold too
SYM_TOL = 1e-14
FD_TOL = 1e-8


def _params(model: str, regime: str = "cruise") -> dict[str, float]:
    p = get_model(model).guess(regime)
    if "sweep" in p:
        p["sweep"] = 0.1
    return p


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("V", [0.0, 0.6])
def test_symmetric_wingbeat_has_no_roll_yaw_or_side_force(model, V):
    # a symmetric wingbeat, also pitching (q only keeps the symmetry): Mx = Mz = Fy = 0
    for rate in ((0.0, 0.0, 0.0), (0.0, 0.3, 0.0)):
        r = wingbeat_moments(model, _params(model), V, body_rate=rate)
        assert abs(r.moment_body[0]) < SYM_TOL and abs(r.moment_body[2]) < SYM_TOL
        assert abs(r.force_body[1]) < SYM_TOL
        assert np.linalg.norm(r.force_body) > 1e-3  # not a trivially zero wingbeat


@pytest.mark.parametrize("model", MODELS)
def test_a_wingbeat_symmetric_in_time_has_no_mean_pitching_moment(model):
    """The shoulders sit at the torso origin (the centre of mass).  In base, m1 and m3
    the flap is a sine and the twist its quadrature cosine, so at phases t and -t the
    wing's span is mirrored about the stroke plane's mid-line while every panel meets the
    same relative air (the flap rate, the twist and the stroke plane's tilt are even in
    t); its force along the flap axis is even and its height odd, and the pitching
    moment ``rho sin(phi) F_n`` is odd in phase: zero in the mean for any parameters
    and speed (round-off), so pitch is moved by the shoulders' offsets (sweep, dihedral)
    and the tail only.  m2's sweep and m4/m5's wrist lag and fold phase break the
    symmetry (the moment is not zero there: the test can tell)."""
    rng = np.random.default_rng(7)
    spec = get_model(model).params
    lo = np.array([p.lower for p in spec])
    hi = np.array([p.upper for p in spec])
    pitch_moments = []
    for _ in range(4):
        x = lo + (hi - lo) * rng.random(len(spec))
        for V in (0.0, 0.5):
            r = wingbeat_moments(model, dict(zip(get_model(model).param_names, x)), V)
            pitch_moments.append(abs(r.moment_body[1]) / max(1e-12, np.linalg.norm(r.force_body)))
    if model in ("base", "m1", "m3"):
        assert max(pitch_moments) < 1e-15 * 100  # round-off of a 64-sample mean
    else:
        assert max(pitch_moments) > 1e-4


@pytest.mark.parametrize("model", MODELS)
def test_whole_bird_force_is_cycle_whole_bird_mean_in_body_axes(model):
    p = _params(model)
    w = evaluate_cycle(model, p, 0.6).whole_bird_mean
    want = earth_to_body(p["pitch"], (float(w.Fx), float(w.Fy), float(w.Fz)))
    r = wingbeat_moments(model, p, 0.6)
    np.testing.assert_allclose(r.force_body, np.array(want, dtype=float), rtol=0, atol=1e-13)


@pytest.mark.parametrize("model", MODELS)
def test_mirror_symmetry_flips_roll_and_yaw(model):
    # u -> -u for the differential inputs (and p, r -> -p, -r) is the mirror image
    k = len(CONTROL_INPUTS[model])
    u = np.array([0.05, -0.04, 0.03, 0.02])[:k]
    diff = np.array([kind == "diff" for _, kind in CONTROL_INPUTS[model]])
    mirror_u = np.where(diff, -u, u)
    a = wingbeat_moments(model, _params(model), 0.5, u=u, body_rate=(0.2, 0.1, -0.3))
    b = wingbeat_moments(model, _params(model), 0.5, u=mirror_u, body_rate=(-0.2, 0.1, 0.3))
    assert abs(a.moment_body[0]) > 1e-3 and abs(a.moment_body[2]) > 1e-4
    flip = np.array([-1.0, 1.0, -1.0])
    np.testing.assert_allclose(b.moment_body, flip * a.moment_body, rtol=0, atol=1e-14)
    np.testing.assert_allclose(b.force_body, -flip * a.force_body, rtol=0, atol=1e-14)


def test_wing_params_applies_diff_and_sym_inputs():
    p = _params("m3")
    right, left = wing_params("m3", p, [0.1, 0.2, 0.3, 0.4])
    assert right["stroke_plane"] == pytest.approx(p["stroke_plane"] + 0.05)
    assert left["stroke_plane"] == pytest.approx(p["stroke_plane"] - 0.05)
    assert right["flap_amp"] - left["flap_amp"] == pytest.approx(0.2)
    assert right["twist_amp"] - left["twist_amp"] == pytest.approx(0.3)
    assert right["sweep"] == left["sweep"] == pytest.approx(0.4)  # m3 has no sweep: default 0
    assert right["pitch"] == left["pitch"] == p["pitch"]


@pytest.mark.parametrize("model", ["m1", "m3", "base"])
def test_added_joints_at_zero_are_the_model_itself(model):
    # sweep / stroke plane added to a model that lacks them change nothing at 0
    p = _params(model)
    mx = input_model(model)
    assert set(mx.param_names) >= set(p)
    r = wingbeat_moments(model, p, 0.5, backend="numpy")
    w = evaluate_cycle(model, p, 0.5, backend="numpy").whole_bird_mean
    want = earth_to_body(p["pitch"], (float(w.Fx), 0.0, float(w.Fz)))
    np.testing.assert_allclose(r.force_body, np.array(want, dtype=float), rtol=0, atol=1e-13)


@pytest.mark.parametrize("strips", [1, 4])
@pytest.mark.parametrize("V", [0.4, 1.0])
def test_damping_of_a_wing_that_does_not_flap_is_strip_theory(strips, V):
    # flap 0, twist 0, pitch 0: each element meets the air at alpha = 0.  A roll rate p
    # adds vz = p y: dFz/dvz = -(rho S / 2) V (2 Clmax + Cd0), so Lp = -(rho / 2) V
    # (2 Clmax + Cd0) sum(S y^2) over both wings' elements; a yaw rate r adds vx = -r y:
    # dFx/dvx = -rho S Cd0 V, so Nr = -rho V Cd0 sum(S y^2).
    bird = Bird(strips=strips)
    r = wingbeat_moments(
        "m1", {"pitch": 0.0, "flap_amp": 0.0, "twist_amp": 0.0}, V, bird, jacobians=True
    )
    if strips == 1:
        ys, area = np.array([0.5]), np.array([1.0])
    else:
        ys, area = (np.arange(4) + 0.5) / 4, np.full(4, 0.25)
    sy2 = 2.0 * np.sum(area * ys**2)  # both wings
    pol = bird.polar
    assert r.moment_drate[0, 0] == pytest.approx(
        -0.5 * V * (2 * pol.cl_max + pol.cd0) * sy2, abs=FD_TOL
    )
    assert r.moment_drate[2, 2] == pytest.approx(-V * pol.cd0 * sy2, abs=FD_TOL)


def test_hover_roll_damping_is_negative_and_grows_with_amplitude_and_frequency():
    # in hover every velocity scales with omega, so dM/dp scales with omega exactly (the
    # flapping counter-torque, Hedrick, Cheng & Deng 2009: proportional to f Phi); with
    # amplitude it grows monotonically (about linearly: Lp / Phi within 1 % here)
    p = _params("m1", "hover")
    lp = []
    for amp in (0.2, 0.4, 0.7, 1.0):
        r = wingbeat_moments("m1", {**p, "flap_amp": amp}, 0.0, jacobians=True)
        lp.append(r.moment_drate[0, 0])
    assert lp[0] < 0 and lp[3] < lp[2] < lp[1] < lp[0]
    per_amp = np.array(lp) / np.array([0.2, 0.4, 0.7, 1.0])
    assert np.ptp(per_amp) < 0.01 * abs(per_amp.mean())
    slow = wingbeat_moments("m1", p, 0.0, Bird(omega=1.0), jacobians=True).moment_drate[0, 0]
    fast = wingbeat_moments("m1", p, 0.0, Bird(omega=2.0), jacobians=True).moment_drate[0, 0]
    assert slow < 0 and fast == pytest.approx(2.0 * slow, rel=1e-7)


def test_cruise_roll_damping_is_negative_and_mostly_from_the_forward_speed():
    # in cruise the freestream dominates: Lp stays near the still wing's -(rho/2) V
    # (2 Clmax + Cd0) S y^2 (docs/moments.md gives the numbers); flapping changes it by
    # a few per cent either way
    p = _params("m1", "cruise")
    still = -0.5 * 0.5 * 4.05 * 2 * 0.25
    for amp in (0.2, 0.7, 1.0):
        lp = wingbeat_moments("m1", {**p, "flap_amp": amp}, 0.5, jacobians=True).moment_drate
        assert lp[0, 0] < 0 and abs(lp[0, 0] / still - 1) < 0.1


@pytest.mark.parametrize("model", MODELS)
def test_jacobians_match_central_differences(model):
    p = _params(model)
    u0 = np.array([0.02, -0.01, 0.03, 0.01])
    rate0 = np.array([0.1, -0.05, 0.2])
    r = wingbeat_moments(model, p, 0.5, u=u0, body_rate=rate0, jacobians=True)
    h = 1e-6
    for i in range(4):
        e = np.eye(4)[i] * h
        a = wingbeat_moments(model, p, 0.5, u=u0 + e, body_rate=rate0, backend="numpy")
        b = wingbeat_moments(model, p, 0.5, u=u0 - e, body_rate=rate0, backend="numpy")
        np.testing.assert_allclose(
            r.moment_du[:, i], (a.moment_body - b.moment_body) / (2 * h), rtol=0, atol=FD_TOL
        )
        np.testing.assert_allclose(
            r.force_du[:, i], (a.force_body - b.force_body) / (2 * h), rtol=0, atol=FD_TOL
        )
    for i in range(3):
        e = np.eye(3)[i] * h
        a = wingbeat_moments(model, p, 0.5, u=u0, body_rate=rate0 + e, backend="numpy")
        b = wingbeat_moments(model, p, 0.5, u=u0, body_rate=rate0 - e, backend="numpy")
        np.testing.assert_allclose(
            r.moment_drate[:, i], (a.moment_body - b.moment_body) / (2 * h), rtol=0, atol=FD_TOL
        )
        np.testing.assert_allclose(
            r.force_drate[:, i], (a.force_body - b.force_body) / (2 * h), rtol=0, atol=FD_TOL
        )


@pytest.mark.parametrize(
    "kwargs, text",
    [
        ({"u": [0.1]}, "u=[0.1] is invalid"),
        ({"u": [np.nan, 0, 0, 0]}, "is invalid"),
        ({"body_rate": (0, 1)}, "body_rate has shape (2,)"),
        ({"body_rate": (0, np.inf, 0)}, "body_rate=inf is invalid"),
    ],
)
def test_bad_inputs_are_one_line(kwargs, text):
    with pytest.raises(BirdsimError, match=None) as exc:
        wingbeat_moments("m1", _params("m1"), 0.5, **kwargs)
    assert text in str(exc.value) and "\n" not in str(exc.value)


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("strips", [1, 3])
def test_kernel_equals_numpy_reference(model, strips):
    # the compiled means against the numpy path (1e-12, as every kernel mean); its exact
    # derivatives against the reference's central differences (FD_TOL)
    bird = Bird(strips=strips)
    kw = dict(u=[0.02, -0.01, 0.03, 0.01], body_rate=(0.1, -0.05, 0.2), jacobians=True)
    a = wingbeat_moments(model, _params(model, "hover"), 0.3, bird, **kw)
    b = wingbeat_moments(model, _params(model, "hover"), 0.3, bird, backend="numpy", **kw)
    for f in ("force_body", "moment_body"):
        np.testing.assert_allclose(getattr(a, f), getattr(b, f), rtol=0, atol=1e-12)
    for f in ("force_du", "moment_du", "force_drate", "moment_drate"):
        np.testing.assert_allclose(getattr(a, f), getattr(b, f), rtol=0, atol=FD_TOL)


def test_a_symmetric_sweep_may_be_part_of_the_baseline():
    # m3 with sweep 0.1 given in params is m3 with u = sweep(sym) 0.1 from sweep 0
    p = _params("m3")
    a = wingbeat_moments("m3", {**p, "sweep": 0.1}, 0.5)
    b = wingbeat_moments("m3", p, 0.5, u=[0.0, 0.0, 0.0, 0.1])
    np.testing.assert_allclose(a.moment_body, b.moment_body, rtol=0, atol=1e-15)
    assert abs(a.moment_body[1]) > 1e-3
