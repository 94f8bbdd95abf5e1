"""The figures of a turning flight for ``birdsim fly --json`` (any units: the log's).

Per wingbeat (the within-beat bobbing averaged out): the heading of the wingbeat-mean
horizontal velocity, the flown path's centripetal acceleration ``a_c = V dpsi/dt`` (the
heading's change over a wingbeat times the mean horizontal speed), the bank
(:func:`birdsim.flight.bank.bank_of`, about the horizontal heading) and the sideslip
(:func:`birdsim.flight.bank.sideslip_of`, in the body's horizontal plane).  The *steady*
wingbeats are those where the reference turns at (within 2 % of) its largest turn rate
for the whole wingbeat and the one before and after (the ramps left out); there a
coordinated turn has the bank ``atan(a_c / g)`` of the path it flew.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.flight.bank import bank_of, sideslip_of

TWO_PI = 2.0 * math.pi
#: A wingbeat is steady when the reference's turn rate is within this fraction of its
#: largest over it and its neighbours.
STEADY_FRACTION = 0.02
#: A wingbeat counts for the heading change when its mean horizontal speed is above this
#: fraction of the flight's largest.
MOVING_FRACTION = 0.1


def _per_beat(t_beats: np.ndarray, values: np.ndarray, n: int) -> np.ndarray:
    idx = np.floor(t_beats + 1e-9).astype(int)
    return np.array([values[idx == b].mean(axis=0) for b in range(n)])


def turn_series(arrays: dict[str, Any]) -> dict[str, np.ndarray] | None:
    """Per whole wingbeat of a flight whose reference leaves the x-z plane (None for a
    straight one or one shorter than two wingbeats), radians: ``psi`` and ``psi_ref``
    (headings of the flown and reference wingbeat-mean horizontal velocity, unwrapped),
    ``bank`` and ``sideslip`` (wingbeat means), ``speed`` (the mean horizontal speed),
    ``coordinated`` (``atan(a_c / g)`` of the
    flown path, right wing down > 0 as ``bank``), ``steady`` (bool) and ``t_beats`` (the
    middle of each wingbeat)."""
    y_ref = np.asarray(arrays.get("y_ref", np.zeros(1)), dtype=float)
    if not np.any(y_ref != 0.0) or "quat" not in arrays:
        return None
    omega = float(arrays["omega"])
    t = np.asarray(arrays["t"], dtype=float)
    t_beats = t * omega / TWO_PI
    n = int(np.floor(t_beats[-1] + 1e-9))  # whole wingbeats flown
    if n < 2:
        return None
    vel = np.stack([arrays["vx"], arrays["vy"], arrays["vz"]], axis=1).astype(float)
    v = _per_beat(t_beats, vel, n)
    psi = np.unwrap(np.arctan2(v[:, 1], v[:, 0]))
    beat_time = TWO_PI / omega
    # the reference's velocity from its positions (per sample), its heading per wingbeat
    ref = np.stack([arrays["x_ref"], y_ref], axis=1).astype(float)
    ref_v = np.gradient(ref, t, axis=0)
    rv = _per_beat(t_beats, ref_v, n)
    psi_ref = np.unwrap(np.arctan2(rv[:, 1], rv[:, 0]))
    rate_ref = np.abs(np.gradient(psi_ref))
    steady = rate_ref > (1.0 - STEADY_FRACTION) * rate_ref.max()
    steady[1:-1] &= steady[:-2] & steady[2:]
    steady[[0, -1]] = False
    bank = _per_beat(t_beats, bank_of(np.asarray(arrays["quat"], dtype=float)), n)
    slip = _per_beat(t_beats, sideslip_of(np.asarray(arrays["quat"], dtype=float), vel), n)
    a_c = np.hypot(v[:, 0], v[:, 1]) * np.gradient(psi) / beat_time  # to the left
    coordinated = np.arctan2(-a_c, float(arrays["gravity"]))  # seed: right wing down > 0
    return {
        "t_beats": np.arange(n) + 0.5,
        "psi": psi,
        "psi_ref": psi_ref,
        "bank": bank,
        "sideslip": slip,
        "coordinated": coordinated,
        "steady": steady,
        "speed": np.hypot(v[:, 0], v[:, 1]),
    }


def turn_figures(arrays: dict[str, Any]) -> dict[str, Any] | None:
    """Heading change, bank and sideslip of a flight whose reference leaves the x-z
    plane (None for a straight one): degrees, per whole wingbeat (:func:`turn_series`)."""
    series = turn_series(arrays)
    if series is None:
        return None
    psi, psi_ref, steady = series["psi"], series["psi_ref"], series["steady"]
    bank, slip, coordinated = series["bank"], series["sideslip"], series["coordinated"]
    # the heading of a wingbeat at rest (the u-turn's perch) is noise: the change is
    # taken between the first and last wingbeat moving at a tenth of the top speed
    moving = np.flatnonzero(series["speed"] > MOVING_FRACTION * series["speed"].max())
    first, last = (int(moving[0]), int(moving[-1])) if len(moving) else (0, len(psi) - 1)
    out: dict[str, Any] = {
        "heading_change_deg": math.degrees(psi[last] - psi[first]),
        "heading_change_reference_deg": math.degrees(psi_ref[last] - psi_ref[first]),
        "steady_wingbeats": int(steady.sum()),
        "bank_max_deg": float(np.degrees(np.abs(bank)).max()),
        "sideslip_max_deg": float(np.degrees(np.abs(slip)).max()),
    }
    if steady.any():
        d_bank = np.degrees(bank[steady] - coordinated[steady])
        out.update(
            {
                "steady_bank_deg": float(np.degrees(np.mean(bank[steady]))),
                "steady_coordinated_bank_deg": float(np.degrees(np.mean(coordinated[steady]))),
                "steady_bank_error_max_deg": float(np.abs(d_bank).max()),
                "steady_sideslip_max_deg": float(np.degrees(np.abs(slip[steady])).max()),
            }
        )
    return out


__all__ = ["turn_figures", "turn_series"]
