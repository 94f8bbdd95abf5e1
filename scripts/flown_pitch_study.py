"""The pitch inputs chosen on the free, rocking body's own prediction (docs/free-body.md,
"the landing: a pitch plant from the flown state"; a study, not the flight code).

At a control step the flight's state (the MjData, the bird's momenta, the schedule's
filters, the tail) is copied, flown on for :data:`WINDOW` ``[1]`` wingbeats with the
inputs held (the table's wingbeat, the stroke plane's compensation and the wind as the
next interval has them), and put back bit for bit (:func:`restored`).  Modes:

* ``ratio``: every ``--every`` control steps the shoulders' (sweep, dihedral) flown effect
  on the mean pitch over the window's part ``WINDOW`` (a step of ``STEP`` rad) over the
  loop's wingbeat-mean model's (``pitch_input_probe.model_response``, the held
  Jacobian): the loop's pitch row for each is the held one times that ratio.
* ``mpc``: the shoulders (and with ``--tail`` the tail's elevation) chosen every
  ``--every`` steps so that the predicted mean pitch over the window's part meets the
  command's (its rate and acceleration carried) up to ``--alpha`` of the miss; the
  sensitivities measured by one more prediction per input; ``--anchor held`` predicts
  with the inputs last chosen (the loop's shoulders unused), ``loop`` with the loop's of
  this step and the least change from them (weight ``--mu``, the inputs scaled by their
  bounds); ``--gate`` limits it (``stiff0``: where the tail has no pitch stiffness;
  ``deadzone``: only a predicted miss beyond ``--deadzone`` degrees is corrected, and
  only while the loop's estimated error is beyond it; ``tailrange``: entered where the
  loop counts on the tail's stiffness, the tail has air (above ``SLOW_SPEED``) and the
  body's estimated pitch less the air path's angle puts the tail beyond ``ALPHA_MAX``,
  left after ``--calm`` control steps with the stiffness back and the body in range).

    PYTHONPATH=$PWD python scripts/flown_pitch_study.py --preset landing
        [--bird models/pigeon.toml | --bird ""] [--mode mpc] [--every 2] [--anchor held]
        [--tail] [--mu 0] [--alpha 0.3] [--gate all] [--deadzone 3] [--calm 1]
        [--window 0.25 1] [--clip -10 10] [--inertia-scale 1] [--off] [--identity 16]
"""

from __future__ import annotations

import argparse
import dataclasses
import math

import numpy as np
from pitch_input_probe import model_response

import birdsim.flight.freeflight as freeflight_mod
from birdsim.commands.fly import load_table_for
from birdsim.flight import attitude as attitude_mod
from birdsim.flight import flown_pitch
from birdsim.flight.attitude_jacobians import INPUTS
from birdsim.flight.attitude_pitch import _lsq
from birdsim.flight.attitude_summary import attitude_figures, unfolded_euler
from birdsim.flight.bounded_lsq import bounded_lsq
from birdsim.flight.flightlog import log_arrays, summary
from birdsim.flight.flown_pitch import DIHEDRAL, STEP, SWEEP, TAIL, WINDOW
from birdsim.flight.flown_prediction import SAMPLES, nose_up, predict
from birdsim.flight.pitch_section import SLOW_SPEED
from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS, demo_bird
from birdsim.flight.simulate import SimConfig
from birdsim.mujoco.tail import ALPHA_MAX, TailControls
from birdsim.physics.bird import Bird


class Study:
    """One flight's predictive pitch (see the module); ``opts`` the parsed options."""

    def __init__(self, opts) -> None:
        self.o = opts
        self.count = 0
        self.ratio = np.ones(len(INPUTS))
        self.held: np.ndarray | None = None
        self.engaged = False
        self.calm = 0
        self.log: list = []

    def _times(self, fb, n: int) -> tuple[np.ndarray, np.ndarray]:
        t = np.arange(n) * (fb.red.period / SAMPLES)
        return t, t >= self.o.window[0] * fb.red.period - 1e-9

    def ratios(self, att, fb, args, shoulder, tail) -> None:
        """The shoulders' flown / model ratios into ``ratio`` (mode ``ratio``)."""
        base = predict(fb, args, shoulder, tail, self.o.window[1])[1]
        t, last = self._times(fb, len(base))
        damping, k = float(att.rate_jac[1, 1]), -float(att.stiffness[1])
        unit = float(model_response(t, 1.0, damping, k, float(att.inertia[1]))[last].mean())
        row = [fb.time / fb.red.period]
        for i, j in ((SWEEP, 0), (DIHEDRAL, 1)):
            moved = np.array(shoulder, dtype=float)
            moved[j] += STEP
            q = predict(fb, args, moved, tail, self.o.window[1])[1]
            flown = float(nose_up(q, base)[last].mean())
            model = unit * float(att._jac[2][1, i]) * STEP
            r = flown / model if abs(model) > 1e-12 else 1.0
            self.ratio[i] = min(max(r, self.o.clip[0]), self.o.clip[1])
            row.append(r)
        self.log.append(row)

    def choose(self, att, fb, args, shoulder, tail, ref3, params, err_pitch):
        """(shoulder, tail) of this control step (mode ``mpc``)."""
        o = self.o
        on = att.straight and att._jac is not None
        if on and o.gate == "stiff0":
            on = att.stiffness[1] <= 0.0
        if on and o.gate == "tailrange":  # in: the body left the tail's range the loop
            v = fb.d.qvel  # counts on; out: the command's stiffness back, body within it
            air = (float(v[0] - fb.m.opt.wind[0]), float(v[2] - fb.m.opt.wind[2]))
            alpha = ref3[0] - err_pitch - math.atan2(air[1], air[0])
            out_of_range = alpha > ALPHA_MAX
            if not self.engaged:  # the tail has air (above slow flight's gate)
                fast = math.hypot(*air) > SLOW_SPEED
                self.engaged = att.stiffness[1] > 0.0 and out_of_range and fast
                self.calm = 0
            else:  # left after --calm control steps with the model holding again
                held = out_of_range or att.stiffness[1] <= 0.0
                self.calm = 0 if held else self.calm + 1
                self.engaged = self.calm < self.o.calm
            on = self.engaged
        dz = math.radians(o.deadzone) if o.gate == "deadzone" else 0.0
        if on and o.gate == "deadzone" and self.held is None:
            on = abs(err_pitch) > dz
        if not on:
            self.held = None
            return shoulder, tail
        k, self.count = self.count, self.count + 1
        if self.held is not None and k % o.every:
            return self._out(tail)
        lo, hi = att.bounds(params)
        idx = [SWEEP, DIHEDRAL, TAIL] if o.tail else [SWEEP, DIHEDRAL]
        prev = self.held if o.anchor == "held" else None
        x0 = np.array([*(shoulder if prev is None else prev[:2]),
                       *([tail.elevation if prev is None else prev[2]] if o.tail else [])])  # fmt: skip
        self._rs = (tail.spread, tail.roll)
        base = self._predict(fb, args, x0)
        t, last = self._times(fb, len(base))
        th0 = float(nose_up(base)[last].mean())
        ref = float(np.mean(ref3[0] + ref3[1] * t[last] + 0.5 * ref3[2] * t[last] ** 2))
        miss = ref - th0
        if abs(miss) <= dz:
            self.held = None
            return shoulder, tail
        miss -= math.copysign(dz, miss)
        sens = np.zeros(len(x0))
        for j in range(len(x0)):
            moved = x0.copy()
            moved[j] += STEP
            sens[j] = float(nose_up(self._predict(fb, args, moved), base)[last].mean()) / STEP
        if o.mu > 0.0:  # the least change from x0 (scaled by the bounds)
            s = (hi[idx] - lo[idx]) / 2
            a = np.vstack([sens * s, math.sqrt(o.mu) * np.eye(len(x0))])
            b = np.concatenate([[(1.0 - o.alpha) * miss], np.zeros(len(x0))])
            dx, _ = bounded_lsq(a, b, (lo[idx] - x0) / s, (hi[idx] - x0) / s)
            self.held = x0 + dx * s
        else:
            want = float(sens @ x0) + (1.0 - o.alpha) * miss
            self.held, _ = _lsq(sens, want, lo[idx], hi[idx], 1e-4)
        self.log.append([fb.time / fb.red.period, math.degrees(th0), math.degrees(ref), *sens])
        return self._out(tail)

    def _tail(self, elevation: float) -> TailControls:
        return TailControls(float(elevation), *self._rs)

    def _predict(self, fb, args, x):
        tail = self._tail(x[2]) if len(x) > 2 else fb.cb.tail_controls
        return predict(fb, args, x[:2], tail, self.o.window[1])[1]

    def _out(self, tail):
        h = self.held
        return (h[:2], tail) if len(h) == 2 else (h[:2], self._tail(h[2]))


def fly_study(preset: str, bird, opts, beats: float | None = None):
    """The flight with the study's hooks (``opts.off``: none), and the Study."""
    study = Study(opts)
    loops: list = []
    calls: dict = {}
    make, update, step = freeflight_mod.attitude_loop_for, attitude_mod.AttitudeLoop.update, \
        freeflight_mod.interval  # fmt: skip

    def loop_for(*a, **k):
        loops.append(make(*a, **k))
        return loops[-1]

    def upd(self, params, pitch_cmd, speed, err, rates, dt, **kw):
        saved = self._jac
        adj = None
        if opts.mode == "ratio" and saved is not None and not np.all(study.ratio == 1.0):
            jac = np.array(saved[2])
            jac[1] *= study.ratio
            adj = self._jac = (saved[0], saved[1], jac, saved[3])
        out = update(self, params, pitch_cmd, speed, err, rates, dt, **kw)
        if adj is not None and self._jac is adj:
            self._jac = saved
        r, a = kw.get("rate_cmd"), kw.get("acc_cmd")
        calls["ref3"] = (pitch_cmd, 0.0 if r is None else r[1], 0.0 if a is None else a[1])
        calls["params"], calls["err"] = params, float(err[1])
        return out

    def hooked(fb, right, times, t, dt, left, offset, wind, record, every):
        att = loops[-1] if loops else None
        if att is not None and att.enabled and "ref3" in calls:
            args = (right, left, offset, wind)
            sh, tail = fb.schedule.shoulder_target, fb.cb.tail_controls
            if opts.mode == "mpc":
                sh, tail = study.choose(att, fb, args, sh, tail, calls["ref3"],
                                        calls["params"], calls["err"])  # fmt: skip
            elif att.straight and att._jac is not None:
                if opts.gate == "stiff0" and att.stiffness[1] > 0.0:
                    study.ratio[:] = 1.0
                elif study.count % opts.every == 0:
                    study.ratios(att, fb, args, sh, tail)
                study.count += 1
            fb.schedule.shoulder_target, fb.cb.tail_controls = sh, tail
        return step(fb, right, times, t, dt, left, offset, wind, record, every)

    shipped = flown_pitch.ENABLED  # the study's variants replace the shipped one (C)
    flown_pitch.ENABLED = False
    if not opts.off:
        freeflight_mod.attitude_loop_for, freeflight_mod.interval = loop_for, hooked
        attitude_mod.AttitudeLoop.update = upd
    try:
        table = load_table_for(bird, opts.model, None)
        r = freeflight_mod.fly(PATH_PRESETS[preset], table, bird, opts.model, beats=beats,
                               config=SimConfig(attitude="free"))  # fmt: skip
    finally:
        freeflight_mod.attitude_loop_for, freeflight_mod.interval = make, step
        attitude_mod.AttitudeLoop.update = update
        flown_pitch.ENABLED = shipped
    return r, study


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--bird", default="models/pigeon.toml")
    ap.add_argument("--model", default=DEMO_MODEL)
    ap.add_argument("--preset", default="landing")
    ap.add_argument("--mode", default="mpc", choices=["mpc", "ratio"])
    ap.add_argument("--every", type=int, default=2)
    ap.add_argument("--anchor", default="held", choices=["held", "loop"])
    ap.add_argument("--tail", action="store_true")
    ap.add_argument("--mu", type=float, default=0.0)
    ap.add_argument("--alpha", type=float, default=0.3)
    ap.add_argument("--gate", default="all", choices=["all", "stiff0", "deadzone", "tailrange"])
    ap.add_argument("--deadzone", type=float, default=3.0)
    ap.add_argument("--clip", type=float, nargs=2, default=(-10.0, 10.0))
    ap.add_argument("--inertia-scale", type=float, default=1.0)
    ap.add_argument("--off", action="store_true", help="the attitude loop alone (flown_pitch off)")
    ap.add_argument("--identity", type=float, default=0.0,
                    help="fly this many wingbeats measuring ratios (applied as 1) and say "
                         "whether the flight is bit for bit the one without")  # fmt: skip
    ap.add_argument("--calm", type=int, default=1, help="tailrange: steps within to leave")
    ap.add_argument("--window", type=float, nargs=2, default=WINDOW)
    ap.add_argument("--print-log", action="store_true")
    o = ap.parse_args()
    bird = Bird.from_toml(o.bird) if o.bird else demo_bird()
    if o.inertia_scale != 1.0:  # a sensitivity run, not the model
        bird = dataclasses.replace(
            bird, body_inertia=tuple(o.inertia_scale * x for x in bird.body_inertia)
        )
    if o.identity:
        o.mode, o.clip, o.every = "ratio", (1.0, 1.0), 1
        a, _ = fly_study(o.preset, bird, _off(o), o.identity)
        b, st = fly_study(o.preset, bird, o, o.identity)
        same = all(np.array_equal(a.arrays[k], b.arrays[k]) for k in a.arrays
                   if isinstance(a.arrays[k], np.ndarray))  # fmt: skip
        print(f"{len(st.log)} measurements; the flight bit for bit the same: {same}")
        return
    r, st = fly_study(o.preset, bird, o)
    s = summary(log_arrays(r, o.preset))
    f = attitude_figures(r.arrays)
    key = "rms_altitude_error_after_start" if o.preset == "cruise" else "rms_error_after_start"
    print(f"{o.preset}: path RMS {s[key]!r}, pitch RMS {f['wingbeat_mean_pitch_rms_error_deg']:.3f} "
          f"deg, attitude-saturated {f['attitude_saturated_samples']}, table-saturated "
          f"wingbeats {s['wingbeats_saturated']}, rocking {f['rocking_median_deg']:.1f} deg")  # fmt: skip
    a = r.arrays
    _, p, _ = unfolded_euler(a["yaw"], a["pitch"], a["roll"])
    n = 64
    b = len(p) // n
    cmd = np.asarray(a["pitch_command"])[: b * n].reshape(b, n).mean(1)
    e = p[: b * n].reshape(b, n).mean(1) - cmd
    print("pitch error per wingbeat (deg):", " ".join(f"{x:+.0f}" for x in np.degrees(e)))
    if o.print_log:
        for row in st.log:
            print(" ".join(f"{x:+.3f}" for x in row))


def _off(o):
    ns = argparse.Namespace(**vars(o))
    ns.off = True
    return ns


if __name__ == "__main__":
    main()
