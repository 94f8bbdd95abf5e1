"""Where do the screen-candidate polishes of a table build win?  Usage:

``python scripts/polish_study.py collect --out polish.csv [--models base m1 ...] [--settings polish_rule=0 ...] [--tables T.npz ...]``
    builds each model's default 11^3 table (or each given table's configuration; not
    written anywhere) with the measurement
    hook :data:`birdsim.tables.sweeps.POLISH_PROBE` installed and writes one CSV row per
    polish of a screen candidate in ``_solve_cell``: what was known before the polish
    and its outcome (``win``: it replaced the answer so far).

``python scripts/polish_study.py analyse polish.csv [--near 0.12 --excess 0.1]``
    prints wins and evaluations by kind of polish (from rows collected with
    ``polish_rule=0``: every polish run) and what the rule of ``_solve_cell``
    (``BuildSettings.polish_near`` / ``polish_excess``) skips and loses, also at other values.

Columns: ``good`` (the warm start beat the best screen candidate by ``screen_gap``),
``rank`` (0 = best screen candidate), ``cand_cost``, ``screen_best``, ``warm_cost``
(the warm start's SLSQP answer), ``warm_miss`` / ``cand_miss`` / ``miss`` (max force
miss of warm answer / candidate / polished answer), ``dist_max`` (largest parameter
distance candidate - warm answer, in box widths), ``evaluations`` (of this polish),
``before_cost`` (best answer before this polish), ``cost`` (after polishing), ``win``,
``sol_dist_max`` (polished answer - warm answer), ``r0_*`` (second candidate: its
distance to the first candidate and to the first's polished answer, the first's cost -
warm cost), ``n_cheaper`` / ``n_within`` (screen candidates cheaper than the warm
answer / than it + ``screen_gap``).  A cold cell (no warm start) has empty warm columns.
"""

from __future__ import annotations

import argparse
import csv
import os
import sys
import tempfile
import threading
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from birdsim.tables import sweeps
from birdsim.tables.build import BuildConfig, BuildSettings, Grid, build_table, config_from_meta
from birdsim.tables.lookup import load_table

COLUMNS = (
    "model",
    "fx",
    "fz",
    "v",
    "climb",
    "cold",
    "good",
    "rank",
    "screen_best",
    "cand_cost",
    "cand_miss",
    "warm_cost",
    "warm_miss",
    "warm_converged",
    "warm_evaluations",
    "warm_iterations",
    "dist_max",
    "dist_rms",
    "before_cost",
    "cost",
    "miss",
    "converged",
    "evaluations",
    "win",
    "sol_dist_max",
    "r0_cand_dist",
    "r0_sol_dist",
    "r0_cost_minus_warm",
    "n_cheaper",
    "n_within",
)
_OUT_DIR: Path | None = None
_LAST = threading.local()  # the first polish of the cell being solved in this thread


def _probe(
    *,
    cfg: Any,
    prob: Any,
    demand: tuple,
    warm: Any,
    before: Any,
    rank: int,
    candidate: np.ndarray,
    screen_cost: np.ndarray,
    screen_force: tuple,
    sol: Any,
    evaluations: int,
) -> None:
    """:data:`sweeps.POLISH_PROBE`: appends one row to this process's file."""
    fx, fz, v, climb = demand
    span = np.where(prob.upper > prob.lower, prob.upper - prob.lower, 1.0)
    st = cfg.settings
    row: dict[str, Any] = dict(
        model=cfg.model,
        fx=fx,
        fz=fz,
        v=v,
        climb=climb,
        cold=warm is None,
        rank=rank,
        screen_best=screen_cost[0],
        cand_cost=screen_cost[rank],
        cand_miss=max(abs(screen_force[0] - fx), abs(screen_force[1] - fz)),
        before_cost=np.inf if before is None else before.cost,
        cost=sol.cost,
        miss=max(abs(sol.Fx - fx), abs(sol.Fz - fz)),
        converged=sol.converged,
        evaluations=evaluations,
        win=before is None or sol.cost < before.cost - st.switch_margin,
    )
    if warm is not None:
        dx = np.abs(candidate - warm.x) / span
        row.update(
            good=warm.cost < screen_cost[0] - st.screen_gap,
            warm_cost=warm.cost,
            warm_miss=max(abs(warm.Fx - fx), abs(warm.Fz - fz)),
            warm_converged=warm.converged,
            warm_evaluations=warm.evaluations,
            warm_iterations=warm.iterations,
            dist_max=float(dx.max()),
            dist_rms=float(np.sqrt(np.mean(dx**2))),
            sol_dist_max=float((np.abs(sol.x - warm.x) / span).max()),
            n_cheaper=int(np.sum(screen_cost < warm.cost)),
            n_within=int(np.sum(screen_cost < warm.cost + st.screen_gap)),
        )
        if rank == 0:
            _LAST.first = (demand, candidate.copy(), sol)
        elif (
            getattr(_LAST, "first", (None,))[0] == demand
        ):  # this cell's first polish (one cell per thread)
            _, cand0, sol0 = _LAST.first
            row.update(
                r0_cand_dist=float((np.abs(candidate - cand0) / span).max()),
                r0_sol_dist=float((np.abs(candidate - sol0.x) / span).max()),
                r0_cost_minus_warm=sol0.cost - warm.cost,
            )
    assert _OUT_DIR is not None
    with open(_OUT_DIR / f"{os.getpid()}.csv", "a", newline="") as f:
        csv.DictWriter(f, COLUMNS).writerow({k: row.get(k, "") for k in COLUMNS})


def _settings(pairs: list[str]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for p in pairs:
        k, _, val = p.partition("=")
        default = getattr(BuildSettings(), k)
        out[k] = (
            type(default)(float(val))
            if not isinstance(default, bool)
            else val.lower() in ("1", "true")
        )
    return out


def collect(
    models: list[str],
    out: Path,
    jobs: int,
    overrides: dict[str, Any],
    tables: list[Path] | None = None,
) -> None:
    """Builds each model's 11^3 table (or, with ``tables``, each table's own configuration)
    with the probe and writes the rows to ``out``."""
    global _OUT_DIR
    with tempfile.TemporaryDirectory() as tmp:
        _OUT_DIR = Path(tmp)
        sweeps.POLISH_PROBE = _probe  # inherited by the forked worker processes
        try:
            configs = [BuildConfig(model=m, grid=Grid.default(11)) for m in models]
            if tables:
                configs = [config_from_meta(load_table(p)) for p in tables]
            for cfg in configs:
                t0 = time.perf_counter()
                cfg = replace(cfg, settings=replace(cfg.settings, **overrides))
                table = build_table(cfg, jobs=jobs)
                print(
                    f"{cfg.model}: {time.perf_counter() - t0:.1f} s, {table.evaluations.mean():.0f} wingbeats per cell",
                    flush=True,
                )
        finally:
            sweeps.POLISH_PROBE = None
        with open(out, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(COLUMNS)
            for part in sorted(Path(tmp).glob("*.csv")):
                w.writerows(csv.reader(part.open()))
    print(f"wrote {out}")


def load(path: Path) -> dict[str, np.ndarray]:
    rows = list(csv.DictReader(path.open()))
    cols: dict[str, np.ndarray] = {}
    for k in COLUMNS:
        vals = [r[k] for r in rows]
        if k == "model":
            cols[k] = np.array(vals)
        elif k in ("cold", "good", "warm_converged", "converged", "win"):
            cols[k] = np.array([v == "True" for v in vals])
        else:
            cols[k] = np.array([float(v) if v != "" else np.nan for v in vals])
    return cols


def rule_skips(
    d: dict[str, np.ndarray], near: float, excess: float, margin: float = 1e-4
) -> np.ndarray:
    """The polishes (rows measured with ``polish_rule=0``) that :func:`sweeps._solve_cell`'s
    rule would skip: after a warm start, (a) the warm answer within ``margin`` of the
    cost floor (0 for the default weights away from V = 0; 0 at V = 0 too, pitch >= 0),
    or (b) the candidate within ``near`` of the warm answer and costing 1 to 1 + ``excess``
    times as much.  (a) is exact with the answer so far; the rows give the warm answer's
    cost, a lower bound of it, so this count is a lower bound of (a)."""
    warm, cw, cc = ~d["cold"], d["warm_cost"], d["cand_cost"]
    with np.errstate(invalid="ignore"):
        bound = cw <= margin
        near_ = (d["dist_max"] <= near) & (cw <= cc) & (cc <= (1.0 + excess) * cw)
    return warm & (bound | near_)


def analyse(path: Path, near: float, excess: float) -> None:
    """Wins and evaluations by kind of polish; what the rule skips and loses."""
    d = load(path)
    warm = ~d["cold"]
    gain = d["before_cost"] - d["cost"]
    ev = d["evaluations"]
    skip = rule_skips(d, near, excess)
    print(
        "model  kind       polishes  wingbeats  wins  gain median / max   | rule: skipped  wingbeats saved  wins lost"
    )
    for m in sorted(set(d["model"])):
        sel = d["model"] == m
        for name, k in (
            ("cold", d["cold"]),
            ("poor warm", warm & ~d["good"]),
            ("good warm", warm & d["good"]),
        ):
            s = sel & k
            wins = s & d["win"]
            g = gain[wins & warm]
            gs = f"{np.median(g):.1e} / {g.max():.1e}" if g.size else "-"
            print(
                f"{m:5s}  {name:9s}  {s.sum():8d}  {ev[s].sum():9.0f}  {wins.sum():4d}  {gs:17s} | "
                f"{(s & skip).sum():5d} ({(s & skip).sum() / max(s.sum(), 1):3.0%})  {ev[s & skip].sum() / max(ev[s].sum(), 1):5.0%}  "
                f"{(wins & skip).sum():4d}"
            )
    lost = skip & d["win"]
    print(
        f"all: {warm.sum()} polishes after a warm start, {(warm & d['win']).sum()} wins; the rule (near {near}, excess {excess}) "
        f"skips {skip.sum()} ({skip.sum() / warm.sum():.0%}), {ev[skip].sum() / ev[warm].sum():.0%} of their wingbeats, "
        f"loses {lost.sum()} wins"
        + (f" (largest gain {gain[lost].max():.1e})" if lost.any() else "")
    )
    print("\nother thresholds: near  excess  skipped  wingbeats saved  wins lost")
    for n_ in (0.08, 0.1, 0.12, 0.14, 0.16, 0.2):
        for e_ in (0.1, 0.3, 0.5, 1.0):
            sk = rule_skips(d, n_, e_)
            print(
                f"  {n_:4.2f}  {e_:4.1f}  {sk.sum() / warm.sum():4.0%}  {ev[sk].sum() / ev[warm].sum():4.0%}  {(sk & d['win']).sum():3d}"
            )


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    sub = ap.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("collect")
    c.add_argument("--models", nargs="+", default=["base", "m1", "m2", "m3", "m4"])
    c.add_argument("--out", type=Path, required=True)
    c.add_argument("--jobs", type=int, default=2)
    c.add_argument("--settings", nargs="*", default=[], help="BuildSettings overrides NAME=VALUE")
    c.add_argument(
        "--tables",
        nargs="*",
        type=Path,
        help="build these tables' configurations instead (e.g. tables/seed-m3-climb.npz)",
    )
    a = sub.add_parser("analyse")
    a.add_argument("csv", type=Path)
    a.add_argument("--near", type=float, default=BuildSettings().polish_near)
    a.add_argument("--excess", type=float, default=BuildSettings().polish_excess)
    args = ap.parse_args(argv)
    if args.cmd == "collect":
        collect(args.models, args.out, args.jobs, _settings(args.settings), args.tables)
    else:
        analyse(args.csv, args.near, args.excess)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
