"""Is the free body's pitch command reachable?  Per wingbeat of a free flight (default:
the pigeon's landing, m3): the commanded pitch, its rate and second difference, the
table's pitch, the wingbeat-mean pitch flown, and on the held body at the commanded
state (the table's wingbeat with its stroke plane compensated for the command, the
command's pitch, the airspeed; measured fresh at the middle of every wingbeat) the
moment ``M_0`` with the inputs at zero, the pitch damping and stiffness, the rocking's
rectified moment, the moment needed to follow the command (``I theta_c'' - M_0 - D
theta_c'``) and the largest nose-down and nose-up moment of the pitch inputs (sweep,
dihedral, tail elevation) within their bounds: linear (the Jacobian's row times the
bounds) and measured at that corner.  Then the smallest RMS pitch error any controller
could reach on the wingbeat-mean model with that authority
(:func:`birdsim.flight.pitch_feasibility.least_tracking_error`).  Reduced units: moments
in table units (weight x semispan), nose up > 0.

    PYTHONPATH=$PWD python scripts/landing_pitch_bound.py [--bird models/pigeon.toml] [--preset landing]
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from birdsim.commands.fly import load_table_for
from birdsim.flight import attitude as attitude_mod
from birdsim.flight import pitch_plan as pitch_plan_mod
from birdsim.flight.attitude_jacobians import (
    INPUTS,
    held_mean_moments,
    measured_jacobian,
    measured_rate_derivatives,
)
from birdsim.flight.attitude_stiffness import measured_pitch_stiffness
from birdsim.flight.attitude_summary import attitude_figures, unfolded_euler
from birdsim.flight.freeflight import fly
from birdsim.flight.pitch_feasibility import (
    beat_differences,
    corner_inputs,
    least_tracking_error,
    pitch_authority,
    required_moment,
)
from birdsim.flight.pitch_rocking import rocking_pitch_moment
from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS, demo_bird
from birdsim.flight.simulate import SimConfig
from birdsim.physics.bird import Bird

PITCH_INPUTS = [i for i, (name, kind, _) in enumerate(INPUTS) if kind == "shoulder"] + [
    [name for name, _, _ in INPUTS].index("tail_elevation")
]
TWO_PI = 2.0 * math.pi


def recorded_flight(bird, model: str, preset: str):
    """(the flight's arrays, per control step records, per wingbeat measurements)."""
    steps, beats = [], {}
    original = attitude_mod.AttitudeLoop.update

    def update(self, params, pitch_cmd, speed, err, rates, dt, **kw):
        out = original(self, params, pitch_cmd, speed, err, rates, dt, **kw)
        t, period = self.fb.time, self.fb.red.period
        jp = pitch_cmd if kw.get("jac_pitch") is None else kw["jac_pitch"]
        at = params if kw.get("jac_params") is None else np.array(kw["jac_params"])
        acc = kw.get("acc_cmd")
        rate = kw.get("rate_cmd")
        steps.append(
            (t, pitch_cmd, float(rate[1]) if rate is not None else 0.0,
             float(acc[1]) if acc is not None else 0.0, float(self.saturated),
             float(params[list(self.fb.schedule.names).index("pitch")]))
        )  # fmt: skip
        b = int(t // period)
        if t >= (b + 0.5) * period and b not in beats:  # the middle of wingbeat b
            fb, inertia = self.fb, float(self.inertia[1])
            m0, jac = measured_jacobian(fb, at, jp, speed)
            damping = float(measured_rate_derivatives(fb, at, jp, speed)[1, 1])
            k = measured_pitch_stiffness(fb, at, jp, speed, m0)
            rock, rock_pp = rocking_pitch_moment(fb, at, jp, speed, inertia)
            lo, hi = self.bounds(params)
            row = np.zeros(len(INPUTS))
            row[PITCH_INPUTS] = jac[1, PITCH_INPUTS]
            lo_p, hi_p = np.where(row != 0, lo, 0.0), np.where(row != 0, hi, 0.0)
            lin = pitch_authority(row, lo_p, hi_p)
            meas = []
            for up in (False, True):
                u = corner_inputs(row, lo_p, hi_p, up)
                meas.append(held_mean_moments(fb, at, jp, speed, [np.zeros(3)], u)[0][1] - m0[1])
            tail = [name for name, _, _ in INPUTS].index("tail_elevation")
            beats[b] = dict(
                speed=speed, pitch=jp, m0=float(m0[1]), damping=damping, stiffness=k,
                rocking=rock, rocking_pp=rock_pp, lin=lin, meas=tuple(meas), inertia=inertia,
                tail_j=float(jac[1, tail]), t=t, row=jac[1].copy(),
            )  # fmt: skip
        return out

    plans = []
    original_plan = pitch_plan_mod.PitchPlan.__init__

    def plan_init(self, *args, **kw):
        original_plan(self, *args, **kw)
        plans.append(self)

    attitude_mod.AttitudeLoop.update = update
    pitch_plan_mod.PitchPlan.__init__ = plan_init
    try:
        table = load_table_for(bird, model, None)
        r = fly(PATH_PRESETS[preset], table, bird, model, config=SimConfig(attitude="free"))
    finally:
        attitude_mod.AttitudeLoop.update = original
        pitch_plan_mod.PitchPlan.__init__ = original_plan
    return r.arrays, np.array(steps), beats, (plans[0] if plans else None)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--bird", default="models/pigeon.toml")
    ap.add_argument("--model", default=DEMO_MODEL)
    ap.add_argument("--preset", default="landing")
    args = ap.parse_args()
    bird = Bird.from_toml(args.bird) if args.bird else demo_bird()
    a, steps, beats, plan = recorded_flight(bird, args.model, args.preset)
    period = TWO_PI  # reduced
    n_beats = int(round(a["t"][-1] / period))
    n = len(a["t"]) // n_beats
    _, pitch, _ = unfolded_euler(a["yaw"], a["pitch"], a["roll"])
    mean = lambda v: np.asarray(v[: n_beats * n]).reshape(n_beats, n).mean(axis=1)  # noqa: E731
    cmd, flown = mean(a["pitch_command"]), mean(pitch)
    bidx = (steps[:, 0] // period).astype(int)
    inertia = next(iter(beats.values()))["inertia"]
    table_pitch = np.array([steps[bidx == b, 5].mean() for b in range(n_beats)])
    per_ctl = int(round(period / float(np.median(np.diff(steps[:, 0])))))
    raw = plan.raw[: n_beats * per_ctl].reshape(n_beats, per_ctl).mean(axis=1) if plan else cmd
    rock_flown = np.asarray(pitch[: n_beats * n]).reshape(n_beats, n)
    rock_flown = np.ptp(rock_flown, axis=1)
    rate_b, acc_b = beat_differences(cmd, period)
    rate_f, acc_f = beat_differences(flown, period)
    u_mean = np.stack([mean(a[f"u_{name}"]) for name, _, _ in INPUTS], axis=1)
    deg = math.degrees
    print(f"pitch inertia {inertia:.4f} (reduced); moments in table units")
    print("figures:", {k: round(v, 4) for k, v in attitude_figures(a).items()})
    print(
        "beat  cmd   table  flown  err | cmd rate deg/beat  2nd diff deg/beat^2 |  V    "
        "tail k   D_q   | M_0     rock   I*acc   needed | down(lin/meas)   up(lin/meas) | margin"
        " | J u flown  missed | plan's table pitch | rocking pp held/flown deg"
    )
    req_steps, lo_steps, hi_steps, d_steps, k_steps, misses = [], [], [], [], [], []
    for b in range(n_beats):
        m = beats.get(b)
        if m is None:
            continue
        need = float(required_moment(inertia, acc_b[b], rate_b[b], m["m0"], m["damping"]))
        down = max(m["lin"][0], m["meas"][0])  # the weaker of the two (conservative)
        up = min(m["lin"][1], m["meas"][1])
        margin = min(up - need, need - down)
        delivered = float(m["row"] @ u_mean[b])
        missed = (
            inertia * acc_f[b] - m["m0"] - m["damping"] * rate_f[b]
            - m["stiffness"] * (flown[b] - cmd[b]) - delivered
        )  # fmt: skip
        tp = f"{deg(table_pitch[b]):6.1f}"
        print(
            f"{b:3d} {deg(cmd[b]):6.1f} {tp} {deg(flown[b]):6.1f} {deg(flown[b] - cmd[b]):6.1f} |"
            f" {deg(rate_b[b]) * period:8.2f} {deg(acc_b[b]) * period**2:8.2f} |"
            f" {m['speed']:.3f} {m['stiffness']:+.4f} {m['damping']:+.4f} |"
            f" {m['m0']:+.4f} {m['rocking']:+.4f} {inertia * acc_b[b]:+.4f} {need:+.4f} |"
            f" {m['lin'][0]:+.4f}/{m['meas'][0]:+.4f} {m['lin'][1]:+.4f}/{m['meas'][1]:+.4f} |"
            f" {margin:+.4f} | {delivered:+.4f} {missed:+.4f} | {deg(raw[b]):6.1f} |"
            f" {deg(m['rocking_pp']):5.1f} {deg(rock_flown[b]):5.1f}",
            flush=True,
        )
        if b >= 2:
            misses.append((missed, missed - m["rocking"], delivered))
        sel = bidx == b  # the control steps of wingbeat b: the command's own rate and acc
        req_steps.append(
            required_moment(inertia, steps[sel, 3], steps[sel, 2], m["m0"], m["damping"])
        )
        lo_steps.append(np.full(sel.sum(), down))
        hi_steps.append(np.full(sel.sum(), up))
        d_steps.append(np.full(sel.sum(), m["damping"]))
        k_steps.append(np.full(sel.sum(), m["stiffness"]))
    req = np.concatenate(req_steps)
    dt = float(np.median(np.diff(steps[:, 0])))
    rocking = np.concatenate(
        [np.full(np.sum(bidx == b), beats[b]["rocking"]) for b in sorted(beats)]
    )
    lo, hi = np.concatenate(lo_steps), np.concatenate(hi_steps)
    damping, stiffness = np.concatenate(d_steps), np.concatenate(k_steps)
    for label, r in (("held body", req), ("with the rocking's moment", req - rocking)):
        rms, err, _ = least_tracking_error(r, lo, hi, inertia, dt, damping, stiffness)
        late = err[2 * int(round(period / dt)) :]
        over = int(np.sum((r < lo) | (r > hi)))
        print(
            f"{label}: steps beyond the authority {over} of {len(r)}; least RMS pitch error "
            f"after two wingbeats {deg(float(np.sqrt(np.mean(late**2)))):.3f} deg "
            f"(largest {deg(float(np.abs(err).max())):.3f})"
        )
    # what the held model misses, against the loop's delay: a moment the loop learns of
    # only after a delay L (the four samples' 7/16 wingbeat) turns the body by d L^2 / 2 I
    # before any answer (an estimate, not a bound: a slow moment the integral trims)
    d = np.array(misses)
    lag = 7.0 / 16.0 * period
    for label, v in (
        ("missed moment", d[:, 0]),
        ("its change from the wingbeat before", np.diff(d[:, 0])),
        ("missed moment less the rocking's", d[:, 1]),
    ):
        rms = float(np.sqrt(np.mean(v**2)))
        print(
            f"{label}: RMS {rms:.4f} table units after two wingbeats;"
            f" turns the body by {deg(rms * lag**2 / (2 * inertia)):.1f} deg in 7/16 wingbeat"
        )
    slope, icpt = np.polyfit(d[:, 2], d[:, 0], 1)
    r2 = float(np.corrcoef(d[:, 2], d[:, 0])[0, 1] ** 2)
    print(
        f"missed moment against the inputs' moment flown (J u): slope {slope:+.2f}, "
        f"R^2 {r2:.2f} (-1: the inputs deliver nothing in flight, or the loop answers a "
        "disturbance exactly)"
    )


if __name__ == "__main__":
    main()
