"""StateSequence: the renderer draws any per-instant state sequence (not only a
table-driven playback), with its overlay and an optional reference path."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim.errors import BirdsimError
from birdsim.render import gl

try:
    BACKEND = gl.select_gl("auto")
except gl.GLError:  # pragma: no cover
    BACKEND = None

from birdsim import Bird  # noqa: E402
from birdsim.flight.manoeuvre import PRESETS  # noqa: E402
from birdsim.render.renderer import (
    RenderOptions,
    Scene,
    StateSequence,
    play_for_video,
    render_states,
    states_from_playback,
    video_info,
)  # noqa: E402

needs_gl = pytest.mark.skipif(BACKEND is None, reason="no headless OpenGL (libOSMesa or libEGL)")


def glide_states(frames: int = 6, **kw) -> StateSequence:
    """The rest pose moving forward at 1 semispan per beat, wings still."""
    from birdsim.mujoco.model import build_model

    m = build_model("m4")
    t = np.arange(frames) * 0.1
    qpos = np.tile(m.key("rest").qpos, (frames, 1))
    qpos[:, 0] = t
    qvel = np.zeros((frames, m.nv))
    qvel[:, 0] = 1.0
    base = dict(model="m4", bird=Bird(), t_beats=t, qpos=qpos, qvel=qvel)
    base.update(kw)
    return StateSequence(**base)


def opts(**kw) -> RenderOptions:
    base = dict(width=160, height=128, fps=10, progress=False)
    base.update(kw)
    return RenderOptions(**base)


@pytest.mark.parametrize(
    "change, words",
    [
        (dict(t_beats=np.zeros((2, 2))), "t_beats has shape"),
        (dict(qpos=np.zeros((5, 23))), "do not match"),
        (dict(qvel=np.full((6, 20), np.nan)), "NaN"),
        (dict(instants_per_frame=0), "instants_per_frame"),
        (dict(reference_path=np.zeros((4, 2))), "reference_path"),
        (dict(overlay=[["a"]] * 5), "overlay has 5 entries"),
    ],
)
def test_bad_sequences_are_one_line(change, words):
    with pytest.raises(BirdsimError, match=words):
        glide_states(**change)


def test_overlay_from_list_or_callable():
    a = glide_states(overlay=[[f"k={k}"] for k in range(6)])
    b = glide_states(overlay=lambda k: [(f"k={k}", (255, 0, 0))])
    assert a.overlay_at(3) == ["k=3"] and b.overlay_at(3) == [("k=3", (255, 0, 0))]
    assert glide_states().overlay_at(2) == []
    assert glide_states(instants_per_frame=4).frames == 2  # ceil(6 / 4)


@needs_gl
@pytest.mark.render
def test_reference_path_is_drawn_as_thin_lines():
    path = np.array([[-2.0, 0.0, 1.0], [0.0, 0.0, 2.0], [2.0, 0.0, 3.0]])
    with (
        Scene(glide_states(), opts(trails=False, overlay=False, camera="side")) as plain,
        Scene(
            glide_states(reference_path=path), opts(trails=False, overlay=False, camera="side")
        ) as with_path,
    ):
        plain.update(0)
        with_path.update(0)
        assert with_path.renderer.scene.ngeom == plain.renderer.scene.ngeom + len(path) - 1
        drawn = [with_path.renderer.scene.geoms[plain.renderer.scene.ngeom + k] for k in range(2)]
        assert all(
            g.type == int(__import__("mujoco").mjtGeom.mjGEOM_LINE) and g.segid == -1 for g in drawn
        )
        # the segments start at the path's points (mjv_connector: a line's pos is its start)
        np.testing.assert_allclose([drawn[0].pos, drawn[1].pos], path[:2], atol=1e-6)
        assert np.abs(with_path.rgb(0).astype(int) - plain.rgb(0).astype(int)).sum() > 0


@needs_gl
@pytest.mark.render
def test_playback_adapter_draws_what_the_playback_scene_draws(tmp_path):
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).parent))
    from test_render import small_table

    o = opts(seconds=0.5)
    pb = play_for_video(PRESETS["cruise"], small_table(), o)
    states = states_from_playback(pb, o.trail_substeps)
    with Scene(pb, o) as a, Scene(states, o) as b:
        assert a.frames == b.frames == 5
        ra, rb = a.rgb(3), b.rgb(3)
        # equal but for where two translucent pathline segments cross: MuJoCo depth-sorts
        # translucent geoms and equal depths may blend in either order (seen once under
        # load: 21 of 61440 values); anything drawn differently changes far more
        differ = np.any(ra != rb, axis=-1)
        assert differ.mean() <= 1e-3, f"{differ.sum()} pixels differ"
    res = render_states(states, tmp_path / "x.mp4", o)
    assert video_info(res.path)["frames"] == 5 == res.frames
