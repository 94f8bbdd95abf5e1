"""Clips as they come (issue 26, item 5): the clean render, the short overlay, a legible
plot strip, one time base for render and export, saturation said on stderr (an error
with --strict), the units of the JSON summary's errors."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from birdsim.cli import main
from birdsim.physics.bird import Bird
from birdsim.render.options import RenderOptions
from birdsim.render.timebase import beat_rate_for, describe

PIGEON = "models/pigeon.toml"
FAST = 'name = "fast"\nduration = 4\n[[keyframe]]\nt = 0\nV = 0.5\nz = 6\n[[keyframe]]\nt = 2\nV = 1.5\nz = 6\n'


def test_one_time_base_for_render_and_export():
    pigeon = Bird.from_toml(PIGEON)
    rate, words = beat_rate_for(pigeon, None, None)
    assert words == "real time" and rate == pytest.approx(1.0 / pigeon.period)
    slow, words = beat_rate_for(pigeon, None, "4")
    assert slow == pytest.approx(rate / 4) and "4x slow motion" in words
    seed, words = beat_rate_for(Bird(), None, None)
    assert seed == 2.0 and "2 wingbeats per second" in words
    assert beat_rate_for(pigeon, "3", None)[0] == 3.0
    line = describe(rate, "real time", 30)
    assert f"{30 / rate:.1f} frames per wingbeat" in line and "--slow-motion" in line
    # export's own time per second (bird time units per second of video) is the same
    from birdsim.export.frames import time_per_second

    assert time_per_second(pigeon, None) == pytest.approx(rate * pigeon.period)
    assert time_per_second(Bird(), None) == pytest.approx(seed * Bird().period)


def test_export_prints_its_time_base(tmp_path, capsys):
    log = tmp_path / "hover.npz"
    assert (
        main(["fly", "hover", "--seconds", str(2 * 2 * math.pi), "--out", str(log), "--quiet"]) == 0
    )
    capsys.readouterr()
    assert main(["export", str(log), "--format", "csv", "--out", str(tmp_path / "h.csv")]) == 0
    out = capsys.readouterr().out
    assert "birdsim export: time base: 2 wingbeats per second (a bird without SI units)" in out


def test_saturation_is_one_warning_line_or_an_error_with_strict(tmp_path, capsys):
    path = tmp_path / "fast.toml"
    path.write_text(FAST)
    assert main(["fly", str(path), "--quiet"]) == 0
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("birdsim fly: warning: saturated in ")
    assert "birdsim envelope --model m3" in lines[0]
    n = int(lines[0].split("saturated in ")[1].split()[0])
    assert f"saturated in {n} wingbeat(s)" in captured.out  # the summary agrees
    out = tmp_path / "fast.npz"
    assert main(["fly", str(path), "--quiet", "--strict", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--strict: saturated in" in err[0]
    assert not out.exists()  # nothing written


def test_json_errors_carry_their_units(capsys):
    seconds = 2 * 2 * math.pi
    assert main(["fly", "hover", "--json", "--seconds", str(seconds)]) == 0
    seed = json.loads(capsys.readouterr().out)
    assert seed["error_unit"] == "semispans" and "errors_semispans" not in seed
    pigeon = Bird.from_toml(PIGEON)
    assert (
        main(["fly", "hover", "--json", "--bird", PIGEON, "--seconds", str(3 * pigeon.period)]) == 0
    )
    info = json.loads(capsys.readouterr().out)
    assert info["error_unit"] == "m"
    for key, v in info["errors_semispans"].items():
        assert v == pytest.approx(info[key] / pigeon.semispan, rel=1e-12, nan_ok=True)


def test_plot_strip_legend_has_its_own_row():
    from PIL import ImageFont

    from birdsim.render.overlay import PlotStrip

    t = np.linspace(0, 1, 50)
    strip = PlotStrip(640, 480, t, [("a", np.sin(9 * t), (255, 0, 0))], ImageFont.load_default())
    rows = np.asarray(strip._y(np.linspace(-1, 1, 11)))
    assert rows.min() >= strip.label_h  # no curve in the legend's row
    alpha = np.asarray(strip.layer)[: strip.label_h, :, 3]
    assert alpha.min() >= 150  # the row has its dark backing everywhere


def test_options_of_clean_and_overlay():
    o = RenderOptions(reference=False, trails=False, overlay=False)
    assert not (o.reference or o.trails or o.overlay)
    assert RenderOptions().overlay_detail == "short"
    from birdsim.errors import BirdsimError

    with pytest.raises(BirdsimError, match="--overlay 'most' is unknown"):
        RenderOptions(overlay_detail="most")


def _gl_helpers():
    from test_render_states import glide_states, needs_gl, opts

    return glide_states, needs_gl, opts


@pytest.mark.render
def test_clean_draws_no_reference_and_short_overlay_has_three_lines():
    glide_states, needs_gl, opts = _gl_helpers()
    from birdsim.render.gl import resolve_gl

    try:
        resolve_gl("auto")
    except Exception as exc:  # no headless OpenGL here
        pytest.skip(str(exc))
    from birdsim.render.scene import Scene

    path = np.array([[-2.0, 0.0, 1.0], [0.0, 0.0, 2.0], [2.0, 0.0, 3.0]])
    lines = [(f"line {k}", (255, 255, 255)) for k in range(6)]
    brief = [("t 1.00 s", (255, 255, 255)), ("error 0.01 m", (255, 255, 255))]
    states = glide_states(reference_path=path, overlay=lambda k: lines, brief=lambda k: brief)
    with (
        Scene(glide_states(), opts(trails=False, overlay=False)) as plain,
        Scene(states, opts(trails=False, overlay=False, reference=False)) as clean,
        Scene(states, opts(trails=False)) as short,
        Scene(states, opts(trails=False, overlay_detail="full")) as full,
    ):
        plain.update(0)
        clean.update(0)
        assert clean.renderer.scene.ngeom == plain.renderer.scene.ngeom  # no path drawn
        assert short.overlay_lines(0) == brief
        assert len(full.overlay_lines(0)) > 3
        np.testing.assert_array_equal(clean.rgb(0), plain.rgb(0))  # bird and world only
