"""The wingbeat-mean pitching moment a turning preset's pitch loop flies on
(docs/turning.md, "The pigeon's cruise circle: what the 5.3-wingbeat pitch swing is",
2026-12-03): the preset flown free (m3), and at the attitude loop's first Jacobian
measurement from wingbeat ``--at`` on, the held body at its wingbeat and airspeed pitched
about the command: the rocking's rectified pitching moment
(:func:`birdsim.flight.pitch_rocking.rocking_pitch_moment`, table units, > 0 nose up),
the rocking's peak to peak (degrees), the held body's mean pitching moment and its static
pitch stiffness (:func:`birdsim.flight.attitude_stiffness.measured_pitch_stiffness`, per
rad, < 0 restoring).  A positive sum of the two slopes larger than the loop's ``Kp I`` is
a branch the loop does not hold.

    PYTHONPATH=$PWD python scripts/turn_pitch_branch.py circle --bird models/pigeon.toml --at 38
"""

from __future__ import annotations

import argparse
from typing import Any

import numpy as np

#: Pitch offsets from the measured command (rad) the held body is measured at.
OFFSETS = (-0.3, -0.2, -0.1, -0.05, 0.0, 0.05, 0.1, 0.2)


def branch_rows(fb: Any, params: np.ndarray, pitch: float, speed: float, inertia: float) -> list:
    """Per :data:`OFFSETS`: (held pitch deg, rectified moment, rocking peak to peak deg,
    held mean pitching moment, held stiffness per rad), reduced units."""
    from birdsim.flight.attitude_stiffness import _mean_moment, measured_pitch_stiffness
    from birdsim.flight.pitch_rocking import rocking_pitch_moment

    rows = []
    for dp in OFFSETS:
        th = pitch + dp
        m, ptp = rocking_pitch_moment(fb, params, th, speed, inertia)
        k = measured_pitch_stiffness(fb, params, th, speed)
        m0 = float(_mean_moment(fb, params, th, speed)[1])
        rows.append((float(np.degrees(th)), m, float(np.degrees(ptp)), m0, k))
    return rows


def main() -> None:
    from turn_coupling_study import TURN_NAMES, fly_preset, or_exit

    from birdsim.flight import attitude

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("preset", choices=TURN_NAMES, help="turning preset")
    parser.add_argument("--bird", default=None, help="bird file (default: the seed bird)")
    parser.add_argument("--at", type=float, default=38.0, help="wingbeat to measure from")
    args = parser.parse_args()
    measure, done = attitude.AttitudeLoop._measure, []

    def measured(self: Any, params: np.ndarray, pitch: float, speed: float, turn: Any) -> Any:
        out = measure(self, params, pitch, speed, turn)
        beat = self.fb.time / self.fb.red.period
        if not done and beat >= args.at:
            done.append(beat)
            print(f"wingbeat {beat:.1f}: pitch {np.degrees(pitch):.1f} deg, V {speed:.3f}")
            print("held pitch (deg) | rectified moment | rocking p-p (deg) | held M0 | stiffness")
            for row in branch_rows(self.fb, params, pitch, speed, float(self.inertia[1])):
                print("{:6.1f} | {:+.5f} | {:5.1f} | {:+.5f} | {:+.5f}".format(*row))
        return out

    attitude.AttitudeLoop._measure = measured
    try:
        or_exit(parser, lambda: fly_preset(args.bird, args.preset))
    finally:
        attitude.AttitudeLoop._measure = measure


if __name__ == "__main__":
    main()
