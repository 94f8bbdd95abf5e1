"""Issue 27: the attitude loop's held-body pose compiled (``fast_hold``: MuJoCo's position
and velocity stages and the aero kernel in one numba call) gives the Python callback's
numbers bit for bit: the Jacobian and rate-derivative measurements of m4 and m5 (its
folding hand) with the tail deflected, a body rate and a wind, and the callback's tail
state after them; with the switch off the reference runs."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from birdsim.flight import fast_hold
from birdsim.flight.attitude_jacobians import (
    _hold,
    measured_jacobian,
    measured_rate_derivatives,
    measured_with_rocking,
)
from birdsim.flight.simulate import FreeBird, SimConfig
from birdsim.mujoco.model import pitch_quat
from birdsim.mujoco.tail import TailControls
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model

BIRD = Bird.from_toml("models/seed-bird.toml")
pytestmark = pytest.mark.skipif(fast_hold.kernel is None, reason="numba missing")


def _measure(fb, params, compiled: bool, monkeypatch) -> list:
    monkeypatch.setattr(fast_hold, "ENABLED", compiled)
    calls = [0]
    hold = fast_hold.hold

    def counted(*a, **k):
        done = hold(*a, **k)
        calls[0] += done
        return done

    monkeypatch.setattr(fast_hold, "hold", counted)
    rows = fast_hold.hold_rows

    def counted_rows(m, d, qpos, *a, **k):  # every pose of a compiled loop counted
        done = rows(m, d, qpos, *a, **k)
        calls[0] += done * len(qpos)
        return done

    monkeypatch.setattr(fast_hold, "hold_rows", counted_rows)
    fb.cb.tail_controls = TailControls(0.1, 0.8, -0.05)
    omega = np.array([0.02, -0.01, 0.03])
    m0, jac = measured_jacobian(fb, params, 0.1, 0.9, omega)
    rate = measured_rate_derivatives(fb, params, 0.1, 0.9)
    fb.m.opt.wind[:] = (0.05, 0.02, -0.03)  # a wind: _hold itself under it
    d = fb._jac_data
    _hold(fb.m, d, fb.d.qpos, fb.d.qvel, pitch_quat(0.2), 0.8, omega)
    fb.m.opt.wind[:] = 0.0
    monkeypatch.setattr(fast_hold, "hold", hold)
    monkeypatch.setattr(fast_hold, "hold_rows", rows)
    assert (calls[0] > 100) == compiled
    return [m0, jac, rate, d.qfrc_passive.copy(), fb.cb.tail_force_body, fb.cb.tail_alpha]


@pytest.mark.parametrize("model", ["m4", "m5"])
def test_compiled_hold_is_the_callback(model, monkeypatch):
    kin = get_model(model)
    guess = kin.guess("cruise")
    params = np.array([guess[n] for n in kin.param_names])
    out = {}
    for compiled in (True, False):
        with FreeBird(model, BIRD, params, config=SimConfig(attitude="free")) as fb:
            assert mujoco.get_mjcb_passive() is fb.cb
            out[compiled] = _measure(fb, params, compiled, monkeypatch)
    for a, b in zip(out[True], out[False]):
        assert np.array_equal(a, b), (a, b)  # bitwise
    assert np.any(out[False][3] != 0.0) and out[False][5] != 0.0  # forces, a tail angle


@pytest.mark.parametrize("model", ["m4", "m5"])
def test_compiled_rows_are_the_held_loop(model, monkeypatch):
    """The rocking measurement's loop of held poses (moment and the wings' relative
    angular momentum per pose, ``mj_mulM`` called from numba) in one compiled call:
    bitwise the reference's loop, the callback's tail state and call count as it leaves
    them."""
    kin = get_model(model)
    guess = kin.guess("cruise")
    params = np.array([guess[n] for n in kin.param_names])
    out, rows, used = {}, fast_hold.hold_rows, [0]

    def counted(*a, **k):
        done = rows(*a, **k)
        used[0] += done
        return done

    monkeypatch.setattr(fast_hold, "hold_rows", counted)
    for compiled in (True, False):
        monkeypatch.setattr(fast_hold, "ENABLED", compiled)
        used[0] = 0
        with FreeBird(model, BIRD, params, config=SimConfig(attitude="free")) as fb:
            fb.cb.tail_controls = TailControls(0.1, 0.8, -0.05)
            inertia = np.array([0.3, 0.5, 0.7])
            got = measured_with_rocking(fb, params, 0.1, 0.9, inertia, np.array([0.02, 0, 0.03]))
            out[compiled] = [*got, fb.cb.tail_force_body, fb.cb.tail_alpha, fb.cb.calls]
        assert (used[0] > 0) == compiled
    for a, b in zip(out[True], out[False]):
        assert np.array_equal(a, b), (a, b)  # bitwise
