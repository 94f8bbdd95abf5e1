"""The turning rows' birdsim values (issue 23 item 5): the slow level 90-degree turn
(``birdsim fly turn-90``, attitude free, model m3) read as Ros et al. 2011, Hedrick &
Biewener 2007 and Warrick & Dial 1998 read their birds.

The rows are the pigeon's; when the pigeon cannot fly the turn yet (a saturated sample
or a path RMS beyond the issue's 0.1 semispan), the seed bird's turn is used instead,
its lengths scaled to the pigeon by the semispans (every other value is an angle or a
yes/no, the same in any units), and :func:`turn_values` says so (``source``).

Per whole wingbeat of the turn (the wingbeats where the reference turns faster than
:data:`TURNING_FRACTION` of its largest rate), in the body's axes (MuJoCo: x forward,
y left, z dorsal):

* the wingbeat-mean aerodynamic force (the log's whole-bird force minus the weight)
  and its direction; *fixed in the body* when every wingbeat's direction lies within
  :data:`FIXED_DEG` of their mean (birdsim's criterion, stated in the data file);
* its angle forward of the dorsal axis (the mean direction), shown beside Ros's cone;
* the radius of the steady turn: the mean horizontal speed over the heading's rate;
* the heading's change per wingbeat against the roll (bank) at mid-downstroke (phase 0
  of the wingbeat, the sample nearest it): yes when they correlate with the turn's
  sign (the bank into the turn) with r^2 > :data:`R2_MIN`;
* the bank started and arrested within one downstroke: yes when, in the wingbeats of
  the roll-in, the body's roll rate rises and falls back to within 10 % of its peak
  inside the downstroke half of the wingbeat (phase -pi/2 to pi/2). The attitude loop
  acts on wingbeat means, so no is the expected answer.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird

#: The model the turning flight uses (the turning presets are laid out for it).
TURN_MODEL = "m3"
#: A wingbeat belongs to the turn when the reference turns faster than this fraction of
#: its largest rate.
TURNING_FRACTION = 0.5
#: Largest angle (degrees) of a wingbeat's force direction from the mean: "fixed".
FIXED_DEG = 5.0
#: Smallest r^2 of heading change per wingbeat against the roll at mid-downstroke.
R2_MIN = 0.5
#: A flight meets the issue's tracking target: path RMS after two wingbeats at most
#: this (semispans) with no saturated sample.
RMS_TARGET = 0.1


def _quat_matrix(q: np.ndarray) -> np.ndarray:
    w, x, y, z = np.moveaxis(np.asarray(q, dtype=float), -1, 0)
    return np.stack(
        [
            np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
            np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
            np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
        ],
        axis=-2,
    )


def turn_readings(log: dict[str, Any]) -> dict[str, float]:
    """The turning rows' quantities from a turning flight's log (``log_arrays``):
    ``force_spread_deg``, ``force_angle_deg``, ``radius`` (the log's length unit),
    ``heading_roll_r2`` (signed: negative when they correlate against the turn),
    ``bank_in_downstroke`` (1 or 0)."""
    from birdsim.flight.bank import bank_of
    from birdsim.flight.turn_summary import turn_series

    series = turn_series(log)
    if series is None:
        raise BirdsimError("turn_readings: the log is not of a turning flight")
    omega = float(log["omega"])
    t = np.asarray(log["t"], dtype=float)
    phase = t * omega  # rad; 0 = mid-downstroke
    beat = np.floor(phase / (2 * math.pi) + 1e-9).astype(int)
    n = len(series["psi"])
    rate_ref = np.abs(np.gradient(series["psi_ref"]))
    turning = rate_ref > TURNING_FRACTION * rate_ref.max()
    # the wingbeat-mean aerodynamic force in body axes
    weight = float(log["mass"]) * float(log["gravity"])
    force = np.stack([log["force_x"], log["force_y"], log["force_z"]], axis=1).astype(float)
    force[:, 2] += weight  # the log's force includes the weight (world z up)
    rot = _quat_matrix(np.asarray(log["quat"], dtype=float))
    f_body = np.einsum("nji,nj->ni", rot, force)
    beats = [b for b in range(n) if turning[b]]
    means = np.array([f_body[beat == b].mean(axis=0) for b in beats])
    unit = means / np.linalg.norm(means, axis=1, keepdims=True)
    mean_dir = unit.mean(axis=0)
    mean_dir /= np.linalg.norm(mean_dir)
    spread = np.degrees(np.arccos(np.clip(unit @ mean_dir, -1.0, 1.0))).max()
    angle = math.degrees(math.atan2(mean_dir[0], mean_dir[2]))
    # the steady turn's radius: horizontal speed over the heading's rate
    vel = np.stack([log["vx"], log["vy"]], axis=1).astype(float)
    period = 2 * math.pi / omega
    speed = np.array([np.hypot(*vel[beat == b].mean(axis=0)) for b in range(n)])
    dpsi = np.gradient(series["psi"]) / period
    # (the turn-90 has hardly a steady wingbeat: its 5-wingbeat ramps take 80 % of the
    # heading change; the wingbeats within 10 % of the largest rate stand for it)
    steady = series["steady"] if series["steady"].any() else rate_ref > 0.9 * rate_ref.max()
    radius = float(np.mean(speed[steady] / np.abs(dpsi[steady])))
    # heading change per wingbeat against the bank at mid-downstroke (seed: right wing
    # down > 0, so a left turn banks < 0): signed by the turn's direction
    bank = bank_of(np.asarray(log["quat"], dtype=float))
    mid = [int(np.argmin(np.abs(phase - 2 * math.pi * b))) for b in range(n)]
    change = np.diff(series["psi"])
    roll_mid = -bank[mid][1:]
    r = float(np.corrcoef(change, roll_mid)[0, 1]) if np.std(roll_mid) > 0 else 0.0
    turn_sign = math.copysign(1.0, series["psi_ref"][-1] - series["psi_ref"][0])
    r2 = math.copysign(r * r, r * turn_sign)
    # the roll rate within the downstroke in the wingbeats of the roll-in
    w_body = np.asarray(log["omega_body"], dtype=float)  # seed body axes (p, q, r)
    roll_in = [b for b in range(n) if turning[b]][:2]
    arrested = []
    for b in roll_in:
        down = (beat == b) & (np.cos(phase) > 0.0)
        p = w_body[down, 0] * turn_sign
        if len(p) < 3:
            continue
        peak = np.abs(p).max()
        arrested.append(peak > 0 and abs(p[0]) < 0.1 * peak and abs(p[-1]) < 0.1 * peak)
    return {
        "force_spread_deg": float(spread),
        "force_angle_deg": angle,
        "radius": radius,
        "heading_roll_r2": r2,
        "bank_in_downstroke": float(bool(arrested) and all(arrested)),
    }


def _fly_turn(bird: Bird) -> tuple[dict[str, Any], dict[str, Any]]:
    from birdsim.commands.common import load_table_for
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import fly
    from birdsim.flight.simulate import SimConfig
    from birdsim.flight.turn_presets import TURN_PRESETS

    table = load_table_for(bird, TURN_MODEL, None)
    path = TURN_PRESETS["turn-90"]
    r = fly(path, table, bird, TURN_MODEL, config=SimConfig(attitude="free"))
    log = log_arrays(r, path.name)
    return log, summary(log)


_CACHE: dict[str, tuple[dict[str, float], str]] = {}


def turn_values(bird: Bird) -> tuple[dict[str, float], str]:
    """birdsim's values of the turning rows by compare key (in the rows' units) and the
    flight they come from (one line); ({}, why) when neither the bird nor the seed bird
    flies the turn.  Remembered per bird (the flights are deterministic)."""
    key = repr(bird)
    if key not in _CACHE:
        _CACHE[key] = _turn_values(bird)
    values, source = _CACHE[key]
    return dict(values), source


def _turn_values(bird: Bird) -> tuple[dict[str, float], str]:
    from birdsim.flight.presets import demo_bird

    source, scale = f"{bird.name} turn-90", 1.0
    try:
        log, info = _fly_turn(bird)
        flown = info["saturated_samples"] == 0 and info["rms_error_after_start"] <= (
            RMS_TARGET * bird.semispan
        )
    except BirdsimError:
        flown = False
    if not flown:
        seed = demo_bird()
        try:
            log, info = _fly_turn(seed)
        except BirdsimError as exc:
            return {}, f"turn-90 not flown ({exc})"
        source = f"the seed bird's turn-90 scaled to {bird.name} ({bird.name} does not fly it yet)"
        scale = bird.semispan / seed.semispan
    g = turn_readings(log)
    values = {
        "turn_force_fixed_in_body": float(g["force_spread_deg"] <= FIXED_DEG),
        "turn_force_angle_in_body": g["force_angle_deg"],
        "turn_radius": g["radius"] * scale,
        "turn_heading_rate_follows_roll": float(g["heading_roll_r2"] > R2_MIN),
        "turn_bank_within_downstroke": g["bank_in_downstroke"],
    }
    detail = (
        f"; force spread {g['force_spread_deg']:.1f} deg, heading-roll r^2 "
        f"{g['heading_roll_r2']:.2f}, path RMS {info['rms_error_after_start']:.3g}, "
        f"{info['saturated_samples']} saturated samples"
    )
    return values, source + detail


__all__ = ["TURN_MODEL", "turn_readings", "turn_values"]
