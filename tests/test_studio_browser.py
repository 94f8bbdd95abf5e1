"""The studio and the 3-D view in a real browser: Debian's chromium, headless, driven by
Playwright for Python (tests/browser_helpers.py); WebGL through SwiftShader.

Measured and printed (not asserted): the time from pressing fly to the bird in the page,
and the redraw time of a scrub (``seek``) at 800x600. With ``BIRDSIM_SCREENSHOTS=DIR``
the screenshots of the README are written to DIR (``make screenshots``).
"""

from __future__ import annotations

import io
import os
import time
from pathlib import Path

import numpy as np
import pytest
from browser_helpers import ServerThread, launch, skip_reason

REASON = skip_reason()
pytestmark = pytest.mark.skipif(REASON is not None, reason=str(REASON))
REPO = Path(__file__).resolve().parents[1]
IGNORED_CONSOLE = ("GPU stall due to ReadPixels",)  # SwiftShader's performance notes


@pytest.fixture(scope="module")
def folder(tmp_path_factory) -> Path:
    w = tmp_path_factory.mktemp("studio-browser")
    (w / "climb.toml").write_text((REPO / "examples" / "climb-and-level.toml").read_text())
    (w / "broken.toml").write_text("name = = 1\n[keyframe\n")
    from birdsim.flight.flock import PRESET_FOLDER

    turning = PRESET_FOLDER / "paths" / "turning.toml"  # a flock of two, 3 wingbeats
    text = f'path = "{turning}"\nmodel = "m3"\nattitude = "free"\nrule = "offsets"\n'
    text += f"seconds = {3 * 2 * np.pi}\n"
    text += "[[bird]]\noffset = [0.0, 0.0, 0.0]\n[[bird]]\noffset = [-3.5, 3.5, 0.0]\n"
    (w / "two.toml").write_text(text)
    return w


@pytest.fixture(scope="module")
def server(folder):
    s = ServerThread(folder)
    yield s
    s.stop()


@pytest.fixture(scope="module")
def browser():
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        ctx = launch(p, viewport=(1400, 900))
        yield ctx
        ctx.close()


@pytest.fixture(scope="module")
def studio(server, browser):
    """The studio page after flying the cruise preset (the first flight)."""
    page = browser.new_page()
    messages = _listen(page)
    page.goto(server.url)
    page.wait_for_selector("#keyframes tbody tr")
    t0 = time.perf_counter()
    page.click("#fly")
    page.wait_for_function(
        "window.birdsimViewers && window.birdsimViewers.length >= 1", timeout=90_000
    )
    print(f"\nstudio: cruise in the page {time.perf_counter() - t0:.2f} s after pressing fly")
    page.messages = messages
    return page


def _listen(page) -> list[str]:
    """The page's console messages and page errors, as they come ("type: text")."""
    messages: list[str] = []
    page.on("console", lambda m: messages.append(f"{m.type}: {m.text}"))
    page.on("pageerror", lambda e: messages.append(f"pageerror: {e}"))
    return messages


def _errors(messages):
    return [
        m
        for m in messages
        if m.split(":")[0] in ("error", "pageerror") and not any(s in m for s in IGNORED_CONSOLE)
    ]


def _shoot(page, name, **kw):
    out = os.environ.get("BIRDSIM_SCREENSHOTS")
    if not out:
        return
    from PIL import Image

    img = Image.open(io.BytesIO(page.screenshot(**kw))).convert("RGB")
    img = img.quantize(colors=128, method=Image.Quantize.MEDIANCUT)
    Path(out).mkdir(parents=True, exist_ok=True)
    img.save(Path(out) / name, optimize=True)


def test_studio_loads_with_webgl_and_no_console_errors(studio):
    assert studio.evaluate("!!document.createElement('canvas').getContext('webgl2')")
    assert studio.evaluate("window.birdsimViewer.ready") is True
    assert _errors(studio.messages) == []


def _project(m, p):
    """A scene point through the page's camera matrices (column-major) to pixels."""
    view = np.array(m["view"]).reshape(4, 4).T
    proj = np.array(m["projection"]).reshape(4, 4).T
    clip = proj @ view @ np.array([*p, 1.0])
    ndc = clip[:3] / clip[3]
    return (ndc[0] + 1) / 2 * m["width"], (1 - ndc[1]) / 2 * m["height"]


def test_the_bird_moves_where_the_log_says(studio, server):
    fid = studio.evaluate("document.querySelector('.st-flight').dataset.flight")
    log = server.store.flight(fid).log
    v = "window.birdsimViewers[0]"
    duration = studio.evaluate(f"{v}.duration")
    assert duration == pytest.approx(float(log["t"][-1] - log["t"][0]), rel=1e-6)
    studio.evaluate(f"{v}.setCamera('overview')")  # a camera that does not follow
    canvas = studio.locator(".st-flight .bv-canvas canvas").first
    shots, where = [], []
    for t in (0.2 * duration, 0.8 * duration):
        studio.evaluate(f"{v}.seek({t})")
        pos = studio.evaluate(f"{v}.birdScreenPosition()")
        m = studio.evaluate(f"{v}.cameraMatrices()")
        x = np.interp(t + log["t"][0], log["t"], log["x"])  # seed bird: metres = semispans
        z = np.interp(t + log["t"][0], log["t"], log["z"])
        px, py = _project(m, (x, 0.0, z))
        assert pos["x"] == pytest.approx(px, abs=1.5) and pos["y"] == pytest.approx(py, abs=1.5)
        shots.append(
            np.asarray(
                __import__("PIL.Image").Image.open(io.BytesIO(canvas.screenshot())).convert("L"),
                float,
            )
        )
        where.append((pos["x"], pos["y"]))
    assert np.hypot(where[1][0] - where[0][0], where[1][1] - where[0][1]) > 20  # it flew
    diff = np.abs(shots[1] - shots[0])
    for x, y in where:  # the pictures differ where the bird was and where it is
        box = diff[max(0, int(y) - 12) : int(y) + 12, max(0, int(x) - 12) : int(x) + 12]
        assert (box > 15).mean() > 0.05, (x, y, (box > 15).mean())  # bird: ~10 px across
    # scrubbing: redraw time per frame at this canvas (560x360 in the studio)
    ms = studio.evaluate(
        f"(() => {{ const v = {v}; const gl = v.renderer.getContext(); const px = new Uint8Array(4); const t0 = performance.now(); for (let k = 0; k < 20; k++) {{ v.seek(v.duration * k / 20); gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px); }} return (performance.now() - t0) / 20; }})()"
    )
    print(
        f"studio: scrub redraw {ms:.1f} ms per frame (430x300 canvas, drawing finished: readPixels)"
    )
    studio.evaluate(f"{v}.setCamera('follow'); {v}.seek({0.5 * duration})")


def test_editing_a_keyframe_changes_the_flight(studio, server):
    z_in = studio.locator('#keyframes tbody tr >> nth=0 >> input[data-key="z"]')
    z_in.fill("7")
    n = studio.evaluate("window.birdsimViewers.length")
    studio.click("#fly")
    studio.wait_for_function(f"window.birdsimViewers.length > {n}", timeout=90_000)
    ref_z = studio.evaluate("window.birdsimViewer.data.reference.filter((_, i) => i % 3 == 2)")
    assert np.mean(ref_z) == pytest.approx(7.0, abs=1e-6)
    first = studio.evaluate("window.birdsimViewers[0].data.reference.filter((_, i) => i % 3 == 2)")
    assert np.mean(first) == pytest.approx(6.0, abs=1e-6)
    fids = studio.evaluate(
        "Array.from(document.querySelectorAll('.st-flight')).map(e => e.dataset.flight)"
    )
    assert len(fids) == 2  # side by side
    late = server.store.flight(fids[1]).log
    assert np.mean(late["z"][late["t"] > late["t"][-1] / 2]) == pytest.approx(7.0, abs=0.05)
    studio.evaluate("window.birdsimViewers.forEach(v => v.seek(0.45 * v.duration))")
    _shoot(studio, "studio.png", clip={"x": 0, "y": 0, "width": 1400, "height": 720})
    z_in.fill("6")
    assert _errors(studio.messages) == []


def test_dragging_a_keyframe_handle_edits_the_table(studio):
    """The newest flight's view shows the path's keyframes as handles; dragging one up
    in the flight's plane raises its z in the table (cruise: a speed-form keyframe)."""
    v = "window.birdsimViewer"
    studio.evaluate(f"{v}.setCamera('side'); {v}.seek(0)")
    handle = studio.evaluate(
        f"{v}.project([{v}.handles.items[0].position.x, 0, {v}.handles.items[0].position.z])"
    )
    box = studio.locator(".st-flight .bv-canvas canvas").last.bounding_box()
    x, y = box["x"] + handle["x"], box["y"] + handle["y"]
    z_in = studio.locator('#keyframes tbody tr >> nth=0 >> input[data-key="z"]')
    before = float(z_in.input_value())
    studio.mouse.move(x, y)
    studio.mouse.down()
    studio.mouse.move(x, y - 40, steps=5)
    studio.mouse.up()
    after = float(z_in.input_value())
    assert after > before + 0.2, (before, after)  # 40 px up at the side camera: ~1 semispan
    z_in.fill(str(before))


def test_a_bad_file_shows_the_one_line_message(studio):
    studio.select_option("#source", "broken.toml")
    studio.wait_for_function("!document.getElementById('error').hidden")
    text = studio.inner_text("#error")
    assert "is not valid TOML" in text and "\n" not in text.strip()
    studio.select_option("#source", "cruise")
    studio.wait_for_function("document.getElementById('error').hidden")


def test_each_download_is_a_valid_file(studio):
    fid = studio.evaluate("document.querySelector('.st-flight').dataset.flight")
    get = studio.context.request.get
    base = studio.url.rstrip("/") + f"/api/flight/{fid}/download/"
    links = studio.evaluate(
        "Array.from(document.querySelector('.st-flight').querySelectorAll('a.st-download')).map(a => a.getAttribute('href'))"
    )
    assert sorted(h.rsplit("/", 1)[1] for h in links) == ["bvh", "csv", "html", "log", "mp4", "usd"]
    bodies = {}
    for kind in ("log", "csv", "bvh", "usd", "html"):
        r = get(base + kind)
        assert r.status == 200, (kind, r.text()[:200])
        bodies[kind] = r.body()
    r = get(base + "mp4?size=160x128", timeout=300_000)
    assert r.status == 200, r.text()[:200]
    bodies["mp4"] = r.body()
    assert bodies["mp4"][4:8] == b"ftyp"
    assert bodies["usd"].startswith(b"#usda")
    assert bodies["bvh"].startswith(b"HIERARCHY") and b"MOTION" in bodies["bvh"]
    rows = bodies["csv"].decode().splitlines()
    assert rows[0].startswith("frame,time") and len(rows[1].split(",")) == len(rows[0].split(","))
    with np.load(io.BytesIO(bodies["log"])) as z:
        assert str(z["format"]) == "birdsim-flight-log"
    assert b'id="birdsim-scene"' in bodies["html"]


def test_the_view_plays_with_the_network_blocked(server, browser, tmp_path):
    """birdsim view's file, opened from disk with every request but file:// aborted."""
    from birdsim.cli import main

    fid = next(iter(server.store.flights))
    log_path = tmp_path / "cruise.npz"
    from birdsim.studio.downloads import log_bytes

    log_path.write_bytes(log_bytes(server.store.flight(fid).log))
    out = tmp_path / "cruise.html"
    assert main(["view", str(log_path), "--out", str(out)]) == 0
    assert out.stat().st_size < 3_000_000
    page = browser.new_page()
    page.set_viewport_size({"width": 1280, "height": 800})
    requested: list[str] = []

    def block(route):
        requested.append(route.request.url)
        route.abort()

    page.route("http*://**/*", block)
    page.context.set_offline(True)
    messages = _listen(page)
    try:
        page.goto(out.as_uri())
        page.wait_for_function("window.birdsimViewer && window.birdsimViewer.ready", timeout=30_000)
        v = "window.birdsimViewer"
        assert page.evaluate(f"{v}.duration") > 0
        before = page.evaluate(f"{v}.birdScreenPosition()")
        page.evaluate(f"{v}.setCamera('overview'); {v}.play()")
        page.wait_for_timeout(800)
        t = page.evaluate(f"{v}.time")
        page.evaluate(f"{v}.pause()")
        assert t > 0.5  # 800 ms at 2 wingbeats per second: about 10 time units
        after = page.evaluate(f"{v}.birdScreenPosition()")
        assert after != before
        page.set_viewport_size({"width": 800, "height": 600})
        ms = page.evaluate(
            f"(() => {{ const v = {v}; const gl = v.renderer.getContext(); const px = new Uint8Array(4); const t0 = performance.now(); for (let k = 0; k < 30; k++) {{ v.seek(v.duration * k / 30); gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px); }} return (performance.now() - t0) / 30; }})()"
        )
        print(
            f"\nview: scrub redraw {ms:.1f} ms per frame (800x500 canvas, 800x600 window, drawing finished: readPixels)"
        )
        page.set_viewport_size({"width": 1280, "height": 800})
        page.evaluate(f"{v}.setCamera('follow'); {v}.seek({v}.duration * 0.4)")
        _shoot(page, "view.png", clip={"x": 0, "y": 0, "width": 1230, "height": 720})
    finally:
        page.context.set_offline(False)
        page.close()
    assert requested == []  # the page asked for nothing
    assert _errors(messages) == []


def test_the_view_of_a_flock_frames_every_bird(browser, tmp_path):
    """birdsim view of a two-bird flock's log (2 semispans apart): both birds are drawn
    (a torso body per bird), the cameras aim at the flock's centre, and every torso is
    inside the canvas for every camera but the overview, at three instants."""
    from birdsim.cli import main

    src = tmp_path / "f.toml"
    src.write_text('path = "cruise"\n[[bird]]\noffset = [0, 0, 0]\n[[bird]]\noffset = [0, 2, 0]\n')
    log = tmp_path / "flock.npz"
    assert main(["fly", str(src), "--quiet", "--seconds", "2", "--out", str(log)]) == 0
    out = tmp_path / "flock.html"
    assert main(["view", str(log), "--out", str(out)]) == 0
    page = browser.new_page()
    messages = _listen(page)
    try:
        page.goto(out.as_uri())
        page.wait_for_function("window.birdsimViewer && window.birdsimViewer.ready", timeout=30_000)
        v = "window.birdsimViewer"
        torsos = f"Object.values({v}.bodies).filter((b) => b.group.name.endsWith('torso')).map((b) => b.group)"
        assert page.evaluate(f"{torsos}.length") == 2
        for cam in ("follow", "side", "chase", "top"):
            for frac in (0.0, 0.5, 1.0):
                got = page.evaluate(
                    f"(() => {{ const v = {v}; v.setCamera('{cam}'); v.seek(v.duration * {frac});"
                    f" const ts = {torsos}; const c = ts[0].position.clone().add(ts[1].position).multiplyScalar(0.5);"
                    f" return {{ target: v.orbit.target.distanceTo(c),"
                    f" px: ts.map((g) => v.project([g.position.x, g.position.y, g.position.z])) }}; }})()"
                )
                # the centre of the logged tracks vs the replayed torsos: 4 decimals, interpolation
                assert got["target"] < 0.01, (cam, frac, got)
                for p in got["px"]:
                    assert 0 < p["x"] < 800 and 0 < p["y"] < 500, (cam, frac, got)
    finally:
        page.close()
    assert _errors(messages) == []


def test_a_flock_is_flown_from_the_page(server, browser):
    """Choosing a flock disables the page's bird, model, gusts and open loop (its file gives
    them; the server refuses them) and the page flies it and draws both birds; the page
    used to send its default bird with every flight, so a flock was refused in the browser."""
    page = browser.new_page()
    messages = _listen(page)
    try:
        page.goto(server.url)
        page.wait_for_selector("#keyframes tbody tr")
        page.select_option("#source", "two.toml")
        page.wait_for_function("document.getElementById('bird').disabled")
        assert page.evaluate("document.getElementById('add-gust').disabled")
        page.click("#fly")
        page.wait_for_function(
            "window.birdsimViewers && window.birdsimViewers.length >= 1", timeout=120_000
        )
        assert page.evaluate("document.getElementById('error').hidden")
        summary = page.inner_text(".st-flight .st-summary")
        assert "2 birds, worst bird" in summary, summary
        page.select_option("#source", "cruise")
        page.wait_for_function("!document.getElementById('bird').disabled")
        assert _errors(messages) == []
    finally:
        page.close()
