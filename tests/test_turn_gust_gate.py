"""The cruise turn's side-gust gate (``birdsim.flight.turn_gust_gate`` in
``birdsim.flight.flown_lateral``; docs/turning.md, "Gust stage, thirteenth pass"): it
opens on a roll error beyond the calm turns' in a steady bank without an input on its
bound, stays :data:`TURN_CALM_STEPS` calm steps, takes back the lateral path integral it
held, and leaves slow turns and straight flight as they were."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

import birdsim.flight.flown_lateral as fl
import birdsim.flight.turn_gust_gate as tg
from birdsim.flight.attitude import LAT_INPUTS
from birdsim.flight.attitude_jacobians import INPUTS

TWO_PI = 2.0 * np.pi


def _track(ramp_from: float | None = None) -> SimpleNamespace:
    """A circle's plan: bank -0.7 rad, steady; or rolling in at 0.1 rad per wingbeat
    until reduced time ``ramp_from``."""

    def plan(t: float) -> tuple:
        rate = 0.1 / TWO_PI if ramp_from is not None and t < ramp_from else 0.0
        return (0.02 * t, 0.02, 0.0), (-0.7, rate, 0.0)

    return SimpleNamespace(bank_plan=plan)


def _att(cruise: bool = True) -> SimpleNamespace:
    u = np.zeros(len(INPUTS))
    u[LAT_INPUTS] = 0.2  # every lateral input off its bound
    return SimpleNamespace(enabled=True, straight=False, _jac=(), u=u, per_inertia=cruise)


def test_the_gust_gate_opens_in_a_steady_bank_beyond_the_calm_turns_roll():
    lo, hi = -np.ones(len(INPUTS)), np.ones(len(INPUTS))
    rolled = np.array([tg.GUST_ROLL_RAD + 0.01, 0.0, 0.0])
    t = 25.0 * TWO_PI
    # the seed bird's calm cruise turns where the plan is steady: roll error <= 0.039 rad
    assert 0.039 < tg.GUST_ROLL_RAD < fl.ENGAGE_ROLL_RAD
    assert tg.steady_bank(_track(), t)
    assert fl.FlownLateral(_track()).gate(_att(), lo, hi, -rolled, t)
    assert not fl.FlownLateral(_track()).gate(_att(), lo, hi, rolled * 0.5, t)
    # rolling in (the plan's bank moving within 1.5 wingbeats before now): not a gust
    rolling = _track(ramp_from=t - 1.0 * TWO_PI)
    assert not tg.steady_bank(rolling, t)
    assert not fl.FlownLateral(rolling).gate(_att(), lo, hi, rolled, t)
    assert not tg.steady_bank(rolling, t + 0.4 * TWO_PI)
    assert tg.steady_bank(rolling, t + 0.6 * TWO_PI)  # 1.5 wingbeats after the roll-in
    # a slow turn and straight flight keep the bounded gate only
    assert not fl.FlownLateral(_track()).gate(_att(cruise=False), lo, hi, rolled, t)
    assert not fl.FlownLateral(None).gate(_att(), lo, hi, rolled, t)


def test_the_gust_gate_stays_and_takes_back_the_lateral_integral():
    lo, hi = -np.ones(len(INPUTS)), np.ones(len(INPUTS))
    t, calm = 25.0 * TWO_PI, np.zeros(3)
    gate = fl.FlownLateral(_track())
    gate.lateral_integral[0] = 1.5  # what the path loop had summed before the gust
    assert gate.gate(_att(), lo, hi, np.array([0.08, 0.0, 0.0]), t)
    gate.lateral_integral[0] = 6.0  # the gust's offset summed meanwhile
    for _ in range(tg.TURN_CALM_STEPS - 1):
        assert gate.gate(_att(), lo, hi, calm, t)
    assert gate.lateral_integral[0] == 6.0
    assert not gate.gate(_att(), lo, hi, calm, t)
    assert gate.lateral_integral[0] == 1.5
    # a slow turn leaves after straight flight's calm steps and keeps its integral
    slow = fl.FlownLateral(_track())
    slow.engaged, slow.lateral_integral[0] = True, 6.0
    for _ in range(fl.CALM_STEPS - 1):
        assert slow.gate(_att(cruise=False), lo, hi, calm, t)
    assert not slow.gate(_att(cruise=False), lo, hi, calm, t)
    assert slow.lateral_integral[0] == 6.0


@pytest.mark.slow
def test_the_circle_gusts_the_bounded_gate_missed_come_back_nearer():
    """`birdsim fly circle --attitude free` with the gust from 25.875 (mirror; the
    bounded gate never engaged there: 16 gusts' worst, 0.229 over 60 wingbeats) and from
    25: the largest distance from the calm flight (semispans, 3-D) from 8 wingbeats after
    the gust to wingbeat 45.  Without the gust gate 0.229 / 0.184; with it 0.119 / 0.111
    (the target, 0.05, is not met)."""
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.freeflight import fly, parse_gust
    from birdsim.flight.simulate import SimConfig
    from birdsim.flight.turn_presets import TURN_PRESETS

    bird = load_bird(None)
    table = load_table_for(bird, "m3", None)
    cfg = SimConfig(attitude="free")
    circle, beats = TURN_PRESETS["circle"], 45.0
    calm = fly(circle, table, bird, "m3", config=cfg, beats=beats).arrays
    for start, side in ((25.875, -0.15), (25.0, 0.15)):
        gust = [parse_gust(f"{start}:1:0:{side}:0")]
        g = fly(circle, table, bird, "m3", config=cfg, beats=beats, gusts=gust).arrays
        n = min(len(calm["t"]), len(g["t"]))
        late = calm["t"][:n] / TWO_PI >= start + 8.0
        d = np.sqrt(sum((g[k][:n] - calm[k][:n]) ** 2 for k in ("x", "y", "z")))[late]
        assert late.any() and np.all(np.isfinite(d))
        assert d.max() < 0.15, (start, side, float(d.max()))
