"""``birdsim report``: the dissertation's analysis regenerated from our own numbers.

Every figure family is one function that computes its data (``birdsim/figdata.py``,
the optimisers, the tables), draws it (``birdsim/plots.py``), writes the PNGs and
returns :class:`Entry` records: what the figure shows, what the dissertation printed
in the same place and a list of :class:`Claim` checks -- each a statement of the
dissertation tested against our numbers (never a hard-coded verdict).  ``index.html``
shows every figure with those lines.
"""

from __future__ import annotations

import html
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from birdsim.report import figdata as fd
from birdsim.report import plots
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.errors import BirdsimError
from birdsim.physics.examples import EXAMPLES
from birdsim.io import write_atomic

PI = math.pi


@dataclass(frozen=True)
class Resolution:
    """Grid sizes of the report.  ``quick`` keeps every figure but on coarse grids."""

    samples: int = 64  # per wingbeat for histories and paths
    landscape_samples: int = 32  # per wingbeat on the big grids
    cfx: int = 181  # advance angle points (twist gets half)
    wrist_map: int = 31  # lag x bias points
    wrist_amp: int = 16  # amplitude points of Fig 27
    wrist_opt: int = 19  # lag/bias points of Fig 27
    landscape: int = 41  # plotted axes of the cost landscapes
    profile: int = 31  # profiled (minimised-over) axes
    m4_landscape: int = 21
    m4_profile: int = 11
    sweep_speeds: int = 21
    optimiser_nodes: int = 12
    build_grid: int = 3  # demand grid per axis of the build-time study
    table_grid: int = 7  # Fx and Fz nodes of tables built here when none is committed
    table_screen: int = 1024  # screen candidates per V slice of tables built here
    quick: bool = False

    def build_settings(self):
        """Table-build settings of the report's own builds (coarser in quick mode)."""
        from birdsim.tables.build import BuildSettings

        if not self.quick:
            return BuildSettings(screen=self.table_screen)
        return BuildSettings(screen=self.table_screen, n_search=12, n_final=16, v_passes=False)


FULL = Resolution()
QUICK = Resolution(
    samples=16, landscape_samples=12, cfx=31, wrist_map=7, wrist_amp=4, wrist_opt=5, landscape=9, profile=5,
    m4_landscape=5, m4_profile=3, sweep_speeds=4, optimiser_nodes=12, build_grid=2, table_grid=2, table_screen=64, quick=True,
)

#: "Small Fx and Fz requirements" of secs 4.1.1 and 4.1.4 (the text does not print them).
SMALL_DEMAND = (0.1, -0.1)


@dataclass(frozen=True)
class Claim:
    """One statement of the dissertation and whether our numbers bear it out."""

    statement: str
    holds: bool
    ours: str

    def __post_init__(self) -> None:
        object.__setattr__(self, "holds", bool(self.holds))  # numpy bools print as np.True_


@dataclass(frozen=True)
class Entry:
    """One figure of the report."""

    file: str
    title: str
    shows: str
    dissertation: str  # what the dissertation printed here ("" if nothing comparable)
    claims: tuple[Claim, ...] = ()
    note: str = ""

    @property
    def verdict(self) -> str:
        if not self.claims:
            return "no printed counterpart" if not self.dissertation else "not checked"
        held = sum(c.holds for c in self.claims)
        if held == len(self.claims):
            return "agrees"
        if held == 0:
            return "disagrees"
        return f"agrees in part ({held} of {len(self.claims)})"


@dataclass(frozen=True)
class Context:
    out: Path
    res: Resolution
    bird: Bird

    def save(self, fig, name: str) -> str:
        plots.save_png(fig, self.out / f"{name}.png")
        return f"{name}.png"


# ---- 1. force and power histories ----------------------------------------------------


def _phase_mask(n: int, lo: float, hi: float) -> np.ndarray:
    ph = np.arange(n) / n
    return (ph >= lo) & (ph < hi)


def _down(n: int) -> np.ndarray:
    return _phase_mask(n, 0.0, 0.25) | _phase_mask(n, 0.75, 1.0)


def _history_claims(eq: int, c, cyc: dict) -> tuple[str, list[Claim]]:
    """What the dissertation says about the example of equation ``eq`` (sec. 3.5) and
    the test of each statement on our cycle ``c`` (``cyc`` holds the other examples)."""
    m = c.mean
    Fx, Fz = float(m.Fx), float(m.Fz)
    n = c.Fz.shape[-1]
    down = _down(n)
    fz, fx, p = c.Fz, c.Fx + float(c.body_drag_x), c.P
    near = lambda centre: _phase_mask(n, centre - 0.1, centre + 0.1)  # noqa: E731
    if eq == 57:
        return "Fig 12: oscillating negative Fz over the cycle; oscillating Fx with no net horizontal force.", [
            Claim("Fz is negative (upward) over the whole cycle", bool(fz.max() <= 1e-9), f"max Fz = {fz.max():+.3g}"),
            Claim("net upward force", Fz < 0, f"mean Fz = {Fz:+.4f}"),
            Claim("no net Fx", abs(Fx) < 1e-6, f"mean Fx = {Fx:+.2g}"),
        ]
    if eq == 58:
        return (
            "Fig 13: Fz negative over most of the cycle with a small positive part near phase 0.5; a net thrust "
            "(mean Fx > 0); Fx negative near phases 0.25 and 0.75; more power on the downstroke.",
            [
                Claim("Fz < 0 over most of the cycle", bool(np.mean(fz < 0) > 0.5), f"Fz < 0 on {np.mean(fz < 0):.0%} of the cycle"),
                Claim("small positive Fz near phase 0.5", bool(fz[near(0.5)].max() > 0), f"max Fz near 0.5 = {fz[near(0.5)].max():+.3f}"),
                Claim("net thrust", Fx > 0, f"mean Fx = {Fx:+.4f}"),
                Claim(
                    "Fx < 0 near phases 0.25 and 0.75",
                    bool(fx[near(0.25)].min() < 0 and fx[near(0.75)].min() < 0),
                    f"min Fx near 0.25 / 0.75 = {fx[near(0.25)].min():+.3f} / {fx[near(0.75)].min():+.3f}",
                ),
                Claim("more power on the downstroke", bool(p[down].mean() > p[~down].mean()), f"mean P down / up = {p[down].mean():.3f} / {p[~down].mean():.3f}"),
            ],
        )
    if eq == 61:
        b = cyc[57]
        return "Fig 15: Fz like the base model's; power the same as the base model's.", [
            Claim("mean Fz equals the base model's", bool(np.isclose(Fz, float(b.mean.Fz), rtol=1e-6)), f"{Fz:+.4f} vs base {float(b.mean.Fz):+.4f}"),
            Claim("power history the same as the base model's", bool(np.allclose(p, b.P, atol=1e-9)), f"max |dP| = {np.abs(p - b.P).max():.2g}"),
        ]
    if eq == 62:
        b = cyc[58]
        dfx = np.abs(fx - (b.Fx + float(b.body_drag_x))).max() / np.abs(b.Fx).max()
        dp = np.abs(p - b.P).max() / np.abs(b.P).max()
        return "Fig 16: Fx and power appear identical to the base model's; Fz differs somewhat.", [
            Claim("Fx history within 10% of the base model's", bool(dfx < 0.1), f"max |dFx| / max |Fx| = {dfx:.1%}"),
            Claim("power history within 10% of the base model's", bool(dp < 0.1), f"max |dP| / max |P| = {dp:.1%}"),
            Claim("mean Fz differs from the base model's", abs(Fz - float(b.mean.Fz)) > 1e-3, f"{Fz:+.4f} vs base {float(b.mean.Fz):+.4f}"),
        ]
    if eq == 68:
        b = cyc[61]
        return "Fig 18: Fz like model 1's but smaller; Fx unaffected by the sweep; power negative near phases 0.25 and 0.75.", [
            Claim("smaller upward force than model 1", abs(Fz) < abs(float(b.mean.Fz)), f"mean Fz {Fz:+.4f} vs m1 {float(b.mean.Fz):+.4f}"),
            Claim("Fx history unchanged from model 1", bool(np.allclose(fx, b.Fx, atol=1e-9)), f"max |dFx| = {np.abs(fx - b.Fx).max():.2g}"),
            Claim(
                "power negative near phases 0.25 and 0.75 (DESIGN.md: no consistent reading gives this)",
                bool(p.min() < 0),
                f"min P = {p.min():+.3g}",
            ),
        ]
    if eq == 69:
        return "Fig 19: Fz differs between downstroke and upstroke; near phase 0.25 negative Fx; for phases 0.75-1 positive Fx and power.", [
            Claim(
                "Fz differs between the two half-strokes",
                abs(fz[down].mean() - fz[~down].mean()) > 1e-3,
                f"mean Fz down / up = {fz[down].mean():+.3f} / {fz[~down].mean():+.3f}",
            ),
            Claim("Fx < 0 near phase 0.25", bool(fx[near(0.25)].min() < 0), f"min Fx near 0.25 = {fx[near(0.25)].min():+.3f}"),
            Claim(
                "Fx and power > 0 for phases 0.75-1",
                bool(fx[_phase_mask(n, 0.75, 1)].mean() > 0 and p[_phase_mask(n, 0.75, 1)].mean() > 0),
                f"mean Fx, P there = {fx[_phase_mask(n, 0.75, 1)].mean():+.3f}, {p[_phase_mask(n, 0.75, 1)].mean():+.3f}",
            ),
        ]
    if eq == 75:
        b = cyc[61]
        return "Fig 21: less upward Fz on the downstroke, more on the upstroke; a net negative Fx; power identical to model 1.", [
            Claim(
                "less upward force on the downstroke than on the upstroke",
                bool(fz[down].mean() > fz[~down].mean()),
                f"mean Fz down / up = {fz[down].mean():+.3f} / {fz[~down].mean():+.3f}",
            ),
            Claim("net negative Fx", Fx < 0, f"mean Fx = {Fx:+.4f}"),
            Claim("power identical to model 1", bool(np.allclose(p, b.P, atol=1e-9)), f"max |dP| = {np.abs(p - b.P).max():.2g}"),
        ]
    if eq == 76:
        return "Fig 22: Fz negative over the entire cycle; Fx negative over the entire cycle; much more power on the downstroke.", [
            Claim("Fz <= 0 over the whole cycle", bool(fz.max() <= 1e-9), f"max Fz = {fz.max():+.3g}"),
            Claim("Fx < 0 over the whole cycle", bool(fx.max() < 0), f"max Fx = {fx.max():+.3g}"),
            Claim("more power on the downstroke", bool(p[down].mean() > p[~down].mean()), f"mean P down / up = {p[down].mean():.3f} / {p[~down].mean():.3f}"),
        ]
    pm = c.panel_mean
    arm, hand = pm["arm"], pm["hand"]
    jp = {g: float(v.mean()) for g, v in c.joint_power.items()}
    if eq == 87:
        rms = np.sqrt(np.mean(c.panel_force_earth[..., 0] ** 2, axis=-1))
        return "Fig 24: panel 2 carries more than half of Fz and most of Fx; most of the power is spent on panel 1 (the shoulder).", [
            Claim("panel 2 carries more than half of mean Fz", float(hand.Fz) / Fz > 0.5, f"hand share = {float(hand.Fz) / Fz:.0%}"),
            Claim("panel 2 carries most of the Fx oscillation", bool(rms[1] > rms[0]), f"rms Fx arm / hand = {rms[0]:.3f} / {rms[1]:.3f}"),
            Claim(
                "most power on panel 1 (DESIGN.md: no consistent reading gives this)",
                float(arm.P) > float(hand.P),
                f"mean P arm / hand = {float(arm.P):.4f} / {float(hand.P):.4f}",
            ),
            Claim(
                "the shoulder joint delivers most of the power",
                jp["shoulder"] > jp["wrist"],
                f"joint power shoulder / wrist = {jp['shoulder']:.4f} / {jp['wrist']:.4f}",
            ),
        ]
    if eq == 88:
        return "Fig 25: panel 1 gives no net Fz, panel 2 does; panel 2 gives more Fx; the shoulder dominates the power.", [
            Claim("no net Fz on panel 1", abs(float(arm.Fz)) < 1e-9, f"arm mean Fz = {float(arm.Fz):+.2g}"),
            Claim("net upward Fz on panel 2", float(hand.Fz) < 0, f"hand mean Fz = {float(hand.Fz):+.4f}"),
            Claim("panel 2 gives more Fx than panel 1", float(hand.Fx) > float(arm.Fx), f"mean Fx arm / hand = {float(arm.Fx):+.4f} / {float(hand.Fx):+.4f}"),
            Claim("the shoulder joint delivers most of the power", jp["shoulder"] > jp["wrist"], f"joint power shoulder / wrist = {jp['shoulder']:.4f} / {jp['wrist']:.4f}"),
        ]
    return "", []


def fig_histories(ctx: Context) -> list[Entry]:
    cycles = {
        ex.equation: evaluate_cycle(ex.model, ex.params, ex.speed, bird=ctx.bird, n=ctx.res.samples, check_bounds=False)
        for ex in EXAMPLES
    }
    entries = []
    for ex in EXAMPLES:
        c = cycles[ex.equation]
        params = ", ".join(f"{k} {v:.3g}" for k, v in ex.params.items())
        title = f"Model {ex.model}, {ex.regime} example (eq. {ex.equation}, cf. Fig {ex.figure}), V = {ex.speed:g}"
        fig = plots.histories(c, f"{title}\n{params} (rad)")
        name = ctx.save(fig, f"histories_{ex.model}_{ex.regime}")
        said, claims = _history_claims(ex.equation, c, cycles)
        shows = "Force and power of the right wing over one wingbeat" + (", per panel" if ex.model == "m4" else "") + "; dashed: cycle mean."
        entries.append(Entry(name, title, shows, said, tuple(claims)))
    return entries


# ---- 2. thrust coefficient -----------------------------------------------------------


def fig_thrust(ctx: Context) -> list[Entry]:
    polar = ctx.bird.polar
    zeta = np.linspace(0.0, PI / 2, ctx.res.cfx)
    twist = np.linspace(0.0, PI / 4, max(ctx.res.cfx // 2, 8))
    cfx = fd.thrust_coefficient(polar, zeta[:, None], twist[None, :])
    fig = plots.thrust_coefficient(zeta, twist, cfx, f"Thrust coefficient of a translating, twisting section (eq. 23, Fig 9), {polar.kind} polar")
    name = ctx.save(fig, "thrust_coefficient")
    hover = cfx[-1]
    best_hover = float(twist[np.argmax(hover)])
    slope0 = (cfx[:, 1] - cfx[:, 0]) / (twist[1] - twist[0])  # d C_Fx / d twist at zero twist
    helps = zeta[slope0 > 0]
    threshold = float(helps.min()) if helps.size else float("nan")
    envelope = cfx.max(axis=1)
    on_line = fd.thrust_coefficient(polar, twist, twist)
    claims = (
        Claim("in hover (zeta = pi/2) any twist gives C_Fx >= 0", bool(hover.min() >= -1e-12), f"min C_Fx at pi/2 = {hover.min():+.3f}"),
        Claim(
            "in hover the largest C_Fx is at twist = pi/4",
            abs(best_hover - PI / 4) <= (twist[1] - twist[0]),
            f"best twist at pi/2 = {best_hover:.3f} rad",
        ),
        Claim("at small advance angle twist reduces C_Fx", bool(slope0[1] < 0), f"dC_Fx/dtwist at zeta = {zeta[1]:.2f}: {slope0[1]:+.3f}"),
        Claim(
            "twist helps (dC_Fx/dtwist > 0 at zero twist) only for pi/4 < zeta < pi/2",
            abs(threshold - PI / 4) < 0.05,
            f"twist helps above zeta = {threshold:.3f} rad (pi/4 = 0.785; drag moves it down from the lift-only pi/4)",
        ),
        Claim("the largest C_Fx falls as zeta -> 0", bool(np.all(np.diff(envelope) >= -1e-12)), f"max C_Fx {envelope[0]:+.3f} at 0 to {envelope[-1]:+.3f} at pi/2"),
        Claim(
            "the line twist = zeta separates positive and negative modes",
            bool(np.all(on_line <= 0) and np.max(np.abs(on_line)) <= polar.coefficients(np.zeros(1))[1][0] + 1e-12),
            f"C_Fx on the line = -C_D0 cos(zeta), in [{on_line.min():+.3f}, {on_line.max():+.3f}]: the zero contour lies just below it",
        ),
    )
    return [
        Entry(
            name,
            "Thrust coefficient over advance angle and twist (Fig 9)",
            "C_Fx = C_L sin(zeta) - C_D cos(zeta) at incidence zeta - theta_f (eq. 20/23 with the printed eq. 23's missing "
            "sin(zeta) restored), from the bird's polar; black: C_Fx = 0, green: twist = advance angle, magenta: best twist.",
            "Fig 9: with hover advance angle any twist gives thrust, best at pi/4; at small advance angle twist lowers thrust; "
            "twist only helps for pi/4 < zeta < pi/2; the line theta_f = zeta bounds the positive mode; the maximum falls as zeta -> 0.",
            claims,
        )
    ]


# ---- 3. wrist lag and bias -----------------------------------------------------------


def fig_wrist(ctx: Context) -> list[Entry]:
    r = ctx.res
    lag = np.linspace(0.0, PI / 2, r.wrist_map)
    bias = np.linspace(0.0, PI / 2, r.wrist_map)
    pairs = [(PI / 5, 2 * PI / 5), (2 * PI / 5, PI / 5)]
    maps_ = [fd.wrist_upward_force(pf, pw, lag[:, None], bias[None, :], bird=ctx.bird, n=r.landscape_samples) for pf, pw in pairs]
    fig = plots.maps(
        lag, bias,
        [(f"Phi_f = {pf / PI:.1f} pi, Phi_w = {pw / PI:.1f} pi", v) for (pf, pw), v in zip(pairs, maps_)],
        x_label="wrist lag Delta (rad)", y_label="wrist bias Psi (rad)",
        value_label=f"upward force -Fz ({plots.ND})",
        title="Model m4, cruise-like study (sec. 3.5.7, Fig 26): upward force over wrist lag and bias\nV = 0.5, pitch = twist = stroke plane = 0",
        extra=[[(PI / 2, PI / 4, "dissertation's optimum (pi/2, pi/4)")]] * 2,
        footnote=plots.FORCE_NOTE,
    )
    name1 = ctx.save(fig, "wrist_lag_bias")
    argmaxes = [np.unravel_index(np.argmax(v), v.shape) for v in maps_]
    tol = lag[1] - lag[0]
    opt_claims = tuple(
        Claim(
            f"optimum at lag pi/2, bias pi/4 for Phi_f = {pf / PI:.1f} pi, Phi_w = {pw / PI:.1f} pi",
            bool(abs(lag[i] - PI / 2) <= tol and abs(bias[j] - PI / 4) <= tol),
            f"ours at lag {lag[i]:.2f}, bias {bias[j]:.2f} (grid step {tol:.2f})",
        )
        for (pf, pw), (i, j) in zip(pairs, argmaxes)
    ) + (
        Claim(
            "more force with the larger amplitude on panel 1",
            bool(maps_[1].max() > maps_[0].max()),
            f"max upward force {maps_[0].max():.4f} (larger wrist) vs {maps_[1].max():.4f} (larger shoulder)",
        ),
    )
    e1 = Entry(
        name1,
        "Upward force over wrist lag and bias for two amplitude pairs (Fig 26)",
        "Mean upward force -Fz of model m4 over the wrist lag and bias; star: our maximum, ring: the dissertation's.",
        "Fig 26: both maxima at lag pi/2 and bias pi/4; more force with the larger amplitude on panel 1.",
        opt_claims,
        note="'F_z(max)' is read as the most upward mean Fz; amplitudes and bias beyond the default bounds are evaluated without bound checks.",
    )
    amps = np.linspace(PI / 2 / r.wrist_amp, PI / 2, r.wrist_amp)
    grid = np.linspace(0.0, PI / 2, r.wrist_opt)
    opt = fd.wrist_optimum(amps, amps, grid, grid, bird=ctx.bird, n=r.landscape_samples)
    fig = plots.wrist_optimum(opt, "Model m4 (sec. 3.5.7, Fig 27): wrist lag and bias of the largest upward force, V = 0.5")
    name2 = ctx.save(fig, "wrist_optimum")
    corner = opt.lag_star[0, -1]
    e2 = Entry(
        name2,
        "Best wrist lag and bias over the two amplitudes (Fig 27)",
        f"For each (Phi_f, Phi_w): the lag Delta* and bias Psi* (searched on a {r.wrist_opt}-point grid over [0, pi/2]) that give the largest upward force, and that force.",
        "Fig 27: Delta* = pi/2 over most amplitudes, dropping to 0 at small Phi_f and large Phi_w; Psi* roughly pi/4.",
        (
            Claim("Delta* = pi/2 over most amplitudes", bool(np.mean(np.isclose(opt.lag_star, PI / 2)) > 0.5), f"on {np.mean(np.isclose(opt.lag_star, PI / 2)):.0%} of the amplitude pairs"),
            Claim("Delta* drops to 0 at small Phi_f, large Phi_w", bool(corner < PI / 4), f"Delta* at the smallest Phi_f, largest Phi_w = {corner:.2f}"),
            Claim("Psi* approximately pi/4", bool(abs(np.median(opt.bias_star) - PI / 4) < 0.15), f"median Psi* = {np.median(opt.bias_star):.2f} (pi/4 = 0.79)"),
        ),
    )
    return [e1, e2]


# ---- 4. optimisation spaces ----------------------------------------------------------


def _cost_function(model: str, demand: tuple[float, float], previous: dict[str, float] | None = None, nu: float = 0.0):
    """The project cost (birdsim.tables.cost) of a grid, as a :data:`figdata.CostFunction`."""
    from birdsim.tables.cost import CostWeights, breakdown_from_forces, other_cost
    from birdsim.physics.kinematics import get_model

    m = get_model(model)
    weights = CostWeights(distance=nu)

    def cost(means: fd.GridMeans, params, speed) -> np.ndarray:
        shape = means.Fx.shape
        X = np.stack([np.broadcast_to(params[k], shape) for k in m.param_names], axis=-1)
        prev = None if previous is None else np.array([previous[k] for k in m.param_names])
        other = other_cost(m, X, speed, weights, prev)
        return breakdown_from_forces(means.Fx, means.Fz, means.P, demand[0], demand[1], weights, other).total

    return cost


def fig_landscapes(ctx: Context) -> list[Entry]:
    r = ctx.res
    flap = np.linspace(0.0, PI / 2, r.landscape)
    twist = np.linspace(0.0, PI / 4, r.landscape)
    pitch = np.linspace(0.0, PI / 2, r.profile)
    demand = SMALL_DEMAND

    def base_landscape(speed: float, previous=None, nu=0.0) -> fd.Landscape:
        return fd.landscape(
            "base", speed, _cost_function("base", demand, previous, nu), ("flap_amp", flap), ("twist_amp", twist),
            profile={"pitch": pitch}, bird=ctx.bird, n=r.landscape_samples,
        )

    speeds = (0.2, 0.7, 3.0)
    ls = [base_landscape(v) for v in speeds]
    note = f"demand Fx = {demand[0]}, Fz = {demand[1]} (the 'small requirements'; not printed in the text); cost = |dFx| + |dFz| + 0.5|P|, minimised over body pitch at each cell; " + plots.FORCE_NOTE
    fig = plots.maps(
        flap, twist, [(f"V = {v:g}: best ({l.best['flap_amp']:.2f}, {l.best['twist_amp']:.2f}), pitch {l.best['pitch']:.2f}", l.cost) for v, l in zip(speeds, ls)],
        x_label="flap amplitude Phi_f (rad)", y_label="twist amplitude Theta_f (rad)", value_label=f"cost ({plots.ND})",
        title="Base model optimisation spaces (Fig 33): cost over flap and twist amplitude", mark="min", footnote=note, shared_scale=False,
    )
    name1 = ctx.save(fig, "cost_flap_twist")
    # "valley" measure: the fraction of cells within 10% (of the cost range) of the minimum
    flat = [float(np.mean(l.cost <= l.cost.min() + 0.1 * np.ptp(l.cost))) for l in ls]
    e1 = Entry(
        name1,
        "Cost over flap and twist amplitude at V = 0.2, 0.7, 3 (Fig 33)",
        "The project cost over (Phi_f, Theta_f) for the base model, body pitch chosen best on its grid in each cell; star: the grid minimum (the valley is narrow: a finer grid or an optimiser finds lower points).",
        "Fig 33: a distinct valley at V = 0.2, an almost flat low-cost region at V = 0.7 (minimum near Phi_f = 0.98, Theta_f = 0.28), a clear valley again at V = 3.",
        (
            Claim(
                "the intermediate speed has the widest low-cost region",
                flat[1] > max(flat[0], flat[2]),
                "share of cells within 10% of the cost range above the minimum: " + ", ".join(f"V={v:g}: {f:.0%}" for v, f in zip(speeds, flat)),
            ),
            Claim(
                "V = 0.7 minimum near Phi_f = 0.98, Theta_f = 0.28",
                abs(ls[1].best["flap_amp"] - 0.98) < 0.15 and abs(ls[1].best["twist_amp"] - 0.28) < 0.15,
                f"ours at ({ls[1].best['flap_amp']:.2f}, {ls[1].best['twist_amp']:.2f}), within 0.15 rad counts",
            ),
        ),
    )
    l6 = base_landscape(0.6)
    prev = dict(pitch=l6.best["pitch"], flap_amp=l6.best["flap_amp"], twist_amp=l6.best["twist_amp"])
    l7d = base_landscape(0.7, previous=prev, nu=0.2)
    l7 = ls[1]
    fig = plots.maps(
        flap, twist,
        [
            (f"V = 0.6: best ({l6.best['flap_amp']:.2f}, {l6.best['twist_amp']:.2f})", l6.cost),
            (f"V = 0.7: best ({l7.best['flap_amp']:.2f}, {l7.best['twist_amp']:.2f})", l7.cost),
            (f"V = 0.7, distance cost nu = 0.2: best ({l7d.best['flap_amp']:.2f}, {l7d.best['twist_amp']:.2f})", l7d.cost),
        ],
        x_label="flap amplitude Phi_f (rad)", y_label="twist amplitude Theta_f (rad)", value_label=f"cost ({plots.ND})",
        title="Base model (Fig 34): the distance cost (eq. 93) holds the V = 0.7 optimum near the V = 0.6 one",
        mark="min", footnote=note, shared_scale=False,
        extra=[[], [], [(prev["flap_amp"], prev["twist_amp"], "V = 0.6 optimum")]],
    )
    name2 = ctx.save(fig, "cost_distance")
    d_free = math.dist((l7.best["flap_amp"], l7.best["twist_amp"]), (prev["flap_amp"], prev["twist_amp"]))
    d_held = math.dist((l7d.best["flap_amp"], l7d.best["twist_amp"]), (prev["flap_amp"], prev["twist_amp"]))
    e2 = Entry(
        name2,
        "The distance cost between V = 0.6 and 0.7 (Fig 34)",
        "Cost over (Phi_f, Theta_f) at V = 0.6, 0.7 and 0.7 plus nu |x - x_0.6| (nu = 0.2); pitch chosen best in each cell.",
        "Fig 34: V = 0.6 optimum (1.03, 0.40); at V = 0.7 without the distance cost (0.97, 0.26), with it (1.03, 0.38): the distance cost holds the solution.",
        (
            Claim(
                "the distance cost keeps the V = 0.7 optimum closer to the V = 0.6 one",
                d_held <= d_free,
                f"distance from the V = 0.6 optimum: {d_free:.3f} rad without, {d_held:.3f} rad with nu = 0.2",
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
        params = dict(pitch=pitch[None, :], flap_amp=PI / 4, twist_amp=twist, stroke_plane=0.0, **fd.wrist_activity(k[:, None]))
        maps_.append(-fd.grid_means("m4", params, 0.0, bird=ctx.bird, n=r.landscape_samples).Fz)
    fig = plots.maps(
        k, pitch, [(f"Theta_f = {t}", v) for t, v in zip(("0", "pi/16"), maps_)],
        x_label="wrist activity K (non-dimensional, eq. 95)", y_label="body pitch theta (rad)",
        value_label=f"upward force -Fz ({plots.ND})",
        title="Model m4 (Fig 49): upward force over wrist activity K and body pitch\nV = 0, Phi_f = pi/4, stroke plane 0; (Phi_w, Delta, Psi) = K (pi/4, pi/2, pi/4)",
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
            "Mean upward force of model m4 in hover (V = 0) over K and pitch, without twist (left) and with twist pi/16 (right).",
            "Fig 49: no twist: zero force at pitch pi/2 for every K, and for pitch < pi/2 the largest K gives the most force; "
            "twist pi/16: at pitch pi/2 the most force with K = 0, and lower pitch favours larger K.",
            (
                Claim("no twist, pitch pi/2: zero force for every K", bool(np.abs(m0[:, -1]).max() < 1e-9), f"max |Fz| there = {np.abs(m0[:, -1]).max():.2g}"),
                Claim("no twist, pitch < pi/2: K = 1 gives the most force", bool(np.mean(best_k0 == 1.0) > 0.5), f"K = 1 best on {np.mean(best_k0 == 1.0):.0%} of the pitch values"),
                Claim("twist pi/16, pitch pi/2: K = 0 best", bool(best_k1[-1] == 0.0), f"best K at pitch pi/2 = {best_k1[-1]:.2f}"),
                Claim("twist pi/16: lower pitch favours larger K", bool(best_k1[0] > best_k1[-1]), f"best K at pitch 0 / pi/2 = {best_k1[0]:.2f} / {best_k1[-1]:.2f}"),
            ),
        )
    )
    # Figs 50-51: cost over K and flap amplitude, pitch and twist minimised over
    kk = np.linspace(0.0, 1.0, r.m4_landscape)
    flap = np.linspace(0.0, PI / 4, r.m4_landscape)
    prof = {"pitch": np.linspace(0.0, PI / 2, r.m4_profile), "twist_amp": np.linspace(0.0, PI / 4, r.m4_profile)}
    speeds = (0.0, 0.5, 1.0)
    rows = []
    for label, bird in (("hand as long as the arm (Fig 50)", replace(ctx.bird, hand_span_fraction=0.5)), ("hand half the arm, the default (Fig 51)", ctx.bird)):
        row = []
        for v in speeds:
            row.append(
                fd.landscape(
                    "m4", v, _cost_function("m4", SMALL_DEMAND), ("K", kk), ("flap_amp", flap), fixed={"stroke_plane": 0.0},
                    profile=prof, derived=lambda p: fd.wrist_activity(p["K"]), bird=bird, n=r.landscape_samples,
                )
            )
        rows.append((label, row))
    names = []
    for (label, row), stem in zip(rows, ("wrist_activity_cost_equal_hand", "wrist_activity_cost")):
        fig = plots.maps(
            kk, flap, [(f"V = {v:g}: best K = {l.best['K']:.2f}", l.cost) for v, l in zip(speeds, row)],
            x_label="wrist activity K (non-dimensional)", y_label="shoulder flap amplitude Phi_f (rad)", value_label=f"cost ({plots.ND})",
            title=f"Model m4 optimisation spaces over K, {label}",
            mark="min", shared_scale=False,
            footnote=f"demand Fx = {SMALL_DEMAND[0]}, Fz = {SMALL_DEMAND[1]}; stroke plane 0; pitch and twist chosen best per cell; " + plots.FORCE_NOTE,
        )
        names.append(ctx.save(fig, stem))
    best_equal = [l.best["K"] for l in rows[0][1]]
    best_half = [l.best["K"] for l in rows[1][1]]
    out.append(
        Entry(
            names[0],
            "Cost over wrist activity K, hand as long as the arm (Fig 50)",
            "Cost of model m4 over (K, Phi_f) at V = 0, 0.5, 1 with arm and hand each half the semispan; pitch and twist chosen best per cell.",
            "Fig 50 (an 'arbitrarily sized' hand): K = 0 at V = 0, an irregular space with two minima at V = 0.5, K about 0.37 at V = 1.",
            (Claim("K = 0 best at V = 0", best_equal[0] == 0.0, "best K at V = 0, 0.5, 1: " + ", ".join(f"{b:.2f}" for b in best_equal)),),
        )
    )
    out.append(
        Entry(
            names[1],
            "Cost over wrist activity K, hand half the arm (Fig 51)",
            "As above with the default geometry (hand span = half the arm span, semispan 1).",
            "Fig 51: K = 0 at low speed; the valley moves to larger K as V rises, K = 1 at V = 1.",
            (
                Claim("K = 0 best at V = 0", best_half[0] == 0.0, f"best K at V = 0: {best_half[0]:.2f}"),
                Claim("best K grows with speed", bool(np.all(np.diff(best_half) >= 0) and best_half[-1] > best_half[0]), "best K at V = 0, 0.5, 1: " + ", ".join(f"{b:.2f}" for b in best_half)),
                Claim("K = 1 best at V = 1", best_half[-1] == 1.0, f"best K at V = 1: {best_half[-1]:.2f}"),
            ),
        )
    )
    return out


# ---- 7. control-point paths ----------------------------------------------------------

#: The captions' parameters (OCR read: Fig 41 prints Phi_f = 0.79, Theta_f = 1.5 and
#: Fig 42 Phi_f = "0.1.5", Theta_f = 1.5 -- Theta_f is bounded by pi/4 and the text says
#: flap and twist are at their maxima, so the two are read as Phi_f = 1.5, Theta_f = 0.79).
CP_CASES: tuple[tuple[str, str, int, float, tuple[float, float], dict[str, float]], ...] = (
    # model, case, figure, V, demand (Fx, Fz) from the text, caption parameters
    ("base", "hover", 41, 0.0, (0.0, -0.5), dict(pitch=1.5, flap_amp=1.5, twist_amp=0.79)),
    ("base", "take-off", 42, 0.0, (0.5, -0.5), dict(pitch=0.7, flap_amp=1.5, twist_amp=0.79)),
    ("base", "cruise", 43, 0.9, (0.0, -0.2), dict(pitch=0.02, flap_amp=0.75, twist_amp=0.25)),
    ("m3", "hover", 46, 0.0, (0.0, -0.5), dict(pitch=1.2, flap_amp=0.75, twist_amp=0.79, stroke_plane=0.35)),
    ("m3", "take-off", 47, 0.0, (0.5, -0.5), dict(pitch=0.25, flap_amp=1.5, twist_amp=0.79, stroke_plane=0.35)),
    ("m3", "cruise", 48, 0.9, (0.0, -0.25), dict(pitch=0.0, flap_amp=0.4, twist_amp=0.16, stroke_plane=0.25)),
    ("m4", "hover", 53, 0.0, (0.0, -0.5), dict(pitch=1.2, flap_amp=0.79, twist_amp=0.79, stroke_plane=0.35, wrist_amp=0.01, wrist_bias=0.02, wrist_lag=1.55)),
    ("m4", "take-off", 54, 0.0, (0.5, -0.5), dict(pitch=0.1, flap_amp=0.79, twist_amp=0.79, stroke_plane=0.35, wrist_amp=0.01, wrist_bias=0.01, wrist_lag=1.55)),
    ("m4", "cruise", 55, 0.9, (0.0, -0.25), dict(pitch=0.0, flap_amp=0.62, twist_amp=0.41, stroke_plane=0.21, wrist_amp=0.30, wrist_bias=0.29, wrist_lag=1.55)),
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
        c = evaluate_cycle(model, params, speed, bird=ctx.bird, n=ctx.res.samples, check_bounds=False).mean
        stem = f"cp_paths_{model}_{case.replace('-', '')}"
        text = ", ".join(f"{k} {v:g}" for k, v in params.items())
        title = f"Model {model}, {case} (cf. Fig {figno}): control-point paths and chord lines\n{text} (rad); at V = {speed:g}: mean Fx {float(c.Fx):+.3f}, Fz {float(c.Fz):+.3f}"
        name = ctx.save(plots.cp_paths(p, title), stem)
        x_ext, z_ext = np.ptp(p.path[0, :, 0]), np.ptp(p.path[0, :, 2])
        fx, fz = float(c.Fx), float(c.Fz)
        claims: list[Claim] = [
            Claim(
                f"the caption's parameters answer the demand Fx = {demand[0]:g}, Fz = {demand[1]:g}: upward"
                + (" and forward" if demand[0] > 0 else ""),
                fz < 0 and (fx > 0 or demand[0] <= 0),
                f"mean Fx {fx:+.3f}, Fz {fz:+.3f}",
            )
        ]
        said = f"Fig {figno}: CP path and chord lines of the optimum for V = {speed:g}, Fx = {demand[0]:g}, Fz = {demand[1]:g}."
        if case == "hover":
            claims.append(Claim("hover: a near-horizontal stroke (more fore-aft than vertical travel)", bool(x_ext > z_ext), f"CP travel X {x_ext:.2f}, Z {z_ext:.2f}"))
            said += " Hover uses a near-horizontal stroke."
        if case == "cruise":
            claims.append(Claim("cruise: a near-vertical stroke", bool(z_ext > x_ext), f"CP travel X {x_ext:.2f}, Z {z_ext:.2f}"))
            said += " Cruise uses a near-vertical stroke."
        if model == "m4" and case == "cruise":
            a_arm, a_hand = _loop_area(p.path[0]), _loop_area(p.path[1])
            claims.append(Claim("the hand CP traces an ellipse (a loop, unlike the arm's arc)", a_hand > 5 * a_arm, f"enclosed area arm {a_arm:.4f}, hand {a_hand:.4f}"))
            said += " The wrist's lag and bias make the second CP trace an ellipse."
        entries.append(
            Entry(
                name,
                f"Model {model} {case}: control-point paths (Fig {figno})",
                "Plan, rear, side and perspective views of each panel's CP over one wingbeat with the chord line at 16 instants (leading edge dotted); "
                "relative to the shoulder, earth-oriented axes with up = -Z; the title gives the mean force these parameters produce.",
                said,
                tuple(claims),
                note="Parameters from the dissertation's caption (Figs 41-42: flap and twist read swapped, see docs/report.md)." if figno in (41, 42) else "Parameters from the dissertation's caption.",
            )
        )
    return entries


# ---- 5. solutions over speed ---------------------------------------------------------


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


_SWEEP_SAID = {
    "base": "Figs 35/38: pitch falls with speed (not vertical at V = 0 because of the Fx demand); twist at its maximum for V up to ~0.3, "
    "then falling to almost none at V = 1; forward and backward passes agree at low and high speed.",
    "m1": "Fig 44: model 1 follows the base model closely; in hover it uses maximum values.",
    "m2": "",
    "m3": "Fig 45: at low speed the maximum stroke-plane angle plus some body pitch (their sum = the base model's pitch); in cruise no body pitch, the stroke plane vectors the force.",
    "m4": "Fig 52 (Fx = 0, stroke plane omitted, backward pass): maximum pitch, flap and twist in hover; wrist amplitude and bias small at low speed, "
    "rising at intermediate speeds; the lag stays at pi/2.",
}


def _sweep_claims(model: str, fwd: fd.SpeedSweep, bwd: fd.SpeedSweep, base_fwd: fd.SpeedSweep | None) -> list[Claim]:
    from birdsim.physics.kinematics import get_model

    m = get_model(model)
    col = {n: fwd.params[:, i] for i, n in enumerate(fwd.param_names)}
    up = {p.name: p.upper for p in m.params}
    v = fwd.speeds
    ends = np.abs(fwd.params[[0, -1]] - bwd.params[[0, -1]]).max()
    claims = []
    if model == "base":
        low = v <= 0.3 + 1e-9
        claims += [
            Claim("pitch falls with speed", bool(col["pitch"][-1] < col["pitch"][0]), f"pitch {col['pitch'][0]:.2f} at V = 0, {col['pitch'][-1]:.2f} at V = 1"),
            Claim("not pitched vertically at V = 0", bool(col["pitch"][0] < PI / 2 - 0.05), f"pitch at V = 0: {col['pitch'][0]:.2f}"),
            Claim("twist at its maximum up to V ~ 0.3", bool(np.all(col["twist_amp"][low] > up["twist_amp"] - 0.02)), f"twist for V <= 0.3: {', '.join(f'{t:.2f}' for t in col['twist_amp'][low])}"),
            Claim("almost no twist at V = 1", bool(col["twist_amp"][-1] < 0.1), f"twist at V = 1: {col['twist_amp'][-1]:.2f}"),
        ]
    if model == "m1" and base_fwd is not None:
        diff = np.abs(fwd.params - base_fwd.params).max()
        claims += [
            Claim("follows the base model closely", bool(diff < 0.2), f"largest parameter difference to the base model: {diff:.3f} rad"),
            Claim("maximum flap and twist in hover", bool(col["flap_amp"][0] > up["flap_amp"] - 0.02 and col["twist_amp"][0] > up["twist_amp"] - 0.02), f"at V = 0: flap {col['flap_amp'][0]:.2f}, twist {col['twist_amp'][0]:.2f}"),
        ]
    if model == "m3" and base_fwd is not None:
        total = col["pitch"][0] + col["stroke_plane"][0]
        claims += [
            Claim("maximum stroke plane at V = 0", bool(col["stroke_plane"][0] > up["stroke_plane"] - 0.01), f"stroke plane at V = 0: {col['stroke_plane'][0]:.3f}"),
            Claim("pitch + stroke plane at V = 0 equals the base model's pitch", bool(abs(total - base_fwd.params[0, 0]) < 0.05), f"{total:.3f} vs base {base_fwd.params[0, 0]:.3f}"),
            Claim("no body pitch in cruise, the stroke plane used", bool(col["pitch"][-1] < 0.05 and col["stroke_plane"][-1] > 0.05), f"at V = 1: pitch {col['pitch'][-1]:.3f}, stroke plane {col['stroke_plane'][-1]:.3f}"),
        ]
    if model == "m4":
        hover = [col[k][0] > up[k] - 0.05 for k in ("pitch", "flap_amp", "twist_amp")]
        claims += [
            Claim("maximum pitch, flap and twist in hover", all(hover), f"at V = 0: pitch {col['pitch'][0]:.2f}, flap {col['flap_amp'][0]:.2f}, twist {col['twist_amp'][0]:.2f}"),
            Claim("wrist amplitude and bias small at V = 0, larger at high speed", bool(col["wrist_amp"][0] < 0.1 and col["wrist_bias"][0] < 0.1 and col["wrist_amp"][-1] > col["wrist_amp"][0]), f"wrist amp {col['wrist_amp'][0]:.2f} -> {col['wrist_amp'][-1]:.2f}, bias {col['wrist_bias'][0]:.2f} -> {col['wrist_bias'][-1]:.2f}"),
            Claim("lag at pi/2 where the wrist moves", bool(np.all(np.abs(col["wrist_lag"][col["wrist_amp"] > 0.05] - PI / 2) < 0.1)), f"lag where wrist amp > 0.05: {', '.join(f'{x:.2f}' for x in col['wrist_lag'][col['wrist_amp'] > 0.05]) or 'none'}"),
        ]
    if model in ("base", "m1", "m3"):
        claims.append(Claim("forward and backward passes agree at V = 0 and V = 1", bool(ends < 0.05), f"largest difference at the ends: {ends:.3f} rad"))
    return claims


def _missed(sw: fd.SpeedSweep, demand: tuple[float, float]) -> np.ndarray:
    return np.maximum(np.abs(sw.achieved[:, 0] - demand[0]), np.abs(sw.achieved[:, 1] - demand[1])) > 0.01


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
                ("backward pass (V = 1 -> 0)", bwd.params[:, i], {"ls": "--", "marker": "s", "ms": 3, "mfc": "none"}),
            ]
            if model == "m1" and name in base_fwd.param_names:
                items.append(("base model, forward (Fig 44)", base_fwd.params[:, base_fwd.param_names.index(name)], {"color": "0.6", "lw": 3, "alpha": 0.6, "zorder": 0}))
            series[f"{name} (rad)"] = items
        series[f"achieved force ({plots.ND})"] = [
            ("Fx, forward", fwd.achieved[:, 0], {"color": "tab:blue"}), ("Fz, forward", fwd.achieved[:, 1], {"color": "tab:orange"}),
            ("Fx, backward", bwd.achieved[:, 0], {"color": "tab:blue", "ls": "--"}), ("Fz, backward", bwd.achieved[:, 1], {"color": "tab:orange", "ls": "--"}),
            ("Fx demand", np.full_like(fwd.speeds, demand[0]), {"color": "k", "ls": ":"}), ("Fz demand", np.full_like(fwd.speeds, demand[1]), {"color": "0.5", "ls": ":"}),
        ]
        fig = plots.lines(
            fwd.speeds, series, x_label=f"flight speed V ({plots.ND})",
            title=f"Model {model}: optimal wingbeat over speed for Fx = {demand[0]:g}, Fz = {demand[1]:g}, forward and backward passes"
            + (" (stroke plane held at 0)" if model == "m4" else ""),
            footnote="SLSQP warm-started from the previous speed; forward pass starts from the upper bounds, backward from "
            + ("small shoulder and large wrist values" if model == "m4" else "the cruise guess") + "; " + plots.FORCE_NOTE,
            ncols=3 if len(series) > 4 else 2,
        )
        name = ctx.save(fig, f"speed_sweep_{model}")
        entries.append(
            Entry(
                name, f"Model {model}: solutions over speed (forward and backward passes)",
                "Each parameter of the optimum over speed, solved speed by speed with warm starts in both directions, and the force it achieves.",
                _SWEEP_SAID[model], tuple(_sweep_claims(model, fwd, bwd, base_fwd)),
                note=f"Demand Fx = {demand[0]:g}, Fz = {demand[1]:g}: the dissertation asks for 'small' demands without printing them. "
                + "Speeds where the optimum misses the demand by more than 0.01: "
                + "; ".join(
                    f"{sw.direction} " + (", ".join(f"V={v:.2f}" for v in sw.speeds[_missed(sw, demand)]) or "none")
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
    f_strong = fd.speed_sweep("base", strong, speeds, up, bird=ctx.bird, n=ctx.res.landscape_samples)
    cases = [(SMALL_DEMAND, base_fractions), (strong, f_strong)]
    fig = plots.fractions(
        speeds, [(f"Fx = {d[0]:g}, Fz = {d[1]:g}", sw.fractions) for d, sw in cases], FRACTION_NAMES,
        "Base model (Fig 36): cost fractions of the forward-pass optimum over speed, for the small demand of the sweeps and a strong upward demand",
        footnote="force x = |dFx|, force z = |dFz|, power = 0.5|P|, other = orientation + distance costs; " + plots.FORCE_NOTE,
    )
    name = ctx.save(fig, "cost_fractions")
    claims = []
    for d, sw in cases:
        fr = {n: sw.fractions[:, i] for i, n in enumerate(FRACTION_NAMES)}
        i08 = int(np.argmin(np.abs(speeds - 0.8)))
        tag = f" (Fz = {d[1]:g})"
        claims += [
            Claim("the Fz deficit dominates at V = 0" + tag, bool(np.argmax(sw.fractions[0]) == FRACTION_NAMES.index("force_z")), "shares at V = 0: " + ", ".join(f"{n} {100 * fr[n][0]:.0f}%" for n in FRACTION_NAMES)),
            Claim("power about 90% near V = 0.8" + tag, bool(fr["power"][i08] > 0.8), f"power share at V = {speeds[i08]:.2f}: {100 * fr['power'][i08]:.0f}%"),
            Claim("the Fx deficit rises at the top speed" + tag, bool(fr["force_x"][-1] > fr["force_x"][i08] + 0.01), f"Fx share {100 * fr['force_x'][i08]:.0f}% at V = {speeds[i08]:.2f}, {100 * fr['force_x'][-1]:.0f}% at V = 1"),
        ]
    entries.append(
        Entry(
            name, "Cost fractions over speed (Fig 36)",
            "Each cost term as a share of the total cost of the base model's forward-pass optimum at each speed, for two demands.",
            "Fig 36: at low speed the Fz deficit dominates; the power share rises to about 90% at V = 0.8; beyond, the Fx deficit rises.",
            tuple(claims),
            note="Where the optimum meets the demand exactly, the force shares are zero and power is the whole cost; the dissertation's "
            "low-speed Fz deficit means its demand was out of reach there, hence the second, strong demand.",
        )
    )
    return entries


# ---- 6. table slices -----------------------------------------------------------------

TABLE_SPEEDS = (0.0, 0.5, 0.9)
TABLE_FOLDER = Path(__file__).resolve().parents[1] / "tables"


def _table(ctx: Context, model: str):
    """The committed table of ``model`` if there is one, else a small one built here."""
    from birdsim.tables.lookup import load_table, table_paths

    npz, _ = table_paths(TABLE_FOLDER / model)
    if npz.exists() and not ctx.res.quick:
        return load_table(npz), f"committed table {npz.relative_to(TABLE_FOLDER.parent)}"
    from birdsim.tables.build import BuildConfig, Grid, build_table

    k = ctx.res.table_grid
    grid = Grid.parse("V=" + "|".join(f"{v:g}" for v in TABLE_SPEEDS), size=k)
    t = build_table(BuildConfig(model, grid, bird=ctx.bird, settings=ctx.res.build_settings()), jobs=1)
    why = "--quick" if ctx.res.quick else "no committed table"
    return t, f"built here on a {k} x {k} (Fx, Fz) grid at V = 0, 0.5, 0.9 ({why})"


def fig_tables(ctx: Context) -> list[Entry]:
    from birdsim.physics.kinematics import get_model

    entries = []
    for model in ("base", "m1", "m2", "m3", "m4"):
        t, source = _table(ctx, model)
        vax = t.axes["V"]
        iv = [int(np.argmin(np.abs(vax - v))) for v in TABLE_SPEEDS]
        speeds = [float(vax[i]) for i in iv]
        m = get_model(model)
        ok = (t.status == "ok")[:, :, iv]
        vals = t.params[:, :, iv, :]
        fig = plots.table_slices(
            t.axes["Fx"], t.axes["Fz"], speeds, list(t.param_names), vals, ok, [(p.lower, p.upper) for p in m.params],
            f"Model {model}: lookup-table slices, each parameter over the demanded (Fx, Fz) at V = " + ", ".join(f"{v:g}" for v in speeds),
            footnote=f"{source}; colour scale = the parameter's bounds; " + plots.FORCE_NOTE,
        )
        name = ctx.save(fig, f"table_{model}")
        pitch = vals[..., list(t.param_names).index("pitch")]
        flap = vals[..., list(t.param_names).index("flap_amp")]
        mid = 1 if len(iv) > 1 else 0
        claims = (
            Claim("body pitch falls with speed", bool(np.mean(pitch[..., -1]) < np.mean(pitch[..., 0])), f"mean pitch {np.mean(pitch[..., 0]):.2f} at V = {speeds[0]:g}, {np.mean(pitch[..., -1]):.2f} at V = {speeds[-1]:g}"),
            Claim(
                "flap amplitude grows with the upward demand",
                bool(np.mean(flap[:, 0, mid]) > np.mean(flap[:, -1, mid])),
                f"mean flap at V = {speeds[mid]:g}: {np.mean(flap[:, 0, mid]):.2f} for Fz = {t.axes['Fz'][0]:g}, {np.mean(flap[:, -1, mid]):.2f} for Fz = {t.axes['Fz'][-1]:g}",
            ),
        )
        figs = {"base": "Fig 40", "m1": "appendix 6", "m3": "appendix 7", "m4": "appendix 8"}
        entries.append(
            Entry(
                name, f"Model {model}: table slices at V = 0, 0.5, 0.9 ({figs.get(model, 'no printed counterpart')})",
                f"Every parameter of the optimal wingbeat over the demand grid, rows by speed; crosses: demand missed ({source}).",
                "Fig 40: body pitch falls as speed rises; flap amplitude grows with the (upward) Fz demand." if model in figs else "",
                claims,
                note=f"{int(ok.sum())} of {ok.size} cells meet the demand within the table's reach tolerance.",
            )
        )
    return entries


# ---- 8. optimisers and build time ----------------------------------------------------


def fig_optimisers(ctx: Context) -> list[Entry]:
    nodes = ctx.res.optimiser_nodes
    runs = {
        "f": [fd.optimiser_run("f", "complete", nodes=nodes), fd.optimiser_run("f", "slsqp", x0=(0.0, 1.0)), fd.optimiser_run("f", "evolutionary")],
        "g": [
            fd.optimiser_run("g", "complete", nodes=nodes), fd.optimiser_run("g", "slsqp", x0=(0.0, 1.0)),
            fd.optimiser_run("g", "slsqp", x0=(0.8, 0.5)), fd.optimiser_run("g", "slsqp", x0=(0.7, 0.7)), fd.optimiser_run("g", "evolutionary"),
        ],
    }
    u = np.linspace(0, 1, 101)
    gx, gy = np.meshgrid(u, u, indexing="ij")
    pts = np.stack([gx.ravel(), gy.ravel()], axis=-1)
    grids = [fd.test_function_f(pts).reshape(gx.shape), fd.test_function_g(pts).reshape(gx.shape)]
    fig = plots.optimiser_runs([runs["f"], runs["g"]], grids, "Optimisers on the test functions f (eq. 89, top) and g (eq. 90, bottom), Figs 28-30")
    name1 = ctx.save(fig, "optimiser_paths")
    series = {
        f"best {k}(x, y) so far - min {k} + 1e-6 ({plots.ND})": [(r.label, r.best_so_far - (0.25 if k == "f" else 0.0) + 1e-6, {"x": np.arange(1, len(r.values) + 1)}) for r in rs]
        for k, rs in runs.items()
    }
    fig = plots.lines(np.arange(1), series, x_label="function evaluations", title="Convergence of the optimisers (Fig 31): error of the best point so far", logy=True,
                      footnote="plotted: best value so far minus the global minimum (0.25 for f, 0 for g) plus 1e-6, log scale")
    for ax in fig.axes:
        ax.set_xscale("log")
    name2 = ctx.save(fig, "optimiser_convergence")
    cf, sf, ef = runs["f"]
    cg, sg1, sg2, sg3, eg = runs["g"]
    claims = (
        Claim("complete search (12 nodes) misses f's minimum by 0.0021", bool(nodes == 12 and abs(cf.value - 0.25 - 0.0021) < 5e-5), f"ours: f({cf.x[0]:.4f}, {cf.x[1]:.4f}) = {cf.value:.4f} ({nodes} nodes, {cf.evaluations} evaluations)"),
        Claim("gradient method finds f's minimum exactly from (0, 1)", abs(sf.value - 0.25) < 1e-6, f"SLSQP: {sf.value:.6f} after {sf.iterations} iterations, {sf.evaluations} evaluations"),
        Claim("the evolutionary method gets within 0.001 of f's minimum", abs(ef.value - 0.25) < 1e-3, f"{ef.value:.5f} after {ef.evaluations} evaluations"),
        Claim("complete search finds g's global minimum 0 at a node", abs(cg.value) < 1e-12, f"g = {cg.value:.4f} at ({cg.x[0]:.2f}, {cg.x[1]:.2f})"),
        Claim("gradient method from (0, 1) stays at g(0, 1) = 0.9093", abs(sg1.value - 0.9093) < 1e-4, f"ends at g({sg1.x[0]:.3f}, {sg1.x[1]:.3f}) = {sg1.value:.4f}"),
        Claim("from (0.8, 0.5) it ends in g(1, 0) = 0.2273", abs(sg2.value - 0.2273) < 1e-4, f"ends at g({sg2.x[0]:.3f}, {sg2.x[1]:.3f}) = {sg2.value:.4f}"),
        Claim("from (0.7, 0.7) it finds g(0, 0) = 0", abs(sg3.value) < 1e-6, f"ends at g({sg3.x[0]:.3f}, {sg3.x[1]:.3f}) = {sg3.value:.4f}"),
        Claim("the evolutionary method finds g's global minimum", abs(eg.value) < 1e-3, f"{eg.value:.5f} after {eg.evaluations} evaluations"),
        Claim("accuracy ranks gradient > evolutionary > complete search on f", bool(abs(sf.value - 0.25) <= abs(ef.value - 0.25) <= abs(cf.value - 0.25)), f"errors {abs(sf.value - 0.25):.1e}, {abs(ef.value - 0.25):.1e}, {abs(cf.value - 0.25):.1e}"),
    )
    table3 = "Table 3 (ours): " + "; ".join(f"{r.function}: {r.label}: error {r.value - (0.25 if r.function == 'f' else 0):.4f}, {r.evaluations} evaluations" for r in runs["f"] + runs["g"])
    e1 = Entry(
        name1, "Optimisers on f and g (Figs 28-30, Table 3)",
        "Every point each solver evaluated (colour = order), over the function's contours; star = its answer.",
        "Table 3 / Figs 28-30: CSA error 0.0021 on f (144 nodes), GBM exact on f in 4 iterations, GA error 0.0005; on g the GBM ends in local minima from (0, 1) and (0.8, 0.5) "
        "and finds 0 from (0.7, 0.7); CSA and GA find 0.",
        claims, note=table3 + ". Our 'evaluations' count every function value including SLSQP's finite-difference points; the dissertation counted iterations.",
    )
    e2 = Entry(
        name2, "Convergence of the optimisers (Fig 31)",
        "Error of the best point found so far against the number of function evaluations, per solver.",
        "Fig 31: the complete search steps down as it sweeps (f's minimum node after 66 of 144 evaluations); the gradient method converges in 3-4 iterations; the GA is less predictable.",
        (Claim("the gradient method needs the fewest evaluations on f", bool(sf.evaluations < min(cf.evaluations, ef.evaluations)), f"evaluations: complete {cf.evaluations}, SLSQP {sf.evaluations}, evolutionary {ef.evaluations}"),),
    )
    return [e1, e2, _build_time(ctx)]


def _build_time(ctx: Context) -> Entry:
    import platform

    from birdsim.tables.build import BuildConfig, Grid, build_table
    from birdsim.physics.kinematics import get_model

    k = ctx.res.build_grid
    models = ("base", "m1", "m2", "m3", "m4")
    dof, secs = [], []
    repeats = 1 if ctx.res.quick else 3
    for model in models:
        best = math.inf
        for _ in range(repeats):  # the fastest of a few runs: least disturbed by other jobs
            t0 = time.perf_counter()
            build_table(BuildConfig(model, Grid.default(k), bird=ctx.bird, settings=ctx.res.build_settings()), jobs=1)
            best = min(best, time.perf_counter() - t0)
        secs.append(best)
        dof.append(len(get_model(model).param_names))
    dof_a, secs_a = np.array(dof, dtype=float), np.array(secs)
    slope = float(np.polyfit(np.log(dof_a), np.log(secs_a), 1)[0])
    series = {"build time (s, this machine)": [(m, np.array([s]), {"x": np.array([d]), "marker": "o", "ms": 8, "ls": ""}) for m, d, s in zip(models, dof, secs)]}
    cells = k**3
    fig = plots.lines(
        np.arange(1), series, x_label="free parameters of the model (DOF)",
        title=f"Table-build time against the number of free parameters (Fig 63), {k} x {k} x {k} grid, one process",
        footnote=f"measured on {platform.machine()} ({platform.processor() or 'cpu'}), {cells} cells per table, while other jobs may share the machine; "
        f"log-log slope {slope:.2f}",
        ncols=1,
    )
    name = ctx.save(fig, "build_time")
    return Entry(
        name, "Table-build time against the number of free parameters (Fig 63)",
        f"Seconds to build a {k} x {k} x {k} table ({'default' if not ctx.res.quick else 'coarse --quick'} settings, one process; fastest of {repeats}) for each model, measured during this report run.",
        "Fig 63: time grows roughly quadratically with the number of free parameters (hours per full table on a 2.8 GHz Pentium 4).",
        (
            Claim("time grows with the number of free parameters", bool(secs[-1] > secs[0]), f"base ({dof[0]} DOF) {secs[0]:.2f} s, m4 ({dof[-1]} DOF) {secs[-1]:.2f} s"),
            Claim("roughly quadratic growth", bool(1.0 <= slope <= 3.0), f"log-log slope of time against DOF = {slope:.2f}"),
        ),
        note="A small grid: the absolute times are this machine's on this grid, not a full table's.",
    )


# ---- the report ----------------------------------------------------------------------


@dataclass(frozen=True)
class Family:
    key: str
    heading: str
    build: Callable[[Context], list[Entry]]


FAMILIES: tuple[Family, ...] = (
    Family("histories", "1. Force and power over one wingbeat (Figs 12-25)", fig_histories),
    Family("thrust", "2. Thrust coefficient over advance angle and twist (Fig 9)", fig_thrust),
    Family("wrist", "3. Wrist lag and bias (Figs 26-27)", fig_wrist),
    Family("landscapes", "4a. Optimisation spaces of the base model (Figs 33-34)", fig_landscapes),
    Family("activity", "4b. Wrist activity coefficient K (Figs 49-51)", fig_wrist_activity),
    Family("sweeps", "5. Solutions over speed and cost fractions (Figs 35-38, 44, 45, 52)", fig_sweeps),
    Family("tables", "6. Lookup-table slices at V = 0, 0.5, 0.9 (Fig 40, appendices 6-8)", fig_tables),
    Family("paths", "7. Control-point paths and chord lines (Figs 41-43, 46-48, 53-55)", fig_paths),
    Family("optimisers", "8. Optimiser comparison and table-build time (Figs 28-31, Table 3, Fig 63)", fig_optimisers),
)


@dataclass
class Section:
    family: Family
    entries: list[Entry] = field(default_factory=list)
    seconds: float = 0.0
    error: str = ""


def build_report(
    out: Path | str,
    *,
    quick: bool = False,
    force: bool = False,
    bird: Bird | None = None,
    only: Sequence[str] | None = None,
    progress: bool = True,
) -> list[Section]:
    """Regenerate every figure into ``out`` (PNGs) and write ``out/index.html``.

    Refuses an existing ``index.html`` without ``force``.  ``only`` restricts the run to
    some family keys (:data:`FAMILIES`).
    """
    out = Path(out)
    plots.pyplot()  # fail early with the install hint when matplotlib is missing
    index = out / "index.html"
    if index.exists() and not force:
        raise BirdsimError(f"--out {str(out)!r} already holds a report; allowed: a new folder, or --force to overwrite")
    if out.exists() and not out.is_dir():
        raise BirdsimError(f"--out {str(out)!r} is a file; allowed: a folder")
    keys = [f.key for f in FAMILIES]
    for k in only or ():
        if k not in keys:
            raise BirdsimError(f"--only {k!r} is unknown; allowed: {', '.join(keys)}")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise BirdsimError(f"--out {str(out)!r} cannot be created: {exc.strerror}") from None
    ctx = Context(out, QUICK if quick else FULL, bird or Bird())
    families = [f for f in FAMILIES if not only or f.key in only]
    from tqdm import tqdm

    sections = []
    bar = tqdm(families, desc="report", unit="family", disable=not progress)
    for fam in bar:
        bar.set_postfix_str(fam.key)
        t0 = time.perf_counter()
        sec = Section(fam)
        try:
            sec.entries = fam.build(ctx)
        except ImportError as exc:  # a part of the project this family needs is missing
            sec.error = f"not built: needs {exc.name or exc} (not available in this checkout)"
        sec.seconds = time.perf_counter() - t0
        sections.append(sec)
    write_atomic(index, render_html(sections, ctx).encode())
    return sections


_BADGE = {"agrees": "#2e7d32", "disagrees": "#c62828"}


def render_html(sections: Sequence[Section], ctx: Context) -> str:
    e = html.escape
    parts = [
        "<!doctype html><html><head><meta charset='utf-8'><title>birdsim report</title><style>",
        "body{font-family:sans-serif;max-width:1250px;margin:auto;padding:1em;color:#222}"
        "figure{margin:1.5em 0;border-top:1px solid #ccc;padding-top:1em}img{max-width:100%}"
        ".badge{color:#fff;padding:1px 6px;border-radius:4px;font-size:90%}"
        "li.ok::marker{content:'\\2714  ';color:#2e7d32}li.no::marker{content:'\\2718  ';color:#c62828}"
        ".small{color:#555;font-size:90%}",
        "</style></head><body>",
        "<h1>birdsim: the dissertation's analysis, regenerated</h1>",
        f"<p class='small'>Every figure is computed by this checkout's code (birdsim report{' --quick: coarse grids' if ctx.res.quick else ''}); "
        f"{e(plots.FORCE_NOTE)}; angles in radians; all quantities non-dimensional (rho = omega = semispan = 1). "
        "Each figure lists the dissertation's statements about the same figure and whether our numbers bear them out.</p>",
    ]
    for sec in sections:
        parts.append(f"<h2>{e(sec.family.heading)}</h2><p class='small'>built in {sec.seconds:.1f} s</p>")
        if sec.error:
            parts.append(f"<p><b>{e(sec.error)}</b></p>")
        for ent in sec.entries:
            colour = _BADGE.get(ent.verdict, "#ef6c00" if ent.claims else "#777")
            parts.append(f"<figure id='{e(ent.file)}'><h3>{e(ent.title)}</h3><img src='{e(ent.file)}' alt='{e(ent.title)}'>")
            parts.append(f"<figcaption><p>{e(ent.shows)}</p>")
            if ent.dissertation:
                parts.append(f"<p><b>Dissertation:</b> {e(ent.dissertation)}</p>")
            parts.append(f"<p><b>Ours:</b> <span class='badge' style='background:{colour}'>{e(ent.verdict)}</span></p>")
            if ent.claims:
                parts.append("<ul>" + "".join(
                    f"<li class='{'ok' if c.holds else 'no'}'>{e(c.statement)}: {e(c.ours)}</li>" for c in ent.claims
                ) + "</ul>")
            if ent.note:
                parts.append(f"<p class='small'>{e(ent.note)}</p>")
            parts.append("</figcaption></figure>")
    parts.append("</body></html>")
    return "\n".join(parts)
