"""Is issue 23's gust target reachable?  "A side gust of 30 % for one wingbeat during
``circle``: back within 0.05 semispan in at most 8 wingbeats", bounded two ways (seed
bird, m3, attitude free; reduced units: semispans, time 2 pi per wingbeat).

``PYTHONPATH=. python scripts/turn_gust_bound.py`` flies the calm circle and the four
gusts of ``scripts/turn_gust_study.py`` (from wingbeat 25, 25.25, 25.5, the mirror) and
prints one JSON line:

* ``authority``: the reduced gravity g, the plan's steady bank phi0 = atan(a_c / g), the
  sideways acceleration (relative to the turn's) that a bank change gives with the vertical
  force held, ``g (tan(phi0 + d) - tan(phi0))``: at the lateral loop's bound
  ``turning.BANK_CORRECTION_MAX`` inwards and outwards, and wings level (d = -phi0).
* per gust, ``state``: the gusted flight minus the calm one at the gust's end (one-wingbeat
  means; ``y`` to the left of the calm heading, the circle's inside, and its rate ``v``;
  the height ``z``); ``physics``: the least time (wingbeats after the gust's end) in which
  a bang-bang sideways acceleration within that authority brings the offset to rest
  within 0.05 semispan after a dead time D (the bird drifting at ``v`` meanwhile; D = 0,
  1, 2 wingbeats); ``state_2_later`` and ``physics_2_later``: the same from the state two
  wingbeats after the gust's end (what the flown loop has made of it by then; D = 0), also
  with the outward authority of rolling to wings level; ``loop``: the same state under the turn's lateral loop
  (``bank.lateral_acceleration``, a triple pole of ``bank.LATERAL_BEATS`` with its
  integral) on a double integrator behind a dead time D, bounded at the same
  authority: the wingbeats until it stays within 0.05 (the model
  of docs/turning.md's fifth gust pass), for the turn's 6 wingbeats and for 4 (null: not
  within 40 wingbeats).

Every time is in wingbeats after the gust's start (the target: 8).  The bounds use only
the lateral axis: the height and the along-track distance are left
to their own loops (their errors at the gust's end are printed).
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np
from turn_gust_study import GUSTS, WITHIN, fly_circle, left_of

TWO_PI = 2.0 * math.pi
BACK_BEATS = 8.0


def min_rest_time(y: float, v: float, a_pos: float, a_neg: float, within: float) -> float:
    """The least time (reduced) that brings a double integrator from offset ``y`` and rate
    ``v`` to rest (``v = 0``) at an offset within ``+-within``, its acceleration bang-bang
    between ``+a_pos`` and ``-a_neg`` (both > 0): the least over the rest points
    ``yt`` in ``[-within, within]`` of the two one-switch sequences."""
    best = math.inf
    for yt in np.linspace(-within, within, 201):
        for u1, u2 in ((a_pos, -a_neg), (-a_neg, a_pos)):
            # phase 1 at u1 from v to the switch's rate vm, phase 2 at u2 from vm to 0:
            # (vm^2 - v^2) / (2 u1) - vm^2 / (2 u2) = yt - y
            coef = 1.0 / (2.0 * u1) - 1.0 / (2.0 * u2)
            vm2 = (yt - y + v * v / (2.0 * u1)) / coef
            if vm2 < 0.0:
                continue
            vm = -math.copysign(math.sqrt(vm2), u2)  # phase 2 decelerates vm
            t1, t2 = (vm - v) / u1, -vm / u2
            if t1 >= -1e-12 and t2 >= -1e-12:
                best = min(best, max(t1, 0.0) + max(t2, 0.0))
    return best


def loop_settle_time(
    y: float,
    v: float,
    beats: float,
    delay: float,
    a_pos: float,
    a_neg: float,
    within: float = WITHIN,
    horizon: float = 40.0,
    per_beat: int = 256,
) -> float | None:
    """Wingbeats until a double integrator from ``(y, v)`` under the turn's lateral loop
    (``bank.lateral_acceleration`` with ``LATERAL_BEATS = beats``), its command arriving
    ``delay`` wingbeats late and bounded to ``[-a_neg, a_pos]``, stays within ``within``
    (None if it does not by ``horizon``)."""
    from birdsim.flight import bank

    old = bank.LATERAL_BEATS
    bank.LATERAL_BEATS = beats
    try:
        dt = TWO_PI / per_beat
        n, k = int(horizon * per_beat), int(round(delay * per_beat))
        pipe = [0.0] * (k + 1)
        integral, ys = 0.0, np.empty(n)
        for i in range(n):
            integral += dt * y
            pipe.append(min(max(bank.lateral_acceleration(y, v, integral), -a_neg), a_pos))
            a = pipe.pop(0)
            y, v = y + dt * v + 0.5 * dt * dt * a, v + dt * a
            ys[i] = y
    finally:
        bank.LATERAL_BEATS = old
    out = np.flatnonzero(np.abs(ys) > within)
    if not len(out):
        return 0.0
    return None if out[-1] == n - 1 else float((out[-1] + 1) / per_beat)


def authority() -> dict[str, float]:
    """The sideways acceleration a bank change gives about the circle's steady bank."""
    from birdsim.commands.common import load_bird
    from birdsim.flight.track import TrackFrame
    from birdsim.flight.turn_presets import TURN_PRESETS
    from birdsim.flight.turning import BANK_CORRECTION_MAX
    from birdsim.physics.units import reduced_bird

    g = reduced_bird(load_bird(None)).gravity
    track = TrackFrame(TURN_PRESETS["circle"], 60 * TWO_PI, g)
    a_c = abs(track.state(25.0 * TWO_PI).a_lat)
    phi0 = math.atan(a_c / g)
    d = BANK_CORRECTION_MAX
    return {
        "gravity": g,
        "a_c": a_c,
        "bank_deg": math.degrees(phi0),
        "inward_at_bound": g * (math.tan(phi0 + d) - math.tan(phi0)),
        "outward_at_bound": g * (math.tan(phi0) - math.tan(phi0 - d)),
        "outward_wings_level": a_c,
    }


def gust_state(calm: dict, gusted: dict, end: float) -> dict[str, float]:
    """Gusted minus calm at wingbeat ``end`` (one-wingbeat means): the offset to the left
    of the calm heading and its rate, the along-track distance, the height."""
    n = min(len(calm["t"]), len(gusted["t"]))
    fwd, left = left_of(calm, n)
    dp = np.stack([gusted[k][:n] - calm[k][:n] for k in ("x", "y")], 1)
    dv = np.stack([gusted[k][:n] - calm[k][:n] for k in ("vx", "vy")], 1)
    tb = calm["t"][:n] / TWO_PI
    m = (tb >= end - 0.5) & (tb < end + 0.5)
    return {
        "y": float((dp * left).sum(1)[m].mean()),
        "v": float((dv * left).sum(1)[m].mean()),
        "along": float((dp * fwd).sum(1)[m].mean()),
        "z": float((gusted["z"][:n] - calm["z"][:n])[m].mean()),
    }


def bound_study() -> dict[str, Any]:
    auth = authority()
    a_in, a_out = auth["inward_at_bound"], auth["outward_at_bound"]
    calm = fly_circle(beats=36).arrays
    out: dict[str, Any] = {"authority": {k: round(v, 6) for k, v in auth.items()}}
    for name, gust in GUSTS.items():
        start, duration = (float(s) for s in gust.split(":")[:2])
        gusted = fly_circle(beats=36, gust=gust).arrays
        st = gust_state(calm, gusted, start + duration)
        phys, loop = {}, {}
        for d in (0.0, 1.0, 2.0):
            y1 = st["y"] + st["v"] * d * TWO_PI  # drifting through the dead time
            t = min_rest_time(y1, st["v"], a_in, a_out, WITHIN) / TWO_PI
            phys[f"D{d:g}"] = round(duration + d + t, 2)
            for beats in (6.0, 4.0):
                t = loop_settle_time(st["y"], st["v"], beats, d, a_in, a_out)
                loop[f"L{beats:g}_D{d:g}"] = None if t is None else round(duration + t, 2)
        # two wingbeats later: the state the flown loop has built by then, from rest of
        # the dead time (D = 0)
        late = gust_state(calm, gusted, start + duration + 2.0)
        t_late = min_rest_time(late["y"], late["v"], a_in, a_out, WITHIN) / TWO_PI
        t_level = min_rest_time(late["y"], late["v"], a_in, auth["outward_wings_level"], WITHIN)
        out[name] = {
            "state": {k: round(v, 4) for k, v in st.items()},
            "physics": phys,
            "loop": loop,
            "state_2_later": {k: round(v, 4) for k, v in late.items()},
            "physics_2_later": round(duration + 2.0 + t_late, 2),
            "physics_2_later_wings_level": round(duration + 2.0 + t_level / TWO_PI, 2),
        }
    return out


if __name__ == "__main__":
    print(json.dumps(bound_study()))
