"""Model m5, the folding wing: its reduction to m4, the fold's geometry against hand
calculations, the hand's area following the extension, the span ratio, the kernels."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim import Bird, evaluate_cycle, get_model
from birdsim.errors import BirdConfigError
from birdsim.physics import kernel
from birdsim.physics.cycle import sample_phases
from birdsim.physics.span import span_ratio, tip_span

M4, M5 = get_model("m4"), get_model("m5")
OTHER = Bird(
    semispan=0.35,
    chord=0.09,
    hand_chord=0.07,
    hand_span_fraction=0.4,
    rho=1.2,
    omega=40.0,
    cp_span_fraction=0.6,
    strips=3,
    elbow_span_fraction=0.3,
    fold_coupling=1.7,
)


def _m4_sets(count: int, seed: int) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    lo, hi = M4.bounds
    X = lo + (hi - lo) * rng.random((count, len(lo)))
    return {n: X[:, i] for i, n in enumerate(M4.param_names)}


def _m5_sets(count: int, seed: int) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    lo, hi = M5.bounds
    X = lo + (hi - lo) * rng.random((count, len(lo)))
    return {n: X[:, i] for i, n in enumerate(M5.param_names)}


@pytest.mark.parametrize("bird", [Bird(), OTHER], ids=["seed", "other"])
@pytest.mark.parametrize("backend", ["numpy", "kernel"])
def test_m5_without_fold_and_supination_is_m4(bird, backend):
    # The elbow and wrist-sweep hinges at angle 0 are identities and the offsets
    # e + (a - e) and (r - e) + e equal m4's a and r up to one rounding: round-off only
    # (1e-14 of the force scale; the fold phase then has no effect).
    p4 = _m4_sets(12, 5)
    rng = np.random.default_rng(6)
    p5 = {**p4, "fold_amp": 0.0, "supination_amp": 0.0, "fold_phase": rng.uniform(-1.5, 1.5, 12)}
    V = np.linspace(0.0, bird.omega * bird.semispan, 12)
    a = evaluate_cycle("m4", p4, V, bird=bird, backend=backend, n=64)
    b = evaluate_cycle("m5", p5, V, bird=bird, backend=backend, n=64)
    scale = bird.rho * bird.omega**2 * bird.semispan**3 * bird.chord
    for k in ("Fx", "Fy", "Fz", "P"):
        unit = scale * (bird.omega * bird.semispan if k == "P" else 1.0)
        np.testing.assert_allclose(
            getattr(b.mean, k) / unit, getattr(a.mean, k) / unit, rtol=0, atol=1e-14
        )
    if backend == "numpy":
        np.testing.assert_allclose(
            b.panel_force_earth / scale, a.panel_force_earth / scale, rtol=0, atol=1e-14
        )
        np.testing.assert_allclose(b.cp_position_body, a.cp_position_body, atol=1e-15)


def test_fold_geometry_by_hand():
    # A flat wing (no flap, twist, stroke plane or wrist flap): the tip at
    # mid-downstroke is the extended semispan; at the fold's peak (phase pi + phi_F)
    # the forearm has turned forward by F and the hand back by k F relative to it:
    # tip y = e + f cos F + h cos((k - 1) F), x = f sin F - h sin((k - 1) F).
    bird = Bird(elbow_span_fraction=0.4, fold_coupling=1.5, hand_span_fraction=0.3)
    F = 0.8
    p = dict(
        pitch=0.0,
        flap_amp=0.0,
        twist_amp=0.0,
        stroke_plane=0.0,
        wrist_amp=0.0,
        wrist_bias=0.0,
        wrist_lag=0.0,
        fold_amp=F,
        fold_phase=0.0,
        supination_amp=0.0,
    )
    arm = 1.0 - 0.3
    e, f, h = 0.4 * arm, 0.6 * arm, 0.3
    span = tip_span("m5", p, np.array([0.0, np.pi]), bird=bird)
    assert span[0] == pytest.approx(2.0, abs=1e-15)
    expected = e + f * math.cos(F) + h * math.cos(0.5 * F)
    assert span[1] == pytest.approx(2.0 * expected, abs=1e-15)
    assert span_ratio("m5", p, bird=bird) == pytest.approx(expected, abs=1e-15)
    c = evaluate_cycle("m5", p, 0.5, bird=bird, n=4, backend="numpy")
    # the hand's control point (half the hand span out from the wrist) at phase pi
    hand = c.cp_position_body[1, 2] if c.cp_position_body.ndim == 3 else None
    assert hand is not None
    x = f * math.sin(F) - 0.5 * h * math.sin(0.5 * F)
    y = e + f * math.cos(F) + 0.5 * h * math.cos(0.5 * F)
    np.testing.assert_allclose(hand, [x, y, 0.0], atol=1e-15)


def test_hand_area_follows_the_wrist():
    # The force is linear in the area, so the hand's force history with area loss
    # lambda is the lossless history times 1 - lambda (1 - cos q_w) / 2 at every sample,
    # q_w = k F (1 - cos(wt - phi_F)) / 2 the wrist flexion (exact up to round-off).
    p = {k: v[0] for k, v in _m5_sets(1, 9).items()}
    lossless = Bird(hand_fold_area_loss=0.0)
    lossy = Bird(hand_fold_area_loss=0.7, fold_coupling=1.3)
    lossless = Bird(hand_fold_area_loss=0.0, fold_coupling=1.3)
    a = evaluate_cycle("m5", p, 0.4, bird=lossless, n=32, backend="numpy")
    b = evaluate_cycle("m5", p, 0.4, bird=lossy, n=32, backend="numpy")
    wt = a.time * lossless.omega
    q = 1.3 * p["fold_amp"] * (1.0 - np.cos(wt - p["fold_phase"])) / 2.0
    factor = 1.0 - 0.7 * (1.0 - np.cos(q)) / 2.0
    np.testing.assert_allclose(
        b.panel_force_earth[1], a.panel_force_earth[1] * factor[:, None], atol=1e-15
    )
    np.testing.assert_allclose(
        b.panel_force_earth[0], a.panel_force_earth[0], atol=0
    )  # the arm keeps its area


@pytest.mark.parametrize("bird", [Bird(), OTHER, Bird(hand_fold_area_loss=1.0, fold_coupling=2.0)])
def test_fold_kernel_equals_numpy_and_gradients_are_exact(bird):
    # Means: same physics, another summation order: 1e-12 of the force scale (the
    # kernels' contract).  Gradients against central differences, h = 1e-6: truncation
    # ~1e-12, round-off ~1e-10, so 1e-6 relative per row is a real check.
    p = _m5_sets(10, 11)
    V = np.linspace(0.0, bird.omega * bird.semispan, 10)
    C = np.zeros(10)
    a = evaluate_cycle("m5", p, V, bird=bird, n=64)
    b = evaluate_cycle("m5", p, V, bird=bird, n=64, backend="numpy")
    assert a.panel_means is not None
    scale = bird.rho * bird.omega**2 * bird.semispan**3 * bird.chord
    for k in ("Fx", "Fz", "P"):
        unit = scale * (bird.omega * bird.semispan if k == "P" else 1.0)
        np.testing.assert_allclose(getattr(a.mean, k) / unit, getattr(b.mean, k) / unit, atol=1e-12)
    ph = sample_phases(64, False)
    vals, grads = kernel.means_and_gradients(M5, p, V, C, bird, ph)
    X = np.stack([p[n] for n in M5.param_names], -1)
    h = 1e-6
    for i in range(X.shape[1]):
        Xp, Xm = X.copy(), X.copy()
        Xp[:, i] += h
        Xm[:, i] -= h
        fp = kernel.means_and_gradients(M5, dict(zip(M5.param_names, Xp.T)), V, C, bird, ph)[0]
        fm = kernel.means_and_gradients(M5, dict(zip(M5.param_names, Xm.T)), V, C, bird, ph)[0]
        fd = (fp - fm) / (2 * h)
        err = np.abs(grads[:, :, i] - fd)
        assert np.all(err <= 1e-6 * np.abs(fd) + 1e-9 * np.abs(vals).max()), (i, err.max())


def test_supination_turns_the_hand_leading_edge_up_in_the_upstroke():
    # Supination about the hand's span axis adds to the angle fed to the twist matrix,
    # whose positive sense is leading edge up (the twist -Theta cos wt is +Theta at
    # mid-upstroke): the hand's angle of attack rises in the upstroke.
    base = {n: 0.0 for n in M5.param_names} | dict(pitch=0.1, flap_amp=0.6, twist_amp=0.2)
    up = dict(base, supination_amp=0.8)
    bird = Bird()
    from birdsim.physics.joints import joint_states

    s0 = joint_states(M5, {k: np.array(v) for k, v in base.items()}, bird, np.array([np.pi]))
    s1 = joint_states(M5, {k: np.array(v) for k, v in up.items()}, bird, np.array([np.pi]))
    assert float(s0["supination"].angle.flat[0]) == 0.0
    assert float(s1["supination"].angle.flat[0]) == pytest.approx(0.8, abs=1e-15)


@pytest.mark.parametrize(
    "field, value",
    [
        ("fold_coupling", 2.5),
        ("fold_coupling", -0.1),
        ("elbow_span_fraction", 0.0),
        ("hand_fold_area_loss", 1.2),
    ],
)
def test_bird_refuses_a_skeleton_out_of_range(field, value):
    with pytest.raises(BirdConfigError, match=f"bird.{field}=.*allowed") as info:
        Bird(**{field: value})
    assert "\n" not in str(info.value)


def test_forces_reports_the_span_ratio(capsys):
    # every wingbeat's output carries its span ratio: the CLI's equals physics.span's
    import json

    from birdsim.cli import main

    args = ["forces", "--model", "m5", "--speed", "0.5", "--json"]
    assert main([*args, "--param", "fold_amp=0.6"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["span_ratio"] == pytest.approx(float(span_ratio("m5", out["params"])), abs=0)
    assert out["span_ratio"] < 0.95  # a fold of 0.6 rad at mid-upstroke shortens the span
    assert main(["forces", "--model", "m3", "--speed", "0.5", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["span_ratio"] == pytest.approx(1.0, abs=1e-12)


@pytest.mark.parametrize("fraction", [0.0, 1.0])
def test_kernel_refuses_a_bird_without_m5_geometry(fraction):
    """The fused kernel called directly (kernel.means, means_and_gradients, and the cost's
    forces that call them) refuses an m5 bird with no arm or no hand in evaluate_cycle's
    one line; before, it returned the forces of a wing with a zero-area panel."""
    from birdsim.errors import BirdsimError
    from birdsim.tables.cost import forces, forces_and_gradients

    if not kernel.available():
        pytest.skip("no compiled kernel")
    bird = Bird(hand_span_fraction=fraction)
    flat = {k: v[:2] for k, v in _m5_sets(2, 3).items()}
    v, z = np.full(2, 0.4), np.zeros(2)
    X = np.stack([flat[n] for n in M5.param_names], axis=-1)
    with pytest.raises(BirdsimError) as ref:
        evaluate_cycle("m5", flat, v, bird=bird, n=16)
    line = str(ref.value)
    assert "\n" not in line and f"hand_span_fraction={fraction!r}" in line
    calls = (
        lambda: kernel.means(M5, flat, v, z, np.zeros((2, 3)), bird, sample_phases(16, False)),
        lambda: kernel.means_and_gradients(M5, flat, v, z, bird, sample_phases(16, False)),
        lambda: forces(M5, X, v, bird, 16),
        lambda: forces_and_gradients(M5, X, v, bird, 16),
    )
    for call in calls:
        with pytest.raises(BirdsimError) as err:
            call()
        assert str(err.value) == line
    assert kernel.available()  # a refused bird does not switch the kernel off
    out = kernel.means(
        M4,
        {k: v for k, v in _m4_sets(2, 3).items()},
        v,
        z,
        np.zeros((2, 3)),
        bird,
        sample_phases(16, False),
    )
    assert out is not None  # m4 keeps its zero-span panels (Bird allows 0 and 1)


def test_the_pigeon_carries_its_weight_at_slow_speed_only_with_the_wider_flap_bound():
    """m5's shoulder flap is bounded by pi/2 (m1-m3's), not m4's pi/4: trimmed level flight
    of the pigeon at Usherwood's 4.46 m/s needs a flap amplitude near 1.03 rad.  From the
    same starts (the trimmed wingbeat of docs/validation.md, rounded, and the model's
    hover guess) the bound pi/2 trims (residuals within TRIM_TOL of the weight) and pi/4
    leaves more than 10 % of the weight unsupported (16 % with the validation's starts)."""
    import dataclasses
    from pathlib import Path

    from birdsim.validation.trim import trim_sweep

    pigeon = Bird.from_toml(Path(__file__).resolve().parent.parent / "models" / "pigeon.toml")
    m5 = get_model("m5")
    assert m5.spec("flap_amp").upper == pytest.approx(math.pi / 2, abs=0)
    narrow = dataclasses.replace(
        m5,
        params=tuple(
            dataclasses.replace(p, upper=math.pi / 4) if p.name == "flap_amp" else p
            for p in m5.params
        ),
    )
    start = dict(pitch=0.27, flap_amp=1.03, twist_amp=0.785, stroke_plane=1.047)
    start |= dict(wrist_amp=0.14, wrist_bias=0.0, wrist_lag=1.571)
    start |= dict(fold_amp=0.43, fold_phase=-1.23, supination_amp=0.0)
    guess = m5.guess("hover")
    for model, trims in ((m5, True), (narrow, False)):
        lo, hi = model.bounds
        rows = [np.clip([p[n] for n in model.param_names], lo, hi) for p in (start, guess)]
        best = min(
            (trim_sweep(model, pigeon, [4.46], start_from=[r], backward=False) for r in rows),
            key=lambda s: s.points[0].cost,
        ).points[0]
        assert best.trimmed is trims, (model.spec("flap_amp").upper, best.residual_z)
        if not trims:
            assert best.residual_z > 0.10  # net force / weight: the weight not carried
