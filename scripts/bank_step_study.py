"""The bank's step response in the circle (issue 23's inner loop, docs/turning.md "Gust stage,
ninth pass"): seed bird, m3, attitude free, the ``circle`` preset.

``python scripts/bank_step_study.py`` flies the circle twice with the lateral loop opened at
wingbeat 20 (its correction held at 0, as ``turn_gust_study.py --step`` does), the second
time with DB degrees (``--size``, 5) added to the bank command from wingbeat 25 on: a raw
step of the value (no rate or acceleration fed forward), or over ``--ramp`` wingbeats a
smoothstep with its rate and acceleration.  Printed: per quarter wingbeat the commanded and
the flown bank's difference from the first flight (degrees; the flown as the one-wingbeat
centred mean and as the sample), then one line of figures in wingbeats after the step, from
the one-wingbeat means: ``t50`` and ``t90`` (first reaching 50 / 90 % of the step), the peak
(per cent of the step) and when, and the mean over wingbeats 5-8 after the step (the lateral
loop is open, so the bank does not have to settle on the step exactly).

``--set MODULE.NAME=VALUE`` (repeatable) sets a module constant first, as in
``turn_gust_study.py``.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np
from turn_gust_study import apply_settings, fly_circle

TWO_PI = 2.0 * math.pi
OPEN_AT = 20.0  # wingbeat the lateral loop is opened at
STEP_AT = 25.0  # wingbeat the bank step starts


def smoothstep(x: float) -> tuple[float, float, float]:
    """(value, slope, curvature) of ``3 x^2 - 2 x^3`` on [0, 1], held outside."""
    if x <= 0.0:
        return 0.0, 0.0, 0.0
    if x >= 1.0:
        return 1.0, 0.0, 0.0
    return 3 * x * x - 2 * x**3, 6 * x * (1 - x), 6 - 12 * x


@contextmanager
def bank_step(size_deg: float, ramp: float) -> Iterator[Any]:
    """Open the lateral loop at :data:`OPEN_AT` and add the step to the bank command from
    :data:`STEP_AT` (raw, or a smoothstep over ``ramp`` wingbeats); yields the control hook."""
    from birdsim.flight import turning

    loop, attitude = turning.lateral_acceleration, turning.turn_attitude
    now = [0.0]

    def hook(_k: int, t: float, _fb: Any) -> None:
        now[0] = t / TWO_PI

    def opened(y: float, vy: float, integral: float = 0.0, omega: float = 1.0) -> float:
        return loop(y, vy, integral, omega) if now[0] < OPEN_AT else 0.0

    def stepped(heading: float, bank: tuple, pitch: tuple) -> Any:
        b = math.radians(size_deg)
        if ramp > 0.0:
            s, ds, dds = smoothstep((now[0] - STEP_AT) / ramp)
            add = (b * s, b * ds / (ramp * TWO_PI), b * dds / (ramp * TWO_PI) ** 2)
        else:
            add = (b if now[0] >= STEP_AT else 0.0, 0.0, 0.0)
        return attitude(heading, tuple(x + a for x, a in zip(bank, add)), pitch)

    turning.lateral_acceleration, turning.turn_attitude = opened, stepped  # type: ignore[assignment]
    try:
        yield hook
    finally:
        turning.lateral_acceleration, turning.turn_attitude = loop, attitude  # type: ignore[assignment]


def step_figures(beats: np.ndarray, flown: np.ndarray, size: float) -> dict[str, float | None]:
    """Figures of the response ``flown`` (one-wingbeat means at ``beats``, wingbeats after
    the step) to a step of ``size``: t50, t90, the peak (per cent of the step) and its time,
    and the mean over wingbeats 5-8 after the step."""
    rel = np.asarray(flown, dtype=float) / size
    b = np.asarray(beats, dtype=float)
    after = b >= 0.0

    def first(level: float) -> float | None:
        hit = np.flatnonzero(after & (rel >= level))
        return float(b[hit[0]]) if len(hit) else None

    i = int(np.argmax(np.where(after, rel, -np.inf)))
    late = (b >= 5.0) & (b <= 8.0)
    return {
        "t50": first(0.5),
        "t90": first(0.9),
        "peak_pct": round(100.0 * float(rel[i]), 1),
        "t_peak": float(b[i]),
        "late_mean_pct": round(100.0 * float(rel[late].mean()), 1) if late.any() else None,
    }


def step_study(size_deg: float, ramp: float, beats: float = 34.0) -> list[dict[str, Any]]:
    """The rows and the figures (see the module)."""
    from birdsim.flight.bank import bank_of

    flights = []
    for s in (0.0, size_deg):
        with bank_step(s, ramp) as hook:
            flights.append(fly_circle(beats=beats, hook=hook).arrays)
    a0, a1 = flights
    n = min(len(a0["t"]), len(a1["t"]))
    tb = a0["t"][:n] / TWO_PI
    dcmd = np.degrees(np.asarray(a1["bank_command"][:n]) - np.asarray(a0["bank_command"][:n]))
    dbank = np.degrees(bank_of(a1["quat"][:n]) - bank_of(a0["quat"][:n]))

    def mean_about(v: np.ndarray, b: float) -> float:
        return float(v[(tb >= b - 0.5) & (tb < b + 0.5)].mean())

    rows: list[dict[str, Any]] = []
    grid = np.arange(STEP_AT - 1.0, beats - 0.5, 0.25)
    for b in grid:
        rows.append(
            {
                "wingbeat": float(b),
                "bank_command_deg": round(mean_about(dcmd, b), 2),
                "bank_flown_deg": round(mean_about(dbank, b), 2),
                "bank_flown_sample_deg": round(float(dbank[np.argmin(np.abs(tb - b))]), 2),
            }
        )
    flown = np.array([r["bank_flown_deg"] for r in rows])
    rows.append(step_figures(grid - STEP_AT, flown, size_deg))
    return rows


def refuse(message: str) -> None:
    """Bad input: one line on stderr, exit 2."""
    print(message, file=sys.stderr)
    sys.exit(2)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--size", type=float, default=5.0, help="the step (degrees)")
    parser.add_argument("--ramp", type=float, default=0.0, help="smoothstep (wingbeats; 0: raw)")
    parser.add_argument("--set", action="append", default=[], help="MODULE.NAME=VALUE")
    args = parser.parse_args()
    if not (math.isfinite(args.size) and args.size != 0.0):
        refuse(f"--size {args.size!r}: allowed: a finite number of degrees, not 0")
    if not (math.isfinite(args.ramp) and args.ramp >= 0.0):
        refuse(f"--ramp {args.ramp!r}: allowed: a finite number of wingbeats >= 0")
    apply_settings(args.set)
    for row in step_study(args.size, args.ramp):
        print(json.dumps(row))


if __name__ == "__main__":
    main()
