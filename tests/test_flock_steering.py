"""Steered flocks (issue 27 item 2; birdsim/flight/steering.py, flock_lockstep.py): the
rules' accelerations (Reynolds 1987) on hand-made states, the birds' places by a turning
leader path, the lockstep that leaves the flights alone when the rules are off, and the
separation rule moving two close birds apart through their own wings."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from birdsim.flight.flock import FlockError, load_flock
from birdsim.flight.flock_fly import flock_summary, fly_flock, jobs_for
from birdsim.flight.path_file import get_flight
from birdsim.flight.steering import FlockPath, SteeringConfig, rule_accelerations

G = 0.01  # a gravity (reduced units) for the rules' bound
DEFAULT = SteeringConfig()
TURNING = str(Path(__file__).parent.parent / "birdsim/data/flocks/paths/turning.toml")


def _rules(pos, vel=None, goal=None, goal_vel=None, cfg=DEFAULT, t=math.inf):
    pos = np.asarray(pos, dtype=float)
    z = np.zeros_like(pos)
    return rule_accelerations(
        pos,
        z if vel is None else np.asarray(vel, float),
        pos if goal is None else np.asarray(goal, float),
        z if goal_vel is None else np.asarray(goal_vel, float),
        z,
        z,
        cfg,
        G,
    ) if t == math.inf else rule_accelerations(pos, z, pos, z, z, z, cfg, G, t)  # fmt: skip


def test_birds_on_their_places_and_apart_are_left_alone():
    """Every bird at its goal, at rest relative to it, farther apart than the separation
    radius: no steering (exactly 0)."""
    pos = [[0, 0, 0], [-3.5, 3.5, 0], [-3.5, -3.5, 0]]
    assert np.array_equal(_rules(pos), np.zeros((3, 3)))


def test_separation_pushes_two_close_birds_apart_equally():
    """Two birds 1 semispan apart (radius 2.5): equal and opposite pushes along the line
    between them, away from each other (to round-off)."""
    cfg = SteeringConfig(max_accel=1e9)
    acc = _rules([[0, 0, 0], [0, 0, 1.0]], cfg=cfg)
    np.testing.assert_allclose(acc[0], -acc[1], rtol=0, atol=1e-18)
    assert acc[0, 2] < 0 < acc[1, 2] and acc[0, 0] == acc[0, 1] == 0
    w = 1.0 / (cfg.tau_beats * 2 * math.pi)
    # the linear law: separation x (1 - d / radius) x w^2 at d = 1
    assert acc[1, 2] == pytest.approx(w * w * cfg.separation * (1 - 1.0 / 2.5), rel=1e-12)


def test_cohesion_and_alignment_follow_the_neighbours_drift():
    """A bird whose two neighbours drifted 1 semispan up (and drift up at 0.01) off their
    places while it sits on its own: steered up (cohesion and alignment), they down."""
    goal = np.array([[0, 0, 0], [0, 4, 0], [0, -4, 0]], float)
    pos = goal + [[0, 0, 0], [0, 0, 1], [0, 0, 1]]
    vel = [[0, 0, 0], [0, 0, 0.01], [0, 0, 0.01]]
    acc = _rules(pos, vel, goal, cfg=SteeringConfig(max_accel=1e9))
    assert acc[0, 2] > 0 and acc[1, 2] < 0 and acc[2, 2] < 0


def test_the_rules_are_bounded_and_fade_in():
    """|acc| <= max_accel g always; 0 at t = 0 and half at half the fade-in."""
    cfg = SteeringConfig()
    pos = [[0, 0, 0], [0, 0, 0.1]]
    full = _rules(pos, cfg=cfg)
    assert np.linalg.norm(full, axis=1).max() == pytest.approx(cfg.max_accel * G, rel=1e-12)
    assert np.array_equal(_rules(pos, cfg=cfg, t=0.0), np.zeros((2, 3)))
    half = _rules(pos, cfg=cfg, t=0.5 * cfg.start_beats * 2 * math.pi)
    np.testing.assert_allclose(half, 0.5 * full, rtol=1e-12)


def test_a_place_by_a_turning_path_is_a_parallel_path():
    """On the flock-seed preset's turning path (radius 50): the place 7 semispans left flies
    the parallel arc of radius 43 at speed 0.5 x 43 / 50 in the steady turn, 7
    semispans from the leader's track; its rates are its positions' derivatives
    (central differences, 1e-6)."""
    path = get_flight(TURNING, turning=True)
    fp = FlockPath(path, np.array([-3.5, 7.0, 0.0]), turn_offset=True)
    t = np.array([20.0, 25.0]) * 2 * math.pi  # in the steady turn
    g, lead = fp.goal(t), path.sample(t + fp.lag)
    np.testing.assert_allclose(np.hypot(g["vx"], g["vy"]), 0.5 * 43 / 50, rtol=1e-6)
    np.testing.assert_allclose(np.hypot(g["x"] - lead["x"], g["y"] - lead["y"]), 7.0, rtol=1e-12)
    h = 1e-3
    gp, gm = fp.goal(t + h), fp.goal(t - h)
    for k in "xy":
        np.testing.assert_allclose((gp[k] - gm[k]) / (2 * h), g["v" + k], atol=1e-6)
        np.testing.assert_allclose((gp[k] - 2 * g[k] + gm[k]) / h**2, g["a" + k], atol=1e-6)


def _flock(tmp_path: Path, rule: str, offsets, extra: str = "") -> str:
    text = f'path = "{TURNING}"\nmodel = "m3"\nattitude = "free"\nrule = "{rule}"\n{extra}'
    for o in offsets:
        text += f"[[bird]]\noffset = [{o[0]}, {o[1]}, {o[2]}]\n"
    p = tmp_path / f"{rule}.toml"
    p.write_text(text)
    return str(p)


def test_the_lockstep_with_the_rules_off_flies_the_birds_one_by_one(tmp_path):
    """Rules off (weights 0): the lockstep (threads taking turns, the callback swapped at
    every control update) flies each bird exactly as flying them one after another
    does (bitwise: the same arithmetic in the same process)."""
    offsets = [(0.0, 0.0, 0.0), (-3.5, 3.5, 0.0)]
    off = "[steering]\nseparation = 0\ncohesion = 0\nalignment = 0\n"
    _, steer_jobs = jobs_for(_flock(tmp_path, "steer", offsets, off), "m3", seconds=3.0)
    _, plain_jobs = jobs_for(_flock(tmp_path, "offsets", offsets), "m3", seconds=3.0)
    steered, plain = fly_flock(steer_jobs), fly_flock(plain_jobs)
    assert np.array_equal(steered["steer"], np.zeros_like(steered["steer"]))
    for k in ("x", "y", "z", "x_ref", "y_ref", "qpos", "qvel", "power"):
        assert np.array_equal(steered[k], plain[k]), k


@pytest.mark.slow  # 2 x 2 birds x 6 wingbeats free (~10 s)
def test_separation_moves_two_close_birds_apart_with_their_wings(tmp_path):
    """Two birds one above the other 1.2 semispans apart on the turning path: steered,
    the separation rule moves their references apart and the birds follow with their
    own wings (no force on a body): after 6 wingbeats they are more than 1.6 apart, while
    under the offsets rule they stay within 0.1 of 1.2; each bird flies its own
    (steered) reference within 0.2 semispan RMS after the start, none saturated."""
    offsets = [(0.0, 0.0, 0.0), (0.0, 0.0, 1.2)]
    seconds = 6 * 2 * math.pi
    out = {}
    for rule in ("offsets", "steer"):
        _, jobs = jobs_for(_flock(tmp_path, rule, offsets), "m3", seconds=seconds)
        a = fly_flock(jobs)
        gap = np.linalg.norm(
            np.stack([a[k][1] - a[k][0] for k in ("x", "y", "z")], axis=-1), axis=-1
        )
        out[rule] = (a, gap)
    assert np.all(np.abs(out["offsets"][1] - 1.2) < 0.1)
    assert out["steer"][1][-1] > 1.6
    info = flock_summary(out["steer"][0], 1.0)
    assert info["worst_rms_error_after_start_semispans"] < 0.2
    assert info["saturated_samples"] == 0


def test_steering_needs_the_free_attitude_and_known_keys(tmp_path):
    p = Path(_flock(tmp_path, "steer", [(0, 0, 0)])).read_text()
    bad = tmp_path / "bad.toml"
    bad.write_text(p.replace('attitude = "free"', 'attitude = "posed"'))
    with pytest.raises(FlockError, match="attitude free"):
        load_flock(str(bad))
    bad.write_text(p + "[steering]\nspeed = 1\n")
    with pytest.raises(FlockError, match="steering key 'speed' is unknown"):
        load_flock(str(bad))
    bad.write_text(p.replace('rule = "steer"', 'rule = "swarm"'))
    with pytest.raises(FlockError, match="rule='swarm'; allowed: offsets, steer"):
        load_flock(str(bad))


@pytest.mark.slow  # 12 birds x 36 wingbeats, attitude free (~20-40 s CPU)
def test_the_seed_flock_preset_meets_the_issues_targets():
    """`flock-seed` (12 seed birds steered through a 90-degree turn): every bird within 0.2
    semispan RMS of its own reference after the start, no two birds closer than one
    semispan at any sample, no saturated sample (issue 27's targets); the birds turn
    (the leader's heading changes by 90 degrees to 1 degree)."""
    flock, jobs = jobs_for("flock-seed", "m3")
    arrays = fly_flock(jobs)
    info = flock_summary(arrays, 1.0)
    assert info["n_birds"] == 12
    assert info["worst_rms_error_after_start_semispans"] < 0.2
    assert info["min_separation_semispans"] > 1.0
    assert info["saturated_samples"] == 0
    vx, vy = arrays["vx"][0], arrays["vy"][0]
    assert math.degrees(math.atan2(vy[-1], vx[-1])) == pytest.approx(90.0, abs=1.0)
