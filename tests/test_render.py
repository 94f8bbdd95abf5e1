"""Headless rendering: short clips of every preset, the MP4 they make, bad input, GL choice.

Clips are small (160x128, 12 fps, about 1.5 s) so the whole module runs in seconds on
the CPU.  A small in-test LookupTable (the real class) drives the bird, so these tests
do not depend on the committed tables.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from birdsim.errors import BirdsimError
from birdsim.render import gl

try:  # the default back-end here; every test that renders needs one of the two
    BACKEND = gl.select_gl("auto")
except gl.GLError:  # pragma: no cover - a machine without OSMesa and EGL
    BACKEND = None

from birdsim import Bird, get_model  # noqa: E402
from birdsim.cli import main  # noqa: E402
from birdsim.flight.manoeuvre import PRESETS  # noqa: E402
from birdsim.render.renderer import (
    RenderOptions,
    Scene,
    parse_size,
    play_for_video,
    render_manoeuvre,
    video_info,
)  # noqa: E402
from birdsim.tables.cost import FRACTION_NAMES  # noqa: E402
from birdsim.tables.lookup import LookupTable  # noqa: E402

needs_gl = pytest.mark.skipif(BACKEND is None, reason="no headless OpenGL (libOSMesa or libEGL)")
W, H, FPS, SECONDS = 160, 128, 12, 1.5


def small_table(model: str = "m4") -> LookupTable:
    """A 5x3x5 table whose parameters vary smoothly with the demands inside the bounds
    (hover-like large amplitudes at low V and strong lift, cruise-like small ones at V=1)."""
    km = get_model(model)
    axes = {
        "Fx": np.linspace(-0.5, 0.5, 5),
        "Fz": np.linspace(-0.5, 0.0, 3),
        "V": np.linspace(0.0, 1.0, 5),
    }
    FX, FZ, V = np.meshgrid(*axes.values(), indexing="ij")
    lo, hi = km.bounds
    frac = np.clip(
        0.45 + 0.1 * FX[..., None] - 0.8 * FZ[..., None] - 0.35 * V[..., None], 0.05, 0.95
    )
    params = lo + frac * (hi - lo)
    shape = FX.shape
    return LookupTable(
        model=model,
        bird=Bird(),
        param_names=km.param_names,
        axes=axes,
        params=params,
        cost=np.zeros(shape),
        cost_fractions=np.zeros(shape + (len(FRACTION_NAMES),)),
        achieved=np.zeros(shape + (3,)),
        status_code=np.zeros(shape, dtype=np.uint8),
        evaluations=np.zeros(shape, dtype=np.int64),
    )


def options(**kw) -> RenderOptions:
    base = dict(
        width=W,
        height=H,
        fps=FPS,
        seconds=SECONDS,
        beats_per_second=2.0,
        progress=False,
        quality="draft",
    )
    base.update(kw)
    return RenderOptions(**base)


def _frames(path: Path) -> list[np.ndarray]:
    import imageio_ffmpeg

    gen = imageio_ffmpeg.read_frames(str(path))
    meta = next(gen)
    w, h = meta["size"]
    return [np.frombuffer(f, np.uint8).reshape(h, w, 3) for f in gen]


@needs_gl
@pytest.mark.render
@pytest.mark.parametrize("name", list(PRESETS))
def test_preset_clip(tmp_path, name):
    table = small_table()
    out = tmp_path / f"{name}.mp4"
    res = render_manoeuvre(PRESETS[name], table, out, options())
    frames_expected = round(SECONDS * FPS)
    # the file: H.264 in yuv420p, the size and frame count asked for (ffmpeg's own reading)
    info = video_info(out)
    assert info["codec"] == "h264" and str(info["pix_fmt"]).startswith("yuv420p")
    assert info["size"] == (W, H) and info["frames"] == frames_expected == res.frames
    assert sorted(p.name for p in tmp_path.iterdir()) == [out.name]  # no temporary left
    frames = _frames(out)
    assert len(frames) == frames_expected
    for f in frames:  # not blank: a real picture has spread in brightness
        assert f.std() > 10 and f.max() - f.min() > 60

    # the same frames, as segmentation: the bird is in view of the tracking camera in
    # every frame, and its wings move between frames
    pb = play_for_video(PRESETS[name], table, options())
    with Scene(pb, options()) as scene:
        bird_ids, wing_ids = scene.bird_geoms(), scene.wing_geoms()
        masks = []
        for i in range(scene.frames):
            seg = scene.segmentation(i)
            is_geom = seg[..., 1] == int(__import__("mujoco").mjtObj.mjOBJ_GEOM)
            bird = is_geom & np.isin(seg[..., 0], bird_ids)
            # in view: a visible patch of bird (>= 1% of the frame), not touching every edge
            assert bird.sum() >= 0.01 * W * H, f"frame {i}: bird not in view"
            masks.append(is_geom & np.isin(seg[..., 0], wing_ids))
    # wings move: a quarter wingbeat apart (1.5 frames at 2 beats/s and 12 fps -> 2 frames)
    # the wing silhouettes differ by more than 5% of their area
    for a, b in zip(masks[:-2], masks[2:]):
        changed = np.logical_xor(a, b).sum() / max(1, np.logical_or(a, b).sum())
        assert changed > 0.05


@needs_gl
@pytest.mark.render
@pytest.mark.parametrize("model", ["base", "m2", "m4"])
def test_scene_pose_equals_the_drivers_set_pose(model):
    """The renderer poses all instants through the driver's vectorised path; the
    one-instant ``set_pose`` must put every body in the same place."""
    import mujoco

    from birdsim.mujoco.driver import set_pose

    pb = play_for_video(PRESETS["take-off"], small_table(model), options(seconds=0.5))
    with Scene(pb, options(seconds=0.5)) as scene:
        d2 = mujoco.MjData(scene.m)
        for k in (0, pb.frames // 2, pb.frames - 1):
            scene.pose_instant(k)
            f = pb.frame(k)
            set_pose(
                scene.m,
                d2,
                f["angles"],
                f["rates"],
                pitch=f["pitch"],
                position_seed=f["position_seed"],
                velocity_seed=f["velocity_seed"],
                pitch_rate=f["pitch_rate"],
            )
            # same arithmetic on both paths, only the order of floating-point operations differs
            np.testing.assert_allclose(scene.d.xpos, d2.xpos, rtol=0, atol=1e-12)
            np.testing.assert_allclose(scene.d.site_xpos, d2.site_xpos, rtol=0, atol=1e-12)
            np.testing.assert_allclose(scene.d.qvel, d2.qvel, rtol=0, atol=1e-12)


@needs_gl
@pytest.mark.render
def test_failure_midway_leaves_nothing(tmp_path, monkeypatch):
    out = tmp_path / "x.mp4"
    calls = {"n": 0}
    real = Scene.update

    def flaky(self, i):
        calls["n"] += 1
        if calls["n"] > 3:
            raise KeyboardInterrupt
        return real(self, i)

    monkeypatch.setattr(Scene, "update", flaky)
    with pytest.raises(KeyboardInterrupt):
        render_manoeuvre(PRESETS["hover"], small_table(), out, options(trails=False))
    assert list(tmp_path.iterdir()) == []


@needs_gl
@pytest.mark.render
def test_cli_renders_and_refuses_to_overwrite(tmp_path, capsys):
    table = small_table()
    table.save(tmp_path / "t")
    out = tmp_path / "clip.mp4"
    sheet = tmp_path / "clip.png"
    argv = [
        "render",
        "cruise",
        "--kinematic",
        "--table",
        str(tmp_path / "t.npz"),
        "--out",
        str(out),
        "--size",
        "128x96",
        "--fps",
        "10",
        "--seconds",
        "0.5",
        "--quiet",
        "--sheet",
        str(sheet),
    ]
    assert main(argv) == 0
    assert video_info(out)["frames"] == 5
    from PIL import Image

    assert Image.open(sheet).size == (
        4 * 320,
        2 * 240,
    )  # 5 frames -> 2 rows of 4 thumbnails, 320 wide
    before = out.stat().st_mtime_ns
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "exists" in err[0] and "--force" in err[0]
    assert out.stat().st_mtime_ns == before


@pytest.mark.parametrize(
    "args, words",
    [
        (["hovr"], "manoeuvre 'hovr' is unknown"),
        (["hover", "--model", "m9"], "model 'm9' is unknown"),
        (["hover", "--size", "650x480"], "multiples of 16"),
        (["hover", "--size", "640by480"], "malformed"),
        (["hover", "--fps", "0"], "--fps 0 is invalid"),
        (["hover", "--fps", "ten"], "not an integer"),
        (["hover", "--gl", "vulkan"], "--gl 'vulkan' is unknown"),
        (["hover", "--camera", "sky"], "--camera 'sky' is unknown"),
        (
            ["hover", "--out", "/proc/x.mp4"],
            "not writable",
        ),  # /proc refuses new files, even to root
        (["hover", "--out", "/proc/birdsim/x.mp4"], "cannot be created"),
        (["hover", "--out", "x.avi"], "does not end in .mp4"),
        (["hover", "--table", "/nonexistent/t.npz"], "does not exist"),
        (["hover", "--seconds", "3601"], "--seconds 3601.0 is invalid"),
        (
            ["hover", "--beat-rate", "0.001"],
            "= 8000 s of video at --beat-rate 0.001; allowed: at most 3600 s",
        ),  # the hover path: 8 wingbeats
        (
            ["hover", "--quality", "ultra"],
            "--quality 'ultra' is unknown; allowed: draft, good, best",
        ),
        (
            ["hover", "--camera", "drone"],
            "--camera 'drone' is unknown; allowed: track, chase, side, top, overview",
        ),
        (["hover", "--forces", "0"], "--forces '0' is not a positive number"),
        (["hover", "--forces", "-2"], "--forces '-2' is not a positive number"),
        (["hover", "--forces", "big"], "--forces 'big' is not a positive number"),
        (["hover", "--forces", "inf"], "--forces 'inf' is not a positive number"),
        (
            ["hover", "--still", "s.png", "--at", "8.5"],
            "--at '8.5' is outside the clip; allowed: a time in wingbeats in [0, 8]",
        ),
        (["hover", "--still", "s.png", "--at", "-0.1"], "--at '-0.1' is outside the clip"),
        (["hover", "--still", "s.png", "--at", "nan"], "--at 'nan' is outside the clip"),
        (["hover", "--at", "1"], "--at '1' needs --still"),
        (["hover", "--still", "s.jpg"], "--still 's.jpg' does not end in .png"),
    ],
)
def test_bad_input_one_line(tmp_path, capsys, monkeypatch, args, words):
    monkeypatch.chdir(tmp_path)
    assert main(["render", *args]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0], err
    assert not any(p.suffix in (".mp4", ".png") or "partial" in p.name for p in tmp_path.rglob("*"))


def test_table_for_another_model(tmp_path, capsys):
    small_table("m3").save(tmp_path / "m3")
    assert (
        main(
            [
                "render",
                "hover",
                "--kinematic",
                "--model",
                "m4",
                "--table",
                str(tmp_path / "m3.npz"),
                "--out",
                str(tmp_path / "x.mp4"),
            ]
        )
        == 2
    )
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "built for model 'm3', not 'm4'" in err[0]
    assert not (tmp_path / "x.mp4").exists()


def test_missing_gl_library_is_named(monkeypatch, capsys, tmp_path):
    monkeypatch.delenv("MUJOCO_GL", raising=False)
    monkeypatch.setattr(gl, "library_available", lambda backend: False)
    with pytest.raises(gl.GLError, match=r"libOSMesa\.so .*apt-get install libosmesa6"):
        gl.resolve_gl("osmesa")
    with pytest.raises(gl.GLError, match=r"libEGL\.so"):
        gl.resolve_gl("egl")
    with pytest.raises(gl.GLError, match=r"neither libOSMesa\.so .* nor libEGL\.so"):
        gl.resolve_gl("auto")
    small_table().save(tmp_path / "t")
    assert (
        main(
            [
                "render",
                "hover",
                "--table",
                str(tmp_path / "t.npz"),
                "--out",
                str(tmp_path / "x.mp4"),
            ]
        )
        == 2
    )
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "libOSMesa.so" in err[0] and "libEGL.so" in err[0]
    assert list(tmp_path.glob("*.mp4")) == []


def test_auto_prefers_osmesa_and_falls_back_to_egl(monkeypatch):
    monkeypatch.delenv("MUJOCO_GL", raising=False)
    monkeypatch.setattr(gl, "library_available", lambda backend: True)
    assert gl.resolve_gl("auto") == "osmesa"
    monkeypatch.setattr(gl, "library_available", lambda backend: backend == "egl")
    assert gl.resolve_gl("auto") == "egl"
    monkeypatch.setattr(gl, "library_available", lambda backend: True)
    monkeypatch.setenv("MUJOCO_GL", "egl")  # an explicit choice in the environment stands
    assert gl.resolve_gl("auto") == "egl"


def test_parse_size():
    assert parse_size("640x480") == (640, 480) and parse_size("1280X720") == (1280, 720)
    for bad in ("0x0", "17x16", "640", "8192x16"):
        with pytest.raises(BirdsimError):
            parse_size(bad)


@pytest.mark.skipif(
    not gl.library_available("osmesa"), reason="OSMesa not installed: the script would install it"
)
def test_setup_gl_is_quiet_and_idempotent_when_osmesa_is_installed():
    import subprocess

    script = Path(__file__).resolve().parents[1] / "scripts" / "setup_gl.sh"
    res = subprocess.run(["sh", str(script)], capture_output=True, text=True, timeout=60)
    assert res.returncode == 0 and res.stdout == "" and res.stderr == ""


def test_camera_list(capsys):
    assert main(["render", "hover", "--camera", "list"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert [line.split()[0] for line in out] == ["track", "chase", "side", "top", "overview"]


@needs_gl
@pytest.mark.render
def test_still_writes_one_png_and_nothing_else(tmp_path, capsys):
    table = small_table()
    table.save(tmp_path / "t")
    still = tmp_path / "s.png"
    argv = [
        "render",
        "cruise",
        "--kinematic",
        "--table",
        str(tmp_path / "t.npz"),
        "--still",
        str(still),
        "--at",
        "1.25",
        "--size",
        "160x128",
        "--seconds",
        "1",
        "--quality",
        "draft",
        "--forces",
        "2",
        "--camera",
        "chase",
    ]
    assert main(argv) == 0
    from PIL import Image

    img = np.asarray(Image.open(still))
    assert img.shape == (128, 160, 3) and img.std() > 10
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.png", "t.json", "t.npz"]
    assert main(argv) == 2  # exists, no --force
    assert "exists" in capsys.readouterr().err


@needs_gl
@pytest.mark.render
def test_quality_levels_switch_the_effects():
    import mujoco

    from birdsim.render.options import QUALITIES

    rnd = mujoco.mjtRndFlag
    pb = play_for_video(PRESETS["cruise"], small_table(), options(seconds=0.25))
    seen = {}
    for q in ("draft", "good", "best"):
        o = options(seconds=0.25, quality=q, width=64, height=48)
        with Scene(pb, o) as scene:
            flags = scene.renderer.scene.flags
            look = QUALITIES[q]
            assert (
                flags[rnd.mjRND_SHADOW] == (look.shadowsize > 0)
                and flags[rnd.mjRND_SKYBOX] == look.skybox
            )
            assert (
                scene.m.vis.quality.offsamples == look.samples
                and scene.m.vis.quality.shadowsize == look.shadowsize
            )
            seen[q] = scene.rgb(1)
    assert seen["draft"].std() > 10 and seen["best"].std() > 10
    assert (
        np.abs(seen["draft"].astype(int) - seen["good"].astype(int)).mean() > 1
    )  # the sky and shadows show
