"""The smoothness measure (zig-zag share, largest jumps, worst places) on hand-made
arrays, and the targets of the smooth-tables issue on the shipped tables."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from birdsim.tables.lookup import load_table
from birdsim.tables.smoothness import ZIGZAG_RAD, measure, table_smoothness

TABLES = Path(__file__).resolve().parent.parent / "tables"
BEFORE = Path(__file__).resolve().parent / "data" / "tables_before_smoothing.npz"
MODELS = ("base", "m1", "m2", "m3", "m4")
NAMES = ("pitch", "flap_amp")
M4 = ("pitch", "flap_amp", "twist_amp", "stroke_plane", "wrist_amp", "wrist_bias", "wrist_lag")


def axes(*shape):
    return {a: np.arange(n, dtype=float) for a, n in zip(("Fx", "Fz", "V"), shape)}


def test_one_zigzag_along_one_axis_is_counted_once_and_located():
    X = np.zeros((5, 2, 2, 2))
    X[2, 1, 0, 1] = 0.2  # out (0.2 > 0.15) and back, along Fx only
    ok = np.ones(X.shape[:-1], dtype=bool)
    s = measure(NAMES, axes(5, 2, 2), X, ok)
    # triples: along Fx 3 x (2 x 2) = 12; along Fz and V none (2 nodes)
    assert (s.triples, s.zigzag_triples) == (12, 1) and s.zigzag_share == pytest.approx(1 / 12)
    assert s.per_axis == {"Fx": pytest.approx(1 / 12), "Fz": 0.0, "V": 0.0}
    assert s.largest_jump == {"pitch": 0.0, "flap_amp": pytest.approx(0.2)}
    assert s.worst[0] | {} == {
        "size_rad": 0.2,
        "axis": "Fx",
        "param": "flap_amp",
        "cell": [2, 1, 0],
        "Fx": 2.0,
        "Fz": 1.0,
        "V": 0.0,
    }


@pytest.mark.parametrize("middle, zig", [(0.2, True), (0.15, False), (-0.2, True), (0.1, False)])
def test_the_threshold_and_the_sign(middle, zig):
    X = np.zeros((3, 1, 1, 2))
    X[1, 0, 0, 0] = middle
    s = measure(NAMES, axes(3, 1, 1), X, np.ones((3, 1, 1), bool))
    assert s.zigzag_triples == int(zig)
    assert ZIGZAG_RAD == 0.15


def test_a_ramp_and_a_step_are_not_zigzags_and_unreachable_triples_are_skipped():
    X = np.zeros((4, 1, 1, 2))
    X[:, 0, 0, 0] = [0.0, 0.5, 1.0, 1.5]  # a ramp: steps of 0.5 but no out-and-back
    X[:, 0, 0, 1] = [0.0, 0.0, 1.0, 1.0]  # a step
    s = measure(NAMES, axes(4, 1, 1), X, np.ones((4, 1, 1), bool))
    assert s.zigzag_triples == 0 and s.triples == 2 and s.largest_jump["flap_amp"] == 1.0
    X[2, 0, 0, 0] = 0.0  # 0, 0.5, 0, 1.5: two zig-zags ...
    assert measure(NAMES, axes(4, 1, 1), X, np.ones((4, 1, 1), bool)).zigzag_triples == 2
    ok = np.array([True, True, True, False]).reshape(4, 1, 1)  # ... one of them reachable
    s = measure(NAMES, axes(4, 1, 1), X, ok)
    assert (s.triples, s.zigzag_triples) == (1, 1)


def test_the_lag_of_an_idle_wrist_is_skipped():
    X = np.zeros((3, 1, 1, 7))
    X[:, 0, 0, 6] = [0.0, 1.5, 0.0]  # the lag zig-zags ...
    X[:, 0, 0, 4] = [0.3, 0.0, 0.3]  # ... where the middle wrist is idle: no effect
    ok = np.ones((3, 1, 1), bool)
    s = measure(M4, axes(3, 1, 1), X, ok)
    assert s.worst[0]["param"] == "wrist_amp" and s.largest_jump["wrist_lag"] == 0.0
    X[:, 0, 0, 4] = [0.3, 0.3, 0.3]  # an active wrist: the lag counts
    s = measure(M4, axes(3, 1, 1), X, ok)
    assert (
        s.zigzag_triples == 1
        and s.worst[0]["param"] == "wrist_lag"
        and s.largest_jump["wrist_lag"] == 1.5
    )


# ---- the shipped tables (issue: smooth tables) -------------------------------------------------


@pytest.mark.parametrize("model", MODELS)
def test_shipped_tables_are_smooth_and_cost_no_more_than_before(model):
    """Targets: zig-zag share <= 2 %; the mean cost over the cells reachable before the
    regularising pass is at most 1e-3 higher than in the tables built without it
    (tests/data/tables_before_smoothing.npz: their cost and status arrays); no reachable
    cell became unreachable."""
    t = load_table(TABLES / f"{model}.npz")
    s = table_smoothness(t)
    assert s.zigzag_share <= 0.02, (model, s.zigzag_share, s.worst)
    with np.load(BEFORE) as z:
        cost0, ok0 = z[f"{model}_cost"], z[f"{model}_status_code"] == 0
    assert ok0.sum() > 250  # the fixture is the real thing (m4: 296 reachable cells)
    assert np.all(t.status[ok0] == "ok")
    assert t.cost[ok0].mean() - cost0[ok0].mean() <= 1e-3
    tol = t.meta["solver"]["smooth_tol"]
    # per cell: within the stated tolerance of the best found (the cells the pass kept
    # are at most as costly as before; 1e-6: the n = 32 search vs the n = 64 check)
    assert np.max(t.cost[ok0] - cost0[ok0]) <= tol + 1e-6


def test_the_pigeons_m5_flight_table_is_smooth():
    """Issue 24: the pigeon's m5 flight table within 2 % zig-zags (1.3 % as built with m5's
    flap bound pi/2), on a grid mostly reachable (5618 of 6069 cells), so the share is not
    taken over a handful of triples."""
    t = load_table(TABLES / "pigeon-m5.npz")
    s = table_smoothness(t)
    assert s.triples > 10000 and s.zigzag_share <= 0.02, (s.triples, s.zigzag_share, s.worst)


def test_the_seed_birds_m5_table_is_smooth():
    """Issue 24: 2 %.  The table built with the incidence tie-break (w_q 1e-4), a smoothing
    tolerance of 0.03, the regularising pass to its fixed point and the plane moves holds
    1.71 % (29 of 1696 triples; docs/tables.md: at w_q 5e-5..2e-4 the same recipe gives
    2.2-3.3 %); the tables before it held 5.4 % (92) and 7.4 % (125 of 1693).  No reachable
    cell lost: 767 ok, and every cell within the tolerance of the table before it is
    checked by scripts/compare_tables.py (largest +2.46e-2, mean +2.9e-4)."""
    t = load_table(TABLES / "m5.npz")
    s = table_smoothness(t)
    assert int((t.status == "ok").sum()) >= 767
    assert s.triples > 1600 and s.zigzag_share <= 0.02, (s.zigzag_share, s.worst)
