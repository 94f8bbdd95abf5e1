"""Issue 27's flock: the shipped ``flock`` preset (12 pigeons, 10 s, m3, posed attitude)
flown in this process, bird after bird: wall and CPU time (target: within 30 s), the
worst bird's path RMS (target: within 0.2 semispan), the smallest separation (target: at
least one semispan) and the saturated samples (target: none)."""

from __future__ import annotations

import time

from birdsim.flight.flock import load_birds
from birdsim.flight.flock_fly import flock_summary, fly_flock, jobs_for


def main() -> None:
    flock, jobs = jobs_for("flock", "m3")
    w0, c0 = time.perf_counter(), time.process_time()
    arrays = fly_flock(jobs)
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    info = flock_summary(arrays, load_birds(flock)[0].semispan)
    print(
        f"flock preset ({info['n_birds']} pigeons, {info['seconds']:.1f} s, m3 posed): "
        f"{wall:.1f} s wall, {cpu:.1f} s CPU (target 30 s); worst path RMS "
        f"{info['worst_rms_error_after_start_semispans']:.4f} semispan (target 0.2); closest "
        f"two birds {info['min_separation_semispans']:.2f} semispan (target >= 1); "
        f"{info['saturated_samples']} saturated samples"
    )


if __name__ == "__main__":
    main()
