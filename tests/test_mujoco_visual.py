"""The visual bird: planforms with the panels' span and area, massless contact-free
geoms in their own group, mirror-image wings, plumage by bird name."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from birdsim import Bird
from birdsim.mujoco.model import build_model
from birdsim.mujoco.plumage import NEUTRAL, PIGEON, plumage_for
from birdsim.mujoco.visual import VISUAL_GROUP, extrude, panel_planform, polygon_area


@pytest.mark.parametrize(
    "kind, span, chord, bars",
    [
        ("arm", 2 / 3, 1.0, 0),
        ("arm", 0.2, 0.11, 2),
        ("hand", 1 / 3, 1.0, 0),
        ("hand", 0.13, 0.09, 2),
    ],
)
def test_planform_has_the_panels_span_and_area(kind, span, chord, bars):
    pieces = panel_planform(kind, span, chord, bars)
    area = sum(polygon_area(p.polygon) for p in pieces)
    assert area == pytest.approx(span * chord, rel=1e-12)
    # the planform sits on its panel: area centroid within 5 % of the chord of the twist
    # axis (x = 0, where the control point is), the arm's at half span like its CP
    moments = []
    for p in pieces:
        x, y = p.polygon[:, 0], p.polygon[:, 1]
        cross = x * np.roll(y, -1) - np.roll(x, -1) * y
        moments.append(
            [
                ((x + np.roll(x, -1)) * cross).sum() / 6,
                ((y + np.roll(y, -1)) * cross).sum() / 6,
                cross.sum() / 2,
            ]
        )
    mu, mx, a = np.abs(np.sum(moments, axis=0)) * np.sign(np.sum(moments, axis=0)[2])
    assert abs(mx / a) < 0.05 * chord
    if kind == "arm":
        assert mu / a == pytest.approx(span / 2, rel=1e-9)
    u = np.vstack([p.polygon for p in pieces])[:, 0]
    assert u.min() == pytest.approx(0.0, abs=1e-12) and u.max() == pytest.approx(span, rel=1e-9)
    # pieces do not overlap: rasterised union area == summed area (to the grid's resolution)
    Path = pytest.importorskip("matplotlib.path").Path  # the plots extra (make setup installs it)

    xs = np.vstack([p.polygon for p in pieces])
    gu, gx = np.meshgrid(
        np.linspace(xs[:, 0].min(), xs[:, 0].max(), 300),
        np.linspace(xs[:, 1].min(), xs[:, 1].max(), 300),
    )
    pts = np.column_stack([gu.ravel(), gx.ravel()])
    counts = sum(Path(p.polygon).contains_points(pts).astype(int) for p in pieces)
    assert (counts > 1).mean() < 0.002  # only boundary pixels are shared
    cell = (gu[0, 1] - gu[0, 0]) * (gx[1, 0] - gx[0, 0])
    assert (counts > 0).sum() * cell == pytest.approx(span * chord, rel=0.03)


def test_extruded_mesh_is_closed_and_outward():
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    for sign in (1.0, -1.0):
        v, f = extrude([square], sign, 0.1)
        # a closed surface: every edge is used twice, in opposite directions
        edges = {(a, b) for tri in f for a, b in zip(tri, np.roll(tri, -1))}
        assert all((b, a) in edges for a, b in edges)
        # outward: the signed volume (divergence theorem) is + area * thickness
        vol = sum(np.dot(v[a], np.cross(v[b], v[c])) for a, b, c in f) / 6.0
        assert vol == pytest.approx(0.1, rel=1e-12)


@pytest.mark.parametrize("name", ["base", "m4"])
def test_visual_geoms_are_massless_contact_free_and_mirrored(name):
    m = build_model(name)
    vis = np.flatnonzero(m.geom_group == VISUAL_GROUP)
    assert len(vis) > 20
    assert np.all(m.geom_contype[vis] == 0) and np.all(m.geom_conaffinity[vis] == 0)
    names = [m.geom(int(g)).name for g in vis]
    for part in (
        "vis_torso",
        "vis_head",
        "vis_beak",
        "vis_l_eye",
        "vis_r_eye",
        "vis_tail",
        "vis_r_arm_coverts",
        "vis_r_hand_primaries",
    ):
        assert part in names, part
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, m.key("rest").id)
    mujoco.mj_kinematics(m, d)
    # the left wing's pieces are the mirror images (y -> -y) of the right wing's
    for g in vis:
        n = m.geom(int(g)).name
        if n.startswith("vis_r_") and ("arm" in n or "hand" in n):
            mate = m.geom(n.replace("vis_r_", "vis_l_")).id
            np.testing.assert_allclose(d.geom_xpos[g] * [1, -1, 1], d.geom_xpos[mate], atol=1e-9)


def test_plumage_by_bird_name():
    assert (
        plumage_for("pigeon") is PIGEON
        and plumage_for("seed") is NEUTRAL
        and plumage_for("albatross") is NEUTRAL
    )
    assert (
        PIGEON.wing_bars == 2 and PIGEON.neck_specular > NEUTRAL.neck_specular
    )  # dark bars, glossy neck
    m = build_model("m4", Bird(name="pigeon"))
    np.testing.assert_allclose(m.mat_rgba[m.material("plumage_body").id], PIGEON.body)
    assert "vis_r_arm_bars" in [m.geom(i).name for i in range(m.ngeom)]
    assert "vis_r_arm_bars" not in [
        build_model("m4").geom(i).name for i in range(build_model("m4").ngeom)
    ]


def test_zero_span_panel_has_no_dress():
    m = build_model("m4", Bird(hand_span_fraction=0.0))
    names = [m.geom(i).name for i in range(m.ngeom)]
    assert not any(n.startswith("vis_r_hand") for n in names) and "vis_r_arm_coverts" in names
