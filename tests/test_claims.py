"""The dissertation's statements as data (birdsim/report/claims.py, sweep_claims.py):
every example has its registered check, a check is registered once, and the checks
read our numbers (a changed number changes the verdict)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from birdsim import evaluate_cycle
from birdsim.physics.examples import EXAMPLES
from birdsim.report import figdata as fd
from birdsim.report.claims import HISTORY, ClaimRegistry, HistoryView, history_claims
from birdsim.report.records import Claim
from birdsim.report.sweep_claims import SWEEP, sweep_claims


def _cycles(n: int = 32) -> dict:
    return {
        ex.equation: evaluate_cycle(ex.model, ex.params, ex.speed, n=n, check_bounds=False)
        for ex in EXAMPLES
    }


def test_every_example_has_one_registered_check() -> None:
    assert HISTORY.keys() == [ex.equation for ex in EXAMPLES]
    cyc = _cycles()
    for ex in EXAMPLES:
        said, claims = history_claims(ex.equation, cyc[ex.equation], cyc)
        assert said.startswith(f"Fig {ex.figure}:"), (ex.equation, said)
        assert claims and all(isinstance(c, Claim) and c.statement and c.ours for c in claims)
    assert history_claims(1, cyc[57], cyc) == ("", [])  # no printed statement, no claims


def test_a_key_is_registered_once() -> None:
    reg = ClaimRegistry("test")
    reg.add("a", "said")(lambda: [])
    with pytest.raises(ValueError, match="registered twice"):
        reg.add("a", "again")(lambda: [])
    assert reg.said("a") == "said" and reg.said("b") == "" and reg.check("b") == ("", [])


def test_claims_follow_the_numbers() -> None:
    """Eq. 57 (base hover): no net Fx holds on our cycle; add a constant horizontal force
    (as a body drag) and the same statement fails."""
    cyc = _cycles()
    c = cyc[57]
    _, claims = history_claims(57, c, cyc)
    by = {cl.statement: cl.holds for cl in claims}
    assert by == {
        "Fz is negative (upward) over the whole cycle": True,
        "net upward force": True,
        "no net Fx": True,
    }
    shifted = replace(c, body_drag_x=np.asarray(c.body_drag_x) + 0.01)
    _, claims2 = history_claims(57, shifted, cyc)
    assert float(shifted.mean.Fx) == pytest.approx(float(c.mean.Fx) + 0.01, abs=1e-12)
    assert {cl.statement: cl.holds for cl in claims2} == {**by, "no net Fx": False}


def test_history_view_downstroke_is_half_the_cycle() -> None:
    h = HistoryView.of(_cycles(16)[57])
    # phases 0, 1/16, ..., 15/16: [0, 0.25) and [0.75, 1) hold 4 + 4 samples
    assert h.down.sum() == 8 and h.down[0] and not h.down[4] and h.down[12]


def test_sweep_checks_by_model() -> None:
    assert set(SWEEP.keys()) <= {"base", "m1", "m2", "m3", "m4"}
    speeds = np.array([0.0, 0.5, 1.0])
    names = ("pitch", "flap_amp", "twist_amp")
    params = np.array([[1.2, 1.5, 0.785], [0.6, 1.0, 0.4], [0.1, 0.8, 0.05]])
    fwd = fd.SpeedSweep(
        model="base",
        direction="forward",
        speeds=speeds,
        param_names=names,
        params=params,
        cost=np.zeros(3),
        fractions=np.zeros((3, 4)),
        achieved=np.zeros((3, 2)),
    )
    said, claims = sweep_claims("base", fwd, replace(fwd, direction="backward"), None)
    assert said.startswith("Figs 35/38")
    by = {c.statement: c.holds for c in claims}
    assert by["pitch falls with speed"] and by["almost no twist at V = 1"]
    assert by["forward and backward passes agree at V = 0 and V = 1"]
    _, claims = sweep_claims(
        "base", fwd, replace(fwd, params=params + 0.1, direction="backward"), None
    )
    assert not {c.statement: c.holds for c in claims}[
        "forward and backward passes agree at V = 0 and V = 1"
    ]
    assert sweep_claims("m2", fwd, fwd, None) == ("", [])
