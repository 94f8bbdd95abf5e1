"""How much of a cruise gust's post-gust pitch turn the held body's rocking model
predicts (docs/free-body.md, "the rocking's drift measured"; a study, not the flight
code).

A free body starts every wingbeat with the rate of its periodic rocking; a change of the
wingbeat changes that periodic rate at the phase it is flown at while the body keeps its
rate: the body's mean pitch rate moves by minus that change.  Flies the cruise preset
with one gust of ``--frac`` of the cruise speed for one wingbeat from wingbeat 3 (as
``scripts/gust_wingbeats.py``) and at every control step measures, on the held body at
the command's pitch and the cruise airspeed, the periodic rocking's rate of the wingbeat
flown then (the table's smoothed wingbeat plus the stroke plane's smoothed compensation;
:func:`birdsim.flight.pitch_rocking.periodic_rocking`, :data:`JAC_SAMPLES` phases);
prints per wingbeat the sum of minus its change over the phases each control interval
spans, times the period (``drift``, deg per wingbeat: the mean pitch rate the wingbeat's
changes made in that wingbeat), the held body's periodic rocking
rate's first harmonic (``r1``, rad per reduced time, the last step's) and the flap amplitude.  Compare with
``gust_wingbeats.py``'s ``d_th``.  The flight is recorded through the flown-pitch gate's
step (the same bits as without the wrapper).

    PYTHONPATH=$PWD python scripts/rocking_drift.py [--bird models/pigeon.toml]
        [--wind +z] [--frac 0.3] [--beats 8]
"""

from __future__ import annotations

import math

import numpy as np

from birdsim.commands.fly import load_table_for
from birdsim.flight import freeflight
from birdsim.flight.attitude_jacobians import JAC_SAMPLES
from birdsim.flight.gust import parse_gust
from birdsim.flight.pitch_rocking import periodic_rocking
from birdsim.flight.presets import PATH_PRESETS
from birdsim.flight.simulate import SimConfig
from birdsim.physics.bird import Bird
from scripts.gust_wingbeats import gust_arguments

TWO_PI = 2.0 * math.pi
#: The held body's airspeed (reduced: semispan x omega): the cruise preset's.
CRUISE_AIRSPEED = 0.5


def drifts(bird: Bird, model: str, wind: tuple, beats: float) -> dict[int, tuple]:
    """{wingbeat: (predicted drift (rad per reduced time, summed), the rocking rate's
    first harmonic (rad per reduced time, the last step's), flap (rad))} of the
    cruise with the one-wingbeat gust ``wind`` (bird velocity units) from wingbeat 3."""
    out: dict[int, tuple] = {}
    last: dict = {}
    make = freeflight.flown_pitch_for
    speed = CRUISE_AIRSPEED

    def flown_for(free: bool, straight: bool):
        flown = make(free, straight)
        step = flown.step

        def recorded(att, fb, args, ref3, params, err_pitch):
            sched = fb.schedule
            n = len(sched.names)
            wingbeat = sched.output + sched.input_filter.output[n : 2 * n]
            rate = periodic_rocking(fb, wingbeat, ref3[0], speed, float(att.inertia[1]))[3]
            t, beat = fb.time, int(fb.time // TWO_PI)
            drift, _, _ = out.get(beat, (0.0, 0.0, 0.0))
            if last:
                k0, k1 = (int((s % TWO_PI) / TWO_PI * JAC_SAMPLES) for s in (last["t"], t))
                span = [(k0 + i) % JAC_SAMPLES for i in range((k1 - k0) % JAC_SAMPLES + 1)]
                drift -= float(np.mean((rate - last["rate"])[span]))
            r1 = float(np.abs(np.fft.rfft(rate)[1]) * 2 / JAC_SAMPLES)
            out[beat] = (drift, r1, float(wingbeat[sched.names.index("flap_amp")]))
            last.update(t=t, rate=rate)
            step(att, fb, args, ref3, params, err_pitch)

        flown.step = recorded
        return flown

    freeflight.flown_pitch_for = flown_for
    try:
        g = parse_gust("3:1:" + ":".join(f"{w:g}" for w in wind))
        table = load_table_for(bird, model, None)
        freeflight.fly(
            PATH_PRESETS["cruise"], table, bird, model, beats=beats, gusts=[g],
            config=SimConfig(attitude="free"),
        )  # fmt: skip
    finally:
        freeflight.flown_pitch_for = make
    return out


def main() -> None:
    args, bird, wind = gust_arguments(8.0)
    print("beat  drift(deg/beat)  r1(held)  flap")
    for b, (drift, r1, flap) in sorted(drifts(bird, args.model, wind, args.beats).items()):
        print(f"{b:4d} {math.degrees(drift * TWO_PI):10.1f} {r1:13.4f} {flap:6.2f}")


if __name__ == "__main__":
    main()
