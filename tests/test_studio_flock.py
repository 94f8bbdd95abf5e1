"""A flock in the studio (issue 27 item 2): a flock file of the folder (or a flock preset)
chosen as the path is flown as `birdsim fly FLOCK` flies it and drawn with every bird
(birdsim/studio/flock_flights.py; the scene of `birdsim view` for a flock's log)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

pytest.importorskip("flask", reason="the studio needs birdsim[studio] (flask)")

from test_studio_app import _fly  # noqa: E402

from birdsim.flight.flock import PRESET_FOLDER  # noqa: E402
from birdsim.studio.app import create_app  # noqa: E402


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    w = tmp_path_factory.mktemp("studio-flock")
    turning = PRESET_FOLDER / "paths" / "turning.toml"
    text = f'path = "{turning}"\nmodel = "m3"\nattitude = "free"\nrule = "steer"\n'
    text += f"seconds = {3 * 2 * math.pi}\n"  # 3 wingbeats: one after the start
    for o in ((0.0, 0.0, 0.0), (-3.5, 3.5, 0.0)):
        text += f"[[bird]]\noffset = [{o[0]}, {o[1]}, {o[2]}]\n"
    (w / "two.toml").write_text(text)
    return create_app(w).test_client()


def test_a_flock_is_flown_and_drawn_with_every_bird(client):
    o = client.get("/api/options").get_json()
    assert "flock" in o["presets"] and "two.toml" in o["files"]
    p = client.get("/api/path", query_string={"source": "two.toml"}).get_json()
    assert p["path"] is None and "a flock of 2 birds" in p["note"]
    info = _fly(client, {"source": "two.toml", "label": "two"}, timeout=600.0)
    assert info["state"] == "done", info
    scene = client.get(f"/api/flight/{info['flight']}/scene").get_json()
    assert scene["flock"]["n_birds"] == 2
    assert any(str(k).startswith("1:") for k in scene["bodies"])  # the second bird's bodies
    s = scene["summary"]
    assert s["n_birds"] == 2 and s["rms_error"] < 0.2 and s["wingbeats_saturated"] == 0
    log = client.get(f"/api/flight/{info['flight']}/download/log")
    assert log.status_code == 200 and len(log.data) > 1000
    bvh = client.get(f"/api/flight/{info['flight']}/download/bvh")
    assert bvh.status_code == 400 and "one file per bird" in bvh.get_json()["error"]


def test_page_options_that_do_not_apply_to_a_flock_are_refused(client):
    info = _fly(client, {"source": "two.toml", "gusts": ["1:1:0.1:0"]})
    assert info["state"] == "error" and info["error"].startswith("gusts with the flock")


def test_folder_flock_files_stay_inside(client):
    r = client.get("/api/path", query_string={"source": str(Path("/etc/passwd"))})
    assert r.status_code == 400
