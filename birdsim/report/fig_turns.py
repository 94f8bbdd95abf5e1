"""Report family ``turns``: the turning presets flown free (issue 23) -- ground tracks
(x-y, flown vs reference) and the wingbeat-mean bank against time beside the coordinated
bank ``atan(a_c / g)`` of the flown path (:func:`birdsim.flight.turn_summary.turn_series`).

The flights are the demo bird's (seed bird, model m3, the shipped table), as ``birdsim fly
circle`` and ``birdsim fly s-turn`` fly them, whatever bird the rest of the report draws:
the shipped tables are the ones that reach the turns.  The two flights take about 20 s
together (88.5 wingbeats); quick mode flies them too (a turn has no coarse grid).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.report.plot_base import add_footnote, pyplot, wrap

#: The turning presets of the figure (the u-turn, 84 wingbeats from the perch and back,
#: is left to ``birdsim fly u-turn``: it would triple the family's time; docs/turning.md).
PRESETS = ("circle", "s-turn", "turn-90")
#: The issue's coordinated-turn target: every steady wingbeat's bank within this of
#: atan(a_c / g) (degrees).
BANK_TOLERANCE_DEG = 3.0
#: The issue's tracking target: path RMS after two wingbeats (semispans).
RMS_TARGET = 0.1


def fly_turn(name: str) -> tuple[dict[str, Any], dict[str, Any], dict[str, Any]]:
    """Fly the turning preset ``name`` free with the demo bird; (log arrays, summary,
    per-wingbeat series)."""
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import fly
    from birdsim.flight.presets import DEMO_MODEL, demo_bird
    from birdsim.flight.simulate import SimConfig
    from birdsim.flight.turn_presets import TURN_PRESETS
    from birdsim.flight.turn_summary import turn_series
    from birdsim.tables.lookup import load_table
    from birdsim.tables.shipped import shipped_table

    bird = demo_bird()
    table = load_table(shipped_table(bird, DEMO_MODEL))
    result = fly(TURN_PRESETS[name], table, bird, DEMO_MODEL, config=SimConfig(attitude="free"))
    log = log_arrays(result, name)
    series = turn_series(log)
    assert series is not None  # a turning preset always leaves the x-z plane
    return log, summary(log), series


def turns_figure(flights: dict[str, tuple[dict, dict, dict]]) -> Any:
    """Top row: the ground track of each flight (flown solid, reference dashed, equal
    axes); bottom row: wingbeat-mean bank and atan(a_c / g) against wingbeats, the
    steady wingbeats marked."""
    plt = pyplot()
    n = len(flights)
    fig = plt.figure(figsize=(5.2 * n, 8.4), layout="constrained")
    for i, (name, (log, info, s)) in enumerate(flights.items()):
        ax = fig.add_subplot(2, n, i + 1)
        ax.plot(log["y_ref"], log["x_ref"], "k--", lw=1.0, label="reference")
        ax.plot(log["y"], log["x"], "C0", lw=1.4, label="flown")
        ax.plot(log["y"][:1], log["x"][:1], "go", ms=5, label="start")
        ax.set_aspect("equal", adjustable="datalim")
        ax.invert_xaxis()  # y to the left, as seen from above with x up the page
        ax.set_xlabel("y (semispans, to the left)")
        ax.set_ylabel("x (semispans)")
        ax.set_title(f"{name}: ground track, path RMS {info['rms_error_after_start']:.3f} semispan")
        ax.legend(fontsize=8, loc="best")
        ax2 = fig.add_subplot(2, n, n + i + 1)
        t = s["t_beats"]
        ax2.plot(t, np.degrees(s["bank"]), "C0.-", ms=3, label="flown bank (wingbeat mean)")
        ax2.plot(t, np.degrees(s["coordinated"]), "C3-", lw=1.0, label="atan(a_c / g)")
        if s["steady"].any():
            ax2.plot(
                t[s["steady"]],
                np.degrees(s["bank"][s["steady"]]),
                "o",
                mfc="none",
                mec="k",
                ms=5,
                label="steady wingbeats",
            )
        ax2.axhline(0.0, color="0.7", lw=0.6)
        ax2.set_xlabel("wingbeats")
        ax2.set_ylabel("bank (deg, right wing down > 0)")
        ax2.set_title(f"{name}: bank against time")
        ax2.legend(fontsize=8, loc="best")
    fig.suptitle(wrap("Turning presets flown free (seed bird, m3): ground track and bank"))
    add_footnote(
        fig,
        "a_c: centripetal acceleration of the flown path (wingbeat-mean horizontal speed x "
        "heading change per wingbeat); a left turn banks left (negative)",
    )
    return fig


def fig_turns(ctx: Any) -> list[Any]:
    """Report family: the turning presets' ground tracks and bank angles (one figure),
    with the issue's tracking and coordination targets as claims."""
    from birdsim.report.records import Claim, Entry

    flights = {name: fly_turn(name) for name in PRESETS}
    name = ctx.save(turns_figure(flights), "turns")
    claims = []
    for preset, (_, info, s) in flights.items():
        rms = float(info["rms_error_after_start"])
        claims.append(
            Claim(
                f"{preset}: path RMS after two wingbeats <= {RMS_TARGET} semispan, no "
                "saturated sample",
                rms <= RMS_TARGET and int(info["saturated_samples"]) == 0,
                f"{rms:.3f} semispan, {int(info['saturated_samples'])} saturated samples",
            )
        )
        if s["steady"].any():
            d = np.degrees(s["bank"][s["steady"]] - s["coordinated"][s["steady"]])
            worst = float(np.abs(d).max())
            claims.append(
                Claim(
                    f"{preset}: in the steady turn every wingbeat-mean bank within "
                    f"{BANK_TOLERANCE_DEG:g} degrees of atan(a_c / g) (birds bank to turn: "
                    "Ros et al. 2011)",
                    worst <= BANK_TOLERANCE_DEG,
                    f"largest difference {worst:.2f} degrees over {int(s['steady'].sum())} "
                    f"steady wingbeats, mean bank {np.degrees(np.mean(s['bank'][s['steady']])):.1f}"
                    " degrees",
                )
            )
    turned = {p: math.degrees(s["psi"][-1] - s["psi"][0]) for p, (_, _, s) in flights.items()}
    return [
        Entry(
            name,
            "Turning flight: ground tracks and bank",
            "The turning presets flown free (bank to turn) by the seed bird with model m3: "
            "top, the ground track (flown against the reference path); bottom, the "
            "wingbeat-mean bank against the coordinated bank atan(a_c / g) of the flown "
            "path. Heading change flown: "
            + ", ".join(f"{p} {v:.1f} degrees" for p, v in turned.items())
            + ".",
            "",  # the dissertation does not turn (sec. 5.2 names turning as further work)
            tuple(claims),
        )
    ]


__all__ = ["PRESETS", "fig_turns", "fly_turn", "turns_figure"]
