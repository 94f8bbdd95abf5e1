"""`birdsim view` of a flock's log (issue 27, item 2; birdsim/studio/flock_view.py): the
page's inlined scene holds every bird's dressed geoms and one set of poses per bird, the
cameras framing the flock; a flock of one adds nothing to the one-bird scene."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

from birdsim.cli import main
from birdsim.flight.flock_log import load_flock_log
from birdsim.studio.flock_view import ONE_BIRD_DISTANCE, camera_distance, flock_scene
from birdsim.studio.page import scene_json
from birdsim.studio.scene import ViewOptions, flight_scene

SEED = 5.0  # the seed bird's period (its time unit)


def _flock_log(tmp_path: Path, offsets: list[tuple[float, float, float]]) -> Path:
    text = 'path = "cruise"\n'
    for off in offsets:
        text += f"[[bird]]\noffset = [{off[0]}, {off[1]}, {off[2]}]\n"
    src = tmp_path / "f.toml"
    src.write_text(text)
    out = tmp_path / "flock.npz"
    assert main(["fly", str(src), "--quiet", "--seconds", str(0.4 * SEED), "--out", str(out)]) == 0
    return out


def _inlined_scene(html: str) -> dict:
    m = re.search(r'<script[^>]*id="birdsim-scene"[^>]*>(.*?)</script>', html, re.S)
    assert m, "no inlined scene"
    return json.loads(m.group(1))


def test_view_of_a_flock_draws_every_bird_at_its_own_poses(tmp_path, capsys):
    """Two seed birds, the second offset 2 semispans to the left: the page holds two sets
    of moving bodies (torso, arms, hands), each posed at every frame, the same geoms
    once per bird, and the second torso 2 semispans left of the leader's at every frame
    (within 0.05 semispan: each bird flies its own controller on its own shifted
    reference; their path errors are ~0.01)."""
    log = _flock_log(tmp_path, [(0.0, 0.0, 0.0), (0.0, 2.0, 0.0)])
    page = tmp_path / "flock.html"
    assert main(["view", str(log), "--out", str(page)]) == 0
    assert "2 birds" in capsys.readouterr().out
    scene = _inlined_scene(page.read_text())
    n_frames = len(scene["t"])
    assert scene["n_birds"] == 2 and scene["flock"]["n_birds"] == 2
    sets = scene["flock"]["bodies"]
    moving = [[k for k in keys if scene["bodies"][k]["frames"] > 1] for keys in sets]
    assert len(moving[0]) == len(moving[1]) >= 5
    for keys in moving:
        for k in keys:
            assert len(scene["bodies"][k]["pos"]) == 3 * n_frames
            assert len(scene["bodies"][k]["quat"]) == 4 * n_frames
    # the same dressed geoms once per bird (the arena's once)
    per_body = lambda k: sorted(g["name"] for g in scene["geoms"] if str(g["body"]) == k)  # noqa: E731
    for a, b in zip(moving[0], moving[1]):
        assert per_body(a) == per_body(b) and per_body(a)
    torso = [next(k for k in keys if scene["bodies"][k]["name"].endswith("torso")) for keys in sets]
    p0 = np.reshape(scene["bodies"][torso[0]]["pos"], (-1, 3))
    p1 = np.reshape(scene["bodies"][torso[1]]["pos"], (-1, 3))
    assert np.max(np.abs(p1 - p0 - [0.0, 2.0, 0.0])) < 0.05
    # the cameras aim at the flock's centre, the midpoint of the two torsos
    centre = np.reshape(scene["flock"]["centre"], (-1, 3))
    assert np.max(np.abs(centre - 0.5 * (p0 + p1))) < 2e-3  # frames vs replayed MJCF, 4 decimals
    assert scene["flock"]["radius"] == pytest.approx(1.0, abs=0.05)
    # one-bird view flags are refused for a log, flock or not
    assert main(["view", str(log), "--out", str(tmp_path / "x.html"), "--bird", "b.toml"]) == 2


def test_a_flock_of_one_adds_nothing_to_the_one_bird_scene(tmp_path):
    """flock_scene of one bird is flight_scene of that bird plus the `flock`/`n_birds`
    keys (so a one-bird log's page, which never has them, is unchanged)."""
    _, birds = load_flock_log(_flock_log(tmp_path, [(0.0, 0.0, 0.0)]))
    opts = ViewOptions(fps=30)
    one = flock_scene(birds, opts, title="t")
    assert one.pop("n_birds") == 1 and one.pop("flock")["camera_distance"] == ONE_BIRD_DISTANCE
    assert scene_json(one) == scene_json(flight_scene(birds[0], opts, title="t"))


def test_camera_distance_grows_with_the_flock():
    """A lone bird keeps the one-bird cameras; a flock of radius r is seen from a
    distance that grows linearly with r."""
    assert camera_distance(0.0) == ONE_BIRD_DISTANCE
    assert camera_distance(20.0) == pytest.approx(2 * camera_distance(9.5), rel=1e-12)
