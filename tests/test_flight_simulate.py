"""Free flight mechanics (birdsim.flight.simulate): the body's translation is free and
responds to MuJoCo's forces, everything else is prescribed.

Tolerances: momentum and centre of mass are conserved to round-off (<= 1e-9 semispan of
drift per wingbeat, the issue's target); the projection that removes semi-implicit
Euler's O(h^2) momentum error stays below 1e-4 semispan per step; momentum change over a
wingbeat = MuJoCo's aero force (re-evaluated on a fresh MjData) + weight to 1 % of the
weight (the issue's target); free fall to the first-order integrator's g h t."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest

from birdsim.flight.simulate import FreeBird, SimConfig
from birdsim.mujoco.callback import AeroCallback
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.kinematics import get_model

BIRD = Bird(mass=30.0, gravity=0.012)  # models/seed-bird.toml
CRUISE = {
    "pitch": 0.0,
    "flap_amp": 0.55,
    "twist_amp": 0.25,
    "stroke_plane": 0.1,
    "wrist_amp": 0.3,
    "wrist_bias": 0.1,
    "wrist_lag": 1.2,
}


def _params(model: str = "m4", values: dict | None = None) -> np.ndarray:
    kin = get_model(model)
    values = values or CRUISE
    return np.array([values.get(n, kin.guess("cruise")[n]) for n in kin.param_names])


def _fly(fb: FreeBird, params: np.ndarray, beats: int, position, velocity, every: int = 1) -> list:
    n = fb.config.steps_per_beat
    pres = fb.schedule.advance(params, np.arange(n) * fb.h, 0.0, n * fb.h)
    fb.start(np.asarray(position, float), np.asarray(velocity, float), pres)
    rec: list = []
    for _ in range(beats):
        times = fb.time + np.arange(n) * fb.h
        fb.step_many(fb.schedule.advance(params, times, fb.time, n * fb.h), np.zeros(3), rec, every)
    return rec


def _com(m: mujoco.MjModel, qpos: np.ndarray, qvel: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Centre of mass and whole-bird linear momentum / mass from a fresh MjData."""
    d = mujoco.MjData(m)
    d.qpos[:], d.qvel[:] = qpos, qvel
    mujoco.mj_fwdPosition(m, d)
    full = np.zeros((m.nv, m.nv))
    mujoco.mj_fullM(m, d, full)
    torso = m.body("torso").id
    return d.subtree_com[torso].copy(), full[:3] @ qvel / m.body_subtreemass[torso]


@pytest.mark.parametrize("model", ["m4", "base"])
def test_momentum_is_conserved_while_the_body_oscillates(model):
    fb = FreeBird(model, BIRD, _params(model), aero=False, gravity=False)
    per_beat = fb.config.steps_per_beat // 8
    with fb:
        rec = _fly(fb, _params(model), 10, (0.0, 0.0, 6.0), (0.0, 0.0, 0.0), every=per_beat)
    coms = np.array([_com(fb.m, r[1], r[2])[0] for r in rec])
    beat_starts = coms[::8]
    drift = np.abs(np.diff(beat_starts, axis=0)).max()
    assert drift <= 1e-9
    assert np.abs(coms - coms[0]).max() <= 1e-9
    torso = np.array([r[1][:3] for r in rec])
    span = torso.max(axis=0) - torso.min(axis=0)
    assert span[2] > 1e-3  # the body alone bobs against the wings
    assert np.abs(torso[:, 1]).max() < 1e-12  # y stays 0 by symmetry
    assert fb.projection_max < 1e-4  # MuJoCo's own integration agrees to O(h^2)


def test_physics_drives_the_motion():
    """Over a wingbeat of steady flight the whole bird's momentum changes by the
    wingbeat's aero impulse (MuJoCo's callback, re-evaluated) plus its weight."""
    fb = FreeBird("m4", BIRD, _params())
    with fb:
        rec = _fly(fb, _params(), 2, (0.0, 0.0, 6.0), (0.9, 0.0, 0.0), every=1)
    m, h, n = fb.m, fb.h, fb.config.steps_per_beat
    mass = fb.total_mass
    weight = mass * BIRD.gravity
    # a fresh data and callback for the re-evaluation (the flight's callback is uninstalled)
    d = mujoco.MjData(m)
    cb = AeroCallback(m, "m4", fb.red)
    mujoco.set_mjcb_passive(cb)
    try:
        impulse = np.zeros(3)
        for r in rec[n : 2 * n]:
            d.qpos[:], d.qvel[:] = r[1], r[2]
            mujoco.mj_forward(m, d)
            impulse += h * d.qfrc_passive[:3]
    finally:
        mujoco.set_mjcb_passive(None)
    end_qpos, end_qvel = fb.d.qpos.copy(), fb.d.qvel.copy()
    _, v_start = _com(m, rec[n][1], rec[n][2])
    _, v_end = _com(m, end_qpos, end_qvel)
    dp = mass * (v_end - v_start)
    expected = impulse + np.array([0.0, 0.0, -weight]) * n * h
    assert np.abs(dp - expected).max() <= 0.01 * weight * n * h
    assert np.abs(impulse[2]) > 0.5 * weight * n * h  # the wings really carry the bird


def test_heavy_bird_flies_the_core_mean_force(monkeypatch):
    """A bird that cannot bob (a heavy body, nearly massless wings) feels the analytic
    whole-bird mean force of the core (the torso then moves exactly as the core assumes)."""
    import birdsim.mujoco.model as model

    monkeypatch.setattr(model, "PANEL_MASS_FRACTION", 1e-9)
    heavy = Bird(mass=1e6, gravity=0.0)
    fb = FreeBird("m4", heavy, _params(), gravity=False)
    n = fb.config.steps_per_beat
    with fb:
        _fly(fb, _params(), 1, (0.0, 0.0, 6.0), (0.9, 0.0, 0.0), every=n)
    mean_world = (fb.P - fb.total_mass * np.array([0.9, 0.0, 0.0])) / (n * fb.h)
    core = evaluate_cycle("m4", CRUISE, 0.9, bird=fb.red, n=n).whole_bird_mean  # seed axes
    expected = np.array([float(core.Fx), -float(core.Fz)])
    np.testing.assert_allclose(
        mean_world[[0, 2]], expected, atol=2e-5 * np.abs(expected).max()
    )  # what is left: the body moves by 1e-6
    assert abs(expected[1]) > 0.1  # a real lift, not two zeros


def test_free_fall_without_aero():
    fb = FreeBird("m4", BIRD, _params(), aero=False)
    n = fb.config.steps_per_beat
    with fb:
        rec = _fly(fb, _params(), 2, (0.0, 0.0, 6.0), (0.3, 0.0, 0.1), every=n // 4)
    g, h = BIRD.gravity, fb.h
    com0, _ = _com(fb.m, rec[0][1], rec[0][2])
    for r in rec:
        t = r[0]
        com, vel = _com(fb.m, r[1], r[2])
        assert abs(com[2] - (com0[2] + 0.1 * t - 0.5 * g * t * t)) <= g * h * t + 1e-12
        assert abs(com[0] - (com0[0] + 0.3 * t)) <= 1e-12 * max(1.0, t)
        assert abs(vel[2] - (0.1 - g * t)) <= g * h + 1e-12


def test_sim_config_is_checked():
    with pytest.raises(ValueError):
        SimConfig(steps_per_beat=100, control_per_beat=8)
    with pytest.raises(ValueError):
        SimConfig(log_per_beat=16, steps_per_beat=128)
    assert SimConfig().steps_per_beat % SimConfig().log_per_beat == 0
    assert math.isclose(2 * math.pi / SimConfig().steps_per_beat, FreeBird("m4", BIRD, _params()).h)


@pytest.mark.parametrize("attitude,limit", [("posed", 3e-4), ("free", 1.2e-3)])
def test_mujoco_alone_drifts_at_first_order_and_the_projection_removes_it(attitude, limit):
    """Without the momentum projection, MuJoCo's semi-implicit Euler with the wings reset
    to their prescription every step moves the centre of mass of a weightless, airless
    bird by O(h) per wingbeat (measured, m4 at period/128: posed 1.9e-4 semispan per
    wingbeat, free attitude 8.0e-4; a quarter of that at period/512); the projection
    (default on) keeps it at round-off.  Tolerances: the measured drift with 50 % margin,
    and the step-size ratio of a first-order method (4x the steps: at least 3x less)."""
    drift = {}
    for steps in (128, 512):
        config = SimConfig(steps_per_beat=steps, momentum_projection=False, attitude=attitude)
        fb = FreeBird("m4", BIRD, _params(), aero=False, gravity=False, config=config)
        with fb:
            rec = _fly(fb, _params(), 10, (0.0, 0.0, 6.0), (0.0, 0.0, 0.0), every=steps // 8)
        coms = np.array([_com(fb.m, r[1], r[2])[0] for r in rec])
        drift[steps] = np.abs(np.diff(coms[::8], axis=0)).max()
        assert fb.projection_max == 0.0  # nothing was projected
    assert 1e-6 < drift[128] <= limit  # real (not round-off), and small
    assert drift[512] <= drift[128] / 3  # first order in the step


def _angular_momentum(m: mujoco.MjModel, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
    """The whole bird's angular momentum about its centre of mass (world), MuJoCo's own
    (``mj_subtreeVel`` on a fresh MjData), independent of the simulation's bookkeeping."""
    d = mujoco.MjData(m)
    d.qpos[:], d.qvel[:] = qpos, qvel
    mujoco.mj_forward(m, d)
    mujoco.mj_subtreeVel(m, d)
    return d.subtree_angmom[m.body("torso").id].copy()


@pytest.mark.parametrize("projection", [True, False])
def test_free_body_counter_rotates_and_keeps_zero_momenta(projection):
    """Aero and gravity off, an asymmetric wingbeat (left flap amplitude + 0.2 rad): the
    torso turns in pitch, roll and yaw against the wings while the whole bird's linear and
    angular momenta stay zero.  With the projection: <= 1e-9 per wingbeat (the issue's
    target; measured ~2e-16).  Without it MuJoCo's own integration drifts at first order
    (measured at period/128: 3.0e-4 angular momentum per wingbeat, the reason the
    projection stays on) -- asserted as a bound so a regression shows."""
    config = SimConfig(momentum_projection=projection, attitude="free")
    right = _params()
    left = right.copy()
    left[get_model("m4").param_names.index("flap_amp")] += 0.2
    fb = FreeBird("m4", BIRD, right, aero=False, gravity=False, config=config)
    n = config.steps_per_beat
    with fb:
        fb.schedule = type(fb.schedule)(
            fb.m, fb.kin, fb.red, right, smoothing=0.0, initial_left=left
        )
        fb.start(
            np.array([0.0, 0.0, 6.0]),
            np.zeros(3),
            fb.schedule.advance(right, np.arange(n) * fb.h, 0.0, n * fb.h, left),
        )
        rec: list = []
        for _ in range(6):
            times = fb.time + np.arange(n) * fb.h
            fb.step_many(
                fb.schedule.advance(right, times, fb.time, n * fb.h, left), np.zeros(3), rec, n // 8
            )
    ang = np.array([_angular_momentum(fb.m, r[1], r[2]) for r in rec])
    lin = np.array([_com(fb.m, r[1], r[2])[1] for r in rec]) * fb.total_mass
    quat = np.array([r[1][3:7] for r in rec])
    assert fb.root_applied_max == 0.0  # no force or torque on the root, exactly
    if projection:
        assert np.abs(ang).max() <= 1e-9 and np.abs(lin).max() <= 1e-9
    else:
        assert 1e-7 < np.abs(ang).max() <= 5e-3
    # the body really counter-rotates: roll (x) and yaw (z) quaternion parts move
    swing = quat.max(axis=0) - quat.min(axis=0)
    assert swing[1] > 1e-3 and swing[2] > 1e-2 and swing[3] > 1e-3
