"""The attitude loop's lags at a slow swing of the body (docs/turning.md, "The pigeon's
cruise circle: a faster pitch estimate, a lower turn posture", 2026-12-03, p23p): per
period (wingbeats) of a sinusoidal body motion, the gain and phase of the loop's
wingbeat-mean estimate (the trend of :func:`birdsim.flight.body_attitude.wingbeat_fit_matrix`
now, over ``FIT_BEATS`` wingbeats of ``log_per_beat`` samples), of the whole wingbeat's
mean carried to now by the mean rate (``mean + T/2 mean'``, a phase-consistent estimate
that rejects every harmonic of the wingbeat), and the phase of the inputs' smoothing
(:data:`birdsim.flight.wingbeat.INPUT_SMOOTHING_BEATS`, two first-order stages) and of
the control step's hold (half a step of ``control_per_beat``).  Pure arithmetic, no
flight.

    PYTHONPATH=$PWD python scripts/estimate_response.py --periods 2 3 4 5.3 8
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from birdsim.flight.body_attitude import FIT_BEATS, wingbeat_fit_matrix
from birdsim.flight.simulate import SimConfig
from birdsim.flight.wingbeat import INPUT_SMOOTHING_BEATS


def sample_times(per_beat: int, beats: int = FIT_BEATS) -> np.ndarray:
    """The window's sample times before now in wingbeats (the newest 0), oldest first."""
    n = beats * per_beat
    return -np.arange(n - 1, -1, -1) / per_beat


def fit_response(period_beats: float, per_beat: int) -> complex:
    """The loop's estimate (the fit's trend now) of ``exp(i w t)`` at ``t`` = 0, ``w`` =
    2 pi / ``period_beats`` per wingbeat: gain ``abs`` and phase ``angle`` (rad)."""
    tau = sample_times(per_beat)
    fit = wingbeat_fit_matrix(len(tau), 1.0, beats=FIT_BEATS)[0]
    return complex(fit @ np.exp(2j * math.pi * tau / period_beats))


def mean_response(period_beats: float) -> complex:
    """The last wingbeat's mean plus half a wingbeat times its mean rate, for ``exp(i w
    t)``: ``sinc(w / 2) exp(-i w / 2) (1 + i w / 2)``, zero at every harmonic."""
    half = math.pi / period_beats  # w T / 2, T one wingbeat
    return math.sin(half) / half * complex(math.cos(half), -math.sin(half)) * complex(1.0, half)


def smoothing_phase(period_beats: float, tau_beats: float = INPUT_SMOOTHING_BEATS) -> float:
    """Phase (rad, <= 0) of the inputs' two first-order stages of ``tau_beats``."""
    return -2.0 * math.atan(2.0 * math.pi * tau_beats / period_beats)


def hold_phase(period_beats: float, control_per_beat: int) -> float:
    """Phase (rad, <= 0) of the control step's zero-order hold (half a step's delay)."""
    return -math.pi / (period_beats * control_per_beat)


def rows(periods: list[float], per_beat: int, control_per_beat: int) -> list[tuple]:
    """Per period: (period, fit gain, fit phase deg, mean gain, mean phase deg, smoothing
    phase deg, hold phase deg)."""
    out = []
    for p in periods:
        f, m = fit_response(p, per_beat), mean_response(p)
        out.append(
            (
                p,
                abs(f),
                math.degrees(np.angle(f)),
                abs(m),
                math.degrees(np.angle(m)),
                math.degrees(smoothing_phase(p)),
                math.degrees(hold_phase(p, control_per_beat)),
            )
        )
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--periods", type=float, nargs="+", default=[2.0, 3.0, 4.0, 5.3, 8.0])
    args = parser.parse_args()
    if any(p <= 0 or not math.isfinite(p) for p in args.periods):
        parser.exit(2, f"{parser.prog}: error: periods must be positive wingbeats\n")
    cfg = SimConfig()
    print("period  fit gain/phase  mean+rate gain/phase  smoothing  hold  (wingbeats, deg)")
    for r in rows(args.periods, cfg.log_per_beat, cfg.control_per_beat):
        print(
            f"{r[0]:6.2f}  {r[1]:5.3f} {r[2]:6.1f}     {r[3]:5.3f} {r[4]:6.1f}      {r[5]:6.1f} {r[6]:6.1f}"
        )


if __name__ == "__main__":
    main()
