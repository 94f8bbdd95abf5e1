"""The free body's attitude loop, second stage (issue 22): the flapping's rate derivatives
in the loop, the pitch command planned along the path, and the gust recovery.

Tolerances: the MuJoCo-measured rate derivatives (16 phases, one-sided steps of 0.01
rad per time unit) against the analytic core's exact ones: 1 % of the largest entry
(measured agreement: 4 digits; the pitch damping differs by the tail's, which the core
does not have); the closed-loop poles of the gains: 1e-6 relative (polynomial roots of a
triple or double root, whose round-off goes as its cube or square root); flight figures
bounded near what they measured (docs/free-body.md), below the issue's targets."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim.flight.attitude import attitude_gains, damped_gains


def test_measured_rate_derivatives_agree_with_the_analytic_core():
    """Two independent paths to the wingbeat-mean moment's body-rate derivatives: MuJoCo's
    callback on a held body turning at a small rate (measured_rate_derivatives) and the
    analytic core (birdsim.physics.moments, moment_drate).  Cruise-like m3 wingbeat:
    strong roll damping (dMx/dp about -0.47 weight units x semispan per rad per time
    unit, against a whole-bird roll inertia of 0.85), the outer wing's faster air rolling
    a yawing bird (dMx/dr > 0), weak yaw damping; pitch is decoupled by symmetry; the tail
    adds pitch damping the core does not have."""
    from birdsim.flight.attitude import measured_rate_derivatives
    from birdsim.flight.presets import demo_bird
    from birdsim.flight.simulate import FreeBird, SimConfig
    from birdsim.physics.kinematics import get_model
    from birdsim.physics.moments import wingbeat_moments

    bird = demo_bird()
    names = get_model("m3").param_names
    p = np.array([0.12, 0.9, 0.35, 0.12])
    with FreeBird("m3", bird, p, config=SimConfig(attitude="free")) as fb:
        ours = measured_rate_derivatives(fb, p, 0.12, 0.5)
        red = fb.red
    core = wingbeat_moments("m3", dict(zip(names, p)), 0.5, red, jacobians=True).moment_drate
    tol = 0.01 * np.abs(core).max()
    lateral = np.ix_([0, 2], [0, 2])
    np.testing.assert_allclose(ours[lateral], core[lateral], atol=tol)
    assert ours[0, 0] < 0 and ours[2, 2] < 0 and ours[0, 2] > 0
    assert abs(ours[0, 0]) > 5 * abs(ours[2, 2])  # roll is damped far more than yaw
    # symmetry: no pitch from roll or yaw rates, no roll or yaw from the pitch rate
    assert np.abs(ours[1, [0, 2]]).max() < 1e-9 and np.abs(ours[[0, 2], 1]).max() < 1e-9
    assert ours[1, 1] < core[1, 1] < 0  # the tail damps pitch too


@pytest.mark.parametrize("damping", [0.0, 0.03, 0.0796, 0.4])
def test_damped_gains_place_the_closed_loop_poles(damping):
    """With the body's own damping c (per unit inertia) the loop ``s^3 + (c + Kd) s^2 +
    Kp s + Ki`` has its poles at -max(c, omega_a) and a double pole at -omega_a; without
    damping the triple pole of attitude_gains."""
    wa = 1.0 / (2 * math.pi * 2.0)  # 2 wingbeats (AXIS_BEATS)
    g = damped_gains(np.full(3, wa), np.full(3, damping))
    roots = np.sort(np.roots([1.0, damping + g.kd[0], g.kp[0], g.ki[0]]).real)
    want = np.sort([-max(damping, wa), -wa, -wa])
    np.testing.assert_allclose(roots, want, rtol=1e-6 if damping > wa * 1.01 else 2e-3)
    if damping == 0.0:
        plain = attitude_gains(1.0, 2.0)
        for k in ("kp", "kd", "ki"):
            np.testing.assert_allclose(getattr(g, k), getattr(plain, k), rtol=1e-15)


def test_pitch_plan_has_no_lag_and_starts_at_the_start():
    """The planned command of a table pitch that steps at t0: smoothed forward and
    backward, so it crosses the step's midpoint at t0 (no lag; the causal filter's
    crossing is 1.7 time constants late) and is antisymmetric about it; the command
    starts at the flight's start pitch and, the flight's table pitch equal to the plan's,
    follows the plan; a constant table pitch is planned as that constant exactly."""
    from birdsim.flight.pitch_plan import PitchPlan

    dt, tau, t0 = 2 * math.pi / 8, 3 * 2 * math.pi, 20 * 2 * math.pi
    step = lambda t: 0.1 if t < t0 else 1.1  # noqa: E731
    plan = PitchPlan(step, 320, dt, tau, 0.1)
    k0 = int(round(t0 / dt))
    assert plan.plan[k0 - 1] < 0.6 < plan.plan[k0 + 1]
    for s in (8, 24, 48):
        assert plan.plan[k0 - s] + plan.plan[k0 + s] == pytest.approx(1.2, abs=0.02)
    values = [plan.step(k, step(k * dt))[0] for k in range(320)]
    assert abs(values[0] - 0.1) < 0.02  # starts at the start pitch ...
    assert abs(values[k0] - plan.plan[k0 + 1]) < 0.05  # ... and follows the plan
    const = PitchPlan(lambda t: 0.3, 40, dt, tau, 0.3)
    assert np.all(const.plan == 0.3)
    assert [const.step(k, 0.3)[0] for k in range(40)] == [0.3] * 40


def free_cruise_with_gust(beats: float, gust: str) -> dict:
    """The log arrays of the cruise preset flown free (seed bird, the demo model) for
    ``beats`` wingbeats through one gust ``T0:DURATION:WX:WY:WZ``."""
    from birdsim.commands.fly import load_table_for
    from birdsim.flight.freeflight import fly
    from birdsim.flight.gust import parse_gust
    from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS, demo_bird
    from birdsim.flight.simulate import SimConfig

    bird = demo_bird()
    table = load_table_for(bird, DEMO_MODEL, None)
    config = SimConfig(attitude="free")
    path = PATH_PRESETS["cruise"]
    return fly(
        path, table, bird, DEMO_MODEL, beats=beats, gusts=[parse_gust(gust)], config=config
    ).arrays


def test_vertical_gust_is_flown_back_as_posed():
    """A one-wingbeat up gust of 30 % of cruise speed in cruise, attitude free: the largest
    error as the posed body's (measured 0.099 semispan; posed 0.105; before the stroke
    plane's compensation took the table's pitch target: 0.233) and back within 0.05
    semispan for good 5 wingbeats after the gust (measured 4)."""
    a = free_cruise_with_gust(12, "3:1:0:0:0.15")
    err = np.hypot(a["x_ref"] - a["x"], a["z_ref"] - a["z"])
    assert err.max() < 0.12
    assert err[(4 + 5) * 64 :].max() <= 0.05
    assert not a["attitude_saturated"].any()


def test_rocking_weakens_the_flap_amplitudes_yaw():
    """The body's rocking within the wingbeat (measured_with_rocking: the periodic
    counter-rotation from the wings' relative angular momentum and the moment's swing,
    times the phase-dependent rate derivatives) takes most of the differential flap
    amplitude's yaw moment away: measured on the held body -0.081 weight x semispan per
    rad, with the rocking -0.019, and in flight (a free cruise with that input alone)
    about -0.015.  The rate derivatives it returns are measured_rate_derivatives' (the
    same samples); symmetric inputs still neither roll nor yaw the bird (round-off)."""
    import mujoco

    from birdsim.flight.attitude import INPUTS, measured_jacobian, measured_rate_derivatives
    from birdsim.flight.attitude_jacobians import measured_with_rocking
    from birdsim.flight.presets import demo_bird
    from birdsim.flight.simulate import FreeBird, SimConfig

    p = np.array([0.13, 0.9, 0.3, 0.35])
    with FreeBird("m3", demo_bird(), p, config=SimConfig(attitude="free")) as fb:
        mujoco.mj_fwdPosition(fb.m, fb.d)
        full = np.zeros((fb.m.nv, fb.m.nv))
        mujoco.mj_fullM(fb.m, fb.d, full)
        inertia = np.diag(full[3:6, 3:6]).copy()
        _, held = measured_jacobian(fb, p, 0.13, 0.5)
        m0, rocked, rates = measured_with_rocking(fb, p, 0.13, 0.5, inertia)
        np.testing.assert_allclose(rates, measured_rate_derivatives(fb, p, 0.13, 0.5), atol=1e-12)
    names = [i[0] for i in INPUTS]
    flap = names.index("flap_amp")
    assert held[2, flap] < 0 and rocked[2, flap] < 0
    assert abs(rocked[2, flap]) < 0.5 * abs(held[2, flap])
    sym = [names.index(k) for k in ("sweep", "tail_elevation", "dihedral")]
    assert np.abs(rocked[np.ix_([0, 2], sym)]).max() < 1e-9
    assert abs(m0[0]) < 1e-9 and abs(m0[2]) < 1e-9
