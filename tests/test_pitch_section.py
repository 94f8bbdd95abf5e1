"""The slow straight flight's pitch loop on stroboscopic samples
(birdsim.flight.pitch_section; docs/free-body.md, "The pigeon's attitude, seventh stage").

1. The discrete map and the gain: the closed loop ``Phi - Gamma K`` has the placed
   eigenvalues (to 1e-6).
2. On a synthetic body whose wingbeat-mean pitch follows the loop's model (plus a moment
   bias the model does not know) and whose rocking (three harmonics, 0.12 rad) grows and
   shrinks by 15 % at a third of the wingbeat frequency, the loop, started 0.2 rad off the
   command, brings the mean within 0.015 rad of it from wingbeat 8 on (measured 0.0078),
   its estimate of the mean within 0.02 rad RMS (measured 0.011; the one-wingbeat fit's
   0.0093: the four samples' rate, which carries the estimate over their lag, leaks the
   modulation about as much as the fit does, docs/free-body.md).
3. The gate (eighth stage): the loop is entered below ``SLOW_SPEED`` only, and once on it
   stays on above it while the tail has no pitch stiffness; it is left when the
   stiffness appears.
4. The pigeon's free hover (m3, its bird file): measured 1.56 degrees RMS wingbeat-mean
   pitch error after two wingbeats and 0.0175 m path RMS (the code before the seventh
   stage: 3.15 and 0.0210); since the ninth stage's trim (the hover's command 70 instead
   of 65 degrees, its path 0.0069 m) 2.79 degrees; asserted below the issue's 3 degrees
   and 0.020 m (both fail on the code before the seventh stage).  Its take-off:
   measured 7.99 degrees and 0.0127 m with the eighth stage's gate (before it 10.1 and
   0.0128; since the ninth stage 7.79 and 0.0133); asserted below 9 degrees (fails on the
   code before the eighth stage) and 0.025 m.  No attitude-saturated sample, the root's applied force exactly zero.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from birdsim.flight.attitude_jacobians import INPUTS
from birdsim.flight.body_attitude import wingbeat_fit_matrix
from birdsim.flight.pitch_observer import SLOW_SPEED
from birdsim.flight.pitch_section import SectionPitch, placed_gain, section_map
from birdsim.mujoco.sites import pitch_quat

TWO_PI = 2.0 * math.pi


def test_the_placed_gain_places_the_closed_loop_poles():
    phi, gam = section_map(0.78, 0.01, 0.049, TWO_PI / 8, 0.125 * TWO_PI)
    poles = [0.9, 0.9, 0.9, 0.5, 0.5]
    k = placed_gain(phi, gam, poles)
    got = np.sort(np.abs(np.linalg.eigvals(phi - np.outer(gam, k))))
    assert np.allclose(got, np.sort(poles), atol=1e-4), got
    assert np.allclose(np.poly(phi - np.outer(gam, k)), np.poly(poles), atol=1e-6)


def test_the_section_rejects_a_modulated_rocking_and_holds_the_command():
    per_beat, ctl = 64, 8
    dt, n_in = TWO_PI / per_beat, len(INPUTS)
    dih = [name for name, _, _ in INPUTS].index("dihedral")
    jac = np.zeros((3, n_in))
    jac[1, dih] = -0.2
    att = SimpleNamespace(
        inertia=np.ones(3), stiffness=np.zeros(3), rate_jac=np.zeros((3, 3)),
        _jac=(0.0, np.zeros(3), jac, 0.0), u=np.zeros(n_in), integral=np.zeros(3),
        saturated=False, enabled=True, straight=True,
    )  # fmt: skip
    sec = SectionPitch(att, per_beat, TWO_PI / ctl)
    fit = wingbeat_fit_matrix(per_beat, TWO_PI)[0]
    a = math.exp(-dt / (0.125 * TWO_PI))  # the shoulders' two cascaded filters
    f1 = f2 = 0.0
    th, q, bias = 0.2, 0.0, 2e-4  # the mean starts 0.2 rad off; a bias the model lacks
    quats, rates, sec_err, fit_err, off = [], [], [], [], []

    def rocking(t: float) -> tuple[float, float]:
        amp = 0.12 * (1.0 + 0.15 * math.sin(t / 3.0))  # modulated at omega / 3
        s = math.sin(t) + 0.3 * math.sin(2 * t + 1.0) + 0.2 * math.sin(3 * t + 2.0)
        ds = math.cos(t) + 0.6 * math.cos(2 * t + 1.0) + 0.6 * math.cos(3 * t + 2.0)
        return amp * s, amp * ds + 0.12 * 0.15 * math.cos(t / 3.0) / 3.0 * s

    for k in range(12 * ctl):
        t0 = k * TWO_PI / ctl
        for i in range(1, per_beat // ctl + 1 if k else 1):  # the body over the step
            f1 = a * f1 + (1 - a) * att.u[dih]
            f2 = a * f2 + (1 - a) * f1
            acc = jac[1, dih] * f2 + bias
            th += dt * (q + 0.5 * dt * acc)
            q += dt * acc
            r, dr = rocking(t0 - TWO_PI / ctl + i * dt)
            quats.append(pitch_quat(th + r))
            rates.append((0.0, q + dr, 0.0))
        window = (np.array(quats[-per_beat:]), np.array(rates[-per_beat:]))
        out = sec.step(window, (0.0, 0.0, 0.0), 0.0)
        if out is not None:
            att.u[dih] = out[2] / jac[1, dih]
            if k >= 2 * ctl:
                sec_err.append(out[0] - th)
                theta = [-math.asin(2 * (w * y - x * z)) for w, x, y, z in window[0]]
                fit_err.append(float(fit @ np.array(theta)) - th)
            if k >= 8 * ctl:
                off.append(th)
    sec_rms = float(np.sqrt(np.mean(np.square(sec_err))))
    fit_rms = float(np.sqrt(np.mean(np.square(fit_err))))
    assert sec_rms < 0.02, (sec_rms, fit_rms)
    assert np.abs(off).max() < 0.015, np.abs(off).max()


def test_the_gate_enters_slow_and_holds_while_the_tail_has_no_stiffness():
    per_beat, ctl, n_in = 64, 8, len(INPUTS)
    jac = np.zeros((3, n_in))
    jac[1, [name for name, _, _ in INPUTS].index("dihedral")] = -0.2
    att = SimpleNamespace(
        inertia=np.ones(3), stiffness=np.zeros(3), rate_jac=np.zeros((3, 3)),
        _jac=(0.0, np.zeros(3), jac, 0.1),  # measured at the command, as flights do
        u=np.zeros(n_in), integral=np.zeros(3),
        saturated=False, enabled=True, straight=True,
    )  # fmt: skip
    window = (np.array([pitch_quat(0.1)] * per_beat), np.zeros((per_beat, 3)))
    sec = SectionPitch(att, per_beat, TWO_PI / ctl)
    run = lambda v: sec.step(window, (0.1, 0.0, 0.0), v) is not None  # noqa: E731
    fast, slow = SLOW_SPEED + 0.2, SLOW_SPEED - 0.05
    assert not run(fast)  # not entered above SLOW_SPEED
    assert run(slow) and run(fast) and run(fast)  # entered below it, kept above it
    att.stiffness = np.array([0.0, 0.01, 0.0])  # the tail restores: left
    assert not run(fast)
    att.stiffness = np.zeros(3)
    assert not run(fast)  # not entered again above SLOW_SPEED
    assert run(slow)
    att.stiffness = np.array([0.0, 0.01, 0.0])
    assert not run(slow)  # no stiffness from the tail below SLOW_SPEED either


@pytest.mark.slow  # ~10 s each on this machine, with the table's load
@pytest.mark.parametrize(
    "preset,pitch_max,path_max", [("hover", 3.0, 0.020), ("take-off", 9.0, 0.025)]
)
def test_pigeon_slow_flight_pitch_on_the_section(preset, pitch_max, path_max):
    from birdsim.commands.fly import load_table_for
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import fly
    from birdsim.flight.presets import PATH_PRESETS
    from birdsim.flight.simulate import SimConfig
    from birdsim.physics.bird import Bird

    bird = Bird.from_toml("models/pigeon.toml")
    table = load_table_for(bird, "m3", None)
    r = fly(PATH_PRESETS[preset], table, bird, "m3", config=SimConfig(attitude="free"))
    a = r.arrays
    n = 64
    beats = len(a["t"]) // n
    mean = lambda k: np.array([a[k][b * n : (b + 1) * n].mean() for b in range(beats)])  # noqa: E731
    err = (mean("pitch") - mean("pitch_command"))[2:]
    assert math.degrees(np.sqrt(np.mean(err**2))) < pitch_max
    assert summary(log_arrays(r, preset))["rms_error_after_start"] < path_max
    assert not np.any(a["attitude_saturated"])
    assert r.meta["root_applied_max"] == 0.0
