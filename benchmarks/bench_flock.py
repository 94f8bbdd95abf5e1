"""Issue 27's flocks, flown in this process:

* the shipped ``flock`` preset (12 pigeons, 10 s, m3, attitude free, turning 90 degrees,
  rule ``offsets``): wall and CPU time in this process (target: within 30 s), the worst
  bird's path RMS, the smallest separation, the saturated samples;
* the ``flock-seed`` preset (12 seed birds, 36 wingbeats, m3, attitude free, turning
  90 degrees, steered by Reynolds' rules, the birds in lockstep): wall and CPU time
  (target: 12 birds within 30 s), the worst bird's path RMS against its own reference
  (target: within 0.2 semispan), the smallest separation (target: at least one semispan),
  the saturated samples (target: none), the steering's largest displacement;
* the preset on 1 and 2 processes (:mod:`birdsim.flight.flock_parallel`);
* every bird in one MuJoCo model against each bird in its own (8 wingbeats, CPU);
* the lockstep's cost: the preset's first 8 wingbeats steered (lockstep) and under the
  rule ``offsets`` (the same birds one after another, no rules), CPU side by side;
* ``flock-v`` (12 pigeons in a straight V, 10 s, posed): as before the rules.

``python benchmarks/bench_flock.py --birds N [--processes P] [--beats B]`` flies N seed
birds (rows of 5, 3 semispans apart: 20 rows for 100) on the flock-seed preset's path instead
(issue 27: 100 birds within 5 minutes), on P processes, for B wingbeats (default the
path's 36; 80 is a pigeon's 10 s).  CPU is this process's and its children's.  Rows of 10 put the inner birds 13.5 semispans inside the leader's radius of
50 (speed 0.365 omega s): those saturated in the turn and diverged (measured:
docs/fast-flight.md).
"""

from __future__ import annotations

import math
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from birdsim.flight import flock_step
from birdsim.flight.flock import PRESET_FOLDER, load_birds
from birdsim.flight.flock_fly import flock_summary, fly_flock, jobs_for


def _cpu() -> float:
    """CPU seconds of this process and of its ended child processes (user + system)."""
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def _fly(
    source: str, seconds: float | None = None, processes: int = 1
) -> tuple[dict, float, float, dict]:
    flock, jobs = jobs_for(source, "m3", seconds=seconds)
    w0, c0 = time.perf_counter(), _cpu()
    arrays = fly_flock(jobs, processes=processes)
    wall, cpu = time.perf_counter() - w0, _cpu() - c0
    return flock_summary(arrays, load_birds(flock)[0].semispan), wall, cpu, arrays


def _line(name: str, info: dict, wall: float, cpu: float, arrays: dict) -> str:
    steer = float(np.abs(arrays["steer"]).max()) if "steer" in arrays else 0.0
    return (
        f"{name}: {info['n_birds']} birds x {info['seconds']:.4g} s: {wall:.1f} s wall, "
        f"{cpu:.1f} s CPU (target 30 s for 12); worst path RMS "
        f"{info['worst_rms_error_after_start_semispans']:.4f} semispan (target 0.2); closest "
        f"two birds {info['min_separation_semispans']:.2f} semispan (target >= 1); "
        f"{info['saturated_samples']} saturated samples; largest steering {steer:.3f}"
    )


def block(n: int, spacing: float = 3.0, per_row: int = 5) -> str:
    """A flock file of ``n`` seed birds on the preset's path, steered: rows of
    ``per_row`` birds ``spacing`` semispans apart (side by side and row behind row),
    centred on the leader's track."""
    text = (
        f'path = "{PRESET_FOLDER / "paths" / "turning.toml"}"\nmodel = "m3"\n'
        'attitude = "free"\nrule = "steer"\n'
    )
    for i in range(n):
        row, j = divmod(i, per_row)
        width = min(per_row, n - row * per_row)
        y = (j - 0.5 * (width - 1)) * spacing
        text += f"[[bird]]\noffset = [{-row * spacing}, {y}, 0.0]\n"
    return text


def main(argv: list[str] | None = None) -> None:
    argv = sys.argv[1:] if argv is None else argv
    opts = dict(zip(argv[::2], argv[1::2]))
    processes = int(opts.get("--processes", 1))
    beats = float(opts["--beats"]) if "--beats" in opts else None
    seconds = None if beats is None else beats * 2 * math.pi  # the seed bird's time unit
    if "--birds" in opts:
        n = int(opts["--birds"])
        with tempfile.TemporaryDirectory() as tmp:
            p = Path(tmp) / f"block-{n}.toml"
            p.write_text(block(n))
            name = f"block of {n} seed birds (steered, {processes} process(es))"
            print(_line(name, *_fly(str(p), seconds, processes)))
        return
    print(_line("flock preset (12 pigeons, turning, offsets, 10 s)", *_fly("flock")))
    for procs in (1, 2):
        name = f"flock-seed preset (seed birds, turning, steered, {procs} process(es))"
        print(_line(name, *_fly("flock-seed", seconds, procs)))
    beats8 = 8 * 2 * math.pi  # the seed bird's 8 wingbeats in its time unit
    cpus = []
    for shared in (True, False):  # every bird in one MuJoCo model, or each in its own
        flock_step.SHARED_MODEL = shared
        cpus.append(_fly("flock-seed", beats8)[2])
    flock_step.SHARED_MODEL = True
    print(
        f"one MuJoCo model (flock-seed, 8 wingbeats): {cpus[0]:.1f} s CPU, each bird its own "
        f"model {cpus[1]:.1f} s CPU: {cpus[0] / cpus[1] - 1:+.1%}"
    )
    s_info, s_wall, s_cpu, _ = _fly("flock-seed", beats8)
    text = (PRESET_FOLDER / "flock-seed.toml").read_text().replace('rule = "steer"', "")
    text = text.replace('path = "paths/', f'path = "{PRESET_FOLDER}/paths/')
    with tempfile.TemporaryDirectory() as tmp:
        p = Path(tmp) / "offsets.toml"
        p.write_text(text)
        o_info, o_wall, o_cpu, _ = _fly(str(p), beats8)
    print(
        f"lockstep cost (flock-seed, 8 wingbeats): steered in lockstep {s_cpu:.1f} s CPU, "
        f"one by one (rule offsets) {o_cpu:.1f} s CPU: {s_cpu / o_cpu - 1:+.1%}"
    )
    print(_line("flock-v preset (pigeons, straight V, posed)", *_fly("flock-v")))


if __name__ == "__main__":
    main()
