"""The 3-D view's scene (birdsim/studio/scene.py) and page (page.py).

Independent paths held together: the torso drawn by the page is the log's MuJoCo state
replayed through the MJCF (``mj_kinematics``), the trail is the log's own position and
attitude; they must agree. Tolerances: the scene keeps 4 decimals (5e-5 semispans of
rounding) and both are linear interpolations between the same log samples, so 2e-4.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from birdsim.studio.flights import FlightRequest, fly_request, load_path, path_dict
from birdsim.studio.page import MAX_VIEW_BYTES, view_html
from birdsim.studio.scene import (
    MIN_FRAMES_PER_BEAT,
    ViewOptions,
    body_track,
    flight_scene,
    time_base,
)

TOL = 2e-4  # semispans: 4 decimals of rounding + interpolation between the same samples


@pytest.fixture(scope="module")
def hover_log():
    log, info = fly_request(FlightRequest("hover", seconds=2 * 6.283185307179586))
    assert info["wingbeats"] == pytest.approx(2.0, abs=0.05)
    return log


def _body(scene, name):
    return next(b for b in scene["bodies"].values() if b["name"] == name)


def test_replayed_torso_is_the_logged_track(hover_log):
    scene = flight_scene(hover_log)
    torso = _body(scene, "torso")
    n = len(scene["t"])
    assert torso["frames"] == n
    replay = np.array(torso["pos"]).reshape(n, 3)
    track = np.array(scene["track"]["pos"]).reshape(n, 3)
    np.testing.assert_allclose(replay, track, atol=TOL)
    # attitude: the replayed torso quaternion and the logged one (q ~ -q)
    qr = np.array(torso["quat"]).reshape(n, 4)
    qt = np.array(scene["track"]["quat"]).reshape(n, 4)
    qr /= np.linalg.norm(qr, axis=1, keepdims=True)
    qt /= np.linalg.norm(qt, axis=1, keepdims=True)
    np.testing.assert_allclose(np.abs(np.sum(qr * qt, axis=1)), 1.0, atol=TOL)
    assert scene["attitude"] == "quat"  # every flight log carries the body's quaternion


def test_wings_move_and_world_is_static(hover_log):
    scene = flight_scene(hover_log)
    for name in ("r_arm", "l_arm", "r_hand", "l_hand"):
        q = np.array(_body(scene, name)["quat"]).reshape(-1, 4)
        assert np.ptp(q, axis=0).max() > 0.1, name  # the wingbeat: tens of degrees
    assert _body(scene, "perch")["frames"] == 1
    kinds = {g["type"] for g in scene["geoms"]}
    assert {"mesh", "ellipsoid", "sphere"} <= kinds
    assert not any(g["name"].endswith("_panel") for g in scene["geoms"])  # group 1 not drawn


def test_track_uses_quat_and_y_when_the_log_has_them(hover_log):
    """A log with ``quat`` and ``y`` (every log since the free body): the track takes them
    instead of the pitch (a made-up roll of 0.3 rad proves which was read); an older log
    without them: the pitch, and y = 0."""
    old = {k: v for k, v in hover_log.items() if k not in ("quat", "y")}
    log = dict(hover_log)
    n = log["t"].size
    roll = 0.3
    log["quat"] = np.tile([np.cos(roll / 2), np.sin(roll / 2), 0.0, 0.0], (n, 1))
    log["y"] = np.full(n, 0.7)
    pos, quat = body_track(log)
    np.testing.assert_allclose(pos[:, 1], 0.7)
    np.testing.assert_allclose(quat[0], [np.cos(roll / 2), np.sin(roll / 2), 0, 0])
    pos0, quat0 = body_track(old)
    np.testing.assert_allclose(pos0[:, 1], 0.0)
    half = 0.5 * old["pitch"]
    np.testing.assert_allclose(quat0[:, 2], -np.sin(half))  # nose up = about MuJoCo -y
    assert flight_scene(log)["attitude"] == "quat"


def test_time_base_and_frames(hover_log):
    scene = flight_scene(hover_log, ViewOptions(fps=60))
    tb = scene["time_base"]
    # the seed bird: 2 wingbeats per second at 1x, so 60 fps = 30 frames per wingbeat
    assert tb["label"] == "2 wingbeats per second"
    beats = scene["duration"] / tb["period"]
    assert len(scene["t"]) == pytest.approx(30 * beats + 1, abs=1)
    low = flight_scene(hover_log, ViewOptions(fps=1))
    assert len(low["t"]) >= MIN_FRAMES_PER_BEAT * beats
    from birdsim.physics.bird import Bird

    pigeon = Bird.from_toml("models/pigeon.toml")
    assert time_base(pigeon)["label"] == "real time"
    assert time_base(pigeon)["log_time_per_second"] == 1.0


def test_ten_seconds_at_60_fps_fit_in_3_mb():
    """600 frames (10 s at 60 fps) of the dressed bird: under the issue's 3 MB (the
    cruise preset is 5 s at 1x, so 120 frames per second of it)."""
    log, _ = fly_request(FlightRequest("cruise"))
    scene = flight_scene(log, ViewOptions(fps=120))
    assert len(scene["t"]) == pytest.approx(600, abs=2)
    page = view_html(scene).encode()
    assert len(page) < MAX_VIEW_BYTES
    start = page.index(b'id="birdsim-scene">') + len(b'id="birdsim-scene">')
    data = json.loads(page[start : page.index(b"</script>", start)])
    assert data["format"] == "birdsim-view"
    assert b"https://" not in page.split(b"<script>")[0]  # nothing fetched by the page
    assert b"<script src" not in page


def test_preset_as_path_table_flies_the_same(hover_log):
    """The page edits a preset as its path table: flown back, the same flight."""
    from birdsim.flight.presets import PATH_PRESETS

    for name in PATH_PRESETS:
        back = load_path(path_dict(PATH_PRESETS[name]))
        assert back.keyframes == PATH_PRESETS[name].keyframes, name
        assert back.duration_beats == PATH_PRESETS[name].duration_beats
    req = FlightRequest(None, path=path_dict(PATH_PRESETS["hover"]), seconds=2 * 6.283185307179586)
    log, _ = fly_request(req)
    np.testing.assert_array_equal(log["qpos"], hover_log["qpos"])
