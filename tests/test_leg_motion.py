"""The legs' prescribed motion in flight (issue 25; birdsim.flight.leg_motion): the
cosine blend's derivatives, the sequence of motions, and the legs moved by internal
forces only (the whole bird's centre of mass does not move)."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.flight.leg_motion import LegMotion, LegPlan, blend
from birdsim.flight.presets import demo_bird
from birdsim.flight.simulate import FreeBird, SimConfig
from birdsim.flight.wingbeat import Prescription
from birdsim.mujoco.model import build_model
from birdsim.physics.units import reduced_bird


def test_blend_rates_are_the_derivatives():
    """Central differences of s and ds (step 1e-5 of a duration of 2: truncation about
    1e-10, round-off about 1e-11) against the analytic ds, dds."""
    t = np.linspace(0.9, 3.1, 23)
    h = 1e-5
    s, ds, dds = blend(t, 1.0, 2.0)
    sp, dsp, _ = blend(t + h, 1.0, 2.0)
    sm, dsm, _ = blend(t - h, 1.0, 2.0)
    inside = (t > 1.0 + h) & (t < 3.0 - h)
    assert np.allclose(((sp - sm) / (2 * h))[inside], ds[inside], atol=1e-8)
    assert np.allclose(((dsp - dsm) / (2 * h))[inside], dds[inside], atol=1e-8)
    assert s[0] == 0.0 and s[-1] == 1.0 and ds[0] == ds[-1] == 0.0  # held outside


def _rows(m, n):
    return Prescription(
        np.tile(m.qpos0, (n, 1)),
        np.zeros((n, m.nv)),
        np.zeros((n, m.nv)),
        np.zeros((n, 3)),
        np.zeros(n),
    )


def test_plan_takes_the_last_motion_begun():
    m = build_model("m3", reduced_bird(demo_bird()), legs=True)
    tuck = LegMotion(0.0, 1.0, 0.1, 0.0, 1.2, 0.0)
    reach = LegMotion(5.0, 1.0, 0.0, 0.12, 0.0, 1.4)
    t = np.array([0.0, 0.5, 2.0, 5.0, 5.5, 7.0])
    pres = _rows(m, len(t))
    LegPlan((tuck, reach)).apply(m, pres, t)
    for side in ("r", "l"):
        leg = m.jnt_qposadr[m.joint(f"{side}_leg").id]
        hip = m.jnt_qposadr[m.joint(f"{side}_hip").id]
        assert pres.qpos[:, leg] == pytest.approx([0.1, 0.05, 0.0, 0.0, 0.06, 0.12])
        assert pres.qpos[:, hip] == pytest.approx([1.2, 0.6, 0.0, 0.0, 0.7, 1.4])
    # every other row is untouched (the root, the wings)
    legs = [m.jnt_qposadr[m.joint(f"{s}_{n}").id] for s in ("r", "l") for n in ("leg", "hip")]
    other = np.setdiff1d(np.arange(m.nq), legs)
    assert np.array_equal(pres.qpos[:, other], np.tile(m.qpos0[other], (len(t), 1)))


def _drift(steps: int) -> tuple[float, float]:
    """The whole bird's centre of mass's displacement and final speed after the legs
    reach out over one wingbeat (air and gravity off, no momentum projection), and the
    leg coordinate reached."""
    bird = demo_bird()
    red = reduced_bird(bird)
    reach = LegMotion(0.0, red.period, 0.0, 0.12, 0.0, 1.3)
    cfg = SimConfig(steps_per_beat=steps, legs=True, leg_motion=reach, momentum_projection=False)
    with FreeBird("m3", bird, np.zeros(0), config=cfg, aero=False, gravity=False) as fb:
        fb.start(np.array([0.0, 0.0, 5.0]), np.zeros(3), _rows(fb.m, 1))
        c0 = fb.com()[0].copy()
        fb.step_many(_rows(fb.m, steps), np.zeros(3))
        c1, v1 = fb.com()
        leg = float(fb.d.qpos[fb.m.jnt_qposadr[fb.m.joint("r_leg").id]])
    # (the last row is the prescription at (steps - 1) / steps of the blend)
    assert leg == pytest.approx(0.12, abs=1e-3)
    return float(np.linalg.norm(c1 - c0)), float(np.linalg.norm(v1))


def test_legs_move_the_body_not_the_bird():
    """Legs reaching out in flight move the body, not the bird: internal forces leave
    the whole bird's centre of mass where it was.  Without the momentum projection what
    remains is MuJoCo's integration error (the prescribed coordinates set at each step's
    start), first order in the step: measured 2.3e-4 semispan at 128 steps per
    wingbeat, 1.1e-4 at 256 (the legs, 8 % of the mass, move their centres by
    about 0.1: a force on the body would move the bird by about 0.008)."""
    d128, v128 = _drift(128)
    d256, _ = _drift(256)
    assert d128 < 1e-3 and v128 < 1e-3
    assert 1.9 < d128 / d256 < 2.1  # first order (measured 2.002): integration, not a force
