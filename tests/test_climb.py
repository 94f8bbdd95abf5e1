"""Climb in the core: climb = 0 is today's evaluation bit for bit; a climbing bird is a
level bird at speed Vt and pitch theta - gamma, seen in axes turned by gamma."""

from __future__ import annotations

import numpy as np
import pytest

import birdsim
from birdsim import Bird, evaluate_cycle, get_model
from birdsim.errors import BirdsimError
from birdsim.physics.aero import body_drag
from birdsim.physics.frames import body_to_earth


def _random(model: str, count: int, seed: int = 0) -> tuple[dict[str, np.ndarray], np.ndarray]:
    rng = np.random.default_rng(seed)
    lo, hi = get_model(model).bounds
    x = lo + (hi - lo) * rng.random((count, len(lo)))
    return {n: x[:, i] for i, n in enumerate(get_model(model).param_names)}, rng.random(count)


BIRDS = {"plain": Bird(), "strips": Bird(strips=3), "induced": Bird(induced_velocity=True)}


@pytest.mark.parametrize("model", list(birdsim.MODELS))
@pytest.mark.parametrize("bird", list(BIRDS))
def test_zero_climb_is_bit_for_bit_level_flight(model, bird):
    p, v = _random(model, 5)
    a = evaluate_cycle(model, p, v, bird=BIRDS[bird], n=64, backend="numpy")
    b = evaluate_cycle(model, p, v, climb=0.0, bird=BIRDS[bird], n=64, backend="numpy")
    c = evaluate_cycle(model, p, v, climb=np.zeros(5), bird=BIRDS[bird], n=64, backend="numpy")
    for other in (b, c):
        for k in ("Fx", "Fy", "Fz", "P"):
            assert np.array_equal(getattr(a.mean, k), getattr(other.mean, k))
            assert np.array_equal(getattr(a.whole_bird_mean, k), getattr(other.whole_bird_mean, k))
        assert np.array_equal(a.panel_force_earth, other.panel_force_earth)
        assert np.array_equal(a.panel_power, other.panel_power)
        assert np.array_equal(a.body_drag_x, other.body_drag_x)
        assert np.all(other.body_drag_z == 0.0)


@pytest.mark.parametrize("model", list(birdsim.MODELS))
def test_climb_is_level_flight_at_vt_and_pitch_minus_gamma_turned_by_gamma(model):
    # The wings see the air through the body pitch only: at (V, climb) and pitch theta they
    # see what a level bird at Vt = |(V, climb)| and pitch theta - gamma sees, so the forces
    # are the same in body axes; in earth axes they are turned by gamma.  Round-off: 1e-12.
    p, v = _random(model, 6, seed=3)
    climb = np.array([0.4, -0.3, 0.2, -0.5, 0.1, 0.35])
    gamma = np.arctan2(climb, v)
    vt = np.hypot(v, climb)
    level_p = {**p, "pitch": p["pitch"] - gamma}
    a = evaluate_cycle(model, p, v, climb=climb, backend="numpy")
    b = evaluate_cycle(model, level_p, vt, check_bounds=False, backend="numpy")
    g = gamma[:, None]
    fb = b.force_earth
    turned = body_to_earth(g, (fb[..., 0], fb[..., 1], fb[..., 2]))
    for i in range(3):
        np.testing.assert_allclose(a.force_earth[..., i], turned[i], rtol=0, atol=1e-12)
    np.testing.assert_allclose(a.power, b.power, rtol=0, atol=1e-12)
    # body drag: |level drag at theta - gamma| along -(V, -climb) / Vt
    mag = 0.5 * vt**2 * np.abs(np.sin(p["pitch"] - gamma))
    np.testing.assert_allclose(a.body_drag_x, -mag * v / vt, rtol=0, atol=1e-14)
    np.testing.assert_allclose(a.body_drag_z, mag * climb / vt, rtol=0, atol=1e-14)
    np.testing.assert_allclose(
        np.asarray(a.mean.Fz), a.force_earth[..., 2].mean(-1) + a.body_drag_z, atol=1e-14
    )


def test_body_drag_opposes_the_velocity_and_is_eq7_at_zero_climb():
    v, climb, pitch = (
        np.array([0.5, 0.0, 0.3]),
        np.array([0.2, -0.4, 0.0]),
        np.array([0.3, 1.0, 0.6]),
    )
    dx, dz = body_drag(v, climb, pitch, 1.0, 1.0)
    vel = np.stack([v, -climb], -1)  # seed earth (x, z) velocity
    drag = np.stack([dx, dz], -1)
    cross = vel[:, 0] * drag[:, 1] - vel[:, 1] * drag[:, 0]
    np.testing.assert_allclose(cross, 0.0, atol=1e-15)
    assert np.all((vel * drag).sum(-1) < 0)
    assert dx[2] == -0.5 * 0.3**2 * np.sin(0.6) and dz[2] == 0.0


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), "up"])
def test_bad_climb_is_one_line(bad):
    with pytest.raises(BirdsimError, match="climb="):
        evaluate_cycle("m1", {"pitch": 0.1, "flap_amp": 0.5, "twist_amp": 0.1}, 0.5, climb=bad)


def test_induced_velocity_with_climb_runs_and_differs():
    p = {"pitch": 0.3, "flap_amp": 0.8, "twist_amp": 0.3}
    bird = Bird(induced_velocity=True)
    a = evaluate_cycle("m1", p, 0.3, bird=bird).mean
    b = evaluate_cycle("m1", p, 0.3, climb=0.2, bird=bird).mean
    assert np.isfinite(float(b.Fz)) and abs(float(a.Fz) - float(b.Fz)) > 1e-3
