"""One-wingbeat evaluation: agreement with an independent transcription of the
appendix code, the dissertation's example results, invariants and batching."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from reference_flapcost import flapcost_histories

import birdsim
from birdsim import Bird, evaluate_cycle, get_model
from birdsim.physics.cycle import DEFAULT_SAMPLES
from birdsim.physics.examples import EXAMPLES, example

PI = math.pi


def ev(eq: int, **kw):
    # n = 64 unless given: the example tests below index samples (phase k / 64)
    e = example(eq)
    return evaluate_cycle(e.model, e.params, e.speed, check_bounds=False, **{"n": 64, **kw})


# ---- an independent path: the appendix flapcost, transcribed as a loop ---------------


@pytest.mark.parametrize(
    "ex", [e for e in EXAMPLES if e.model != "m4"], ids=lambda e: f"eq{e.equation}"
)
def test_matches_appendix_transcription(ex):
    # Same physics written twice (explicit Table 2 matrices in a loop vs the batched
    # chain): they may differ by round-off only, ~1e-15; 1e-12 leaves room for it.
    cyc = evaluate_cycle(ex.model, ex.params, ex.speed, n=11, endpoint=True, check_bounds=False)
    f_ref, p_ref = flapcost_histories(ex.model, ex.params, ex.speed, cyc.time)
    np.testing.assert_allclose(cyc.force_earth, f_ref, atol=1e-12)
    np.testing.assert_allclose(cyc.power, p_ref, atol=1e-12)


def test_appendix_grid_counts_both_end_points():
    cyc = evaluate_cycle("base", example(57).params, 0.0, n=11, endpoint=True)
    assert cyc.time[0] == 0.0 and cyc.time[-1] == pytest.approx(2 * PI)
    assert float(cyc.mean.Fz) == pytest.approx(cyc.Fz.sum() / 11, abs=1e-15)


def test_periodic_mean_is_converged_at_64_samples():
    # The integrand is smooth and periodic: doubling the samples changes the mean
    # by far less than the 1e-3 a table or a plot could resolve.
    for ex in EXAMPLES:
        a = evaluate_cycle(ex.model, ex.params, ex.speed, n=64, check_bounds=False).mean
        b = evaluate_cycle(ex.model, ex.params, ex.speed, n=512, check_bounds=False).mean
        for k in ("Fx", "Fz", "P"):
            assert abs(float(getattr(a, k)) - float(getattr(b, k))) < 1e-3, (ex.equation, k)


# ---- the dissertation's example results (sec. 3.5) -------------------------------


def test_base_hover_eq57_upward_force_no_net_fx():
    c = ev(57)
    assert np.all(c.Fz <= 1e-12) and float(c.mean.Fz) < -0.2  # oscillating upward force
    assert abs(float(c.mean.Fx)) < 1e-12 and np.ptp(c.Fx) > 0.1  # oscillates, no net Fx
    peak = np.argmin(c.Fz)  # peak force as the wing passes the neutral plane (phase 0, 0.5)
    assert min(peak, abs(peak - 32)) <= 1
    assert np.all(c.P >= -1e-12) and np.argmax(c.P) in (0, 32)  # power synchronous with force


def test_base_cruise_eq58_net_thrust():
    c = ev(58)
    assert float(c.mean.Fx) > 0.02  # mean thrust: "not strictly a cruising case"
    assert float(c.mean.Fz) < -0.05 and (c.Fz < 0).mean() > 0.5  # Fz negative most of the beat
    assert c.Fz[32] > 0  # small positive Fz at phase 0.5 (upstroke through the neutral plane)
    assert c.Fx[16] < 0 and c.Fx[48] < 0  # negative Fx at phases 0.25 and 0.75
    down = np.cos(2 * PI * np.arange(64) / 64) > 0
    assert c.P[down].mean() > 2 * c.P[~down].mean()  # more power on the downstroke


def test_m1_hover_eq61_same_fz_and_power_as_base_less_fx():
    base, m1 = ev(57), ev(61)
    # flap rotation is about body x = earth vertical at pitch pi/2 (sec. 3.5.3)
    np.testing.assert_allclose(m1.Fz, base.Fz, atol=1e-12)
    np.testing.assert_allclose(m1.P, base.P, atol=1e-12)
    assert np.all(np.abs(m1.Fx) <= np.abs(base.Fx) + 1e-12)
    # at large flap angles (|phi| > 0.9 Phi_f = 1.41 rad, cos phi < 0.16) most of the
    # thrust is resolved sideways
    big = np.abs(np.sin(2 * PI * np.arange(64) / 64)) > 0.9
    assert np.all(np.abs(m1.Fx[big]) <= 0.5 * np.abs(base.Fx[big])) and np.abs(m1.Fy).max() > 0.01


def test_m1_cruise_eq62_less_vertical_force_than_base():
    base, m1 = ev(58), ev(62)
    assert float(m1.mean.Fz) < 0 and abs(float(m1.mean.Fz)) < abs(float(base.mean.Fz))
    assert float(m1.mean.Fx) > 0.02


def test_m2_hover_eq68_sweep_moves_force_from_z_to_y():
    m1, m2 = ev(61), ev(68)
    assert abs(float(m2.mean.Fz)) < abs(float(m1.mean.Fz)) and float(m2.mean.Fy) > 0.1
    np.testing.assert_allclose(m2.Fx, m1.Fx, atol=1e-12)  # "F_x is unaffected by the sweep angle"


def test_m3_hover_eq75_net_negative_fx_same_power_as_m1():
    m1, m3 = ev(61), ev(75)
    assert float(m3.mean.Fx) < -0.1
    np.testing.assert_allclose(m3.P, m1.P, atol=1e-12)  # wing motion relative to the air unchanged


def test_m3_cruise_eq76_fz_negative_over_whole_beat():
    c = ev(76)
    assert c.Fz.max() < 0
    assert c.Fx.max() < 0  # "F_x is now negative over the entire cycle"


def test_m4_hover_eq87_hand_carries_most_force():
    c = ev(87)
    hand, arm = c.panel_mean["hand"], c.panel_mean["arm"]
    assert float(hand.Fz) < 0.5 * float(c.mean.Fz) < 0  # more than half of the upward force
    assert float(arm.Fz) < 0  # the arm lifts too, less
    assert abs(float(c.mean.Fx)) < 1e-12


def test_m4_cruise_eq88_net_lift_from_hand_only():
    c = ev(88)
    assert float(c.mean.Fz) < -0.01  # net upward force with pitch = stroke plane = 0
    assert abs(float(c.panel_mean["arm"].Fz)) < 1e-12  # panel 1 alone gives none
    assert float(c.panel_mean["hand"].Fx) > float(c.panel_mean["arm"].Fx)


# ---- invariants -------------------------------------------------------------------------

rng = np.random.default_rng(7)


def random_params(model: str, count: int) -> dict[str, np.ndarray]:
    lo, hi = get_model(model).bounds
    x = lo + (hi - lo) * rng.random((count, len(lo)))
    return {n: x[:, i] for i, n in enumerate(get_model(model).param_names)}


def test_m1_tends_to_base_as_flap_amplitude_vanishes():
    p = random_params("m1", 16)
    v = rng.random(16)
    diffs = []
    for amp in (1e-2, 1e-3, 1e-4):
        p["flap_amp"] = np.full(16, amp)
        a, b = evaluate_cycle("m1", p, v), evaluate_cycle("base", p, v)
        diffs.append(np.abs(a.force_earth - b.force_earth).max())
    # the models differ by the flap rotation, O(Phi_f): the gap shrinks tenfold per decade
    assert diffs[0] > 5 * diffs[1] > 25 * diffs[2] and diffs[2] < 1e-4


@pytest.mark.parametrize("model, extra", [("m3", {"stroke_plane": 0.0}), ("m2", {"sweep": 0.0})])
def test_zero_stroke_plane_or_sweep_is_m1(model, extra):
    p = random_params("m1", 32)
    v = rng.random(32)
    a = evaluate_cycle("m1", p, v)
    b = evaluate_cycle(model, {**p, **{k: np.full(32, x) for k, x in extra.items()}}, v)
    np.testing.assert_allclose(b.force_earth, a.force_earth, atol=1e-14)
    np.testing.assert_allclose(b.power, a.power, atol=1e-14)


def test_m4_with_zero_hand_and_still_wrist_is_m3():
    p = random_params("m4", 32)
    p["wrist_amp"] = p["wrist_bias"] = np.zeros(32)
    v = rng.random(32)
    bird = Bird(hand_span_fraction=0.0)
    a = evaluate_cycle("m4", p, v, bird=bird)
    b = evaluate_cycle("m3", {k: p[k] for k in get_model("m3").param_names}, v, bird=bird)
    np.testing.assert_allclose(a.force_earth, b.force_earth, atol=1e-14)
    np.testing.assert_allclose(a.power, b.power, atol=1e-14)


def test_whole_bird_is_two_wings_plus_body():
    c = evaluate_cycle("m3", random_params("m3", 8), rng.random(8))
    w = c.whole_bird_mean
    np.testing.assert_allclose(w.Fx, 2 * (c.mean.Fx - c.body_drag_x) + c.body_drag_x)
    np.testing.assert_allclose(w.Fz, 2 * c.mean.Fz)
    assert np.all(w.Fy == 0)


def test_body_drag_formula():
    c = evaluate_cycle("m1", dict(pitch=0.5, flap_amp=0.0, twist_amp=0.0), 0.8)
    assert float(c.body_drag_x) == pytest.approx(-0.5 * 0.8**2 * math.sin(0.5))


def test_joint_powers_add_up_to_total():
    c = evaluate_cycle("m4", random_params("m4", 8), rng.random(8))
    np.testing.assert_allclose(
        c.joint_power["shoulder"] + c.joint_power["wrist"], c.power, atol=1e-13
    )


# ---- sec. 3.5.1: strip integration and the control-point location ------------------------


def test_strip_integration_converges_to_cp_at_s_over_sqrt3():
    # A flapping wing in still air: every strip sees the same angle of attack and
    # force ~ r^2, so the integral is 4/3 of the r = s/2 value (eq. 50 vs 45).
    p = dict(pitch=0.7, flap_amp=1.2, twist_amp=0.5)
    cp = evaluate_cycle("m1", p, 0.0).force_earth
    strips = evaluate_cycle("m1", p, 0.0, bird=Bird(strips=200)).force_earth
    at_root3 = evaluate_cycle(
        "m1", p, 0.0, bird=Bird(cp_span_fraction=1 / math.sqrt(3))
    ).force_earth
    # midpoint rule on r^2: relative error exactly 1/(4 N^2) = 6.25e-6 at N = 200
    np.testing.assert_allclose(strips, at_root3 * (1 - 1 / (4 * 200**2)), rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(strips, 4 / 3 * cp, rtol=1e-5, atol=1e-12)


# ---- batching and the whole parameter box (hypothesis) ---------------------------------

MODEL_NAMES = tuple(birdsim.MODELS)


@st.composite
def parameter_sets(draw, model: str | None = None):
    name = model or draw(st.sampled_from(MODEL_NAMES))
    m = get_model(name)
    values = {}
    for spec in m.params:
        values[spec.name] = draw(
            st.one_of(st.just(spec.lower), st.just(spec.upper), st.floats(spec.lower, spec.upper))
        )
    speed = draw(st.one_of(st.just(0.0), st.floats(0.0, 2.0)))
    return name, values, speed


@settings(max_examples=60, deadline=None)
@given(parameter_sets())
def test_finite_over_the_whole_box(case):
    name, values, speed = case
    c = evaluate_cycle(name, values, speed)
    assert np.all(np.isfinite(c.panel_force_earth)) and np.all(np.isfinite(c.panel_power))
    assert all(np.isfinite(float(getattr(c.mean, k))) for k in ("Fx", "Fy", "Fz", "P"))


@settings(max_examples=15, deadline=None)
@given(st.sampled_from(MODEL_NAMES), st.integers(1, 600), st.integers(0, 2**31))
def test_batched_equals_one_at_a_time(name, count, seed):
    r = np.random.default_rng(seed)
    lo, hi = get_model(name).bounds
    x = lo + (hi - lo) * r.random((count, len(lo)))
    v = 1.5 * r.random(count)
    names = get_model(name).param_names
    batch = evaluate_cycle(
        name, {n: x[:, i] for i, n in enumerate(names)}, v, n=64
    )  # layout, not resolution
    for j in sorted({0, count // 2, count - 1}):
        one = evaluate_cycle(name, {n: x[j, i] for i, n in enumerate(names)}, v[j], n=64)
        # same arithmetic in a different array layout: round-off only
        np.testing.assert_allclose(
            batch.panel_force_earth[j], one.panel_force_earth, rtol=0, atol=1e-14
        )
        np.testing.assert_allclose(batch.mean.P[j], one.mean.P, rtol=0, atol=1e-14)


def test_batch_shape_broadcasts():
    p = dict(pitch=np.array([[0.1], [0.2]]), flap_amp=np.array([0.3, 0.4, 0.5]), twist_amp=0.2)
    c = evaluate_cycle("m1", p, 0.5)
    n = DEFAULT_SAMPLES  # the default sample count
    assert (
        c.mean.Fz.shape == (2, 3)
        and c.Fz.shape == (2, 3, n)
        and c.panel_force_earth.shape == (2, 3, 1, n, 3)
    )


def test_shapes_that_do_not_broadcast_are_one_line():
    with pytest.raises(birdsim.BirdsimError, match="do not broadcast"):
        evaluate_cycle("m1", dict(pitch=np.zeros(3), flap_amp=np.zeros(4), twist_amp=0.1), 0.5)


def test_induced_velocity_reduces_hover_lift():
    p = example(61).params
    plain = evaluate_cycle("m1", p, 0.0, check_bounds=False)
    induced = evaluate_cycle("m1", p, 0.0, check_bounds=False, bird=Bird(induced_velocity=True))
    assert float(plain.mean.Fz) < float(induced.mean.Fz) < 0  # the downwash costs lift


@pytest.mark.parametrize("speed", [0.0, 0.5])
def test_induced_velocity_is_the_fixed_point(speed):
    # The returned forces must be those the disc's own inflow produces: recompute the
    # inflow from the returned mean force and evaluate once more.  8 damped iterations
    # left ~1e-4 here; the fixed point agrees to the stopping tolerance (1e-10 in the
    # inflow), 1e-8 in the force leaves room for the force's sensitivity to it.
    from birdsim.physics.aero import induced_velocity
    from birdsim.physics.cycle import _histories, sample_phases

    bird = Bird(induced_velocity=True)
    p = (
        dict(pitch=1.4, flap_amp=1.5, twist_amp=0.7)
        if speed == 0
        else dict(pitch=0.2, flap_amp=1.0, twist_amp=0.3)
    )
    c = evaluate_cycle("m1", p, speed, bird=bird, n=64)
    f = 2.0 * c.force_earth.mean(axis=-2)[None]
    f[:, 1] = 0.0
    vi = induced_velocity(f, np.array([speed]), bird.rho, bird.disc_area)
    air = -vi[:, None] * f / np.linalg.norm(f, axis=-1, keepdims=True)
    flat = {k: np.atleast_1d(v) for k, v in c.params.items()}
    again = _histories(
        get_model("m1"), flat, np.array([float(speed)]), bird, sample_phases(64, False), air
    )
    np.testing.assert_allclose(again.force_earth[0, 0], c.force_earth, rtol=0, atol=1e-8)
