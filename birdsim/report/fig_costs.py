"""Figure families of the cost landscapes: the base model's optimisation spaces
(Figs 33-34) and the wrist activity coefficient K (Figs 49-51)."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from birdsim.report import figdata as fd
from birdsim.report import plots
from birdsim.report.records import SMALL_DEMAND, Claim, Context, Entry

PI = math.pi


def _cost_function(
    model: str,
    demand: tuple[float, float],
    previous: dict[str, float] | None = None,
    nu: float = 0.0,
):
    """The project cost (birdsim.tables.cost) of a grid, as a :data:`figdata.CostFunction`."""
    from birdsim.physics.kinematics import get_model
    from birdsim.tables.cost import CostWeights, breakdown_from_forces, other_cost

    m = get_model(model)
    weights = CostWeights(distance=nu)

    def cost(means: fd.GridMeans, params, speed) -> np.ndarray:
        shape = means.Fx.shape
        X = np.stack([np.broadcast_to(params[k], shape) for k in m.param_names], axis=-1)
        prev = None if previous is None else np.array([previous[k] for k in m.param_names])
        other = other_cost(m, X, speed, weights, prev)
        return breakdown_from_forces(
            means.Fx, means.Fz, means.P, demand[0], demand[1], weights, other
        ).total

    return cost


def fig_landscapes(ctx: Context) -> list[Entry]:
    r = ctx.res
    flap = np.linspace(0.0, PI / 2, r.landscape)
    twist = np.linspace(0.0, PI / 4, r.landscape)
    pitch = np.linspace(0.0, PI / 2, r.profile)
    demand = SMALL_DEMAND

    def base_landscape(speed: float, previous=None, nu=0.0) -> fd.Landscape:
        return fd.landscape(
            "base",
            speed,
            _cost_function("base", demand, previous, nu),
            ("flap_amp", flap),
            ("twist_amp", twist),
            profile={"pitch": pitch},
            bird=ctx.bird,
            n=r.landscape_samples,
        )

    speeds = (0.2, 0.7, 3.0)
    ls = [base_landscape(v) for v in speeds]
    note = (
        f"demand Fx = {demand[0]}, Fz = {demand[1]} (the 'small requirements'; not printed in the "
        "text); cost = |dFx| + |dFz| + 0.5|P|, minimised over body pitch at each cell; "
        + plots.FORCE_NOTE
    )
    fig = plots.maps(
        flap,
        twist,
        [
            (
                f"V = {v:g}: best ({land.best['flap_amp']:.2f}, "
                f"{land.best['twist_amp']:.2f}), pitch {land.best['pitch']:.2f}",
                land.cost,
            )
            for v, land in zip(speeds, ls)
        ],
        x_label="flap amplitude Phi_f (rad)",
        y_label="twist amplitude Theta_f (rad)",
        value_label=f"cost ({plots.ND})",
        title="Base model optimisation spaces (Fig 33): cost over flap and twist amplitude",
        mark="min",
        footnote=note,
        shared_scale=False,
    )
    name1 = ctx.save(fig, "cost_flap_twist")
    # "valley" measure: the fraction of cells within 10% (of the cost range) of the minimum
    flat = [float(np.mean(land.cost <= land.cost.min() + 0.1 * np.ptp(land.cost))) for land in ls]
    e1 = Entry(
        name1,
        "Cost over flap and twist amplitude at V = 0.2, 0.7, 3 (Fig 33)",
        "The project cost over (Phi_f, Theta_f) for the base model, body pitch chosen best on its "
        "grid in each cell; star: the grid minimum (the valley is narrow: a finer grid or an "
        "optimiser finds lower points).",
        "Fig 33: a distinct valley at V = 0.2, an almost flat low-cost region at V = 0.7 (minimum "
        "near Phi_f = 0.98, Theta_f = 0.28), a clear valley again at V = 3.",
        (
            Claim(
                "the intermediate speed has the widest low-cost region",
                flat[1] > max(flat[0], flat[2]),
                "share of cells within 10% of the cost range above the minimum: "
                + ", ".join(f"V={v:g}: {f:.0%}" for v, f in zip(speeds, flat)),
            ),
            Claim(
                "V = 0.7 minimum near Phi_f = 0.98, Theta_f = 0.28",
                abs(ls[1].best["flap_amp"] - 0.98) < 0.15
                and abs(ls[1].best["twist_amp"] - 0.28) < 0.15,
                f"ours at ({ls[1].best['flap_amp']:.2f}, {ls[1].best['twist_amp']:.2f}), within "
                "0.15 rad counts",
            ),
        ),
    )
    l6 = base_landscape(0.6)
    prev = dict(
        pitch=l6.best["pitch"], flap_amp=l6.best["flap_amp"], twist_amp=l6.best["twist_amp"]
    )
    l7d = base_landscape(0.7, previous=prev, nu=0.2)
    l7 = ls[1]
    fig = plots.maps(
        flap,
        twist,
        [
            (f"V = 0.6: best ({l6.best['flap_amp']:.2f}, {l6.best['twist_amp']:.2f})", l6.cost),
            (f"V = 0.7: best ({l7.best['flap_amp']:.2f}, {l7.best['twist_amp']:.2f})", l7.cost),
            (
                f"V = 0.7, distance cost nu = 0.2: best ({l7d.best['flap_amp']:.2f}, "
                f"{l7d.best['twist_amp']:.2f})",
                l7d.cost,
            ),
        ],
        x_label="flap amplitude Phi_f (rad)",
        y_label="twist amplitude Theta_f (rad)",
        value_label=f"cost ({plots.ND})",
        title="Base model (Fig 34): the distance cost (eq. 93) holds the V = 0.7 optimum near the "
        "V = 0.6 one",
        mark="min",
        footnote=note,
        shared_scale=False,
        extra=[[], [], [(prev["flap_amp"], prev["twist_amp"], "V = 0.6 optimum")]],
    )
    name2 = ctx.save(fig, "cost_distance")
    d_free = math.dist(
        (l7.best["flap_amp"], l7.best["twist_amp"]), (prev["flap_amp"], prev["twist_amp"])
    )
    d_held = math.dist(
        (l7d.best["flap_amp"], l7d.best["twist_amp"]), (prev["flap_amp"], prev["twist_amp"])
    )
    e2 = Entry(
        name2,
        "The distance cost between V = 0.6 and 0.7 (Fig 34)",
        "Cost over (Phi_f, Theta_f) at V = 0.6, 0.7 and 0.7 plus nu |x - x_0.6| (nu = 0.2); pitch "
        "chosen best in each cell.",
        "Fig 34: V = 0.6 optimum (1.03, 0.40); at V = 0.7 without the distance cost (0.97, 0.26), "
        "with it (1.03, 0.38): the distance cost holds the solution.",
        (
            Claim(
                "the distance cost keeps the V = 0.7 optimum closer to the V = 0.6 one",
                d_held <= d_free,
                f"distance from the V = 0.6 optimum: {d_free:.3f} rad without, {d_held:.3f} rad "
                "with nu = 0.2",
            ),
        ),
    )
    return [e1, e2]


def fig_wrist_activity(ctx: Context) -> list[Entry]:
    r = ctx.res
    k = np.linspace(0.0, 1.0, r.landscape)
    pitch = np.linspace(0.0, PI / 2, r.landscape)
    out = []
    maps_ = []
    for twist in (0.0, PI / 16):
        params = dict(
            pitch=pitch[None, :],
            flap_amp=PI / 4,
            twist_amp=twist,
            stroke_plane=0.0,
            **fd.wrist_activity(k[:, None]),
        )
        maps_.append(-fd.grid_means("m4", params, 0.0, bird=ctx.bird, n=r.landscape_samples).Fz)
    fig = plots.maps(
        k,
        pitch,
        [(f"Theta_f = {t}", v) for t, v in zip(("0", "pi/16"), maps_)],
        x_label="wrist activity K (non-dimensional, eq. 95)",
        y_label="body pitch theta (rad)",
        value_label=f"upward force -Fz ({plots.ND})",
        title="Model m4 (Fig 49): upward force over wrist activity K and body pitch\nV = 0, Phi_f "
        "= pi/4, stroke plane 0; (Phi_w, Delta, Psi) = K (pi/4, pi/2, pi/4)",
        footnote=plots.FORCE_NOTE,
    )
    out_name = ctx.save(fig, "wrist_activity_force")
    m0, m1 = maps_
    best_k0 = k[np.argmax(m0[:, :-1], axis=0)]  # best K per pitch below pi/2, no twist
    best_k1 = k[np.argmax(m1, axis=0)]
    out.append(
        Entry(
            out_name,
            "Upward force over wrist activity and body pitch (Fig 49)",
            "Mean upward force of model m4 in hover (V = 0) over K and pitch, without twist (left) "
            "and with twist pi/16 (right).",
            "Fig 49: no twist: zero force at pitch pi/2 for every K, and for pitch < pi/2 the "
            "largest K gives the most force; "
            "twist pi/16: at pitch pi/2 the most force with K = 0, and lower pitch favours larger "
            "K.",
            (
                Claim(
                    "no twist, pitch pi/2: zero force for every K",
                    bool(np.abs(m0[:, -1]).max() < 1e-9),
                    f"max |Fz| there = {np.abs(m0[:, -1]).max():.2g}",
                ),
                Claim(
                    "no twist, pitch < pi/2: K = 1 gives the most force",
                    bool(np.mean(best_k0 == 1.0) > 0.5),
                    f"K = 1 best on {np.mean(best_k0 == 1.0):.0%} of the pitch values",
                ),
                Claim(
                    "twist pi/16, pitch pi/2: K = 0 best",
                    bool(best_k1[-1] == 0.0),
                    f"best K at pitch pi/2 = {best_k1[-1]:.2f}",
                ),
                Claim(
                    "twist pi/16: lower pitch favours larger K",
                    bool(best_k1[0] > best_k1[-1]),
                    f"best K at pitch 0 / pi/2 = {best_k1[0]:.2f} / {best_k1[-1]:.2f}",
                ),
            ),
        )
    )
    # Figs 50-51: cost over K and flap amplitude, pitch and twist minimised over
    kk = np.linspace(0.0, 1.0, r.m4_landscape)
    flap = np.linspace(0.0, PI / 4, r.m4_landscape)
    prof = {
        "pitch": np.linspace(0.0, PI / 2, r.m4_profile),
        "twist_amp": np.linspace(0.0, PI / 4, r.m4_profile),
    }
    speeds = (0.0, 0.5, 1.0)
    rows = []
    for label, bird in (
        ("hand as long as the arm (Fig 50)", replace(ctx.bird, hand_span_fraction=0.5)),
        ("hand half the arm, the default (Fig 51)", ctx.bird),
    ):
        row = []
        for v in speeds:
            row.append(
                fd.landscape(
                    "m4",
                    v,
                    _cost_function("m4", SMALL_DEMAND),
                    ("K", kk),
                    ("flap_amp", flap),
                    fixed={"stroke_plane": 0.0},
                    profile=prof,
                    derived=lambda p: fd.wrist_activity(p["K"]),
                    bird=bird,
                    n=r.landscape_samples,
                )
            )
        rows.append((label, row))
    names = []
    for (label, row), stem in zip(rows, ("wrist_activity_cost_equal_hand", "wrist_activity_cost")):
        fig = plots.maps(
            kk,
            flap,
            [
                (f"V = {v:g}: best K = {land.best['K']:.2f}", land.cost)
                for v, land in zip(speeds, row)
            ],
            x_label="wrist activity K (non-dimensional)",
            y_label="shoulder flap amplitude Phi_f (rad)",
            value_label=f"cost ({plots.ND})",
            title=f"Model m4 optimisation spaces over K, {label}",
            mark="min",
            shared_scale=False,
            footnote=f"demand Fx = {SMALL_DEMAND[0]}, Fz = {SMALL_DEMAND[1]}; stroke plane 0; "
            "pitch and twist chosen best per cell; " + plots.FORCE_NOTE,
        )
        names.append(ctx.save(fig, stem))
    best_equal = [land.best["K"] for land in rows[0][1]]
    best_half = [land.best["K"] for land in rows[1][1]]
    out.append(
        Entry(
            names[0],
            "Cost over wrist activity K, hand as long as the arm (Fig 50)",
            "Cost of model m4 over (K, Phi_f) at V = 0, 0.5, 1 with arm and hand each half the "
            "semispan; pitch and twist chosen best per cell.",
            "Fig 50 (an 'arbitrarily sized' hand): K = 0 at V = 0, an irregular space with two "
            "minima at V = 0.5, K about 0.37 at V = 1.",
            (
                Claim(
                    "K = 0 best at V = 0",
                    best_equal[0] == 0.0,
                    "best K at V = 0, 0.5, 1: " + ", ".join(f"{b:.2f}" for b in best_equal),
                ),
            ),
        )
    )
    out.append(
        Entry(
            names[1],
            "Cost over wrist activity K, hand half the arm (Fig 51)",
            "As above with the default geometry (hand span = half the arm span, semispan 1).",
            "Fig 51: K = 0 at low speed; the valley moves to larger K as V rises, K = 1 at V = 1.",
            (
                Claim(
                    "K = 0 best at V = 0",
                    best_half[0] == 0.0,
                    f"best K at V = 0: {best_half[0]:.2f}",
                ),
                Claim(
                    "best K grows with speed",
                    bool(np.all(np.diff(best_half) >= 0) and best_half[-1] > best_half[0]),
                    "best K at V = 0, 0.5, 1: " + ", ".join(f"{b:.2f}" for b in best_half),
                ),
                Claim(
                    "K = 1 best at V = 1",
                    best_half[-1] == 1.0,
                    f"best K at V = 1: {best_half[-1]:.2f}",
                ),
            ),
        )
    )
    return out
