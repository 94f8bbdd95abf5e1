"""The side gust in the circle (issue 23's unmet target), measured as docs/turning.md's
gust passes measure it: seed bird, m3, attitude free, the ``circle`` preset.

``python scripts/turn_gust_study.py`` flies the calm circle and the circle with a side gust
of 0.15 (30 % of the cruise speed) for one wingbeat from wingbeat 25, 25.25, 25.5 and the
mirror gust from 25, and prints one JSON line: the calm circle's path RMS after two
wingbeats (semispans), saturated samples and steady bank miss (degrees, ``turn_figures``),
and per gust the distance from the calm flight (semispans, 3-D): its peak, its largest
value from 8 wingbeats after the gust on (the target: below 0.05), the wingbeats after the
gust until it stays within 0.05 (the flight's end if never), its mean, and the largest
height difference; and that distance's parts from 8 wingbeats after the gust on (the
largest of each: along the calm flight's horizontal heading, to its left, and height);
and, from 8 wingbeats after the gust on, the largest distance from the calm flight's
*track* (``after_8_track``: the nearest point of the calm flight's 3-D trajectory within
:data:`TRACK_BEATS` wingbeats either side, not the calm flight at the same time: an
along-track lag alone does not count there; docs/turning.md, "Gust stage, fourteenth
pass").

``--step DA`` measures the lateral loop's plant instead: two calm circles with the lateral
loop opened at wingbeat 20 (its correction held at 0), one of them with DA (reduced
acceleration, to the left) added to the commanded sideways acceleration over wingbeats
25-30; printed per half wingbeat: the commanded and the flown bank's difference (degrees),
the flown sideways acceleration's difference over DA (from the one-wingbeat mean of the
sideways velocity), the height's difference.

``--phases 16`` flies 16 gusts instead (from wingbeat 25 + k / 8, k = 0-7, both signs, as
docs/turning.md's ninth pass) and prints the mean, median and largest over them of the
distance 8 wingbeats after the gust, of its three parts and of the distance from the calm
flight's track, and how many gusts each measure has within 0.05; ``--per-beat`` adds, per
gust, the one-wingbeat means of the along-track, lateral and height offsets from the calm
flight over wingbeats 0-16 after the gust.

``--set MODULE.NAME=VALUE`` (repeatable) sets a module constant first, e.g. ``--set
birdsim.flight.bank.LATERAL_BEATS=5``, ``--set
birdsim.flight.turning.TURN_AXIS_BEATS=(1.0,3.0,2.0)``.
"""

from __future__ import annotations

import argparse
import ast
import importlib
import json
import math
from typing import Any

import numpy as np

TWO_PI = 2.0 * math.pi
GUSTS = {
    "25": "25:1:0:0.15:0",
    "25.25": "25.25:1:0:0.15:0",
    "25.5": "25.5:1:0:0.15:0",
    "mirror": "25:1:0:-0.15:0",
}
WITHIN = 0.05  # semispans
BACK_BEATS = 8.0
#: The calm flight's trajectory searched this many wingbeats either side of the same time
#: for the nearest point (:func:`track_distance`).
TRACK_BEATS = 4.0
#: Wingbeats after the gust whose one-wingbeat mean offsets ``--per-beat`` prints.
PER_BEAT = 17


def fly_circle(beats: float | None = None, gust: str | None = None, hook: Any = None) -> Any:
    """The seed bird's ``circle`` (m3, free), optionally with ``gust`` (the CLI's form)."""
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.freeflight import fly, parse_gust
    from birdsim.flight.simulate import SimConfig
    from birdsim.flight.turn_presets import TURN_PRESETS

    bird = load_bird(None)
    table = load_table_for(bird, "m3", None)
    gusts = [parse_gust(gust)] if gust else []
    cfg = SimConfig(attitude="free")
    return fly(
        TURN_PRESETS["circle"],
        table,
        bird,
        "m3",
        config=cfg,
        beats=beats,
        gusts=gusts,
        control_hook=hook,
    )


def left_of(calm: dict, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The calm flight's horizontal heading (cos, sin) per sample: (along, left) axes."""
    psi = np.arctan2(calm["vy"][:n], calm["vx"][:n])
    return np.stack([np.cos(psi), np.sin(psi)], 1), np.stack([-np.sin(psi), np.cos(psi)], 1)


def track_distance(
    calm: np.ndarray, flown: np.ndarray, tb: np.ndarray, at: np.ndarray
) -> np.ndarray:
    """The 3-D distance of ``flown[i]`` (positions (n, 3), semispans) from the calm
    flight's trajectory ``calm`` (the same samples' times ``tb``, wingbeats) for each index
    ``i`` of ``at``: the nearest point of the polyline through the calm positions within
    :data:`TRACK_BEATS` wingbeats of ``tb[i]``."""
    out = np.empty(len(at))
    for j, i in enumerate(at):
        near = np.flatnonzero(np.abs(tb - tb[i]) <= TRACK_BEATS)
        a, b = calm[near[:-1]], calm[near[1:]]
        ab = b - a
        u = np.clip(((flown[i] - a) * ab).sum(1) / np.maximum((ab * ab).sum(1), 1e-30), 0.0, 1.0)
        out[j] = float(np.linalg.norm(a + u[:, None] * ab - flown[i], axis=1).min())
    return out


def per_beat_offsets(tb: np.ndarray, parts: dict[str, np.ndarray], start: float) -> list:
    """One-wingbeat means of the offsets ``parts`` (along, lateral, height) over wingbeats
    ``k`` to ``k + 1`` after ``start``, k = 0 .. :data:`PER_BEAT` - 1."""
    rows = []
    for k in range(PER_BEAT):
        m = (tb >= start + k) & (tb < start + k + 1)
        if m.any():
            rows.append([round(float(v[m].mean()), 3) for v in parts.values()])
    return rows


def gust_figures(calm: dict, gusted: dict, start: float) -> dict[str, Any]:
    """Distance figures of ``gusted`` from ``calm`` (reduced arrays) after ``start`` (wingbeats)."""
    n = min(len(calm["t"]), len(gusted["t"]))
    d = np.sqrt(sum((gusted[k][:n] - calm[k][:n]) ** 2 for k in ("x", "y", "z")))
    tb = calm["t"][:n] / TWO_PI
    after = tb >= start
    out = np.flatnonzero(after & (d > WITHIN))
    along, left = left_of(calm, n)
    dxy = np.stack([gusted["x"][:n] - calm["x"][:n], gusted["y"][:n] - calm["y"][:n]], 1)
    late = tb >= start + BACK_BEATS
    parts = {
        "after_8_along": (dxy * along).sum(1),
        "after_8_lateral": (dxy * left).sum(1),
        "after_8_height": gusted["z"][:n] - calm["z"][:n],
    }
    pos = [np.stack([a[k][:n] for k in ("x", "y", "z")], 1) for a in (calm, gusted)]
    track = track_distance(pos[0], pos[1], tb, np.flatnonzero(late))
    return {
        "peak": round(float(d[after].max()), 4),
        "after_8": round(float(d[tb >= start + BACK_BEATS].max()), 4),
        "back_within_0.05": round(float(tb[out[-1]] - start), 2) if len(out) else 0.0,
        "mean": round(float(d[after].mean()), 4),
        "height_max": round(float(np.abs(gusted["z"][:n] - calm["z"][:n])[after].max()), 4),
        "saturated": int(np.sum(np.asarray(gusted["saturated"], dtype=bool))),
        **{k: round(float(np.abs(v[late]).max()), 4) for k, v in parts.items()},
        "after_8_track": round(float(track.max()), 4),
        "per_beat": per_beat_offsets(tb, parts, start),
    }


def calm_figures(result: Any) -> dict[str, Any]:
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.turn_summary import turn_figures

    arrays = log_arrays(result, "circle")
    s, turn = summary(arrays), turn_figures(arrays) or {}
    return {
        "path_rms": s["rms_error_after_start"],
        "saturated": s["saturated_samples"],
        "steady_bank_miss_deg": turn.get("steady_bank_error_max_deg"),
    }


def gust_study() -> dict[str, Any]:
    calm = fly_circle()
    out: dict[str, Any] = {"circle": calm_figures(calm)}
    for name, gust in GUSTS.items():
        gusted = fly_circle(gust=gust)
        out[name] = gust_figures(calm.arrays, gusted.arrays, float(gust.split(":")[0]))
        del out[name]["per_beat"]
    return out


def phases_study(count: int, per_beat: bool = False) -> dict[str, Any]:
    """``count`` gusts (half from each side) spread over a wingbeat from wingbeat 25;
    ``per_beat``: with each gust's one-wingbeat mean offsets (:func:`per_beat_offsets`)."""
    calm = fly_circle()
    half = max(1, count // 2)
    rows = []
    for sign in (1.0, -1.0):
        for k in range(half):
            start = 25.0 + k / half
            gusted = fly_circle(gust=f"{start}:1:0:{0.15 * sign}:0")
            rows.append(gust_figures(calm.arrays, gusted.arrays, start))
    keys = (
        "after_8",
        "after_8_along",
        "after_8_lateral",
        "after_8_height",
        "after_8_track",
        "peak",
    )
    out: dict[str, Any] = {"circle": calm_figures(calm), "gusts": len(rows)}
    for k in keys:
        v = np.array([r[k] for r in rows])
        out[k] = {"mean": round(float(v.mean()), 4), "median": round(float(np.median(v)), 4),
                  "max": round(float(v.max()), 4)}  # fmt: skip
    out["saturated"] = int(sum(r["saturated"] for r in rows))
    out["after_8_each"] = [r["after_8"] for r in rows]
    out["after_8_track_each"] = [r["after_8_track"] for r in rows]
    out["within_0.05"] = {k: sum(r[k] < WITHIN for r in rows) for k in ("after_8", "after_8_track")}
    if per_beat:  # (along, lateral, height) per wingbeat after each gust
        names = [f"{25.0 + k / half}{'+' if s > 0 else '-'}" for s in (1, -1) for k in range(half)]
        out["per_beat"] = {name: r["per_beat"] for name, r in zip(names, rows, strict=True)}
    return out


def step_study(da: float, beats: float = 34.0) -> list[dict[str, float]]:
    """The lateral plant's step response (see the module)."""
    from birdsim.flight import turning
    from birdsim.flight.bank import bank_of

    loop = turning.lateral_acceleration
    now = [0.0]
    step = [0.0]

    def hook(_k: int, t: float, _fb: Any) -> None:
        now[0] = t / TWO_PI

    def opened(y: float, vy: float, integral: float = 0.0, omega: float = 1.0) -> float:
        base = loop(y, vy, integral, omega) if now[0] < 20.0 else 0.0
        return base + (step[0] if 25.0 <= now[0] < 30.0 else 0.0)

    turning.lateral_acceleration = opened  # type: ignore[assignment]
    try:
        flights = []
        for s in (0.0, da):
            step[0] = s
            flights.append(fly_circle(beats=beats, hook=hook).arrays)
    finally:
        turning.lateral_acceleration = loop  # type: ignore[assignment]
    a0, a1 = flights
    n = min(len(a0["t"]), len(a1["t"]))
    tb = a0["t"][:n] / TWO_PI
    _, left = left_of(a0, n)
    dv = np.stack([a1["vx"][:n] - a0["vx"][:n], a1["vy"][:n] - a0["vy"][:n]], 1)
    dvl = (dv * left).sum(1)
    dbank_cmd = np.degrees(np.asarray(a1["bank_command"][:n]) - np.asarray(a0["bank_command"][:n]))
    dbank = np.degrees(bank_of(a1["quat"][:n]) - bank_of(a0["quat"][:n]))
    dz = a1["z"][:n] - a0["z"][:n]

    def mean_about(v: np.ndarray, b: float) -> float:
        return float(v[(tb >= b - 0.5) & (tb < b + 0.5)].mean())

    rows = []
    for b in np.arange(24.5, beats - 0.5, 0.5):
        acc = (mean_about(dvl, b + 0.25) - mean_about(dvl, b - 0.25)) / (0.5 * TWO_PI)
        rows.append(
            {
                "wingbeat": float(b),
                "bank_command_deg": round(mean_about(dbank_cmd, b), 2),
                "bank_flown_deg": round(mean_about(dbank, b), 2),
                "accel_over_da": round(acc / da, 2),
                "height": round(mean_about(dz, b), 4),
            }
        )
    return rows


def apply_settings(settings: list[str]) -> None:
    for item in settings:
        name, _, value = item.partition("=")
        module, _, attr = name.rpartition(".")
        mod = importlib.import_module(module)
        if not hasattr(mod, attr):
            raise SystemExit(f"--set {item!r}: {module} has no {attr}; allowed: a module constant")
        setattr(mod, attr, ast.literal_eval(value))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--step", type=float, default=None, help="the plant's step (DA)")
    parser.add_argument("--set", action="append", default=[], help="MODULE.NAME=VALUE")
    parser.add_argument("--phases", type=int, default=None, help="gusts over a wingbeat")
    parser.add_argument(
        "--per-beat", action="store_true", help="with --phases: offsets per wingbeat"
    )
    args = parser.parse_args()
    apply_settings(args.set)
    if args.phases is not None:
        print(json.dumps(phases_study(args.phases, args.per_beat)))
    elif args.step is not None:
        for row in step_study(args.step):
            print(json.dumps(row))
    else:
        print(json.dumps(gust_study()))


if __name__ == "__main__":
    main()
