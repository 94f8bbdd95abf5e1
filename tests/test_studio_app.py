"""The studio's web app without a browser (Flask's test client): choices, paths, the
folder it may read, absurd sizes refused before work, a flight and its downloads."""

from __future__ import annotations

import io
import time
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("flask", reason="the studio needs birdsim[studio] (flask)")

from birdsim.flight.flock import preset_names as flock_presets  # noqa: E402
from birdsim.studio.app import create_app  # noqa: E402
from birdsim.studio.flights import MAX_KEYFRAMES, MAX_STUDIO_BEATS  # noqa: E402
from birdsim.studio.safety import OutsideError, inside  # noqa: E402

REPO = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def folder(tmp_path_factory) -> Path:
    w = tmp_path_factory.mktemp("studio-folder")
    (w / "climb.toml").write_text((REPO / "examples" / "climb-and-level.toml").read_text())
    (w / "broken.toml").write_text("name = = 1\n[keyframe\n")
    (w / "sub").mkdir()
    (w / "sub" / "pigeon.toml").write_text((REPO / "models" / "pigeon.toml").read_text())
    return w


@pytest.fixture(scope="module")
def client(folder):
    return create_app(folder).test_client()


def _fly(client, body, timeout=120.0):
    r = client.post("/api/fly", json=body)
    assert r.status_code == 200, r.get_json()
    job = r.get_json()["job"]
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        info = client.get(f"/api/job/{job}").get_json()
        if info["state"] != "running":
            return info
        time.sleep(0.05)
    raise AssertionError("the flight did not finish")


def test_options_list_the_folder_and_the_shipped_birds(client, folder):
    o = client.get("/api/options").get_json()
    assert o["folder"] == str(folder.resolve())
    assert "shipped:seed-bird.toml" in o["birds"] and "shipped:pigeon.toml" in o["birds"]
    assert {"climb.toml", "broken.toml", "sub/pigeon.toml"} <= set(o["files"])
    assert o["presets"] == [
        "hover",
        "cruise",
        "take-off",
        "landing",
        "turn-90",
        "circle",
        "s-turn",
        "u-turn",
        *flock_presets(),  # a flock flies every bird of its file (test_studio_flock.py)
    ]
    assert o["default_model"] == "m3"


def test_page_has_no_network_references(client):
    page = client.get("/").get_data(as_text=True)
    assert 'id="studio"' in page and "birdsim-options" in page
    assert "<script src" not in page and '<link rel="stylesheet"' not in page


@pytest.mark.parametrize(
    "name", ["../x.toml", "/etc/passwd", "sub/../../x.toml", "..", "C:\\x.toml"]
)
def test_paths_outside_the_folder_are_refused(client, folder, name):
    with pytest.raises(OutsideError):
        inside(folder, name)
    r = client.get("/api/path", query_string={"source": name})
    assert r.status_code == 400
    assert "outside the studio's folder" in r.get_json()["error"]
    r = client.post("/api/fly", json={"source": "hover", "bird": name})
    assert r.status_code == 400 and "outside" in r.get_json()["error"]


def test_a_link_leading_out_is_refused(client, folder, tmp_path):
    target = tmp_path / "secret.toml"
    target.write_text("semispan = 1.0\n")
    (folder / "link.toml").symlink_to(target)
    try:
        r = client.get("/api/path", query_string={"source": "link.toml"})
        assert r.status_code == 400 and "leads outside" in r.get_json()["error"]
    finally:
        (folder / "link.toml").unlink()


def test_paths_of_presets_and_files(client):
    p = client.get("/api/path", query_string={"source": "take-off"}).get_json()["path"]
    assert p["perch"] == "start" and p["keyframe"][0]["t"] == 0.0
    r = client.get("/api/path", query_string={"source": "climb.toml"}).get_json()
    assert r["path"] is None and "force schedule" in r["note"]
    # a turning preset is flown as it is: the editor's columns would drop its heading
    r = client.get("/api/path", query_string={"source": "circle"}).get_json()
    assert r["path"] is None and "turns out of the vertical plane" in r["note"]
    r = client.get("/api/path", query_string={"source": "broken.toml"})
    assert r.status_code == 400
    msg = r.get_json()["error"]
    assert "is not valid TOML" in msg and "\n" not in msg


@pytest.mark.parametrize(
    "body, text",
    [
        (
            {"path": {"name": "x", "duration": 1e9, "keyframe": [{"t": 0, "z": 6, "x": 0}]}},
            "duration=1000000000.0",
        ),
        (
            {
                "path": {
                    "name": "x",
                    "keyframe": [{"t": i, "z": 6, "x": i} for i in range(MAX_KEYFRAMES + 1)],
                }
            },
            "keyframes: 201 given",
        ),
        ({"source": "hover", "gusts": ["1:1:0:0"] * 51}, "gusts: 51 given"),
        ({"source": "hover", "seconds": 1e7}, f"at most {MAX_STUDIO_BEATS:g} wingbeats"),
        ({"source": "hover", "model": "m9"}, "model 'm9' is unknown"),
        ({"source": "hover", "gusts": ["1:2"]}, "--gust '1:2' has 2 field(s)"),
        ({}, "source is missing"),
    ],
)
def test_absurd_or_bad_requests_are_refused_before_work(client, body, text):
    t0 = time.perf_counter()
    r = client.post("/api/fly", json=body)
    if r.status_code == 200:  # checked in the worker (gust syntax): still one line
        info = _fly(client, body)
        assert info["state"] == "error"
        msg = info["error"]
    else:
        assert r.status_code == 400
        msg = r.get_json()["error"]
        assert time.perf_counter() - t0 < 2.0  # refused before any flying
    assert text in msg and "\n" not in msg


def test_a_huge_request_body_is_refused(client):
    r = client.post("/api/fly", data=b"{" + b" " * 400_000 + b"}", content_type="application/json")
    assert r.status_code == 413 and "larger than" in r.get_json()["error"]


def test_fly_and_download(client, folder):
    body = {"source": "hover", "seconds": 2 * 6.283185307179586}
    info = _fly(client, body)
    assert info["state"] == "done", info
    fid = info["flight"]
    scene = client.get(f"/api/flight/{fid}/scene").get_json()
    assert scene["format"] == "birdsim-view" and scene["summary"]["wingbeats"] == pytest.approx(
        2, abs=0.05
    )
    log = client.get(f"/api/flight/{fid}/download/log")
    assert log.status_code == 200
    with np.load(io.BytesIO(log.get_data())) as z:
        assert str(z["format"]) == "birdsim-flight-log"
        np.testing.assert_array_equal(z["x"].size, np.asarray(z["t"]).size)
    csv = client.get(f"/api/flight/{fid}/download/csv").get_data(as_text=True).splitlines()
    assert csv[0].startswith("frame,time") and len(csv) > 20
    page = client.get(f"/api/flight/{fid}/download/html").get_data(as_text=True)
    assert "birdsim-scene" in page
    bvh = client.get(f"/api/flight/{fid}/download/bvh").get_data(as_text=True)
    assert bvh.startswith("HIERARCHY") and "MOTION" in bvh
    r = client.get(f"/api/flight/{fid}/download/exe")
    assert r.status_code == 400 and "download 'exe' is unknown" in r.get_json()["error"]
    assert client.get("/api/flight/f999/scene").status_code == 400
    assert sorted(p.name for p in folder.iterdir()) == ["broken.toml", "climb.toml", "sub"]
