"""MuJoCo steps per second with the aero callback on and off (side by side, one run),
and the multiple of real time at the model's timestep (bird.period / 512)."""

from __future__ import annotations

import time

import mujoco
import numpy as np

from birdsim import Bird, get_model
from birdsim.mujoco.callback import aero_forces
from birdsim.mujoco.crosscheck import crosscheck
from birdsim.mujoco.driver import trajectory
from birdsim.mujoco.model import build_model
from birdsim.physics.examples import EXAMPLES


def _steps_per_second(m: mujoco.MjModel, traj, seconds: float) -> float:
    """Free torso, wings driven kinematically: the wing qpos/qvel of the analytic
    wingbeat written before every mj_step (what playback does)."""
    d = mujoco.MjData(m)
    d.qpos[:], d.qvel[:] = traj.qpos[0], traj.qvel[0]
    wq, wv = traj.qpos[:, 7:], traj.qvel[:, 6:]
    steps = wq.shape[0]
    n, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < seconds:
        for i in range(steps):
            d.qpos[7:] = wq[i]
            d.qvel[6:] = wv[i]
            mujoco.mj_step(m, d)
        n += steps
    assert np.all(np.isfinite(d.qpos)), "unstable run"
    return n / (time.perf_counter() - t0)


def main() -> None:
    bird = Bird()
    print(
        f"free torso, gravity 0, wings driven kinematically (cruise guess, V = 0.5), Euler, "
        f"timestep = period/512 = {bird.period / 512:.4g}; best of 3 x 0.5 s"
    )
    for name in ("m1", "m4"):
        m = build_model(name, bird, scene=True)
        m.opt.gravity[:] = 0.0
        params = get_model(name).guess("cruise")
        times = np.arange(512) * m.opt.timestep
        traj = trajectory(
            m, name, params, times, bird, position_seed=(0, 0, -50), velocity_seed=(0.5, 0, 0)
        )
        off = max(_steps_per_second(m, traj, 0.5) for _ in range(3))
        with aero_forces(m, name, bird):
            on = max(_steps_per_second(m, traj, 0.5) for _ in range(3))
        dt = m.opt.timestep
        print(
            f"  {name}: callback off {off:8.0f} steps/s ({off * dt:5.0f} x real time) | "
            f"on {on:7.0f} steps/s ({on * dt:5.0f} x real time) | on/off = {on / off:.3f}"
        )
    ex = EXAMPLES[-1]
    t0 = time.perf_counter()
    crosscheck(ex.model, ex.params, ex.speed)
    t1 = time.perf_counter()
    crosscheck(ex.model, ex.params, ex.speed, forward=None)
    t2 = time.perf_counter()
    print(
        f"crosscheck m4 cruise, 64 samples: inverse only {t2 - t1:.3f} s, inverse + held forward {t1 - t0:.3f} s"
    )


if __name__ == "__main__":
    main()
