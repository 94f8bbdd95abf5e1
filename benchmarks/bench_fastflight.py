"""Issue 27's fast free flight: m4, six degrees of freedom, period/128, side by side in one
run: MuJoCo stepping the same model without aerodynamics (the limit of compiling the
loop around it), the step loop alone (16 steps between two control updates, a fixed
prescription; compiled :mod:`birdsim.flight.fast_loop` against the reference
``step_kernel.free_loop`` with the Python callback) and whole closed-loop flights
(``fly``: controller, attitude loop, prescription, logging; 20 wingbeats + the trim's
probe wingbeats and the set-up, and 60 wingbeats), compiled against the reference: the
Python loop with the Python callback, the prescription, the table lookup and the
allocation of before (every switch of the compiled pieces off).  Process CPU time; each
figure the best of three, the two paths alternated (one run's figure moves by up to
30 % on the shared VM).  Target: >= 200 wingbeats per CPU second for the whole flight."""

from __future__ import annotations

import time

import mujoco
import numpy as np

from birdsim.flight import bounded_lsq, fast_loop, fast_prescription
from birdsim.flight.freeflight import fly
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.flight.simulate import FreeBird, SimConfig
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
from birdsim.tables import fast_lookup
from birdsim.tables.lookup import load_table

BEATS = 20.0
#: a longer flight: the set-up (model, trim probes, first Jacobian) weighs less
LONG = 60.0
REPEATS = 3
STEPS = 128
CONTROL = 8


def _bare_mujoco(fb: FreeBird, beats: int) -> float:
    """Wingbeats per CPU second of ``mj_step`` alone on the bird's model (no callback,
    no prescription: the wings keep their last velocities)."""
    m, d = fb.m, fb.d
    n = beats * STEPS
    c0 = time.process_time()
    for _ in range(n):
        mujoco.mj_step(m, d)
    return beats / (time.process_time() - c0)


def _step_loop(fb: FreeBird, beats: int, params: np.ndarray) -> float:
    """Wingbeats per CPU second of ``step_many`` alone (16 steps per call)."""
    k = STEPS // CONTROL
    pres = fb.schedule.advance(params, np.arange(k) * fb.h, 0.0, k * fb.h)
    fb.start(np.array([0.0, 0.0, 6.0]), np.array([0.9, 0.0, 0.0]), pres)
    wind = np.zeros(3)
    c0 = time.process_time()
    for _ in range(beats * CONTROL):
        rec: list = []
        fb.step_many(pres, wind, rec, 2)
    return beats / (time.process_time() - c0)


def _switch(switches: tuple, on: bool) -> None:
    for sw in switches:
        sw.ENABLED = on


def main() -> None:
    bird = Bird.from_toml("models/seed-bird.toml")
    table = load_table("tables/m4.npz")
    kin = get_model("m4")
    guess = kin.guess("cruise")
    params = np.array([guess[n] for n in kin.param_names])
    config = SimConfig(steps_per_beat=STEPS, control_per_beat=CONTROL, attitude="free")
    path = FlightPath("cruise", BEATS, False, False, (PathKeyframe(0.0, 6.0, V=0.9),))
    long_path = FlightPath("cruise", LONG, False, False, (PathKeyframe(0.0, 6.0, V=0.9),))
    warm = FlightPath("warm", 1.0, False, False, (PathKeyframe(0.0, 6.0, V=0.9),))
    switches = (fast_loop, fast_prescription, fast_lookup, bounded_lsq)
    saved = [s.ENABLED for s in switches]
    best: dict[str, float] = {}

    def keep(name: str, value: float) -> None:
        best[name] = max(best.get(name, 0.0), value)

    try:
        for compiled in (True, False):  # compile / warm both
            _switch(switches, compiled)
            fly(warm, table, bird, "m4", config=config)
        for _ in range(REPEATS):
            with FreeBird("m4", bird, params, config=config, aero=False) as fb:
                mujoco.set_mjcb_passive(None)
                keep("mujoco", _bare_mujoco(fb, 40))
            for compiled in (True, False):
                _switch(switches, compiled)
                name = "compiled" if compiled else "reference"
                with FreeBird("m4", bird, params, config=config) as fb:
                    keep(f"loop {name}", _step_loop(fb, 20, params))
                c0 = time.process_time()
                fly(path, table, bird, "m4", config=config)
                c1 = time.process_time()
                fly(long_path, table, bird, "m4", config=config)
                c2 = time.process_time()
                keep(f"fly {name}", BEATS / (c1 - c0))
                keep(f"long {name}", LONG / (c2 - c1))
    finally:
        for sw, value in zip(switches, saved):
            sw.ENABLED = value
    print(
        f"m4 period/{STEPS} mj_step alone, no aerodynamics:  {best['mujoco']:7.1f} wingbeats "
        f"per CPU second ({best['mujoco'] * STEPS:.0f} steps/s)"
    )
    labels = {
        "loop": "step loop (16 steps per call)",
        "fly": f"free flight (fly, {BEATS:g} beats)",
        "long": f"free flight (fly, {LONG:g} beats)",
    }
    for what, label in labels.items():
        c, r = best[f"{what} compiled"], best[f"{what} reference"]
        print(
            f"m4 period/{STEPS} {label:30s}: compiled {c:7.1f}, reference {r:7.1f} "
            f"wingbeats per CPU second; compiled / reference {c / r:.2f}, "
            f"compiled / mj_step alone {c / best['mujoco']:.3f} (best of {REPEATS})"
        )
    print(
        f"target: free flight >= 200 wingbeats per CPU second: {best['fly compiled']:.1f} "
        f"({best['long compiled']:.1f} in a {LONG:g}-wingbeat flight)"
    )


if __name__ == "__main__":
    main()
