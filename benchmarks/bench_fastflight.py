"""Issue 27's fast free flight (and issue 24's m5 free flight), period/128, side by side
in one run, for m4 and m5: MuJoCo stepping the same model without aerodynamics (the
limit of compiling the loop around it), the step loop alone (16 steps between two
control updates, a fixed prescription; compiled :mod:`birdsim.flight.fast_loop` against
the reference ``step_kernel.free_loop`` with the Python callback), whole closed-loop
free flights (``fly``: controller, attitude loop, prescription, logging; 20 wingbeats +
the trim's probe wingbeats and the set-up, and, for m4, 60 wingbeats) compiled against
the reference (every switch of the compiled pieces off,
``birdsim.flight.compiled_switches``: the Python loop with the Python callback, the numpy
prescription and schedule filters, scipy's lookup, path curves and ``lsq_linear``, the
numpy attitude error and the attitude loop's allocation in numpy), and the posed flight
of the same path (the body's pitch prescribed; its own loop, with the compiled
prescription, lookup and path curves).  Process CPU time; each figure the best of three,
the paths alternated (one run's figure moves by up to 30 % on the shared VM).  Targets:
m4 free flight >= 200 wingbeats per CPU second (issue 27), m5 >= 30 (issue 24)."""

from __future__ import annotations

import time

import mujoco
import numpy as np

from birdsim.flight.compiled_switches import SWITCHES
from birdsim.flight.freeflight import fly
from birdsim.flight.path import FlightPath, PathKeyframe
from birdsim.flight.simulate import FreeBird, SimConfig
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model
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


def _model_figures(model: str, bird: Bird, long: bool) -> dict[str, float]:
    table = load_table(f"tables/{model}.npz")
    kin = get_model(model)
    guess = kin.guess("cruise")
    params = np.array([guess[n] for n in kin.param_names])
    config = SimConfig(steps_per_beat=STEPS, control_per_beat=CONTROL, attitude="free")
    posed = SimConfig(steps_per_beat=STEPS, control_per_beat=CONTROL, attitude="posed")
    path = FlightPath("cruise", BEATS, False, False, (PathKeyframe(0.0, 6.0, V=0.9),))
    long_path = FlightPath("cruise", LONG, False, False, (PathKeyframe(0.0, 6.0, V=0.9),))
    warm = FlightPath("warm", 1.0, False, False, (PathKeyframe(0.0, 6.0, V=0.9),))
    switches = SWITCHES
    saved = [s.ENABLED for s in switches]
    best: dict[str, float] = {}

    def keep(name: str, value: float) -> None:
        best[name] = max(best.get(name, 0.0), value)

    try:
        for compiled in (True, False):  # compile / warm both
            _switch(switches, compiled)
            fly(warm, table, bird, model, config=config)
        fly(warm, table, bird, model, config=posed)
        for _ in range(REPEATS):
            with FreeBird(model, bird, params, config=config, aero=False) as fb:
                mujoco.set_mjcb_passive(None)
                keep("mujoco", _bare_mujoco(fb, 40))
            for compiled in (True, False):
                _switch(switches, compiled)
                name = "compiled" if compiled else "reference"
                with FreeBird(model, bird, params, config=config) as fb:
                    keep(f"loop {name}", _step_loop(fb, 20, params))
                c0 = time.process_time()
                fly(path, table, bird, model, config=config)
                keep(f"fly {name}", BEATS / (time.process_time() - c0))
                if long:
                    c0 = time.process_time()
                    fly(long_path, table, bird, model, config=config)
                    keep(f"long {name}", LONG / (time.process_time() - c0))
            _switch(switches, True)
            c0 = time.process_time()
            fly(path, table, bird, model, config=posed)
            keep("posed", BEATS / (time.process_time() - c0))
    finally:
        for sw, value in zip(switches, saved):
            sw.ENABLED = value
    return best


def main() -> None:
    bird = Bird.from_toml("models/seed-bird.toml")
    targets = {"m4": 200.0, "m5": 30.0}
    for model in ("m4", "m5"):
        best = _model_figures(model, bird, long=model == "m4")
        print(
            f"{model} period/{STEPS} mj_step alone, no aerodynamics:  {best['mujoco']:7.1f} "
            f"wingbeats per CPU second ({best['mujoco'] * STEPS:.0f} steps/s)"
        )
        labels = {
            "loop": "step loop (16 steps per call)",
            "fly": f"free flight (fly, {BEATS:g} beats)",
            "long": f"free flight (fly, {LONG:g} beats)",
        }
        for what, label in labels.items():
            if f"{what} compiled" not in best:
                continue
            c, r = best[f"{what} compiled"], best[f"{what} reference"]
            print(
                f"{model} period/{STEPS} {label:30s}: compiled {c:7.1f}, reference {r:7.1f} "
                f"wingbeats per CPU second; compiled / reference {c / r:.2f}, "
                f"compiled / mj_step alone {c / best['mujoco']:.3f} (best of {REPEATS})"
            )
        print(
            f"{model} period/{STEPS} posed flight (fly, {BEATS:g} beats)   : {best['posed']:7.1f} "
            f"wingbeats per CPU second; free compiled / posed "
            f"{best['fly compiled'] / best['posed']:.2f}"
        )
        extra = (
            f" ({best['long compiled']:.1f} in a {LONG:g}-wingbeat flight)"
            if "long compiled" in best
            else ""
        )
        print(
            f"target: {model} free flight >= {targets[model]:g} wingbeats per CPU second: "
            f"{best['fly compiled']:.1f}{extra}"
        )


if __name__ == "__main__":
    main()
