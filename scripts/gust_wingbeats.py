"""A cruise gust wingbeat by wingbeat, attitude free (docs/free-body.md, "the pigeon's
up and +x gusts, diagnosed"; a study, not the flight code).

Flies the cruise preset with one gust of ``--frac`` of the cruise speed (0.5 omega s) for
one wingbeat from wingbeat 3, as ``scripts/free_targets.py --gusts`` does, and prints per
wingbeat (reduced units, the flight log's: lengths in semispans, 2 pi per wingbeat,
moments in weight x semispan, seed body axes, pitch nose up):

* ``ex``, ``ez``: the wingbeat-mean path error along x and z (bird minus reference),
  ``err``: the largest distance from the path over the wingbeat;
* ``pitch``, ``cmd``: the wingbeat-mean body pitch and the attitude loop's command (deg),
  ``sat``: the fraction of samples "attitude saturated";
* ``flown``: the fraction of control steps with the flown-pitch gate engaged
  (:mod:`birdsim.flight.flown_pitch`), ``int_z``: the path loop's integral (z, mean);
* ``tbl``: the table's pitch the path loop asked for (deg, mean), ``flap``: the largest
  flap amplitude (rad), ``sp``: the mean stroke plane (deg, after the compensation);
* the wingbeat's pitch turn (deg) split as the free body's: ``d_th`` the flown change,
  ``q0T`` the rate at the wingbeat's start times the period, ``mean`` the wingbeat-mean
  aerodynamic moment's part ``M_mean T^2 / (2 I)``, ``wave`` the zero-mean part's double
  integral ``(1/I) int_0^T int_0^t (M - M_mean)`` (the rocking's rectified turn: in calm
  flight it and ``q0T`` cancel), ``M1``: the first harmonic's amplitude of the aerodynamic
  pitching moment; ``I`` the whole bird's pitch inertia (the attitude loop's).

The gate and the integral are read by wrapping the flight's own objects (recorded, not
changed: the flight's arrays are the same bits as without the wrappers).

    PYTHONPATH=$PWD python scripts/gust_wingbeats.py [--bird models/pigeon.toml]
        [--wind +z] [--frac 0.3] [--beats 16]
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from birdsim.commands.fly import load_table_for
from birdsim.flight import controller, freeflight
from birdsim.flight.gust import parse_gust
from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS, demo_bird
from birdsim.flight.simulate import SimConfig
from birdsim.physics.bird import Bird

WINDS = {"+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0)}
WINDS.update({"+z": (0, 0, 1), "-z": (0, 0, -1)})


def recorded_flight(bird: Bird, model: str, wind: tuple, beats: float) -> tuple[dict, list, list]:
    """(arrays, [(t, flown gate engaged)], [(t, table pitch, path integral z)]) of the
    cruise with the one-wingbeat gust ``wind`` (bird velocity units) from wingbeat 3."""
    gates: list = []
    commands: list = []
    make_flown, command_at = freeflight.flown_pitch_for, controller.Controller.command_at

    def flown_for(free: bool, straight: bool):
        flown = make_flown(free, straight)
        if flown is not None:
            step = flown.step

            def recorded(att, fb, *args):
                step(att, fb, *args)
                gates.append((fb.time, flown.engaged))

            flown.step = recorded
        return flown

    def recorded_command(self, path, t, est, integral, pitch, w=(0.0, 0.0)):
        cmd = command_at(self, path, t, est, integral, pitch, w)
        commands.append((t, float(cmd.params[self.names.index("pitch")]), float(integral[1])))
        return cmd

    freeflight.flown_pitch_for, controller.Controller.command_at = flown_for, recorded_command
    try:
        g = parse_gust("3:1:" + ":".join(f"{w:g}" for w in wind))
        table = load_table_for(bird, model, None)
        cfg = SimConfig(attitude="free")
        r = freeflight.fly(
            PATH_PRESETS["cruise"], table, bird, model, beats=beats, gusts=[g], config=cfg
        )
    finally:
        freeflight.flown_pitch_for, controller.Controller.command_at = make_flown, command_at
    return r.arrays, gates, commands


def gust_arguments(beats: float) -> tuple[argparse.Namespace, Bird, tuple]:
    """The gust studies' command line (``--bird --model --wind --frac --beats``, ``beats``
    the default): (its arguments, the bird, the gust's wind in bird units)."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--bird", default=None)
    ap.add_argument("--model", default=DEMO_MODEL)
    ap.add_argument("--wind", default="+z", choices=sorted(WINDS))
    ap.add_argument("--frac", type=float, default=0.3)
    ap.add_argument("--beats", type=float, default=beats)
    args = ap.parse_args()
    bird = Bird.from_toml(args.bird) if args.bird else demo_bird()
    v = 0.5 * bird.semispan * 2.0 * math.pi / bird.period  # cruise speed, bird units
    return args, bird, tuple(args.frac * v * c for c in WINDS[args.wind])


def main() -> None:
    args, bird, wind = gust_arguments(16.0)
    a, gates, commands = recorded_flight(bird, args.model, wind, args.beats)
    inertia = pitch_inertia(bird, args.model)
    t, period = np.asarray(a["t"]), 2.0 * math.pi
    n = int(round(len(t) / (t[-1] / period)))
    dt = float(t[1] - t[0])
    ex, ez = np.asarray(a["x"]) - a["x_ref"], np.asarray(a["z"]) - a["z_ref"]
    err = np.sqrt(ex**2 + np.asarray(a["y"]) ** 2 + ez**2)
    m = np.asarray(a["moment_aero"])[:, 1]
    th, q = np.unwrap(a["pitch"]), np.asarray(a["omega_body"])[:, 1]
    gt, ge = (np.array(c, dtype=float) for c in zip(*gates))
    ct, ctab, cint = (np.array(c, dtype=float) for c in zip(*commands))
    print(f"wind {wind}, pitch inertia {inertia:.4f}")
    print("beat     ex      ez     err   pitch    cmd  sat flown  int_z    tbl  flap     sp"
          "   d_th    q0T   mean   wave     M1")  # fmt: skip
    for b in range(len(t) // n - 1):
        s = slice(b * n, (b + 1) * n)
        mm = float(m[s].mean())
        wave = float(np.sum(np.cumsum(m[s] - mm) * dt / inertia) * dt)
        m1 = float(np.abs(np.fft.rfft(m[s])[1]) * 2 / n)
        print(
            f"{b:4d} {ex[s].mean():7.4f} {ez[s].mean():7.4f} {err[s].max():7.4f}"
            f" {math.degrees(th[s].mean()):7.2f} {math.degrees(np.mean(a['pitch_command'][s])):6.2f}"
            f" {np.mean(a['attitude_saturated'][s]):4.2f} {ge[in_beat(gt, b, period)].mean():5.2f}"
            f" {cint[in_beat(ct, b, period)].mean():6.3f} {math.degrees(ctab[in_beat(ct, b, period)].mean()):6.2f}"
            f" {np.max(a['flap_amp'][s]):5.2f} {math.degrees(np.mean(a['stroke_plane'][s])):6.1f}"
            f" {math.degrees(th[(b + 1) * n] - th[b * n]):6.1f} {math.degrees(q[b * n] * period):6.1f}"
            f" {math.degrees(0.5 * mm * period**2 / inertia):6.1f} {math.degrees(wave):6.1f}"
            f" {m1:6.4f}"
        )


def in_beat(times: np.ndarray, beat: int, period: float) -> np.ndarray:
    """Which of ``times`` (reduced) fall in wingbeat ``beat``."""
    return (times >= beat * period) & (times < (beat + 1) * period)


def pitch_inertia(bird: Bird, model: str) -> float:
    """The whole bird's pitch inertia about the centre of mass the attitude loop uses
    (reduced units), read off a zero-length flight's loop."""
    from birdsim.flight import attitude

    seen: list[float] = []
    init = attitude.AttitudeLoop.__init__

    def recorded(self, fb, **kw):
        init(self, fb, **kw)
        seen.append(float(self.inertia[1]))

    attitude.AttitudeLoop.__init__ = recorded
    try:
        table = load_table_for(bird, model, None)
        freeflight.fly(
            PATH_PRESETS["cruise"], table, bird, model, beats=0.2, config=SimConfig(attitude="free")
        )
    finally:
        attitude.AttitudeLoop.__init__ = init
    return seen[-1]


if __name__ == "__main__":
    main()
