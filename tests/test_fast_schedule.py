"""Issue 27's control-update pieces made faster: the schedule's two filters compiled
(``fast_schedule``: bitwise the numpy filters), the allocation's unbounded solve compiled
(``bounded_lsq.kernel``: numba's ``lstsq``, the same LAPACK ``gelsd``), the aero
kernel's constants cached while the callback's switches and the tail's spread stay."""

from __future__ import annotations

import copy

import numpy as np
import pytest
from scipy.optimize import lsq_linear

from birdsim.flight import bounded_lsq, fast_schedule, fast_wingbeat
from birdsim.flight.simulate import FreeBird, SimConfig
from birdsim.mujoco import aero_kernel
from birdsim.mujoco.tail import TailControls
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model

BIRD = Bird.from_toml("models/seed-bird.toml")


def _params(model: str) -> np.ndarray:
    kin = get_model(model)
    guess = kin.guess("cruise")
    return np.array([guess[n] for n in kin.param_names])


@pytest.mark.parametrize("switch", ["fast_schedule", "fast_wingbeat"])
@pytest.mark.parametrize("model", ["m3", "m5"])
def test_compiled_filters_are_the_numpy_filters(monkeypatch, model, switch):
    """Bitwise: every row of the prescription and the filters' states after each
    control update, with the wings differing, a stroke-plane offset and shoulder
    offsets (a wrong operation order or a fused multiply-add shows in the last bit), and
    with both wings and no offset alike (the left wing's parameters None).  Switched:
    ``fast_schedule`` (on: the fused call, whose filters are fast_schedule's; off: the
    numpy filters) and ``fast_wingbeat`` (on: the fused call; off: fast_schedule's
    call, then ``wing_rows``')."""
    assert fast_schedule.kernel is not None and fast_wingbeat.kernel is not None
    module = {"fast_schedule": fast_schedule, "fast_wingbeat": fast_wingbeat}[switch]
    calls = {True: 0, False: 0}
    fused = fast_wingbeat.advance

    def counted(*a, **k):
        out = fused(*a, **k)
        calls[out is not None] += 1
        return out

    monkeypatch.setattr(fast_wingbeat, "advance", counted)
    params = _params(model)
    names = get_model(model).param_names
    left = params.copy()
    left[names.index("flap_amp")] -= 0.05
    offset = np.zeros(len(names))
    offset[names.index("stroke_plane")] = 0.02
    with FreeBird(model, BIRD, params, config=SimConfig(attitude="free")) as fb:
        out = {}
        for compiled in (True, False):
            monkeypatch.setattr(module, "ENABLED", compiled)
            sc = copy.deepcopy(fb.schedule)
            rows = []
            for k in range(6):
                sc.shoulder_target = np.array([0.05, -0.03]) * (k % 3)
                times = k * 0.8 + np.arange(16) * 0.05
                lft = None if k == 0 else left + 0.01 * k
                off = None if k < 2 else offset * k
                pres = sc.advance(params + 0.01 * k, times, k * 0.8, 0.8, lft, off)
                states = (sc.filter.x1, sc.filter.x2, sc.input_filter.x1, sc.input_filter.x2)
                rows.append((pres, tuple(s.copy() for s in states)))
            out[compiled] = rows
    for (a, sa), (b, sb) in zip(out[True], out[False]):
        for x, y in zip(
            (a.qpos, a.qvel, a.qacc, a.params, a.pitch), (b.qpos, b.qvel, b.qacc, b.params, b.pitch)
        ):
            assert np.array_equal(x, y)
        assert (a.params_left is None) == (b.params_left is None)
        if a.params_left is not None:
            assert np.array_equal(a.params_left, b.params_left)
        for x, y in zip(sa, sb):
            assert np.array_equal(x, y)
    assert not np.array_equal(out[True][1][0].qvel, out[True][2][0].qvel)
    assert calls[True] == 6 and calls[False] == 6  # the fused call ran, then did not
    assert out[True][0][0].params_left is None and out[True][1][0].params_left is not None


def test_compiled_allocation_solve_is_numpys():
    """The allocation's shapes ([J s; reg I], 1-2 moment rows, 2-4 inputs): within 1e-12
    of ``np.linalg.lstsq`` (measured bitwise on 15 000 such problems: the same gelsd);
    outside the bounds lsq_linear's answer; a non-finite input raises as numpy does."""
    assert bounded_lsq.kernel is not None
    rng = np.random.default_rng(11)
    same = 0
    for k in range(300):
        rows, cols = (1, 2) if k % 2 else (2, 4)
        a = np.vstack([rng.normal(size=(rows, cols)), rng.uniform(1e-6, 1e-2) * np.eye(cols)])
        b = np.concatenate([rng.normal(size=rows), np.zeros(cols)])
        ref = np.linalg.lstsq(a, b, rcond=-1)[0]
        bound = 2.0 * np.max(np.abs(ref))  # within the bounds: the unbounded solve
        x, mask = bounded_lsq.bounded_lsq(a, b, -bound * np.ones(cols), bound * np.ones(cols))
        np.testing.assert_allclose(x, ref, rtol=1e-12, atol=1e-300)
        assert not mask.any()
        same += np.array_equal(x, ref)
        lb, ub = -0.5 * bound * np.ones(cols), 0.5 * bound * np.ones(cols)
        x, mask = bounded_lsq.bounded_lsq(a, b, lb, ub)  # outside: lsq_linear's answer
        res = lsq_linear(a, b, bounds=(lb, ub))
        assert np.array_equal(x, res.x) and np.array_equal(mask, res.active_mask)
    assert same >= 290  # bitwise in practice
    a = np.array([[1.0, np.nan], [0.0, 1.0], [1.0, 0.0]])
    with pytest.raises(np.linalg.LinAlgError):
        bounded_lsq.bounded_lsq(a, np.ones(3), -np.ones(2), np.ones(2))


def test_aero_constants_follow_the_spread_and_switches():
    """The cached constants equal freshly made ones after the spread, the tail and the
    body drag change (the cache is keyed on them)."""
    with FreeBird("m4", BIRD, _params("m4"), config=SimConfig(attitude="free")) as fb:
        cb = fb.cb
        for spread, tail, drag in (
            (1.0, True, True),
            (0.6, True, True),
            (0.6, False, True),
            (0.6, True, False),
        ):
            cb.tail_controls = TailControls(0.1, spread, -0.05)
            cb.tail, cb.body_drag = tail, drag
            got = aero_kernel.parameters(cb)
            cb.__dict__.pop("_aero_constants")
            fresh = aero_kernel.parameters(cb)
            for x, y in zip(got, fresh):
                assert np.array_equal(x, y)
        assert aero_kernel.parameters(cb)[0] is aero_kernel.parameters(cb)[0]  # cached


def test_lookup_row_is_lookup_many():
    """Bitwise: the controller's one-row lookup against lookup_many's dict (random
    demands inside the grid and beyond its edges, clipped)."""
    from birdsim.tables.lookup import load_table

    table = load_table("tables/m4.npz")
    names = list(table.param_names) + ["achieved_Fx", "achieved_Fz", "achieved_P", "cost"]
    rng = np.random.default_rng(5)
    lo = [float(table.axes[a][0]) for a in table.axis_names]
    hi = [float(table.axes[a][-1]) for a in table.axis_names]
    for _ in range(200):
        fx, fz, v = (
            float(rng.uniform(a - 0.1 * (b - a), b + 0.1 * (b - a))) for a, b in zip(lo, hi)
        )
        row = table.lookup_row(fx, fz, v)
        raw = table.lookup_many(fx, fz, v, clip=True)
        assert np.array_equal(row, np.array([float(raw[n]) for n in names]))
    assert table.lookup_row(float("nan"), -0.1, 0.5) is None  # lookup_many refuses it


@pytest.mark.parametrize("per_beat", [4, 64, 200])
def test_compiled_error_estimate_is_numpys(monkeypatch, per_beat):
    """Bitwise: ErrorWindow.estimate with the compiled means (numpy's pairwise sum along
    the airspeed, row by row along the errors) against numpy's, window after window."""
    from birdsim.flight import fast_window
    from birdsim.flight.controller import ErrorWindow

    rng = np.random.default_rng(per_beat)
    windows = {on: ErrorWindow(per_beat, 2 * np.pi) for on in (True, False)}
    for _ in range(3 * per_beat):
        ep, ev, vx = rng.normal(size=2) * 1e-3, rng.normal(size=2) * 1e-2, 0.9 + 0.1 * rng.normal()
        got = {}
        for on, w in windows.items():
            w.add(ep, ev, vx)
            monkeypatch.setattr(fast_window, "ENABLED", on)
            got[on] = w.estimate()
        for a, b in zip(got[True], got[False]):
            assert np.array_equal(a, b)
    assert fast_window.estimate(windows[True]._rows, per_beat, per_beat, 0.1, 1.0) is None


def test_remembered_exponentials_are_computed_ones(monkeypatch):
    """``fast_schedule.exponentials`` answers a repeated argument set from its memo: the
    same bits as computing them (numpy's ``exp`` of the same quotients), a fresh set for
    a ``rel`` one bit away, and at most ``MEMO_SIZE`` sets kept."""
    rng = np.random.default_rng(2)
    monkeypatch.setattr(fast_schedule, "_EXPONENTIALS", {})
    for _ in range(200):
        rel = np.cumsum(np.full(16, rng.uniform(0.01, 0.1)))
        tau, sig, dt = rng.uniform(1.0, 20.0), rng.uniform(1.0, 20.0), float(rel[-1])
        first = fast_schedule.exponentials(tau, sig, rel, dt)
        again = fast_schedule.exponentials(tau, sig, rel.copy(), dt)
        assert all(a is b for a, b in zip(first, again))  # remembered
        want = np.exp(np.concatenate([-rel / tau, -rel / sig, [-dt / tau, -dt / sig]]))
        got = np.concatenate([first[0], first[1], [first[2], first[3]]])
        assert np.array_equal(got, want)  # bitwise numpy's
        near = rel.copy()
        near[3] = np.nextafter(near[3], 1.0)
        other = fast_schedule.exponentials(tau, sig, near, dt)
        assert other[0] is not first[0] and other[0][3] == np.exp(-near[3] / tau)
        assert len(fast_schedule._EXPONENTIALS) <= fast_schedule.MEMO_SIZE


def test_compiled_tail_frame_is_tail_frame():
    """The aero kernel's tail frame (``tail.frame_into`` compiled) is ``tail_frame`` of
    the clipped controls to the bit, signs of zeros included: random controls within and
    beyond the bounds, through ``aero_kernel.parameters`` of a bird's callback."""
    from birdsim.mujoco.tail import frame_into, tail_frame

    assert aero_kernel.frame_kernel is not None
    rng = np.random.default_rng(4)
    out, ref = np.empty((3, 3)), np.empty((3, 3))
    for e, r in rng.uniform(-0.7, 0.7, (5000, 2)):
        aero_kernel.frame_kernel(float(e), float(r), out)
        frame_into(float(e), float(r), ref)
        assert np.array_equal(out, ref) and np.array_equal(np.signbit(out), np.signbit(ref))
    with FreeBird("m4", BIRD, _params("m4"), config=SimConfig(attitude="free")) as fb:
        for e, s, r in rng.uniform(-1.0, 1.2, (200, 3)):
            fb.cb.tail_controls = TailControls(float(e), float(s), float(r))
            frame = aero_kernel.parameters(fb.cb)[2]
            want = tail_frame(fb.cb.tail_controls.clipped())
            assert np.array_equal(frame, want)
            assert np.array_equal(np.signbit(frame), np.signbit(want))
