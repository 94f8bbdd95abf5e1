"""`birdsim fly --json`'s attitude block (birdsim/flight/attitude_summary.py)."""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest

from birdsim.flight.attitude_summary import attitude_figures, unfolded_euler


def _synthetic(beats: int = 6, n: int = 64, offset: float = 0.1, rock: float = 0.2) -> dict:
    """A body pitched ``offset`` above its command, rocking by +-``rock`` within each
    wingbeat (a whole sine: no mean), rolled by 0.05 rad in wingbeat 3 only."""
    t = np.arange(beats * n) * (2 * math.pi / n)  # reduced time: one wingbeat is 2 pi
    command = 0.3 + 0.01 * np.floor(t / (2 * math.pi))
    roll = np.where((t >= 3 * 2 * math.pi) & (t < 4 * 2 * math.pi), 0.05, 0.0)
    sat = np.zeros(t.size, bool)
    sat[5:9] = True
    return {
        "t": t,
        "pitch": command + offset + rock * np.sin(t),
        "pitch_command": command,
        "roll": roll,
        "yaw": -roll,
        "attitude_saturated": sat,
    }


def test_the_figures_of_a_known_attitude():
    f = attitude_figures(_synthetic())
    # exact up to round-off: the sine averages to zero over whole wingbeats
    assert f["wingbeat_mean_pitch_rms_error_deg"] == pytest.approx(math.degrees(0.1), abs=1e-9)
    assert f["wingbeat_mean_roll_max_deg"] == pytest.approx(math.degrees(0.05), abs=1e-9)
    assert f["wingbeat_mean_yaw_max_deg"] == pytest.approx(math.degrees(0.05), abs=1e-9)
    # peak to peak of 64 samples of a sine of amplitude 0.2: 0.4 to 0.1 % (sampling)
    assert f["rocking_median_deg"] == pytest.approx(math.degrees(0.4), rel=1e-3)
    assert f["attitude_saturated_samples"] == 4
    held = attitude_figures(_synthetic(offset=0.0, rock=0.0))
    assert held["wingbeat_mean_pitch_rms_error_deg"] == 0.0 and held["rocking_median_deg"] == 0.0


def test_a_body_past_the_vertical_is_not_read_as_rolled():
    # a body pitched 100 degrees nose up, as commanded, reads in the log's Euler angles
    # (pitch within +-90) as pitch 80, roll and yaw 180: the figures must see no error
    log = _synthetic(offset=0.0, rock=0.0)
    log["pitch_command"] = np.full(log["t"].size, math.radians(100.0))
    log["pitch"] = np.full(log["t"].size, math.radians(80.0))
    log["roll"] = np.full(log["t"].size, math.pi)
    log["yaw"] = np.full(log["t"].size, -math.pi)
    f = attitude_figures(log)
    # round-off of pi - radians(80) against radians(100): about 1e-14 degrees
    assert f["wingbeat_mean_pitch_rms_error_deg"] == pytest.approx(0.0, abs=1e-9)
    assert f["wingbeat_mean_roll_max_deg"] == pytest.approx(0.0, abs=1e-9)
    assert f["wingbeat_mean_yaw_max_deg"] == pytest.approx(0.0, abs=1e-9)


def test_unfolded_euler_angles_are_the_same_rotations():
    from scipy.spatial.transform import Rotation

    rng = np.random.default_rng(7)
    yaw, pitch, roll = (rng.uniform(-math.pi, math.pi, 2000) for _ in range(3))
    pitch *= 0.5  # the log's range: pitch within +-pi/2
    u = unfolded_euler(yaw, pitch, roll)
    before = Rotation.from_euler("ZYX", np.column_stack([yaw, pitch, roll])).as_matrix()
    after = Rotation.from_euler("ZYX", np.column_stack(u)).as_matrix()
    # the same rotation to round-off (entries of order 1, a few operations: 1e-12)
    assert np.abs(after - before).max() < 1e-12
    assert np.all(np.abs(u[2]) <= 0.5 * math.pi) and np.all(np.abs(np.stack(u)) <= math.pi)
    kept = np.abs(roll) <= 0.5 * math.pi
    assert np.array_equal(u[1][kept], pitch[kept])  # unchanged where roll is within 90


def test_fly_json_reports_the_free_attitude_only():
    def run(*extra: str) -> dict:
        out = subprocess.run(
            [sys.executable, "-m", "birdsim.cli", "fly", "hover", "--json", *extra],
            capture_output=True, text=True, check=True,
        )  # fmt: skip
        return json.loads(out.stdout)

    free = run("--attitude", "free")["attitude"]
    # the seed bird's free hover (docs/free-body.md): pitch within the 3 degrees,
    # the body rocking under the wing forces (3.8 degrees; a posed body: none)
    assert free["wingbeat_mean_pitch_rms_error_deg"] < 3.0
    assert free["rocking_median_deg"] > 1.0
    assert free["attitude_saturated_samples"] == 0
    assert "attitude" not in run()
