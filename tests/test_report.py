"""The report: every figure is built on reduced grids and is a real plot; the numbers
behind the figures agree with independent computations; missing matplotlib and an
existing report give one clear line."""

from __future__ import annotations

import html
import math
import sys
from pathlib import Path

import numpy as np
import pytest

from birdsim import Bird, evaluate_cycle
from birdsim.errors import BirdsimError
from birdsim.physics.frames import body_to_earth, rotate
from birdsim.report import figdata as fd

pytest.importorskip("matplotlib")

from birdsim.report import plots, report  # noqa: E402

PI = math.pi


def _pixels(path: Path) -> np.ndarray:
    import matplotlib.image as mpimg

    img = mpimg.imread(path)  # H x W x 4 floats for PNG
    return np.round(img[..., :3] * 255).astype(np.uint8)


def test_quick_report_every_figure_is_a_real_plot(tmp_path: Path) -> None:
    """One test (so that pytest-xdist builds the report once): every family builds,
    every figure file is a labelled plot, the page lists each with its verdict, and a
    second run without --force is refused."""
    out = tmp_path / "report"
    sections = report.build_report(out, quick=True, progress=False)
    assert [s.family.key for s in sections] == [f.key for f in report.FAMILIES]
    assert not [s.error for s in sections if s.error]
    files = [e.file for s in sections for e in s.entries]
    # 10 histories + 1 + 2 + 2 + 3 + 6 + 5 + 9 paths + 3: no figure silently dropped
    # 41 of the dissertation + table smoothness + the turning presets (issue 23)
    assert len(files) == len(set(files)) == 43
    assert sorted(p.name for p in out.glob("*.png")) == sorted(files)
    for name in files:
        px = _pixels(out / name)
        h, w, _ = px.shape
        assert h >= 300 and w >= 500, name
        packed = px[..., 0].astype(np.uint32) << 16 | px[..., 1].astype(np.uint32) << 8 | px[..., 2]
        colours = np.unique(packed)
        # a blank or single-line canvas has a handful of colours; a labelled plot with
        # antialiased text, lines and colour maps has hundreds
        assert len(colours) > 100, (name, len(colours))
        ink = np.mean(np.any(px < 230, axis=-1))
        assert 0.02 < ink < 0.95, (name, ink)  # neither empty nor a solid block

    page = (out / "index.html").read_text()
    for s in sections:
        for e in s.entries:
            assert f"src='{e.file}'" in page
            assert e.verdict in page
            for c in e.claims:
                assert html.escape(c.statement) in page

    with pytest.raises(BirdsimError, match="--force"):
        report.build_report(out, quick=True, progress=False, only=["thrust"])


def test_cli_report_one_family_and_bad_family(
    tmp_path: Path, capsys: pytest.CaptureFixture
) -> None:
    from birdsim.cli import main

    assert main(["report", "--out", str(tmp_path / "r"), "--quick", "--only", "thrust"]) == 0
    assert (tmp_path / "r" / "thrust_coefficient.png").exists()
    capsys.readouterr()
    assert main(["report", "--out", str(tmp_path / "r2"), "--only", "nonsense"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--only 'nonsense'" in err[0] and "allowed" in err[0]


def test_missing_matplotlib_is_one_clear_line(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in [m for m in sys.modules if m == "matplotlib" or m.startswith("matplotlib.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # makes ``import matplotlib`` fail
    with pytest.raises(BirdsimError, match=r"pip install birdsim\[plots\]") as info:
        plots.pyplot()
    assert "\n" not in str(info.value)


# ---- the numbers behind the figures --------------------------------------------------


@pytest.mark.parametrize(
    "zeta,twist", [(0.3, 0.0), (0.9, 0.4), (PI / 2 - 1e-9, PI / 4), (0.5, 0.7)]
)
def test_thrust_coefficient_equals_the_blade_element_force(zeta: float, twist: float) -> None:
    """Eq. 23 (closed form) against the core's element force on a twisted section moving
    forward at V and down at w = V tan(zeta), rotated into panel axes and back."""
    bird = Bird()
    speed = 1.0
    w = speed * math.tan(zeta)
    v_earth = (np.array(speed), np.array(0.0), np.array(w))  # section relative to the air
    c, s = math.cos(-twist), math.sin(-twist)  # leading edge down = negative pitch-type angle
    vx, _, vz = rotate("y", c, s, v_earth)
    fx, fz = bird.polar.force_panel(vx, vz, 1.0, bird.rho)
    f_earth = rotate("y", c, -s, (fx, np.zeros_like(fx), fz))
    q = 0.5 * bird.rho * (speed**2 + w**2)
    expected = fd.thrust_coefficient(bird.polar, zeta, twist)
    # both are the same algebra in different orders: agreement to round-off
    assert float(f_earth[0]) / q == pytest.approx(float(expected), abs=1e-9)


def test_thrust_coefficient_hover_optimum_is_pi_over_4() -> None:
    twist = np.linspace(0, PI / 4, 181)
    c = fd.thrust_coefficient(Bird().polar, PI / 2, twist)
    # at zeta = pi/2, C_Fx = Clmax sin(2 twist): maximal at the upper bound pi/4, never negative
    assert twist[np.argmax(c)] == pytest.approx(PI / 4)
    assert c.min() >= -1e-12


def test_landscape_profile_matches_brute_force() -> None:
    """The profiled landscape (minimum over pitch per cell) equals an explicit loop."""
    flap = np.linspace(0.2, 1.4, 4)
    twist = np.linspace(0.0, 0.7, 3)
    pitch = np.linspace(0.0, 1.5, 5)

    def cost(means, params, speed):
        return np.abs(means.Fx - 0.1) + np.abs(means.Fz + 0.1) + 0.5 * np.abs(means.P)

    land = fd.landscape(
        "base", 0.5, cost, ("flap_amp", flap), ("twist_amp", twist), profile={"pitch": pitch}, n=16
    )
    for i, f in enumerate(flap):
        for j, t in enumerate(twist):
            vals = []
            for p in pitch:
                m = evaluate_cycle("base", dict(pitch=p, flap_amp=f, twist_amp=t), 0.5, n=16).mean
                vals.append(abs(float(m.Fx) - 0.1) + abs(float(m.Fz) + 0.1) + 0.5 * abs(float(m.P)))
            # same evaluations, batched vs one at a time: equal to round-off
            assert land.cost[i, j] == pytest.approx(min(vals), abs=1e-12)
            assert land.argmin["pitch"][i, j] == pitch[int(np.argmin(vals))]
    k = np.unravel_index(np.argmin(land.cost), land.cost.shape)
    assert land.best["flap_amp"] == flap[k[0]] and land.best["twist_amp"] == twist[k[1]]


def test_grid_means_chunking_is_invisible(monkeypatch: pytest.MonkeyPatch) -> None:
    lag = np.linspace(0, PI / 2, 5)[:, None]
    bias = np.linspace(0, PI / 2, 3)[None, :]
    whole = fd.wrist_upward_force(PI / 5, 2 * PI / 5, lag, bias, n=12)
    monkeypatch.setattr(fd, "CHUNK", 4)  # 15 sets in 4 chunks
    chunked = fd.wrist_upward_force(PI / 5, 2 * PI / 5, lag, bias, n=12)
    np.testing.assert_array_equal(whole, chunked)
    assert whole.shape == (5, 3)


def test_wrist_study_optimum_is_the_dissertation_s() -> None:
    """Sec. 3.5.7 / Fig 26: the upward force peaks at lag pi/2, bias pi/4 for both
    amplitude pairs, and is larger with the larger amplitude at the shoulder."""
    grid = np.linspace(0, PI / 2, 9)  # step pi/16: pi/4 and pi/2 are nodes
    best = []
    for pf, pw in ((PI / 5, 2 * PI / 5), (2 * PI / 5, PI / 5)):
        up = fd.wrist_upward_force(pf, pw, grid[:, None], grid[None, :], n=24)
        i, j = np.unravel_index(np.argmax(up), up.shape)
        assert (grid[i], grid[j]) == (PI / 2, PI / 4)
        best.append(up.max())
    assert best[1] > best[0] > 0


def test_control_point_paths_agree_with_the_cycle() -> None:
    """figdata's chain walk and the cycle's CP positions are two paths to the same
    points; chord lines have the chord's length."""
    params = dict(
        pitch=0.3,
        flap_amp=0.6,
        twist_amp=0.4,
        stroke_plane=0.2,
        wrist_amp=0.3,
        wrist_bias=0.25,
        wrist_lag=1.2,
    )
    bird = Bird()
    p = fd.control_point_paths("m4", params, bird=bird, n=16)
    cyc = evaluate_cycle("m4", params, 0.0, bird=bird, n=16)
    pos = cyc.cp_position_body  # K x N x 3 body axes
    earth = np.stack(body_to_earth(0.3, (pos[..., 0], pos[..., 1], pos[..., 2])), axis=-1)
    np.testing.assert_allclose(p.path, earth, atol=1e-12)
    chord = np.linalg.norm(p.leading - p.trailing, axis=-1)
    np.testing.assert_allclose(chord, 1.0, atol=1e-12)
    # the arm CP sits at half the arm span (2/3) from the shoulder whatever the angles
    assert np.all(np.linalg.norm(p.path[0], axis=-1) == pytest.approx(1 / 3))


def test_wrist_activity_scales_the_upper_bounds() -> None:
    k = fd.wrist_activity(np.array([0.0, 0.5, 1.0]))
    np.testing.assert_allclose(k["wrist_amp"], [0, PI / 8, PI / 4])
    np.testing.assert_allclose(k["wrist_lag"], [0, PI / 4, PI / 2])
    np.testing.assert_allclose(k["wrist_bias"], [0, PI / 8, PI / 4])


@pytest.mark.slow
def test_full_report_builds(tmp_path: Path) -> None:
    """The full-resolution report: every family, every figure."""
    sections = report.build_report(tmp_path / "report", quick=False, progress=False)
    assert not [s.error for s in sections if s.error]
    files = [e.file for s in sections for e in s.entries]
    assert len(files) == 43 and all(
        (tmp_path / "report" / f).stat().st_size > 20_000 for f in files
    )  # 41 + smoothness + turns
