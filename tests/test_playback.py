"""Playback: phase-continuous joint angles and rates from a demand schedule and a table."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.interpolate import RegularGridInterpolator

from birdsim import Bird, get_model
from birdsim.flight.manoeuvre import PRESETS, Keyframe, Manoeuvre
from birdsim.flight.playback import PlaybackConfig, TableMismatchError, frame_times, play
from birdsim.physics.kinematics import joint_states


class SmallTable:
    """A tiny table with LookupTable's interface: each parameter an affine function of
    the demands squeezed into its bounds (different per parameter, so every joint moves
    differently when the demands change)."""

    def __init__(self, model: str = "m4"):
        self.model = model
        km = get_model(model)
        self.param_names = km.param_names
        self.axes = {
            "Fx": np.linspace(-0.5, 0.5, 5),
            "Fz": np.linspace(-0.5, 0.0, 3),
            "V": np.linspace(0.0, 1.0, 5),
        }
        grids = np.meshgrid(*self.axes.values(), indexing="ij")
        lo, hi = km.bounds
        self._f = {}
        for i, p in enumerate(km.params):
            frac = np.clip(
                0.5 + 0.3 * np.sin(1 + i) * grids[0] - 0.6 * np.cos(i) * grids[1] - 0.3 * grids[2],
                0.0,
                1.0,
            )
            self._f[p.name] = RegularGridInterpolator(
                tuple(self.axes.values()), lo[i] + frac * (hi[i] - lo[i])
            )

    def lookup_many(self, Fx, Fz, V, clip=False):
        pts = np.stack(np.broadcast_arrays(Fx, Fz, V), axis=-1)
        return {k: f(pts) for k, f in self._f.items()}


def steady(Fx=0.0, Fz=-0.2, V=0.9, beats=4.0):
    return Manoeuvre("steady", (Keyframe(0.0, Fx, Fz, V, 6.0, "cruise"),), beats)


def step(before, after, t_step=2.0, width=1e-3, beats=6.0):
    """A step change of demand at ``t_step`` (a ramp ``width`` wingbeats wide)."""
    return Manoeuvre(
        "step",
        (
            Keyframe(0.0, *before, 6.0),
            Keyframe(t_step, *before, 6.0),
            Keyframe(t_step + width, *after, 6.0),
        ),
        beats,
    )


@pytest.mark.parametrize("model", ["base", "m1", "m2", "m3", "m4"])
def test_constant_demands_reproduce_the_analytic_wingbeat(model):
    """With constant parameters the playback is the model's own sinusoids, as in cycle."""
    table = SmallTable(model)
    bird = Bird()
    t = np.linspace(0, 3, 97)
    pb = play(steady(), table, t, bird=bird)
    params = {k: float(v[0]) for k, v in table.lookup_many([0.0], [-0.2], [0.9]).items()}
    states = joint_states(get_model(model), params, bird, bird.omega * pb.time, trailing=0)
    for name, st in states.items():
        # 1e-10: filter started in steady state and splines of a constant are exact; only rounding remains
        np.testing.assert_allclose(
            pb.angles[name],
            np.broadcast_to(st.angle, pb.time.shape),
            rtol=0,
            atol=1e-10,
            err_msg=name,
        )
        np.testing.assert_allclose(
            pb.rates[name], np.broadcast_to(st.rate, pb.time.shape), rtol=0, atol=1e-8, err_msg=name
        )
    np.testing.assert_allclose(pb.pitch, params["pitch"], rtol=0, atol=1e-10)
    np.testing.assert_allclose(pb.phase, bird.omega * pb.time, rtol=0, atol=0)


def _step_response(smoothing, model="m4"):
    dt_beats = 1.0 / 1000
    t = np.arange(0.0, 5.0, dt_beats)
    pb = play(
        step((0.0, -0.2, 0.9), (-0.5, -0.5, 0.1)),
        SmallTable(model),
        t,
        config=PlaybackConfig(smoothing_beats=smoothing),
    )
    return pb, dt_beats * pb.bird.period


def test_step_in_demand_keeps_angles_and_rates_continuous_and_consistent():
    pb, dt = _step_response(0.25)
    for name, q in pb.angles.items():
        qd = pb.rates[name]
        scale = max(np.max(np.abs(qd)), 1e-9)
        # rates are the derivative of the angles: central differences agree to O(dt^2);
        # dt = 2pi/1000, |q'''| <~ a few -> error <~ 1e-5 of the rate scale; 1e-3 leaves margin
        fd = (q[2:] - q[:-2]) / (2 * dt)
        assert np.max(np.abs(fd - qd[1:-1])) < 1e-3 * scale, name
        # no jump: per-step changes of angle and rate stay at the size of steady flapping
        # (|dq| <= max|q'| dt, |dq'| <= max|q''| dt with q'' <~ (1.5 omega)^2 x amplitude)
        assert np.max(np.abs(np.diff(q))) <= 1.01 * scale * dt, name
        assert np.max(np.abs(np.diff(qd))) <= 3.0 * max(np.ptp(q), 1e-9) * dt, name
    # the demand step really changed the wingbeat (else the test could not fail)
    i0, i1 = np.searchsorted(pb.t_beats, [1.5, 4.9])
    assert any(abs(v[i1] - v[i0]) > 0.05 for v in pb.params.values())
    assert pb.demand["Fx"][i0] == 0.0 and pb.demand["Fx"][i1] == -0.5


def test_without_smoothing_the_same_step_makes_the_rates_jump():
    """The continuity test above can fail: unsmoothed, the step shows as a rate spike."""
    pb, dt = _step_response(0.0)
    jumps = [
        np.max(np.abs(np.diff(pb.rates[n]))) / (max(np.ptp(q), 1e-9) * dt)
        for n, q in pb.angles.items()
    ]
    assert max(jumps) > 3.0


@pytest.mark.parametrize("name", list(PRESETS))
def test_presets_play_inside_bounds_and_along_the_implied_path(name):
    m = PRESETS[name]
    table = SmallTable("m4")
    t = frame_times(m.duration / 2.0, 24, 2.0)
    pb = play(m, table, t, perch_seed=(1.0, -2.5))
    lo, hi = pb.model.bounds
    for i, p in enumerate(pb.model.param_names):
        assert np.all(pb.params[p] >= lo[i] - 1e-12) and np.all(pb.params[p] <= hi[i] + 1e-12), p
    x = pb.position_seed[:, 0]
    # forward at V: dx/dt equals the (clipped) V, to the trapezoid error of this frame spacing
    dxdt = np.diff(x) / np.diff(pb.time)
    vmid = 0.5 * (pb.velocity_seed[1:, 0] + pb.velocity_seed[:-1, 0])
    np.testing.assert_allclose(dxdt, vmid, rtol=0, atol=2e-3)
    if m.perch == "start":
        assert x[0] == pytest.approx(1.0) and pb.position_seed[0, 2] == pytest.approx(-2.5)
    if name == "hover":
        assert np.ptp(x) == 0


def test_landing_ends_on_the_perch():
    m = PRESETS["landing"]
    pb = play(m, SmallTable(), [0.0, m.keyframes[-1].t, m.duration], perch_seed=(4.0, -2.5))
    np.testing.assert_allclose(pb.position_seed[1:], [[4.0, 0.0, -2.5]] * 2, atol=1e-9)
    assert pb.position_seed[0, 0] < -20  # it came from far away at cruise speed


def test_demands_beyond_the_grid_are_clipped_and_reported():
    m = steady(V=1.4)
    pb = play(m, SmallTable(), [0.0, 1.0])
    assert (
        np.all(pb.clipped) and np.all(pb.demand_used["V"] == 1.0) and np.all(pb.demand["V"] == 1.4)
    )
    assert "V=1.4 outside [0, 1]" in pb.clip_note
    assert play(steady(), SmallTable(), [0.0]).clip_note == ""


def test_table_for_another_model_is_refused():
    with pytest.raises(TableMismatchError, match="built for model 'm3', not 'm4'") as exc:
        play(steady(), SmallTable("m3"), [0.0], model="m4")
    assert "\n" not in str(exc.value)
