"""Figure families of one wingbeat: force and power histories (Figs 12-25), the thrust
coefficient (Fig 9), the wrist lag and bias study (Figs 26-27) and the control-point
paths (Figs 41-55).  Each family computes its numbers (:mod:`birdsim.report.figdata`),
draws them (:mod:`birdsim.report.plots`) and returns :class:`Entry` records."""

from __future__ import annotations

import math

import numpy as np

from birdsim.physics.cycle import evaluate_cycle
from birdsim.physics.examples import EXAMPLES
from birdsim.report import figdata as fd
from birdsim.report import plots
from birdsim.report.claims import history_claims
from birdsim.report.records import Claim, Context, Entry

PI = math.pi


def fig_histories(ctx: Context) -> list[Entry]:
    cycles = {
        ex.equation: evaluate_cycle(
            ex.model, ex.params, ex.speed, bird=ctx.bird, n=ctx.res.samples, check_bounds=False
        )
        for ex in EXAMPLES
    }
    entries = []
    for ex in EXAMPLES:
        c = cycles[ex.equation]
        params = ", ".join(f"{k} {v:.3g}" for k, v in ex.params.items())
        title = (
            f"Model {ex.model}, {ex.regime} example (eq. {ex.equation}, cf. Fig {ex.figure}), "
            f"V = {ex.speed:g}"
        )
        fig = plots.histories(c, f"{title}\n{params} (rad)")
        name = ctx.save(fig, f"histories_{ex.model}_{ex.regime}")
        said, claims = history_claims(ex.equation, c, cycles)
        shows = (
            "Force and power of the right wing over one wingbeat"
            + (", per panel" if ex.model == "m4" else "")
            + "; dashed: cycle mean."
        )
        entries.append(Entry(name, title, shows, said, tuple(claims)))
    return entries


# ---- 2. thrust coefficient -----------------------------------------------------------


def fig_thrust(ctx: Context) -> list[Entry]:
    polar = ctx.bird.polar
    zeta = np.linspace(0.0, PI / 2, ctx.res.cfx)
    twist = np.linspace(0.0, PI / 4, max(ctx.res.cfx // 2, 8))
    cfx = fd.thrust_coefficient(polar, zeta[:, None], twist[None, :])
    fig = plots.thrust_coefficient(
        zeta,
        twist,
        cfx,
        f"Thrust coefficient of a translating, twisting section (eq. 23, Fig 9), {polar.kind} "
        "polar",
    )
    name = ctx.save(fig, "thrust_coefficient")
    hover = cfx[-1]
    best_hover = float(twist[np.argmax(hover)])
    slope0 = (cfx[:, 1] - cfx[:, 0]) / (twist[1] - twist[0])  # d C_Fx / d twist at zero twist
    helps = zeta[slope0 > 0]
    threshold = float(helps.min()) if helps.size else float("nan")
    envelope = cfx.max(axis=1)
    on_line = fd.thrust_coefficient(polar, twist, twist)
    claims = (
        Claim(
            "in hover (zeta = pi/2) any twist gives C_Fx >= 0",
            bool(hover.min() >= -1e-12),
            f"min C_Fx at pi/2 = {hover.min():+.3f}",
        ),
        Claim(
            "in hover the largest C_Fx is at twist = pi/4",
            abs(best_hover - PI / 4) <= (twist[1] - twist[0]),
            f"best twist at pi/2 = {best_hover:.3f} rad",
        ),
        Claim(
            "at small advance angle twist reduces C_Fx",
            bool(slope0[1] < 0),
            f"dC_Fx/dtwist at zeta = {zeta[1]:.2f}: {slope0[1]:+.3f}",
        ),
        Claim(
            "twist helps (dC_Fx/dtwist > 0 at zero twist) only for pi/4 < zeta < pi/2",
            abs(threshold - PI / 4) < 0.05,
            f"twist helps above zeta = {threshold:.3f} rad (pi/4 = 0.785; drag moves it down from "
            "the lift-only pi/4)",
        ),
        Claim(
            "the largest C_Fx falls as zeta -> 0",
            bool(np.all(np.diff(envelope) >= -1e-12)),
            f"max C_Fx {envelope[0]:+.3f} at 0 to {envelope[-1]:+.3f} at pi/2",
        ),
        Claim(
            "the line twist = zeta separates positive and negative modes",
            bool(
                np.all(on_line <= 0)
                and np.max(np.abs(on_line)) <= polar.coefficients(np.zeros(1))[1][0] + 1e-12
            ),
            f"C_Fx on the line = -C_D0 cos(zeta), in [{on_line.min():+.3f}, {on_line.max():+.3f}]: "
            "the zero contour lies just below it",
        ),
    )
    return [
        Entry(
            name,
            "Thrust coefficient over advance angle and twist (Fig 9)",
            "C_Fx = C_L sin(zeta) - C_D cos(zeta) at incidence zeta - theta_f (eq. 20/23 with the "
            "printed eq. 23's missing "
            "sin(zeta) restored), from the bird's polar; black: C_Fx = 0, green: twist = advance "
            "angle, magenta: best twist.",
            "Fig 9: with hover advance angle any twist gives thrust, best at pi/4; at small "
            "advance angle twist lowers thrust; "
            "twist only helps for pi/4 < zeta < pi/2; the line theta_f = zeta bounds the positive "
            "mode; the maximum falls as zeta -> 0.",
            claims,
        )
    ]


# ---- 3. wrist lag and bias -----------------------------------------------------------


def fig_wrist(ctx: Context) -> list[Entry]:
    r = ctx.res
    lag = np.linspace(0.0, PI / 2, r.wrist_map)
    bias = np.linspace(0.0, PI / 2, r.wrist_map)
    pairs = [(PI / 5, 2 * PI / 5), (2 * PI / 5, PI / 5)]
    maps_ = [
        fd.wrist_upward_force(
            pf, pw, lag[:, None], bias[None, :], bird=ctx.bird, n=r.landscape_samples
        )
        for pf, pw in pairs
    ]
    fig = plots.maps(
        lag,
        bias,
        [
            (f"Phi_f = {pf / PI:.1f} pi, Phi_w = {pw / PI:.1f} pi", v)
            for (pf, pw), v in zip(pairs, maps_)
        ],
        x_label="wrist lag Delta (rad)",
        y_label="wrist bias Psi (rad)",
        value_label=f"upward force -Fz ({plots.ND})",
        title="Model m4, cruise-like study (sec. 3.5.7, Fig 26): upward force over wrist lag and "
        "bias\nV = 0.5, pitch = twist = stroke plane = 0",
        extra=[[(PI / 2, PI / 4, "dissertation's optimum (pi/2, pi/4)")]] * 2,
        footnote=plots.FORCE_NOTE,
    )
    name1 = ctx.save(fig, "wrist_lag_bias")
    argmaxes = [np.unravel_index(np.argmax(v), v.shape) for v in maps_]
    tol = lag[1] - lag[0]
    opt_claims = tuple(
        Claim(
            f"optimum at lag pi/2, bias pi/4 for Phi_f = {pf / PI:.1f} pi, Phi_w = {pw / PI:.1f} "
            "pi",
            bool(abs(lag[i] - PI / 2) <= tol and abs(bias[j] - PI / 4) <= tol),
            f"ours at lag {lag[i]:.2f}, bias {bias[j]:.2f} (grid step {tol:.2f})",
        )
        for (pf, pw), (i, j) in zip(pairs, argmaxes)
    ) + (
        Claim(
            "more force with the larger amplitude on panel 1",
            bool(maps_[1].max() > maps_[0].max()),
            f"max upward force {maps_[0].max():.4f} (larger wrist) vs {maps_[1].max():.4f} (larger "
            "shoulder)",
        ),
    )
    e1 = Entry(
        name1,
        "Upward force over wrist lag and bias for two amplitude pairs (Fig 26)",
        "Mean upward force -Fz of model m4 over the wrist lag and bias; star: our maximum, ring: "
        "the dissertation's.",
        "Fig 26: both maxima at lag pi/2 and bias pi/4; more force with the larger amplitude on "
        "panel 1.",
        opt_claims,
        note="'F_z(max)' is read as the most upward mean Fz; amplitudes and bias beyond the "
        "default bounds are evaluated without bound checks.",
    )
    amps = np.linspace(PI / 2 / r.wrist_amp, PI / 2, r.wrist_amp)
    grid = np.linspace(0.0, PI / 2, r.wrist_opt)
    opt = fd.wrist_optimum(amps, amps, grid, grid, bird=ctx.bird, n=r.landscape_samples)
    fig = plots.wrist_optimum(
        opt,
        "Model m4 (sec. 3.5.7, Fig 27): wrist lag and bias of the largest upward force, V = 0.5",
    )
    name2 = ctx.save(fig, "wrist_optimum")
    corner = opt.lag_star[0, -1]
    e2 = Entry(
        name2,
        "Best wrist lag and bias over the two amplitudes (Fig 27)",
        f"For each (Phi_f, Phi_w): the lag Delta* and bias Psi* (searched on a {r.wrist_opt}-point "
        "grid over [0, pi/2]) that give the largest upward force, and that force.",
        "Fig 27: Delta* = pi/2 over most amplitudes, dropping to 0 at small Phi_f and large Phi_w; "
        "Psi* roughly pi/4.",
        (
            Claim(
                "Delta* = pi/2 over most amplitudes",
                bool(np.mean(np.isclose(opt.lag_star, PI / 2)) > 0.5),
                f"on {np.mean(np.isclose(opt.lag_star, PI / 2)):.0%} of the amplitude pairs",
            ),
            Claim(
                "Delta* drops to 0 at small Phi_f, large Phi_w",
                bool(corner < PI / 4),
                f"Delta* at the smallest Phi_f, largest Phi_w = {corner:.2f}",
            ),
            Claim(
                "Psi* approximately pi/4",
                bool(abs(np.median(opt.bias_star) - PI / 4) < 0.15),
                f"median Psi* = {np.median(opt.bias_star):.2f} (pi/4 = 0.79)",
            ),
        ),
    )
    return [e1, e2]


# ---- 7. control-point paths ----------------------------------------------------------

#: The captions' parameters (OCR read: Fig 41 prints Phi_f = 0.79, Theta_f = 1.5 and
#: Fig 42 Phi_f = "0.1.5", Theta_f = 1.5 -- Theta_f is bounded by pi/4 and the text says
#: flap and twist are at their maxima, so the two are read as Phi_f = 1.5, Theta_f = 0.79).
CP_CASES: tuple[tuple[str, str, int, float, tuple[float, float], dict[str, float]], ...] = (
    # model, case, figure, V, demand (Fx, Fz) from the text, caption parameters
    ("base", "hover", 41, 0.0, (0.0, -0.5), dict(pitch=1.5, flap_amp=1.5, twist_amp=0.79)),
    ("base", "take-off", 42, 0.0, (0.5, -0.5), dict(pitch=0.7, flap_amp=1.5, twist_amp=0.79)),
    ("base", "cruise", 43, 0.9, (0.0, -0.2), dict(pitch=0.02, flap_amp=0.75, twist_amp=0.25)),
    (
        "m3",
        "hover",
        46,
        0.0,
        (0.0, -0.5),
        dict(pitch=1.2, flap_amp=0.75, twist_amp=0.79, stroke_plane=0.35),
    ),
    (
        "m3",
        "take-off",
        47,
        0.0,
        (0.5, -0.5),
        dict(pitch=0.25, flap_amp=1.5, twist_amp=0.79, stroke_plane=0.35),
    ),
    (
        "m3",
        "cruise",
        48,
        0.9,
        (0.0, -0.25),
        dict(pitch=0.0, flap_amp=0.4, twist_amp=0.16, stroke_plane=0.25),
    ),
    (
        "m4",
        "hover",
        53,
        0.0,
        (0.0, -0.5),
        dict(
            pitch=1.2,
            flap_amp=0.79,
            twist_amp=0.79,
            stroke_plane=0.35,
            wrist_amp=0.01,
            wrist_bias=0.02,
            wrist_lag=1.55,
        ),
    ),
    (
        "m4",
        "take-off",
        54,
        0.0,
        (0.5, -0.5),
        dict(
            pitch=0.1,
            flap_amp=0.79,
            twist_amp=0.79,
            stroke_plane=0.35,
            wrist_amp=0.01,
            wrist_bias=0.01,
            wrist_lag=1.55,
        ),
    ),
    (
        "m4",
        "cruise",
        55,
        0.9,
        (0.0, -0.25),
        dict(
            pitch=0.0,
            flap_amp=0.62,
            twist_amp=0.41,
            stroke_plane=0.21,
            wrist_amp=0.30,
            wrist_bias=0.29,
            wrist_lag=1.55,
        ),
    ),
)


def _loop_area(path: np.ndarray) -> float:
    """Largest area the closed path encloses in any of the three coordinate planes."""
    best = 0.0
    for a, b in ((0, 1), (1, 2), (0, 2)):
        x, y = path[:, a], path[:, b]
        best = max(best, 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))))
    return best


def fig_paths(ctx: Context) -> list[Entry]:
    entries = []
    for model, case, figno, speed, demand, params in CP_CASES:
        p = fd.control_point_paths(model, params, bird=ctx.bird, n=ctx.res.samples)
        c = evaluate_cycle(
            model, params, speed, bird=ctx.bird, n=ctx.res.samples, check_bounds=False
        ).mean
        stem = f"cp_paths_{model}_{case.replace('-', '')}"
        text = ", ".join(f"{k} {v:g}" for k, v in params.items())
        title = (
            f"Model {model}, {case} (cf. Fig {figno}): control-point paths and chord lines\n"
            f"{text} (rad); at V = {speed:g}: mean Fx {float(c.Fx):+.3f}, Fz {float(c.Fz):+.3f}"
        )
        name = ctx.save(plots.cp_paths(p, title), stem)
        x_ext, z_ext = np.ptp(p.path[0, :, 0]), np.ptp(p.path[0, :, 2])
        fx, fz = float(c.Fx), float(c.Fz)
        claims: list[Claim] = [
            Claim(
                f"the caption's parameters answer the demand Fx = {demand[0]:g}, Fz = "
                f"{demand[1]:g}: upward" + (" and forward" if demand[0] > 0 else ""),
                fz < 0 and (fx > 0 or demand[0] <= 0),
                f"mean Fx {fx:+.3f}, Fz {fz:+.3f}",
            )
        ]
        said = (
            f"Fig {figno}: CP path and chord lines of the optimum for V = {speed:g}, "
            f"Fx = {demand[0]:g}, Fz = {demand[1]:g}."
        )
        if case == "hover":
            claims.append(
                Claim(
                    "hover: a near-horizontal stroke (more fore-aft than vertical travel)",
                    bool(x_ext > z_ext),
                    f"CP travel X {x_ext:.2f}, Z {z_ext:.2f}",
                )
            )
            said += " Hover uses a near-horizontal stroke."
        if case == "cruise":
            claims.append(
                Claim(
                    "cruise: a near-vertical stroke",
                    bool(z_ext > x_ext),
                    f"CP travel X {x_ext:.2f}, Z {z_ext:.2f}",
                )
            )
            said += " Cruise uses a near-vertical stroke."
        if model == "m4" and case == "cruise":
            a_arm, a_hand = _loop_area(p.path[0]), _loop_area(p.path[1])
            claims.append(
                Claim(
                    "the hand CP traces an ellipse (a loop, unlike the arm's arc)",
                    a_hand > 5 * a_arm,
                    f"enclosed area arm {a_arm:.4f}, hand {a_hand:.4f}",
                )
            )
            said += " The wrist's lag and bias make the second CP trace an ellipse."
        entries.append(
            Entry(
                name,
                f"Model {model} {case}: control-point paths (Fig {figno})",
                "Plan, rear, side and perspective views of each panel's CP over one wingbeat with "
                "the chord line at 16 instants (leading edge dotted); "
                "relative to the shoulder, earth-oriented axes with up = -Z; the title gives the "
                "mean force these parameters produce.",
                said,
                tuple(claims),
                note="Parameters from the dissertation's caption (Figs 41-42: flap and twist read "
                "swapped, see docs/report.md)."
                if figno in (41, 42)
                else "Parameters from the dissertation's caption.",
            )
        )
    return entries
