"""The world: a ground checker of a known spacing, collision geoms of the arena, visual
decorations without contacts."""

from __future__ import annotations

import numpy as np
import pytest

from birdsim import Bird
from birdsim.mujoco.arena import GROUND_SPACING
from birdsim.mujoco.model import build_model


@pytest.mark.parametrize("semispan", [1.0, 0.33])
def test_ground_checker_has_squares_of_the_known_spacing(semispan):
    m = build_model("m4", Bird(semispan=semispan, chord=0.3 * semispan))
    mat = m.material("ground").id
    assert m.mat_texuniform[mat]
    # a checker texture holds 2 x 2 squares; texuniform repeats it texrepeat times per unit length
    np.testing.assert_allclose(
        1.0 / (2.0 * m.mat_texrepeat[mat]), GROUND_SPACING * semispan, rtol=1e-6
    )
    assert m.geom_matid[m.geom("floor").id] == mat


def test_arena_collides_and_its_decorations_do_not():
    m = build_model("m4")
    for name in ("floor", "perch_post", "perch_bar"):
        g = m.geom(name).id
        assert m.geom_contype[g] == 1 and m.geom_conaffinity[g] == 2
    for name in ("perch_foot", "perch_knot", "perch_twig0", "perch_twig1", "perch_twig2"):
        g = m.geom(name).id
        assert m.geom_contype[g] == 0 and m.geom_conaffinity[g] == 0
    assert m.ntex == 3 and m.tex_type[m.texture("sky").id] == 2  # mjTEXTURE_SKYBOX
