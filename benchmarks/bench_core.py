"""Cycle evaluation speed: the fused kernel vs the numpy reference side by side, batched
vs one-at-a-time vs a plain per-sample loop, gradients, and the passive callback's cost."""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

import birdsim

sys.path.insert(0, str(Path(__file__).parent.parent / "tests"))
from reference_flapcost import flapcost_histories  # noqa: E402  (the plain approach)


def _params(model: str, count: int, seed: int = 0) -> tuple[dict[str, np.ndarray], np.ndarray]:
    rng = np.random.default_rng(seed)
    m = birdsim.get_model(model)
    lo, hi = m.bounds
    x = lo + (hi - lo) * rng.random((count, len(lo)))
    return {n: x[:, i] for i, n in enumerate(m.param_names)}, rng.random(count)


def _rate(fn, count: int, min_seconds: float = 1.0) -> float:
    fn()  # warm up
    reps, start = 0, time.perf_counter()
    while True:
        fn()
        reps += 1
        elapsed = time.perf_counter() - start
        if elapsed >= min_seconds:
            return reps * count / elapsed


def _kernel_vs_numpy(n: int = 64, count: int = 4096) -> None:
    """Wall-clock wingbeats/s of both backends on the same parameter sets (best of 3),
    and per CPU-second (process time over all threads: on a shared machine the wall
    figure of the threaded kernel depends on what else runs)."""
    import time as _t

    from birdsim.physics import kernel
    from birdsim.tables.cost import forces_and_gradients

    print(f"kernel vs numpy, {count} wingbeats x {n} samples, kernel threads = {kernel.threads()}")
    print(
        f"{'model':6s} {'kernel/s':>10s} {'numpy/s':>10s} {'ratio':>6s} | {'kernel/CPU-s':>12s} {'numpy/CPU-s':>12s} | {'grad/s':>8s}"
    )
    for model in birdsim.MODELS:
        params, speed = _params(model, count)
        best = {}
        for _ in range(3):
            for be in ("kernel", "numpy"):
                t0, c0 = _t.perf_counter(), _t.process_time()
                _ = birdsim.evaluate_cycle(model, params, speed, n=n, backend=be).mean
                w, c = count / (_t.perf_counter() - t0), count / max(_t.process_time() - c0, 1e-9)
                bw, bc = best.get(be, (0.0, 0.0))
                best[be] = (max(bw, w), max(bc, c))
        m = birdsim.get_model(model)
        X = np.stack([params[k] for k in m.param_names], axis=-1)
        grad = _rate(
            lambda m=m, X=X, speed=speed: forces_and_gradients(m, X, speed, birdsim.Bird(), n),
            count,
            0.5,
        )
        (kw, kc), (nw, nc) = best["kernel"], best["numpy"]
        print(
            f"{model:6s} {kw:10.0f} {nw:10.0f} {kw / nw:5.1f}x | {kc:12.0f} {nc:12.0f} | {grad:8.0f}"
        )
    print("targets (issue 17): m4 kernel >= 2e5/s and >= 4x numpy; m3 kernel >= 4e5/s")
    print("target (issue 24): m5 kernel >= 4x its numpy reference")


def _m5_interleaved(reps: int = 5, n: int = 64, count: int = 4096) -> None:
    """Issue 24's m5 target side by side, interleaved ``reps`` times (kernel, then numpy,
    on the same parameter sets), with the load average at each repetition: on a shared
    machine one repetition's wall ratio follows how much CPU each side was given, so the
    median, the range and the per-CPU-second ratio (process time, all threads) are printed."""
    import os as _os
    import time as _t

    from birdsim.physics import kernel

    params, speed = _params("m5", count)
    for be in ("kernel", "numpy"):  # compile / warm up
        _ = birdsim.evaluate_cycle("m5", params, speed, n=n, backend=be).mean
    print(
        f"m5 kernel vs numpy interleaved, {reps} x ({count} wingbeats x {n} samples), "
        f"kernel threads = {kernel.threads()}"
    )
    wall, cpu = [], []
    for r in range(reps):
        row = []
        for be in ("kernel", "numpy"):
            t0, c0 = _t.perf_counter(), _t.process_time()
            _ = birdsim.evaluate_cycle("m5", params, speed, n=n, backend=be).mean
            row += [_t.perf_counter() - t0, max(_t.process_time() - c0, 1e-9)]
        kw, kc, nw, nc = row
        wall.append(nw / kw)
        cpu.append(nc / kc)
        print(
            f"  rep {r}: kernel {kw * 1e3:6.0f} ms wall {kc * 1e3:5.0f} ms CPU | numpy "
            f"{nw * 1e3:6.0f} ms wall {nc * 1e3:5.0f} ms CPU | wall ratio {nw / kw:4.1f}x, "
            f"per CPU-s {nc / kc:4.1f}x | load {_os.getloadavg()[0]:.1f}"
        )
    print(
        f"m5 wall ratio median {np.median(wall):.1f}x (range {min(wall):.1f}-{max(wall):.1f}), "
        f"per CPU-s median {np.median(cpu):.1f}x; target (issue 24): >= 4x"
    )


def _default_samples(count: int = 4096, reference: int = 4096) -> None:
    """The default samples per wingbeat (``DEFAULT_SAMPLES``): its accuracy (share of
    random sets whose mean force, max(|dFx|, |dFz|), is within 1e-7 of n = ``reference``,
    and the 99.9th percentile of that error) and its cost: the kernel at the default n
    against today's numpy path at n = 64, side by side (best of 3), wall clock (the
    kernel's default threads) and per CPU-second."""
    import os as _os
    import time as _t

    from birdsim.physics import kernel
    from birdsim.physics.cycle import DEFAULT_SAMPLES

    n = DEFAULT_SAMPLES
    print(
        f"default samples n = {n}: accuracy against n = {reference}, and kernel@{n} vs numpy@64 "
        f"({count} wingbeats, kernel threads = {kernel.threads()}, load {_os.getloadavg()[0]:.1f})"
    )
    print(
        f"{'model':6s} {'within 1e-7':>11s} {'p99.9':>8s} | {'kernel/s':>9s} {'numpy64/s':>9s} {'ratio':>6s} | "
        f"{'kernel/CPU-s':>12s} {'numpy64/CPU-s':>13s} {'ratio':>6s}"
    )
    for model in birdsim.MODELS:
        params, speed = _params(model, count, seed=11)
        ref = birdsim.evaluate_cycle(model, params, speed, n=reference).mean
        a = birdsim.evaluate_cycle(model, params, speed, n=n).mean
        err = np.maximum(np.abs(a.Fx - ref.Fx), np.abs(a.Fz - ref.Fz))
        best = {}
        for _ in range(3):
            for be, nn in (("kernel", n), ("numpy", 64)):
                t0, c0 = _t.perf_counter(), _t.process_time()
                _ = birdsim.evaluate_cycle(model, params, speed, n=nn, backend=be).mean
                w, c = count / (_t.perf_counter() - t0), count / max(_t.process_time() - c0, 1e-9)
                bw, bc = best.get(be, (0.0, 0.0))
                best[be] = (max(bw, w), max(bc, c))
        (kw, kc), (nw, nc) = best["kernel"], best["numpy"]
        print(
            f"{model:6s} {np.mean(err <= 1e-7):11.3%} {np.quantile(err, 0.999):8.1e} | {kw:9.0f} {nw:9.0f} {kw / nw:5.2f}x | "
            f"{kc:12.0f} {nc:13.0f} {kc / nc:5.2f}x"
        )
    print(
        f"target (issue 17): >= 99.9 % within 1e-7 for every model, kernel@{n} wall >= numpy@64 wall"
    )


def _callback_cost() -> None:
    """Microseconds per call of the passive aero callback (what every MuJoCo step pays)."""
    import time as _t

    import mujoco

    from birdsim.mujoco.callback import AeroCallback
    from birdsim.mujoco.driver import trajectory
    from birdsim.mujoco.model import build_model

    bird = birdsim.Bird()
    for name in ("m1", "m4"):
        m = build_model(name, bird, scene=True)
        traj = trajectory(
            m,
            name,
            birdsim.get_model(name).guess("cruise"),
            np.arange(8) * m.opt.timestep,
            bird,
            position_seed=(0, 0, -50),
            velocity_seed=(0.5, 0, 0.2),
        )
        d = mujoco.MjData(m)
        d.qpos[:], d.qvel[:] = traj.qpos[3], traj.qvel[3]
        mujoco.mj_forward(m, d)
        cb = AeroCallback(m, name, bird)
        best = np.inf
        for _ in range(5):
            t0 = _t.perf_counter()
            for _ in range(1000):
                cb(m, d)
            best = min(best, (_t.perf_counter() - t0) / 1000)
        print(
            f"passive callback {name}: {best * 1e6:6.1f} us per call (climbing body: drag with X and Z parts)"
        )


def main() -> None:
    _kernel_vs_numpy()
    _m5_interleaved()
    _default_samples()
    _callback_cost()
    n = 64
    print(
        f"numpy path: wingbeat evaluations per second, {n} samples each (mean forces and power of one wing)"
    )
    print(
        f"{'model':6s} {'batched':>12s} {'one-at-a-time':>14s} {'plain loop':>11s} {'batch/one':>10s} {'batch/plain':>12s}"
    )
    for model in birdsim.MODELS:
        params, speed = _params(model, 4096)
        batched = _rate(
            lambda model=model, params=params, speed=speed: (
                birdsim.evaluate_cycle(model, params, speed, n=n, backend="numpy").mean
            ),
            4096,
        )
        single_p = {k: float(v[0]) for k, v in params.items()}
        one = _rate(
            lambda model=model, single_p=single_p, speed=speed: (
                birdsim.evaluate_cycle(model, single_p, float(speed[0]), n=n, backend="numpy").mean
            ),
            1,
            0.5,
        )
        if model not in ("m4", "m5"):  # the appendix transcription: single-panel models
            times = np.linspace(0, 2 * np.pi, n, endpoint=False)
            plain = _rate(
                lambda model=model, single_p=single_p, speed=speed, times=times: flapcost_histories(
                    model, single_p, float(speed[0]), times
                ),
                1,
                0.5,
            )
            plain_s, ratio_plain = f"{plain:11.0f}", f"{batched / plain:11.0f}x"
        else:
            plain_s, ratio_plain = f"{'-':>11s}", f"{'-':>12s}"
        print(
            f"{model:6s} {batched:12.0f} {one:14.0f} {plain_s} {batched / one:9.0f}x {ratio_plain}"
        )
    print("target (issue 2): >= 1e5 batched evaluations per second for m3 on this 2-core machine")
