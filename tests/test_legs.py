"""Legs, feet and contact (issue 25): the MJCF, standing, the jump and the touchdown.

Seed bird and pigeon (reduced units); each flight here is a few wingbeats of the contact
loop (< 1 s each)."""

from __future__ import annotations

import subprocess
import sys

import mujoco
import numpy as np
import pytest

from birdsim.flight.contact import ContactBird, beats_to_steps
from birdsim.flight.legwork import jump, touchdown, touchdown_speed
from birdsim.flight.presets import PIGEON_FILE, demo_bird
from birdsim.mujoco.legs import leg_dofs, leg_geometry
from birdsim.mujoco.model import build_model
from birdsim.physics.bird import Bird, BirdConfigError
from birdsim.physics.units import reduced_bird, scales

PERCH_TOP = np.array([6.0, 0.0, 1.54])  # the arena's perch bar: axis at 1.5 s, radius 0.04 s


def _birds():
    return {"seed": demo_bird(), "pigeon": Bird.from_toml(PIGEON_FILE)}


def test_legs_are_opt_in_and_keep_the_mass_and_the_wings():
    bird = demo_bird()
    plain, legged = build_model("m3", bird), build_model("m3", bird, legs=True)
    assert legged.nv == plain.nv + 4 and legged.nq == plain.nq + 4  # hip hinge + slide
    # the whole bird weighs the same (the legs' mass comes out of the torso)
    assert legged.body_subtreemass[1] == pytest.approx(plain.body_subtreemass[1], rel=1e-12)
    # the wings keep their DOF addresses: the legs come last
    assert list(leg_dofs(legged, "hip")) == [plain.nv, plain.nv + 2]
    assert list(leg_dofs(legged)) == [plain.nv + 1, plain.nv + 3]
    assert len(leg_dofs(plain)) == 0
    # only the feet can touch the world
    colliding = {
        legged.geom(g).name
        for g in range(legged.ngeom)
        if legged.geom_contype[g] == 2 or legged.geom_conaffinity[g] == 1
    }
    assert colliding == {"r_foot", "l_foot"}


@pytest.mark.parametrize(
    "key,value", [("leg_length", -0.1), ("toe_span", 0.0), ("leg_mass_fraction", -0.01)]
)
def test_bad_leg_fields_are_refused_in_one_line(key, value):
    with pytest.raises(BirdConfigError) as err:
        Bird(**{key: value})
    assert str(err.value).startswith(f"bird.{key}=") and "\n" not in str(err.value)


def test_bad_leg_field_on_the_command_line_exits_2():
    run = subprocess.run(
        [sys.executable, "-m", "birdsim.cli", "fly", "cruise", "--set", "leg_length=-1"],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 2
    assert "leg_length" in run.stderr and "Traceback" not in run.stderr


def test_pigeon_legs_scale_to_the_seed_birds():
    seed, pigeon = (reduced_bird(b) for b in _birds().values())
    # the seed bird's legs are the pigeon's reduced ones, rounded (models/seed-bird.toml)
    assert seed.leg_length == pytest.approx(pigeon.leg_length, abs=0.005)
    assert seed.toe_span == pytest.approx(pigeon.toe_span, abs=0.005)


@pytest.mark.parametrize("name", ["seed", "pigeon"])
@pytest.mark.parametrize("surface", ["perch", "ground"])
def test_standing_still_for_five_seconds(name, surface):
    """At rest under contact: over 5 s (the pigeon's seconds; 5 time units would be under
    a wingbeat for the seed bird, so it stands the pigeon's 40 wingbeats too) the body
    moves less than 0.001 semispan and the feet carry the weight within 5 %."""
    bird = _birds()[name]
    with ContactBird("m3", bird) as cb:
        cb.place_standing(PERCH_TOP if surface == "perch" else np.zeros(3))
        law = cb.standing_law()
        for _ in range(beats_to_steps(2.0)):  # the legs settle from their unloaded length
            cb.step(law, 0.0)
        start = cb.d.qpos[:7].copy()
        n = beats_to_steps(5.0 * 8.02)
        worst_load = 0.0
        for k in range(n):
            cb.step(law, 0.0)
            if k % 64 == 0:
                worst_load = max(worst_load, abs(cb.foot_normal() / cb.weight - 1.0))
        moved = np.linalg.norm(cb.d.qpos[:3] - start[:3])
        assert moved < 1e-3, moved
        assert worst_load < 0.05, worst_load
        assert np.allclose(cb.d.qpos[3:7], start[3:7], atol=1e-6)  # upright
        assert cb.root_applied_max == 0.0


@pytest.mark.parametrize("name", ["seed", "pigeon"])
def test_take_off_jump_is_the_legs(name):
    """Legs' share of the lift-off momentum >= 0.6 (measured 0.94-0.95 in Provini et al.
    2012: here the wings are still until lift-off, so about 1; the air's drag makes it a
    hair above 1), peak foot force within 1.5-8 weights (the profile asks for 4)."""
    with ContactBird("m3", _birds()[name]) as cb:
        cb.place_standing(PERCH_TOP)
        r = jump(cb)
    assert r.leg_share >= 0.6 and r.leg_share < 1.01
    assert 1.5 <= r.peak_foot_over_weight <= 8.0
    assert r.peak_foot_over_weight == pytest.approx(4.0, abs=0.15)
    assert r.liftoff_velocity[2] > 0 and abs(r.liftoff_velocity[0]) < 1e-3
    assert r.root_applied_max == 0.0
    # lift-off momentum = the feet's and the weight's impulse, to the drag's share
    assert set(np.unique(r.record["phase"])) == {0, 1, 2}


@pytest.mark.parametrize("name", ["seed", "pigeon"])
@pytest.mark.parametrize("surface", ["perch", "ground"])
def test_touchdown_comes_to_rest_on_the_target(name, surface):
    bird = _birds()[name]
    v = touchdown_speed()
    assert v * scales(Bird.from_toml(PIGEON_FILE)).speed == pytest.approx(1.0, rel=2e-3)
    with ContactBird("m3", bird) as cb:
        top = PERCH_TOP if surface == "perch" else np.zeros(3)
        r = touchdown(cb, top, v)
    assert r.rest_beats <= 2.0  # below 1 % of the touchdown speed within 2 wingbeats
    assert np.linalg.norm(r.final_offset) < 0.05  # on the target (semispans)
    assert r.weight_carried == pytest.approx(1.0, abs=0.05)
    assert r.peak_foot_over_weight < 4.0  # below the take-off's peak (4.08)
    assert r.root_applied_max == 0.0


def test_leg_geometry_standing_height():
    g = leg_geometry(reduced_bird(demo_bird()))
    assert g.sole_below_origin(g.q_stand) == pytest.approx(0.06 + 0.21, abs=1e-12)
    assert mujoco.mjtJoint.mjJNT_SLIDE  # the leg is a slide joint (model test above)


def test_jump_lifts_off_at_the_first_wingbeats_pitch():
    """The hips' pitch trim brings the body to ``pitch_to`` by lift-off (the posed flight
    starts at that pitch: without the trim the body stood 8-10 deg higher and the
    animation's pitch jumped in one step).  2 deg: the push itself pitches the body up
    by about 1.5 deg in its last half wingbeat."""
    from birdsim.flight.contact import REST_WINGS
    from birdsim.mujoco.driver import wing_arrays

    pitch_to = np.radians(66.9)
    with ContactBird("m3", demo_bird()) as cb:
        cb.hold_qpos = wing_arrays(cb.m, REST_WINGS)[0][0]
        cb.place_standing(PERCH_TOP, np.radians(20.0))
        jump(cb, after_beats=0.0, pitch_to=pitch_to)
        assert abs(cb.body_pitch() - pitch_to) < np.radians(2.0)
