"""The fused kernel against the numpy reference: equal means (1e-12) for every model
and option, NaN propagation, the numpy fallback when the JIT cannot run.  (Gradients:
test_kernel_dual.py.)"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import birdsim
from birdsim import Bird, evaluate_cycle, get_model
from birdsim.errors import BirdsimError
from birdsim.physics import kernel
from birdsim.physics.aero import RoboflyPolar
from birdsim.physics.cycle import sample_phases

# a bird with every geometric and air property off the seed values (SI-like numbers)
OTHER = Bird(
    semispan=0.35,
    chord=0.09,
    hand_chord=0.07,
    hand_span_fraction=0.4,
    rho=1.2,
    omega=40.0,
    body_drag_area=0.004,
    cp_span_fraction=0.6,
    wrist_twist_ratio=0.3,
)
OPTIONS = {
    "plain": (Bird(), 0.0),
    "strips": (Bird(strips=4), 0.0),
    "induced": (Bird(induced_velocity=True), 0.0),
    "robofly": (Bird(polar=RoboflyPolar()), 0.0),
    "climb": (Bird(), 0.3),
    "induced-climb": (Bird(induced_velocity=True, strips=2), 0.2),
    "descent-strips-robofly": (Bird(strips=3, polar=RoboflyPolar()), -0.4),
    "other-bird": (OTHER, 2.0),
}


def _random(model: str, count: int, seed: int, speed_scale: float = 1.0):
    rng = np.random.default_rng(seed)
    m = get_model(model)
    lo, hi = m.bounds
    X = lo + (hi - lo) * rng.random((count, len(lo)))
    V = speed_scale * rng.random(count)
    V[:3] = 0.0  # hover: flow reversal at every stroke reversal
    return m, X, V


@pytest.mark.parametrize("option", list(OPTIONS))
@pytest.mark.parametrize("model", list(birdsim.MODELS))
def test_kernel_means_equal_numpy(model, option):
    # Same physics, different summation order and addition theorem for sin(wt + phase):
    # round-off only, ~1e-15; 1e-12 (relative to the force scale) is the contract.
    bird, climb = OPTIONS[option]
    m, X, V = _random(model, 16, seed=sum(map(ord, option)), speed_scale=bird.omega * bird.semispan)
    p = {n: X[:, i] for i, n in enumerate(m.param_names)}
    climb = climb * bird.omega * bird.semispan
    a = evaluate_cycle(model, p, V, climb=climb, bird=bird, backend="kernel")
    b = evaluate_cycle(model, p, V, climb=climb, bird=bird, backend="numpy")
    assert a.panel_means is not None and b.panel_means is None
    scale = bird.rho * bird.omega**2 * bird.semispan**3 * bird.chord
    for k in ("Fx", "Fy", "Fz", "P"):
        unit = scale * (bird.omega * bird.semispan if k == "P" else 1.0)
        np.testing.assert_allclose(
            getattr(a.mean, k) / unit, getattr(b.mean, k) / unit, rtol=0, atol=1e-12
        )
        np.testing.assert_allclose(
            getattr(a.whole_bird_mean, k) / unit,
            getattr(b.whole_bird_mean, k) / unit,
            rtol=0,
            atol=1e-12,
        )
    for name in b.panel_names:
        np.testing.assert_allclose(
            a.panel_mean[name].Fz / scale, b.panel_mean[name].Fz / scale, rtol=0, atol=1e-12
        )
    for g, v in b.joint_power_mean.items():
        np.testing.assert_allclose(a.joint_power_mean[g] / scale, v / scale, rtol=0, atol=1e-12)
    # histories, when read, come from the numpy path
    np.testing.assert_array_equal(a.panel_force_earth, b.panel_force_earth)


def test_appendix_grid_and_unknown_backend():
    p = get_model("m3").guess()
    a = evaluate_cycle("m3", p, 0.4, n=11, endpoint=True).mean
    b = evaluate_cycle("m3", p, 0.4, n=11, endpoint=True, backend="numpy").mean
    assert abs(float(a.Fz) - float(b.Fz)) < 1e-14
    with pytest.raises(BirdsimError, match="backend='jax' is unknown"):
        evaluate_cycle("m3", p, 0.4, backend="jax")


def test_nan_in_gives_nan_out():
    m = get_model("m4")
    flat = {k: np.full(3, v) for k, v in m.guess().items()}
    flat["flap_amp"] = np.array([np.nan, 0.5, 0.5])
    flat["pitch"] = np.array([0.3, np.nan, 0.3])
    F, P, JP = kernel.means(
        m,
        flat,
        np.array([0.3, 0.3, np.nan]),
        np.zeros(3),
        np.zeros((3, 3)),
        Bird(),
        sample_phases(16, False),
    )
    for row in range(3):
        assert np.all(np.isnan(F[row, :, [0, 2]])) and np.all(np.isnan(P[row])), row
    vals, grads = kernel.means_and_gradients(
        m, flat, np.array([0.3, 0.3, np.nan]), np.zeros(3), Bird(), sample_phases(16, False)
    )
    assert np.all(np.isnan(vals[:, [0, 2, 3]])) and np.all(np.isnan(grads[:, [0, 2, 3]]))


def test_a_failing_jit_falls_back_to_numpy_with_one_warning(monkeypatch):
    def broken(*args):
        raise RuntimeError("LLVM says no\nsecond line")

    monkeypatch.setattr(kernel, "_means_kernel", broken)
    monkeypatch.setitem(kernel._STATE, "ok", True)
    monkeypatch.setitem(kernel._STATE, "warned", False)
    p = get_model("m2").guess()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        a = evaluate_cycle("m2", p, 0.5)
        b = evaluate_cycle("m2", p, 0.5)
    msgs = [str(w.message) for w in caught]
    assert (
        len(msgs) == 1 and "LLVM says no" in msgs[0] and "\n" not in msgs[0] and "numpy" in msgs[0]
    )
    ref = evaluate_cycle("m2", p, 0.5, backend="numpy")
    assert a.panel_means is None and b.panel_means is None
    assert float(a.mean.Fz) == float(ref.mean.Fz)


def test_without_numba_the_kernel_is_unavailable(monkeypatch):
    monkeypatch.setitem(kernel._STATE, "ok", False)
    c = evaluate_cycle("m1", get_model("m1").guess(), 0.2)
    assert c.panel_means is None and np.isfinite(float(c.mean.Fz))
