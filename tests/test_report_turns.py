"""The report's turning figure (birdsim/report/fig_turns.py) and the per-wingbeat series
it draws (birdsim/flight/turn_summary.py) on an ideal coordinated circle built here."""

from __future__ import annotations

import math

import numpy as np
import pytest

from birdsim.flight.turn_summary import turn_figures, turn_series

pytest.importorskip("matplotlib")


def _ideal_circle(radius=25.0, speed=0.5, gravity=0.3, beats=12, per=64):
    """A level left circle at constant speed flown with the coordinated bank: heading
    along the velocity, left wing down by atan(V^2 / (R g)) (omega 1: a wingbeat is
    2 pi time units)."""
    t = np.arange(beats * per + 1) * 2 * math.pi / per
    psi = speed * t / radius
    bank = -math.atan(speed**2 / (radius * gravity))  # left wing down: seed bank < 0
    # MuJoCo quaternion of Rz(psi) Rx(bank): body y (left) tipped down for bank < 0
    qz = np.stack([np.cos(psi / 2), 0 * psi, 0 * psi, np.sin(psi / 2)], axis=1)
    cx, sx = math.cos(bank / 2), math.sin(bank / 2)
    w, x, y, z = qz.T
    quat = np.stack([w * cx, w * sx, z * sx, z * cx], axis=1)  # qz * qx (Hamilton)
    pos_x, pos_y = radius * np.sin(psi), radius * (1 - np.cos(psi))
    log = {
        "t": t,
        "omega": 1.0,
        "gravity": gravity,
        "vx": speed * np.cos(psi),
        "vy": speed * np.sin(psi),
        "vz": 0 * t,
        "x": pos_x,
        "y": pos_y,
        "x_ref": pos_x,
        "y_ref": pos_y,
        "quat": quat,
    }
    return log, bank


def test_turn_series_finds_the_coordinated_bank_of_an_ideal_circle():
    """Every wingbeat's mean bank equals atan(a_c / g) of the path to 0.05 degree (the
    wingbeat-mean velocity of a circle is shorter than V by the chord factor
    sin(d/2)/(d/2), d = 0.126 rad a wingbeat: 7e-4 of the bank, 0.01 degree here), the
    sideslip is 0, the heading turns V T / R, and every wingbeat but the first and last
    is steady (constant turn rate)."""
    log, bank = _ideal_circle()
    s = turn_series(log)
    assert s is not None and len(s["t_beats"]) == 12
    assert np.degrees(np.abs(s["bank"] - bank)).max() < 1e-6
    assert np.degrees(np.abs(s["coordinated"] - bank)).max() < 0.05
    assert np.degrees(np.abs(s["sideslip"])).max() < 1e-6
    assert s["steady"][1:-1].all() and not s["steady"][[0, -1]].any()
    f = turn_figures(log)
    assert f["steady_bank_error_max_deg"] < 0.05
    assert f["steady_bank_deg"] == pytest.approx(math.degrees(bank), abs=1e-6)


def test_turn_series_is_none_for_a_straight_flight():
    log, _ = _ideal_circle()
    log["y_ref"] = 0 * log["y_ref"]
    assert turn_series(log) is None and turn_figures(log) is None


def test_turns_figure_draws_both_rows(tmp_path):
    """The figure: a ground track and a bank panel per flight, saved as a PNG."""
    from birdsim.report.fig_turns import turns_figure
    from birdsim.report.plot_base import save_png

    log, _ = _ideal_circle()
    info = {"rms_error_after_start": 0.0}
    fig = turns_figure({"ideal": (log, info, turn_series(log))})
    assert len(fig.axes) == 2
    assert [len(ax.lines) for ax in fig.axes] == [3, 4]  # ref, flown, start; bank, atan, steady, 0
    path = save_png(fig, tmp_path / "t.png")
    assert path.stat().st_size > 10_000
