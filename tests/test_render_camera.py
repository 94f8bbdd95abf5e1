"""Cameras: critically damped, lag-free smoothing (no wingbeat jitter), the bird in
frame at every size, the overview keeping the bird in every frame."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from birdsim.render import gl

try:
    BACKEND = gl.select_gl("auto")
except gl.GLError:  # pragma: no cover
    BACKEND = None

from birdsim.flight.manoeuvre import PRESETS  # noqa: E402
from birdsim.render.camera import CameraPose, fit_distance, project, smooth_critically_damped  # noqa: E402
from birdsim.render.renderer import RenderOptions, Scene, play_for_video  # noqa: E402

sys.path.insert(0, str(Path(__file__).parent))
from test_render import small_table  # noqa: E402

needs_gl = pytest.mark.skipif(BACKEND is None, reason="no headless OpenGL (libOSMesa or libEGL)")


def test_smoothing_has_no_lag_and_no_wingbeat_jitter():
    t = np.arange(0, 12, 1 / 120)  # 120 instants per wingbeat
    line = np.column_stack([0.9 * t, 0.0 * t, 2.0 + 0.1 * t])
    bob = 0.08 * np.sin(2 * np.pi * t)  # at the wingbeat frequency
    x = line + np.column_stack([0 * t, 0 * t, bob])
    y = smooth_critically_damped(x, t, 1.0)
    # no lag on a straight path, even at the ends; the bob is attenuated ~1700 times
    # in the middle, and at the ends by what the padding's trend fit leaves (< 10 %)
    assert np.abs(y - line).max() < 0.1 * 0.08
    mid = slice(len(t) // 4, -len(t) // 4)
    assert np.abs(y[mid] - line[mid]).max() < 0.01 * 0.08


def test_projection_centres_the_lookat_and_scales_with_the_field_of_view():
    pose = CameraPose.from_offset(np.array([1.0, 2.0, 3.0]), np.array([-2.0, -2.0, 1.0]))
    np.testing.assert_allclose(pose.position(), [-1.0, 0.0, 4.0], atol=1e-9)
    np.testing.assert_allclose(
        project(np.array([[1.0, 2.0, 3.0]]), pose, 45.0, 4 / 3), [[0.0, 0.0]], atol=1e-9
    )
    # a sphere of the size fit_distance was asked for spans the asked fraction of the frame
    d = fit_distance(2.0, 45.0, 0.5, 0.45)  # portrait: the width is the narrower side
    side = CameraPose.from_offset(np.zeros(3), np.array([0.0, -d, 0.0]))
    u = project(np.array([[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]), side, 45.0, 0.5)
    assert (u[1, 0] - u[0, 0]) / 2 == pytest.approx(0.45, rel=1e-9)


def _bird_mask(scene, i):
    import mujoco

    seg = scene.segmentation(i)
    return (seg[..., 1] == int(mujoco.mjtObj.mjOBJ_GEOM)) & np.isin(seg[..., 0], scene.bird_geoms())


@needs_gl
@pytest.mark.render
@pytest.mark.parametrize("preset", ["hover", "cruise", "take-off", "landing"])
def test_overview_keeps_the_bird_in_every_frame(preset):
    o = RenderOptions(
        width=160,
        height=96,
        fps=4,
        beats_per_second=2.0,
        camera="overview",
        quality="draft",
        progress=False,
        trails=False,
    )
    pb = play_for_video(PRESETS[preset], small_table(), o)
    with Scene(pb, o) as scene:
        fovy = float(scene.m.vis.global_.fovy)
        for i in range(scene.frames):
            k = scene.instant(i)
            uv = project(scene.torso_path[k][None, :], scene.poses[i], fovy, o.width / o.height)[0]
            assert np.all(np.abs(uv) < 0.9), (
                i,
                uv,
            )  # the bird's centre inside the frame, off the edges
            assert uv[1] < 0.4, (i, uv)  # below the overlay text (the top 27 % of a 640x480 frame)
        # the projection is MuJoCo's: the projected centre lies on the bird in the image
        for i in (0, scene.frames // 2, scene.frames - 1):
            uv = project(
                scene.torso_path[scene.instant(i)][None, :],
                scene.poses[i],
                fovy,
                o.width / o.height,
            )[0]
            col, row = int((uv[0] + 1) / 2 * o.width), int((1 - uv[1]) / 2 * o.height)
            mask = _bird_mask(scene, i)
            assert mask[max(0, row - 1) : row + 2, max(0, col - 1) : col + 2].any(), (i, row, col)


@needs_gl
@pytest.mark.render
@pytest.mark.parametrize("camera", ["track", "chase", "side", "top"])
@pytest.mark.parametrize("size", [(160, 128), (96, 192), (256, 64)])
def test_the_bird_fills_a_sensible_part_of_the_frame(camera, size):
    w, h = size
    o = RenderOptions(
        width=w,
        height=h,
        fps=6,
        seconds=1.0,
        camera=camera,
        quality="draft",
        progress=False,
        trails=False,
        overlay=False,
    )
    pb = play_for_video(PRESETS["cruise"], small_table(), o)
    with Scene(pb, o) as scene:
        for i in range(0, scene.frames, 2):
            mask = _bird_mask(scene, i)
            rows, cols = np.flatnonzero(mask.any(axis=1)), np.flatnonzero(mask.any(axis=0))
            assert len(rows), f"frame {i}: no bird"
            extent = max((rows[-1] - rows[0] + 1) / h, (cols[-1] - cols[0] + 1) / w)
            assert 0.15 < extent <= 1.0 and mask.mean() < 0.6, (i, extent, mask.mean())


@needs_gl
@pytest.mark.render
def test_shadows_only_where_the_shadow_is_in_view():
    """The shadow pass costs as much as the picture: it runs only in frames where the
    sun's ray through the bird meets the ground inside the frame."""
    from birdsim.render.camera import project

    table = small_table()
    for preset, camera, expect in (
        ("cruise", "track", "none"),
        ("cruise", "overview", "all"),
        ("take-off", "track", "some"),
    ):
        o = RenderOptions(
            width=64,
            height=48,
            fps=4,
            camera=camera,
            quality="good",
            progress=False,
            trails=False,
            overlay=False,
        )
        with Scene(play_for_video(PRESETS[preset], table, o), o) as scene:
            on = scene.shadows
            assert {"none": not on.any(), "all": on.all(), "some": on.any()}[expect], (
                preset,
                camera,
                on,
            )
            d = scene.m.light_dir[0] / np.linalg.norm(scene.m.light_dir[0])
            for i in range(scene.frames):  # off-frame shadow points really are outside the frame
                p = scene.torso_path[scene.instant(i)]
                uv = project(
                    (p + d * (p[2] / -d[2]))[None, :],
                    scene.poses[i],
                    float(scene.m.vis.global_.fovy),
                    o.width / o.height,
                )[0]
                if np.all(np.abs(uv) < 1.0):
                    assert on[i]
            scene.update(0)
            assert scene.renderer.scene.flags[__import__("mujoco").mjtRndFlag.mjRND_SHADOW] == on[0]
    o = RenderOptions(
        width=64, height=48, fps=4, camera="overview", quality="draft", progress=False
    )
    with Scene(play_for_video(PRESETS["cruise"], table, o), o) as scene:
        assert not scene.shadows.any()


@needs_gl
@pytest.mark.render
@pytest.mark.parametrize("preset", ["hover", "cruise", "take-off", "landing"])
def test_overview_keeps_the_free_flight_in_every_frame(preset):
    """The same projection for the flown path (free flight, the default of `birdsim
    render`): the demo bird with its shipped table, every frame of every preset."""
    import dataclasses

    from birdsim.commands.fly import load_table_for
    from birdsim.flight.flightlog import log_arrays
    from birdsim.flight.flightstates import flight_states
    from birdsim.flight.freeflight import fly
    from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS
    from birdsim.physics.bird import Bird

    bird = Bird.from_toml("models/seed-bird.toml")
    path = PATH_PRESETS[preset]
    log = log_arrays(fly(path, load_table_for(bird, DEMO_MODEL, None), bird, DEMO_MODEL), preset)
    o = RenderOptions(
        width=160,
        height=96,
        fps=4,
        beats_per_second=2.0,
        camera="overview",
        quality="draft",
        progress=False,
        trails=False,
    )
    states = flight_states(log, dataclasses.replace(o, seconds=None), title=preset)
    with Scene(states, o) as scene:
        fovy = float(scene.m.vis.global_.fovy)
        assert scene.frames >= 2 * path.duration_beats - 1
        for i in range(scene.frames):
            uv = project(
                scene.torso_path[scene.instant(i)][None, :],
                scene.poses[i],
                fovy,
                o.width / o.height,
            )[0]
            assert np.all(np.abs(uv) < 0.9), (i, uv)
            # and below the overlay text, which covers the top 27 % of a 640x480 frame
            assert uv[1] < 0.4, (i, uv)
