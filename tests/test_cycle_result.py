"""Cycle results from kernel means: the dissertation's force (right wing + body drag
with its X and Z parts) and the whole bird (two wings + body), without histories."""

from __future__ import annotations

import numpy as np

from birdsim.physics.cycle_result import Cycle, PanelMeans


def _cycle(drag_x: float, drag_z: float) -> Cycle:
    def no_histories():
        raise AssertionError("means must not need histories")

    means = PanelMeans(
        force_earth=np.array([[0.1, 0.02, -0.3], [0.05, -0.01, -0.2]]),  # arm, hand
        power=np.array([0.4, 0.1]),
        joint_power={"shoulder": np.array(0.45), "wrist": np.array(0.05)},
    )
    return Cycle(
        model="m4",
        speed=np.array(0.5),
        params={},
        time=np.zeros(4),
        endpoint=False,
        panel_names=("arm", "hand"),
        body_drag_x=np.array(drag_x),
        climb=np.array(0.3),
        body_drag_z=np.array(drag_z),
        histories=no_histories,
        panel_means=means,
    )


def test_mean_and_whole_bird_from_panel_means():
    c = _cycle(-0.04, 0.01)
    m, w = c.mean, c.whole_bird_mean
    assert np.isclose(m.Fx, 0.15 - 0.04) and np.isclose(m.Fz, -0.5 + 0.01) and np.isclose(m.P, 0.5)
    assert np.isclose(w.Fx, 2 * 0.15 - 0.04) and np.isclose(w.Fz, 2 * -0.5 + 0.01)
    assert w.Fy == 0.0 and np.isclose(w.P, 1.0)
    assert np.isclose(c.panel_mean["hand"].Fz, -0.2)
    assert np.isclose(c.joint_power_mean["wrist"], 0.05)
