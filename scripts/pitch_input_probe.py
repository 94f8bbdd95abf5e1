"""What a pitch input really does to the free body in flight, against what the attitude
loop's held-body Jacobian says it does.  A free flight (default: the pigeon's landing,
m3) is flown twice up to wingbeat ``b + window``; over wingbeats ``[b, b + window)`` the
attitude loop's inputs are frozen at the values it chose at wingbeat ``b`` (the same in
both runs), and in the second run one input is moved by ``delta``.  Printed per ``b``:
the mean over the window's last wingbeat of the pitch difference between the runs
(flown), the same from the wingbeat-mean model the loop allocates with (``I theta'' =
J delta f(t) + D theta' + K theta``, ``J`` the input's held-body Jacobian measured at
``b`` at the commanded state, ``f`` the shoulders' two cascaded input filters, ``D`` and
``K`` the held body's pitch damping and stiffness), their ratio (1: the loop's model is
the plant) and the change of the within-wingbeat rocking (peak to peak).  Reduced
units, degrees printed.

    PYTHONPATH=$PWD python scripts/pitch_input_probe.py [--bird models/pigeon.toml]
        [--input dihedral] [--delta 0.01] [--beats 2,12,20,27] [--window 2]
        [--freeze-compensation] [--inertia-scale 1]
"""

from __future__ import annotations

import argparse
import dataclasses
import math

import numpy as np

import birdsim.flight.freeflight as freeflight_mod
from birdsim.commands.fly import load_table_for
from birdsim.flight import attitude as attitude_mod
from birdsim.flight.attitude_jacobians import (
    INPUTS,
    measured_jacobian,
    measured_rate_derivatives,
    split_inputs,
)
from birdsim.flight.attitude_stiffness import measured_pitch_stiffness
from birdsim.flight.freeflight import fly
from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS, demo_bird
from birdsim.flight.simulate import SimConfig
from birdsim.flight.wingbeat import INPUT_SMOOTHING_BEATS
from birdsim.physics.bird import Bird

TWO_PI = 2.0 * math.pi
NAMES = [name for name, _, _ in INPUTS]


def probed_flight(bird, model, preset, b, window, inp, delta, freeze_comp):
    """(the flight's arrays, the held model at wingbeat ``b``: J, D, K, I)."""
    update, source = attitude_mod.AttitudeLoop.update, freeflight_mod.section_source
    state: dict = {}
    start, end = b * TWO_PI - 1e-9, (b + window) * TWO_PI - 1e-9

    def frozen_update(self, params, pitch_cmd, speed, err, rates, dt, **kw):
        if not start <= self.fb.time < end:
            return update(self, params, pitch_cmd, speed, err, rates, dt, **kw)
        if "u" not in state:  # the loop's choice at b, and the held model there
            update(self, params, pitch_cmd, speed, err, rates, dt, **kw)
            state["u"] = self.u.copy()
            jp = pitch_cmd if kw.get("jac_pitch") is None else kw["jac_pitch"]
            at = params if kw.get("jac_params") is None else kw["jac_params"]
            m0, jac = measured_jacobian(self.fb, at, jp, speed)
            state["model"] = (
                float(jac[1, NAMES.index(inp)]),
                float(measured_rate_derivatives(self.fb, at, jp, speed)[1, 1]),
                measured_pitch_stiffness(self.fb, at, jp, speed, m0),
                float(self.inertia[1]),
            )
        u = state["u"].copy()
        u[NAMES.index(inp)] += delta
        self.u = u
        return split_inputs(self.fb.schedule.names, params, u)

    def frozen_source(att, *args):
        f = source(att, *args)

        def g(*a):  # the stroke plane's compensation held at b's body pitch and rate
            out = f(*a)
            if not (freeze_comp and start <= att.fb.time < end):
                return out
            comp = state.setdefault("comp", (out[0], np.array(out[2], dtype=float)))
            return comp[0], out[1], comp[1], out[3]

        return g

    attitude_mod.AttitudeLoop.update = frozen_update
    freeflight_mod.section_source = frozen_source
    try:
        table = load_table_for(bird, model, None)
        r = fly(
            PATH_PRESETS[preset],
            table,
            bird,
            model,
            beats=b + window + 0.01,
            config=SimConfig(attitude="free"),
        )
    finally:
        attitude_mod.AttitudeLoop.update = update
        freeflight_mod.section_source = source
    return r.arrays, state["model"]


def model_response(t: np.ndarray, jd: float, damping: float, k: float, inertia: float):
    """The loop's wingbeat-mean model's pitch (rad) at ``t`` after a step ``jd`` (J delta)
    through the shoulders' two cascaded input filters (semi-implicit Euler, fine steps)."""
    tau = INPUT_SMOOTHING_BEATS * TWO_PI
    fine = np.linspace(0.0, float(t[-1]), 4000)
    dt = fine[1] - fine[0]
    f1 = f2 = th = w = 0.0
    out = np.empty_like(fine)
    for i in range(len(fine)):
        out[i] = th
        f1 += dt / tau * (jd - f1)
        f2 += dt / tau * (f1 - f2)
        w += dt * (f2 + damping * w + k * th) / inertia
        th += dt * w
    return np.interp(t, fine, out)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--bird", default="models/pigeon.toml")
    ap.add_argument("--model", default=DEMO_MODEL)
    ap.add_argument("--preset", default="landing")
    ap.add_argument("--input", default="dihedral", choices=["sweep", "dihedral", "tail_elevation"])
    ap.add_argument("--delta", type=float, default=0.01)
    ap.add_argument("--beats", default="2,6,12,17,20,22,25,27,30")
    ap.add_argument("--window", type=int, default=2)
    ap.add_argument("--freeze-compensation", action="store_true")
    ap.add_argument("--inertia-scale", type=float, default=1.0)
    args = ap.parse_args()
    bird = Bird.from_toml(args.bird) if args.bird else demo_bird()
    if args.inertia_scale != 1.0:  # a sensitivity run, not the model
        bird = dataclasses.replace(
            bird, body_inertia=tuple(args.inertia_scale * x for x in bird.body_inertia)
        )
    for b in (int(x) for x in args.beats.split(",")):
        run = (bird, args.model, args.preset, b, args.window, args.input)
        a0, (jac, damping, k, inertia) = probed_flight(*run, 0.0, args.freeze_compensation)
        a1, _ = probed_flight(*run, args.delta, args.freeze_compensation)
        sel = (a0["t"] >= b * TWO_PI) & (a0["t"] <= (b + args.window) * TWO_PI)
        t = a0["t"][sel] - b * TWO_PI
        flown = a1["pitch"][sel] - a0["pitch"][sel]
        model = model_response(t, jac * args.delta, damping, k, inertia)
        last = t >= (args.window - 1) * TWO_PI
        mf, mm = float(flown[last].mean()), float(model[last].mean())
        rock = np.ptp(a1["pitch"][sel][last]) - np.ptp(a0["pitch"][sel][last])
        print(
            f"beat {b:2d} {args.input} {args.delta:+.3f}: J {jac:+.4f} D {damping:+.4f} "
            f"K {k:+.4f}; last wingbeat's mean: flown {math.degrees(mf):+.2f} deg, "
            f"model {math.degrees(mm):+.2f} deg, ratio {mf / mm if mm else math.nan:+.2f}; "
            f"rocking change {math.degrees(rock):+.2f} deg",
            flush=True,
        )


if __name__ == "__main__":
    main()
