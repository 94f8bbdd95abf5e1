"""``birdsim export FLOCK_LOG.npz``: a flock's log (``birdsim fly FLOCK --out``) to USD
(one stage with every bird: :mod:`birdsim.export.usd_flock`), BVH or CSV (one file per
bird beside ``--out``: ``f.bvh`` -> ``f-bird00.bvh``, ...)."""

from __future__ import annotations

import argparse
import time
from pathlib import Path
from typing import Any


def export_flock_log(
    args: argparse.Namespace, fps: float, rate_for: Any, metres: float | None
) -> int:
    """Export every bird of the flock log ``args.source``; every output checked first
    (nothing written when one is refused)."""
    from birdsim import export
    from birdsim.commands.common import check_writable, refuse_for_a_log
    from birdsim.export.flightlog import frames_from_log
    from birdsim.flight.flightlog import LogError
    from birdsim.flight.flock_log import load_flock_log, per_bird_paths

    wall0 = time.perf_counter()
    try:
        data, birds = load_flock_log(args.source, "SOURCE")
    except LogError as exc:
        raise export.ExportError(str(exc)) from None
    refuse_for_a_log((), str(birds[0]["model"]), args.model)
    out = Path(args.out)
    outs = [out] if args.format == "usd" else per_bird_paths(out, len(birds))
    for p in outs:
        check_writable(p, args.force)
    rate = rate_for(birds[0]["bird_obj"])
    name = Path(args.source).name
    frames = [
        frames_from_log(
            b,
            fps=fps,
            beat_rate=rate,
            metres_per_unit=metres or 1.0,
            source=f"flock log {name}, bird {i}",
        )
        for i, b in enumerate(birds)
    ]
    if args.format == "usd":
        from birdsim.export.usd_flock import write_usd_flock

        written = [write_usd_flock(frames, out)]
    else:
        written = [export.write(f, args.format, p) for f, p in zip(frames, outs)]
    size = sum(p.stat().st_size for p in written)
    what = f"{written[0]}" if len(written) == 1 else f"{written[0]} ... {written[-1].name}"
    print(
        f"wrote {what} ({args.format}, flock {str(data['flock'])}: {len(birds)} birds, "
        f"{frames[0].frames} frames @ {fps:g} fps, {size / 1e6:.2f} MB, in "
        f"{time.perf_counter() - wall0:.1f} s)"
    )
    return 0


__all__ = ["export_flock_log"]
