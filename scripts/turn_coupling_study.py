"""Where the seed bird's calm ``circle`` leaves its path (docs/turning.md, "The calm circle's
swing: the height loop's sideways share", 2026-12-03): per wingbeat the error along the
track, to the left and in height (semispans), the lateral loop's state (its wingbeat fit
of the side offset, the side offset's integral, its sideways correction ``a_corr``, to the
left) and the path loop's vertical correction ``dv`` (its integral term ``dv_int`` apart)
with the part of it that the banked force turns sideways, ``dv sin|bank|``: the path loop
adds ``dv`` to the force's magnitude at the bank planned without it (``freeflight.fly``'s
turning ``command``), so a push up of ``dv`` comes out ``dv cos(bank)`` up and ``dv
sin(bank)`` into the turn (reduced accelerations, to the left).

    PYTHONPATH=$PWD python scripts/turn_coupling_study.py [--set MODULE.NAME=VALUE ...]
    PYTHONPATH=$PWD python scripts/turn_coupling_study.py --bird models/pigeon.toml --preset s-turn

Prints one line per wingbeat, then per window of wingbeats (2-33, 33-53, 53-end) the
largest 3-D error, where, and the RMS; ``--set`` as ``turn_gust_study.py``'s. ``--bird``
and ``--preset`` fly another bird (m3, free) or turning preset: lengths in the log's
units (semispans), accelerations reduced, as for the seed bird.
"""

from __future__ import annotations

import argparse
import math
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError

TWO_PI = 2.0 * math.pi
#: The turning presets a study can fly (birdsim.flight.turn_presets.TURN_PRESETS).
TURN_NAMES = ("circle", "s-turn", "turn-90", "u-turn")
#: Windows of wingbeats the summary reports (the roll-in's swing, the steady turn after the
#: gust study's 8 wingbeats, the roll-out).
WINDOWS = ((2.0, 33.0), (33.0, 53.0), (53.0, math.inf))


def per_beat(steps: np.ndarray) -> np.ndarray:
    """Per whole wingbeat ``b`` the means of the control steps' records ``steps`` (n, 8:
    wingbeat, y, vy, integral, a_corr, dv, dv_int, bank command) in that wingbeat, with
    the sideways part of the vertical correction ``dv sin|bank|`` appended (rows (b, 9):
    b, y, vy, integral, a_corr, dv, dv_int, bank, leak)."""
    rows = []
    for b in range(int(np.floor(steps[:, 0].max())) + 1):
        m = (steps[:, 0] >= b) & (steps[:, 0] < b + 1)
        if m.any():
            r = steps[m].mean(0)
            leak = float(np.mean(steps[m, 5] * np.abs(np.sin(steps[m, 7]))))
            rows.append([b, *r[1:], leak])
    return np.array(rows)


def fly_preset(bird_file: str | None = None, preset: str = "circle", model: str = "m3") -> Any:
    """``preset`` (a turning preset) flown free with ``model`` (default m3) by the bird of
    ``bird_file`` (None: the seed bird; ``turn_gust_study.fly_circle`` for the seed's circle)."""
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.freeflight import fly
    from birdsim.flight.simulate import SimConfig
    from birdsim.flight.turn_presets import TURN_PRESETS

    bird = load_bird(bird_file)
    table = load_table_for(bird, model, None)
    return fly(TURN_PRESETS[preset], table, bird, model, config=SimConfig(attitude="free"))


def or_exit(parser: Any, call: Any) -> Any:
    """``call()``, with a user's mistake (a :class:`BirdsimError`, e.g. a bad bird file)
    reported in one line and exit 2, as the ``birdsim`` commands do."""
    try:
        return call()
    except BirdsimError as exc:
        parser.exit(2, f"{parser.prog}: error: {exc}\n")


def fly_recorded(bird_file: str | None = None, preset: str = "circle") -> tuple[Any, np.ndarray]:
    """The calm ``preset`` (:func:`fly_preset`) with the lateral loop's and the path loop's
    vertical correction recorded per control step (see :func:`per_beat`)."""
    from birdsim.flight import bank, controller, freeflight

    steps: list[list[float]] = []
    vertical = [0.0, 0.0]
    turn_command, command = freeflight.turn_command, controller.Controller.command

    def recorded_command(self: Any, ref: Any, est: Any, integral: Any, *a: Any, **k: Any) -> Any:
        c = command(self, ref, est, integral, *a, **k)
        vertical[:] = [c.a_cmd[1] - float(ref.az), self.gains.ki * float(integral[1])]
        return c

    def recorded_turn(track: Any, t: float, window: list, per: int, *a: Any, **k: Any) -> Any:
        y, vy = bank.lateral_fit(window, per)
        cmd, a_left, state = turn_command(track, t, window, per, *a, **k)
        lat_integral = a[4] if len(a) > 4 else k["lat_integral"]
        a_corr = a_left - track.state(t).a_lat
        steps.append([t / TWO_PI, y, vy, lat_integral[0], a_corr, *vertical, cmd.bank])
        return cmd, a_left, state

    freeflight.turn_command = recorded_turn  # type: ignore[assignment]
    controller.Controller.command = recorded_command  # type: ignore[method-assign]
    try:
        result = fly_preset(bird_file, preset)
    finally:
        freeflight.turn_command = turn_command  # type: ignore[assignment]
        controller.Controller.command = command  # type: ignore[method-assign]
    return result, np.array(steps)


def main() -> None:
    from turn_gust_study import apply_settings, calm_figures

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--set", action="append", default=[], help="MODULE.NAME=VALUE")
    parser.add_argument("--bird", default=None, help="bird file (default: the seed bird)")
    parser.add_argument("--preset", default="circle", choices=TURN_NAMES, help="turning preset")
    args = parser.parse_args()
    apply_settings(args.set)
    result, steps = or_exit(parser, lambda: fly_recorded(args.bird, args.preset))
    a = {k: np.asarray(v) for k, v in result.arrays.items()}
    tb = a["t"] / TWO_PI
    e = np.stack([a["x"] - a["x_ref"], a["y"] - a["y_ref"], a["z"] - a["z_ref"]], 1)
    psi = np.arctan2(np.gradient(a["y_ref"]), np.gradient(a["x_ref"]))
    along = np.cos(psi) * e[:, 0] + np.sin(psi) * e[:, 1]
    left = -np.sin(psi) * e[:, 0] + np.cos(psi) * e[:, 1]
    print(
        " wb   along    left  height |   y_fit  integral    a_corr |       dv   dv_int  dv sin|bank|"
    )
    for r in per_beat(steps):
        s = (tb >= r[0]) & (tb < r[0] + 1)
        print(
            f"{int(r[0]):3d} {along[s].mean():+.4f} {left[s].mean():+.4f} {e[s, 2].mean():+.4f} |"
            f" {r[1]:+.4f} {r[3]:+8.3f} {r[4]:+.6f} | {r[5]:+.6f} {r[6]:+.6f} {r[8]:+.6f}"
        )
    e3 = np.linalg.norm(e, axis=1)
    for lo, hi in WINDOWS:
        m = (tb >= lo) & (tb < hi)
        i = np.flatnonzero(m)[int(np.argmax(e3[m]))]
        rms = float(np.sqrt(np.mean(e3[m] ** 2)))
        print(f"wingbeats {lo:g}-{hi:g}: largest {e3[i]:.4f} at {tb[i]:.2f}, RMS {rms:.4f}")
    print(calm_figures(result))


if __name__ == "__main__":
    main()
