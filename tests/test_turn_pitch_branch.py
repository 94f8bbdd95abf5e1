"""`scripts/turn_pitch_branch.py` (docs/turning.md, "The pigeon's cruise circle: what the
5.3-wingbeat pitch swing is", 2026-12-03): one row per pitch offset about the command,
the held pitch in degrees and each measurement at that pitch."""

from __future__ import annotations

import math

import pytest
from script_module import SCRIPTS, load_script

from birdsim.flight import attitude_stiffness, pitch_rocking


def test_each_row_holds_the_body_at_the_command_plus_its_offset(monkeypatch):
    branch = load_script("turn_pitch_branch")
    seen = []

    def rocking(fb, params, pitch, speed, inertia):
        seen.append((pitch, speed, inertia))
        return 2.0 * pitch, 0.01

    monkeypatch.setattr(pitch_rocking, "rocking_pitch_moment", rocking)
    monkeypatch.setattr(attitude_stiffness, "measured_pitch_stiffness", lambda *a: -3.0)
    monkeypatch.setattr(attitude_stiffness, "_mean_moment", lambda fb, p, th, v: (0.0, th, 0.0))
    rows = branch.branch_rows(None, None, 0.5, 0.4, 0.78)
    assert len(rows) == len(branch.OFFSETS) and 0.0 in branch.OFFSETS
    for (deg, m, ptp, m0, k), dp in zip(rows, branch.OFFSETS):
        assert deg == pytest.approx(math.degrees(0.5 + dp), rel=1e-15)
        assert m == pytest.approx(2.0 * (0.5 + dp)) and m0 == pytest.approx(0.5 + dp)
        assert ptp == pytest.approx(math.degrees(0.01)) and k == -3.0
    assert [s[1:] for s in seen] == [(0.4, 0.78)] * len(branch.OFFSETS)


def test_an_unknown_preset_is_refused_in_one_line(monkeypatch, capsys):
    branch = load_script("turn_pitch_branch")
    monkeypatch.syspath_prepend(str(SCRIPTS))  # main() imports its sibling when it runs
    monkeypatch.setattr("sys.argv", ["turn_pitch_branch.py", "loop"])
    with pytest.raises(SystemExit) as stop:
        branch.main()
    assert stop.value.code == 2
    assert "invalid choice: 'loop'" in capsys.readouterr().err
