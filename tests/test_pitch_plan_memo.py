"""The pitch plan's feed-forward (``pitch_plan.feedforward_pitch``): a step whose state
and pitch have an earlier step's bits takes that step's answer, the same bits as asking
the table again."""

from __future__ import annotations

import math

import numpy as np

from birdsim.commands.common import load_bird, load_table_for
from birdsim.flight.controller import Controller, gains_for
from birdsim.flight.path_file import get_flight
from birdsim.flight.pitch_plan import feedforward_pitch
from birdsim.physics.units import reduced_bird


def _asked(ctl: Controller, path, names: tuple, times: np.ndarray) -> list[float]:
    """The reference: every step asks the controller (three fixed-point steps from 0 at
    the first time, then one from the last pitch)."""
    i, zero, out, p = names.index("pitch"), np.zeros(2), [], 0.0
    for k, t in enumerate(times):
        for _ in range(3 if k == 0 else 1):
            p = float(ctl.command(path.state(float(t)), None, zero, p).params[i])
        out.append(p)
    return out


def test_feedforward_pitch_memo_is_asking_again(monkeypatch):
    """Cruise (constant velocity: most steps answered from memory) and take-off (the
    state changes: few): every value the reference's bits, and the cruise asks the
    controller far less often."""
    bird = load_bird(None)
    red = reduced_bird(bird)
    calls = []
    command = Controller.command

    def counted(self, *a, **k):
        calls.append(1)
        return command(self, *a, **k)

    for preset, fewer in (("cruise", True), ("take-off", False)):
        table = load_table_for(bird, "m3", None)
        ctl = Controller(table, red, gains_for(red))
        path = get_flight(preset)
        names = ctl.names
        times = np.arange(0.0, path.duration, math.pi / 2)
        calls.clear()
        monkeypatch.setattr(Controller, "command", counted)
        f = feedforward_pitch(ctl, path, names)
        got = [f(float(t)) for t in times]
        n_memo = len(calls)
        monkeypatch.setattr(Controller, "command", command)
        want = _asked(ctl, path, names, times)
        assert np.array(got).tobytes() == np.array(want).tobytes(), preset
        if fewer:
            assert n_memo < len(times) // 2
