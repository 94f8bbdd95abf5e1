"""Figure families of the tables and the optimisers: lookup-table slices (Fig 40,
appendices 6-8), the optimisers on the test functions (Figs 28-31, Table 3) and the
table-build time (Fig 63)."""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from birdsim.report import figdata as fd
from birdsim.report import plots
from birdsim.report.records import Claim, Context, Entry

TABLE_SPEEDS = (0.0, 0.5, 0.9)
TABLE_FOLDER = Path(__file__).resolve().parents[2] / "tables"  # the repository's tables/


def _table(ctx: Context, model: str):
    """The committed table of ``model`` if there is one, else a small one built here."""
    from birdsim.tables.lookup import load_table, table_paths

    npz, _ = table_paths(TABLE_FOLDER / model)
    if npz.exists() and not ctx.res.quick:
        return load_table(npz), f"committed table {npz.relative_to(TABLE_FOLDER.parent)}"
    from birdsim.tables.build import BuildConfig, Grid, build_table

    k = ctx.res.table_grid
    grid = Grid.parse("V=" + "|".join(f"{v:g}" for v in TABLE_SPEEDS), size=k)
    t = build_table(
        BuildConfig(model, grid, bird=ctx.bird, settings=ctx.res.build_settings()), jobs=1
    )
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
            t.axes["Fx"],
            t.axes["Fz"],
            speeds,
            list(t.param_names),
            vals,
            ok,
            [(p.lower, p.upper) for p in m.params],
            f"Model {model}: lookup-table slices, each parameter over the demanded (Fx, Fz) at V = "
            + ", ".join(f"{v:g}" for v in speeds),
            footnote=f"{source}; colour scale = the parameter's bounds; " + plots.FORCE_NOTE,
        )
        name = ctx.save(fig, f"table_{model}")
        pitch = vals[..., list(t.param_names).index("pitch")]
        flap = vals[..., list(t.param_names).index("flap_amp")]
        mid = 1 if len(iv) > 1 else 0
        claims = (
            Claim(
                "body pitch falls with speed",
                bool(np.mean(pitch[..., -1]) < np.mean(pitch[..., 0])),
                f"mean pitch {np.mean(pitch[..., 0]):.2f} at V = {speeds[0]:g}, "
                f"{np.mean(pitch[..., -1]):.2f} at V = {speeds[-1]:g}",
            ),
            Claim(
                "flap amplitude grows with the upward demand",
                bool(np.mean(flap[:, 0, mid]) > np.mean(flap[:, -1, mid])),
                f"mean flap at V = {speeds[mid]:g}: {np.mean(flap[:, 0, mid]):.2f} for Fz = "
                f"{t.axes['Fz'][0]:g}, {np.mean(flap[:, -1, mid]):.2f} for Fz = "
                f"{t.axes['Fz'][-1]:g}",
            ),
        )
        figs = {"base": "Fig 40", "m1": "appendix 6", "m3": "appendix 7", "m4": "appendix 8"}
        entries.append(
            Entry(
                name,
                f"Model {model}: table slices at V = 0, 0.5, 0.9 "
                f"({figs.get(model, 'no printed counterpart')})",
                "Every parameter of the optimal wingbeat over the demand grid, rows by speed; "
                f"crosses: demand missed ({source}).",
                "Fig 40: body pitch falls as speed rises; flap amplitude grows with the (upward) "
                "Fz demand."
                if model in figs
                else "",
                claims,
                note=f"{int(ok.sum())} of {ok.size} cells meet the demand within the table's reach "
                "tolerance.",
            )
        )
    return entries


# ---- 8. optimisers and build time ----------------------------------------------------


def fig_optimisers(ctx: Context) -> list[Entry]:
    nodes = ctx.res.optimiser_nodes
    runs = {
        "f": [
            fd.optimiser_run("f", "complete", nodes=nodes),
            fd.optimiser_run("f", "slsqp", x0=(0.0, 1.0)),
            fd.optimiser_run("f", "evolutionary"),
        ],
        "g": [
            fd.optimiser_run("g", "complete", nodes=nodes),
            fd.optimiser_run("g", "slsqp", x0=(0.0, 1.0)),
            fd.optimiser_run("g", "slsqp", x0=(0.8, 0.5)),
            fd.optimiser_run("g", "slsqp", x0=(0.7, 0.7)),
            fd.optimiser_run("g", "evolutionary"),
        ],
    }
    u = np.linspace(0, 1, 101)
    gx, gy = np.meshgrid(u, u, indexing="ij")
    pts = np.stack([gx.ravel(), gy.ravel()], axis=-1)
    grids = [fd.test_function_f(pts).reshape(gx.shape), fd.test_function_g(pts).reshape(gx.shape)]
    fig = plots.optimiser_runs(
        [runs["f"], runs["g"]],
        grids,
        "Optimisers on the test functions f (eq. 89, top) and g (eq. 90, bottom), Figs 28-30",
    )
    name1 = ctx.save(fig, "optimiser_paths")
    series = {
        f"best {k}(x, y) so far - min {k} + 1e-6 ({plots.ND})": [
            (
                r.label,
                r.best_so_far - (0.25 if k == "f" else 0.0) + 1e-6,
                {"x": np.arange(1, len(r.values) + 1)},
            )
            for r in rs
        ]
        for k, rs in runs.items()
    }
    fig = plots.lines(
        np.arange(1),
        series,
        x_label="function evaluations",
        title="Convergence of the optimisers (Fig 31): error of the best point so far",
        logy=True,
        footnote="plotted: best value so far minus the global minimum (0.25 for f, 0 for g) plus "
        "1e-6, log scale",
    )
    for ax in fig.axes:
        ax.set_xscale("log")
    name2 = ctx.save(fig, "optimiser_convergence")
    cf, sf, ef = runs["f"]
    cg, sg1, sg2, sg3, eg = runs["g"]
    claims = (
        Claim(
            "complete search (12 nodes) misses f's minimum by 0.0021",
            bool(nodes == 12 and abs(cf.value - 0.25 - 0.0021) < 5e-5),
            f"ours: f({cf.x[0]:.4f}, {cf.x[1]:.4f}) = {cf.value:.4f} ({nodes} nodes, "
            f"{cf.evaluations} evaluations)",
        ),
        Claim(
            "gradient method finds f's minimum exactly from (0, 1)",
            abs(sf.value - 0.25) < 1e-6,
            f"SLSQP: {sf.value:.6f} after {sf.iterations} iterations, {sf.evaluations} evaluations",
        ),
        Claim(
            "the evolutionary method gets within 0.001 of f's minimum",
            abs(ef.value - 0.25) < 1e-3,
            f"{ef.value:.5f} after {ef.evaluations} evaluations",
        ),
        Claim(
            "complete search finds g's global minimum 0 at a node",
            abs(cg.value) < 1e-12,
            f"g = {cg.value:.4f} at ({cg.x[0]:.2f}, {cg.x[1]:.2f})",
        ),
        Claim(
            "gradient method from (0, 1) stays at g(0, 1) = 0.9093",
            abs(sg1.value - 0.9093) < 1e-4,
            f"ends at g({sg1.x[0]:.3f}, {sg1.x[1]:.3f}) = {sg1.value:.4f}",
        ),
        Claim(
            "from (0.8, 0.5) it ends in g(1, 0) = 0.2273",
            abs(sg2.value - 0.2273) < 1e-4,
            f"ends at g({sg2.x[0]:.3f}, {sg2.x[1]:.3f}) = {sg2.value:.4f}",
        ),
        Claim(
            "from (0.7, 0.7) it finds g(0, 0) = 0",
            abs(sg3.value) < 1e-6,
            f"ends at g({sg3.x[0]:.3f}, {sg3.x[1]:.3f}) = {sg3.value:.4f}",
        ),
        Claim(
            "the evolutionary method finds g's global minimum",
            abs(eg.value) < 1e-3,
            f"{eg.value:.5f} after {eg.evaluations} evaluations",
        ),
        Claim(
            "accuracy ranks gradient > evolutionary > complete search on f",
            bool(abs(sf.value - 0.25) <= abs(ef.value - 0.25) <= abs(cf.value - 0.25)),
            f"errors {abs(sf.value - 0.25):.1e}, {abs(ef.value - 0.25):.1e}, "
            f"{abs(cf.value - 0.25):.1e}",
        ),
    )
    table3 = "Table 3 (ours): " + "; ".join(
        f"{r.function}: {r.label}: error {r.value - (0.25 if r.function == 'f' else 0):.4f}, "
        f"{r.evaluations} evaluations"
        for r in runs["f"] + runs["g"]
    )
    e1 = Entry(
        name1,
        "Optimisers on f and g (Figs 28-30, Table 3)",
        "Every point each solver evaluated (colour = order), over the function's contours; star = "
        "its answer.",
        "Table 3 / Figs 28-30: CSA error 0.0021 on f (144 nodes), GBM exact on f in 4 iterations, "
        "GA error 0.0005; on g the GBM ends in local minima from (0, 1) and (0.8, 0.5) "
        "and finds 0 from (0.7, 0.7); CSA and GA find 0.",
        claims,
        note=table3
        + ". Our 'evaluations' count every function value including SLSQP's finite-difference "
        "points; the dissertation counted iterations.",
    )
    e2 = Entry(
        name2,
        "Convergence of the optimisers (Fig 31)",
        "Error of the best point found so far against the number of function evaluations, per "
        "solver.",
        "Fig 31: the complete search steps down as it sweeps (f's minimum node after 66 of 144 "
        "evaluations); the gradient method converges in 3-4 iterations; the GA is less "
        "predictable.",
        (
            Claim(
                "the gradient method needs the fewest evaluations on f",
                bool(sf.evaluations < min(cf.evaluations, ef.evaluations)),
                f"evaluations: complete {cf.evaluations}, SLSQP {sf.evaluations}, evolutionary "
                f"{ef.evaluations}",
            ),
        ),
    )
    return [e1, e2, _build_time(ctx)]


def _build_time(ctx: Context) -> Entry:
    import platform

    from birdsim.physics.kinematics import get_model
    from birdsim.tables.build import BuildConfig, Grid, build_table

    k = ctx.res.build_grid
    models = ("base", "m1", "m2", "m3", "m4")
    dof, secs = [], []
    repeats = 1 if ctx.res.quick else 3
    for model in models:
        best = math.inf
        for _ in range(repeats):  # the fastest of a few runs: least disturbed by other jobs
            t0 = time.perf_counter()
            build_table(
                BuildConfig(
                    model, Grid.default(k), bird=ctx.bird, settings=ctx.res.build_settings()
                ),
                jobs=1,
            )
            best = min(best, time.perf_counter() - t0)
        secs.append(best)
        dof.append(len(get_model(model).param_names))
    dof_a, secs_a = np.array(dof, dtype=float), np.array(secs)
    slope = float(np.polyfit(np.log(dof_a), np.log(secs_a), 1)[0])
    series = {
        "build time (s, this machine)": [
            (m, np.array([s]), {"x": np.array([d]), "marker": "o", "ms": 8, "ls": ""})
            for m, d, s in zip(models, dof, secs)
        ]
    }
    cells = k**3
    fig = plots.lines(
        np.arange(1),
        series,
        x_label="free parameters of the model (DOF)",
        title=f"Table-build time against the number of free parameters (Fig 63), {k} x {k} x {k} "
        "grid, one process",
        footnote=f"measured on {platform.machine()} ({platform.processor() or 'cpu'}), {cells} "
        "cells per table, while other jobs may share the machine; "
        f"log-log slope {slope:.2f}",
        ncols=1,
    )
    name = ctx.save(fig, "build_time")
    return Entry(
        name,
        "Table-build time against the number of free parameters (Fig 63)",
        f"Seconds to build a {k} x {k} x {k} table "
        f"({'default' if not ctx.res.quick else 'coarse --quick'} settings, one process; fastest "
        f"of {repeats}) for each model, measured during this report run.",
        "Fig 63: time grows roughly quadratically with the number of free parameters (hours per "
        "full table on a 2.8 GHz Pentium 4).",
        (
            Claim(
                "time grows with the number of free parameters",
                bool(secs[-1] > secs[0]),
                f"base ({dof[0]} DOF) {secs[0]:.2f} s, m4 ({dof[-1]} DOF) {secs[-1]:.2f} s",
            ),
            Claim(
                "roughly quadratic growth",
                bool(1.0 <= slope <= 3.0),
                f"log-log slope of time against DOF = {slope:.2f}",
            ),
        ),
        note="A small grid: the absolute times are this machine's on this grid, not a full "
        "table's.",
    )
