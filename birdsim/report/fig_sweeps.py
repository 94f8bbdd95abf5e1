"""Figure family of the optimum over speed: forward and backward speed sweeps of each
model (Figs 35, 38, 44, 45, 52) and the cost fractions (Fig 36).  The statements
checked are in :mod:`birdsim.report.sweep_claims`."""

from __future__ import annotations

import numpy as np

from birdsim.report import figdata as fd
from birdsim.report import plots
from birdsim.report.records import SMALL_DEMAND, Claim, Context, Entry
from birdsim.report.sweep_claims import sweep_claims


def _sweeps(ctx: Context, model: str):
    """Forward (from the upper bounds at V = 0, sec. 4.1.1) and backward (from the
    cruise guess at V = 1) passes; m4 as Fig 52: Fx = 0, stroke plane held at 0, the
    backward pass from small shoulder and large wrist values."""
    from birdsim.physics.kinematics import get_model

    m = get_model(model)
    speeds = np.linspace(0.0, 1.0, ctx.res.sweep_speeds)
    upper = {p.name: p.upper for p in m.params}
    demand, fixed = SMALL_DEMAND, None
    low = m.guess("cruise")
    if model == "m4":
        demand, fixed = (0.0, SMALL_DEMAND[1]), {"stroke_plane": 0.0}
        low = {p.name: (p.upper if p.name.startswith("wrist") else p.lower) for p in m.params}
        upper["stroke_plane"] = low["stroke_plane"] = 0.0
    kw = dict(fixed=fixed, bird=ctx.bird, n=ctx.res.landscape_samples)
    fwd = fd.speed_sweep(model, demand, speeds, upper, **kw)
    bwd = fd.speed_sweep(model, demand, speeds, low, backward=True, **kw)
    return demand, fwd, bwd


def _missed(sw: fd.SpeedSweep, demand: tuple[float, float]) -> np.ndarray:
    return (
        np.maximum(np.abs(sw.achieved[:, 0] - demand[0]), np.abs(sw.achieved[:, 1] - demand[1]))
        > 0.01
    )


def fig_sweeps(ctx: Context) -> list[Entry]:
    from birdsim.physics.kinematics import get_model

    entries = []
    base_fwd = None
    base_fractions = None
    for model in ("base", "m1", "m2", "m3", "m4"):
        demand, fwd, bwd = _sweeps(ctx, model)
        if model == "base":
            base_fwd = fwd
        series = {}
        for i, name in enumerate(fwd.param_names):
            if model == "m4" and name == "stroke_plane":
                continue  # held at 0 (Fig 52)
            items = [
                ("forward pass (V = 0 -> 1)", fwd.params[:, i], {"marker": "o", "ms": 3}),
                (
                    "backward pass (V = 1 -> 0)",
                    bwd.params[:, i],
                    {"ls": "--", "marker": "s", "ms": 3, "mfc": "none"},
                ),
            ]
            if model == "m1" and name in base_fwd.param_names:
                items.append(
                    (
                        "base model, forward (Fig 44)",
                        base_fwd.params[:, base_fwd.param_names.index(name)],
                        {"color": "0.6", "lw": 3, "alpha": 0.6, "zorder": 0},
                    )
                )
            series[f"{name} (rad)"] = items
        series[f"achieved force ({plots.ND})"] = [
            ("Fx, forward", fwd.achieved[:, 0], {"color": "tab:blue"}),
            ("Fz, forward", fwd.achieved[:, 1], {"color": "tab:orange"}),
            ("Fx, backward", bwd.achieved[:, 0], {"color": "tab:blue", "ls": "--"}),
            ("Fz, backward", bwd.achieved[:, 1], {"color": "tab:orange", "ls": "--"}),
            ("Fx demand", np.full_like(fwd.speeds, demand[0]), {"color": "k", "ls": ":"}),
            ("Fz demand", np.full_like(fwd.speeds, demand[1]), {"color": "0.5", "ls": ":"}),
        ]
        fig = plots.lines(
            fwd.speeds,
            series,
            x_label=f"flight speed V ({plots.ND})",
            title=f"Model {model}: optimal wingbeat over speed for Fx = {demand[0]:g}, Fz = "
            f"{demand[1]:g}, forward and backward passes"
            + (" (stroke plane held at 0)" if model == "m4" else ""),
            footnote="SLSQP warm-started from the previous speed; forward pass starts from the "
            "upper bounds, backward from "
            + ("small shoulder and large wrist values" if model == "m4" else "the cruise guess")
            + "; "
            + plots.FORCE_NOTE,
            ncols=3 if len(series) > 4 else 2,
        )
        name = ctx.save(fig, f"speed_sweep_{model}")
        said, claims = sweep_claims(model, fwd, bwd, base_fwd)
        entries.append(
            Entry(
                name,
                f"Model {model}: solutions over speed (forward and backward passes)",
                "Each parameter of the optimum over speed, solved speed by speed with warm starts "
                "in both directions, and the force it achieves.",
                said,
                tuple(claims),
                note=f"Demand Fx = {demand[0]:g}, Fz = {demand[1]:g}: the dissertation asks for "
                "'small' demands without printing them. "
                + "Speeds where the optimum misses the demand by more than 0.01: "
                + "; ".join(
                    f"{sw.direction} "
                    + (", ".join(f"V={v:.2f}" for v in sw.speeds[_missed(sw, demand)]) or "none")
                    for sw in (fwd, bwd)
                )
                + ".",
            )
        )
        if model == "base":
            base_fractions = fwd
    from birdsim.tables.cost import FRACTION_NAMES

    strong = (SMALL_DEMAND[0], -0.5)  # the largest upward demand of the default grid
    speeds = base_fractions.speeds
    up = {p.name: p.upper for p in get_model("base").params}
    f_strong = fd.speed_sweep(
        "base", strong, speeds, up, bird=ctx.bird, n=ctx.res.landscape_samples
    )
    cases = [(SMALL_DEMAND, base_fractions), (strong, f_strong)]
    fig = plots.fractions(
        speeds,
        [(f"Fx = {d[0]:g}, Fz = {d[1]:g}", sw.fractions) for d, sw in cases],
        FRACTION_NAMES,
        "Base model (Fig 36): cost fractions of the forward-pass optimum over speed, for the small "
        "demand of the sweeps and a strong upward demand",
        footnote="force x = |dFx|, force z = |dFz|, power = 0.5|P|, other = orientation + distance "
        "costs; " + plots.FORCE_NOTE,
    )
    name = ctx.save(fig, "cost_fractions")
    claims = []
    for d, sw in cases:
        fr = {n: sw.fractions[:, i] for i, n in enumerate(FRACTION_NAMES)}
        i08 = int(np.argmin(np.abs(speeds - 0.8)))
        tag = f" (Fz = {d[1]:g})"
        claims += [
            Claim(
                "the Fz deficit dominates at V = 0" + tag,
                bool(np.argmax(sw.fractions[0]) == FRACTION_NAMES.index("force_z")),
                "shares at V = 0: "
                + ", ".join(f"{n} {100 * fr[n][0]:.0f}%" for n in FRACTION_NAMES),
            ),
            Claim(
                "power about 90% near V = 0.8" + tag,
                bool(fr["power"][i08] > 0.8),
                f"power share at V = {speeds[i08]:.2f}: {100 * fr['power'][i08]:.0f}%",
            ),
            Claim(
                "the Fx deficit rises at the top speed" + tag,
                bool(fr["force_x"][-1] > fr["force_x"][i08] + 0.01),
                f"Fx share {100 * fr['force_x'][i08]:.0f}% at V = {speeds[i08]:.2f}, "
                f"{100 * fr['force_x'][-1]:.0f}% at V = 1",
            ),
        ]
    entries.append(
        Entry(
            name,
            "Cost fractions over speed (Fig 36)",
            "Each cost term as a share of the total cost of the base model's forward-pass optimum "
            "at each speed, for two demands.",
            "Fig 36: at low speed the Fz deficit dominates; the power share rises to about 90% at "
            "V = 0.8; beyond, the Fx deficit rises.",
            tuple(claims),
            note="Where the optimum meets the demand exactly, the force shares are zero and power "
            "is the whole cost; the dissertation's "
            "low-speed Fz deficit means its demand was out of reach there, hence the second, "
            "strong demand.",
        )
    )
    return entries
