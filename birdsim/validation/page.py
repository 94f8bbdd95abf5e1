"""The scorecard as an HTML page with figures (matplotlib, Agg), written atomically.

Files in the output folder: ``index.html``, ``power_curve.png``, ``kinematics.png`` and
``scorecard.json`` (the same object ``birdsim validate --json`` prints).
"""

from __future__ import annotations

import html
import json
import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.io import check_output, write_atomic
from birdsim.report.plots import pyplot, save_png
from birdsim.validation.scorecard import AGREE, ROUGH, Row
from birdsim.validation.trim import TrimSweep

PAGE_FILES = ("index.html", "power_curve.png", "kinematics.png", "scorecard.json")

#: Why a quasi-steady blade-element model can miss a measured bird (shown for off rows).
CAUSES = (
    "the seed polar's Cl = 2 sin 2 alpha has no stall and no Reynolds-number effects; "
    "the robofly polar (Dickinson et al. 1999) is a measured flapping-wing polar",
    "no unsteady or added-mass forces: the quasi-steady element force depends only on the "
    "instantaneous velocity (no leading-edge vortex build-up, wake capture or rotational lift)",
    "no induced velocity unless asked for: without the actuator disc's downwash the wing sees "
    "the freestream plus its own flapping only, which underestimates induced power at slow speed",
    "no tail (a real pigeon's tail carries about 8 % of the weight at 4.46 m/s, Usherwood et al. 2005) "
    "and no wing folding: the model's upstroke is a fully extended, rigid wing; a pigeon flips "
    "its hand in a tip-reversal upstroke at slow speed",
    "body drag proportional to sin(pitch) (eq. 7 of the dissertation): it vanishes at zero pitch, "
    "where a real body still has parasite drag",
)


def check_page_folder(out: Path, force: bool) -> None:
    """Refuse an output folder that holds a page already (without ``force``) or is a file."""
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise BirdsimError(f"--out {str(out)!r} is a file; allowed: a folder")
    existing = [f for f in PAGE_FILES if (out / f).exists()]
    if existing and not force:
        raise BirdsimError(
            f"--out {str(out)!r} holds {existing[0]} already; allowed: a new folder, or --force to overwrite"
        )
    # the folder made and written into (before the validation), or one line
    check_output(out / PAGE_FILES[0], True, "--out")


def _power_figure(
    sweep: TrimSweep,
    rows: Sequence[Row],
    variants: dict[str, TrimSweep],
    title: str,
    table_points: Sequence[dict] = (),
):  # noqa: ANN202
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8, 5))
    ok = np.array([p.trimmed for p in sweep.points])
    ax.plot(
        sweep.speeds,
        np.where(ok, sweep.powers, np.nan),
        "-o",
        ms=3,
        color="C0",
        label=f"birdsim {sweep.model}, {sweep.label} (whole bird)",
    )
    if (~ok).any():
        ax.plot(
            sweep.speeds[~ok],
            sweep.powers[~ok],
            "x",
            color="C3",
            label="cannot trim (best wingbeat)",
        )
    for i, (label, vs) in enumerate(variants.items()):
        vok = np.array([p.trimmed for p in vs.points])
        ax.plot(
            vs.speeds,
            np.where(vok, vs.powers, np.nan),
            "--",
            color=f"C{i + 4}",
            label=f"birdsim, {label}",
        )
    tp = [
        (pt["speed"], pt["table_power"]) for pt in table_points if pt.get("table_power") is not None
    ]
    if tp:
        ax.plot(
            *zip(*tp),
            ".",
            color="0.4",
            ms=5,
            label="shipped table, interpolated at the level-flight demand",
        )
    mp = sweep.min_power()
    if mp is not None:
        ax.plot(
            [mp[0]], [mp[1]], "v", color="C0", ms=9, label=f"birdsim minimum power {mp[0]:.1f} m/s"
        )
    for r in rows:
        m = r.measurement
        if m.compare in ("power", "hover_power") and m.kind in ("value", "at_most"):
            x = m.speed_m_s or 0.0
            marker = "s" if m.kind == "value" else "_"
            ax.errorbar(
                [x], [m.value], yerr=[m.uncertainty or 0.0], fmt=marker, color="k", ms=7, capsize=4
            )
            ax.annotate(
                f"{m.author.split(',')[0].split(' ')[0]} {m.year}"
                + (" (max)" if m.kind == "at_most" else ""),
                (x, m.value),
                textcoords="offset points",
                xytext=(6, 4),
                fontsize=8,
            )
        if m.compare == "min_power_speed":
            lo, hi = m.value - (m.uncertainty or 0.0), m.value + (m.uncertainty or 0.0)
            ax.axvspan(
                lo, hi, color="0.85", label=f"measured minimum-power speed ({m.author} {m.year})"
            )
    ax.set_xlabel("flight speed [m/s]")
    ax.set_ylabel("mechanical power, whole bird [W]")
    ax.set_title(title, fontsize=10)
    shown = [p.power for s in (sweep, *variants.values()) for p in s.points if p.trimmed]
    shown += [
        r.measurement.value + (r.measurement.uncertainty or 0.0)
        for r in rows
        if r.measurement.compare in ("power", "hover_power")
    ]
    ax.set_ylim(0, 1.45 * max(shown, default=1.0))
    ax.legend(fontsize=7, loc="upper left", framealpha=0.8)
    ax.grid(alpha=0.3)
    return fig


#: The trends the kinematics figure draws (a trend of another quantity, such as the span
#: ratio, is scored in the table only).
_PLOTTED_TRENDS = {
    "amplitude_slope": "amplitude",
    "body_angle_slope": "body angle",
    "stroke_plane_slope": "stroke plane",
}


def _kinematics_figure(sweep: TrimSweep, rows: Sequence[Row], title: str):  # noqa: ANN202
    plt = pyplot()
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.5))
    ok = np.array([p.trimmed for p in sweep.points])
    v = sweep.speeds

    def series(attr: str) -> np.ndarray:
        return np.where(ok, [getattr(p, attr) for p in sweep.points], np.nan)

    a1.plot(
        v,
        series("amplitude_deg"),
        "-o",
        ms=3,
        label="birdsim: flap amplitude 2 Phi_f (peak to peak)",
    )
    a2.plot(v, series("body_angle_deg"), "-o", ms=3, label="birdsim: body angle (pitch)")
    a2.plot(
        v,
        series("stroke_plane_deg"),
        "-s",
        ms=3,
        label="birdsim: wingtip path to horizontal (side view, highest to lowest point)",
    )
    notes: dict[int, list[str]] = {0: [], 1: []}
    for r in rows:
        m = r.measurement
        if m.kind == "trend" and m.compare in _PLOTTED_TRENDS:  # the span ratio: the table only
            ax = a1 if m.compare == "amplitude_slope" else a2
            ax.axvspan(m.speed_m_s or 0.0, m.speed_to_m_s or 0.0, color="0.93")
            arrow = "decreases" if m.value < 0 else "increases"
            what = _PLOTTED_TRENDS[m.compare]
            notes[0 if ax is a1 else 1].append(
                f"measured {what} {arrow} with speed ({m.speed_m_s:g}-{m.speed_to_m_s:g} m/s, {m.author} {m.year}): birdsim {r.verdict.split(' (')[0]}"
            )
        if m.compare in ("stroke_plane_angle", "body_angle", "amplitude") and m.kind in (
            "value",
            "shown",
        ):
            ax = a1 if m.compare == "amplitude" else a2
            ax.errorbar(
                [m.speed_m_s or 0.0],
                [m.value],
                yerr=[m.uncertainty or 0.0],
                fmt="D",
                color="k",
                capsize=4,
                label=f"measured stroke plane beta ({m.author.split(',')[0]} {m.year}; convention not read)"
                if m.kind == "shown"
                else m.quantity,
            )
    for i, (ax, ylabel) in enumerate(((a1, "amplitude [deg]"), (a2, "angle [deg]"))):
        ax.set_title("\n".join(notes[i]), fontsize=7)
        ax.set_xlabel("flight speed [m/s]")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6, loc="best", framealpha=0.8)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return fig


def diagnose(row: Row) -> str:
    """Which other physics moves an off row towards the measurement, in one sentence."""
    m = row.measurement
    parts, closing = [], []
    for label, v in row.variants.items():
        if v is None:
            parts.append(f"with {label} the bird cannot trim there")
            continue
        if m.kind == "yesno":
            parts.append(f"with {label}: {row.value_text(v)}")
            if (v >= 0.5) == (m.value >= 0.5):
                closing.append(label)
            continue
        if m.kind == "trend":
            fixed = (v < 0) == (m.value < 0) and v != 0
            parts.append(
                f"with {label} the slope is {v:+.3g} ({'right' if fixed else 'still the wrong'} sign)"
            )
            if fixed:
                closing.append(label)
            continue
        base, new = (
            abs(math.log(abs(row.birdsim or 1e-300) / abs(m.value))),
            abs(math.log(abs(v) or 1e-300) - math.log(abs(m.value))),
        )
        parts.append(f"with {label} {v:.3g} {m.unit} ({'closer' if new < base else 'further'})")
        if new < math.log(ROUGH):
            closing.append(label)
    verdict = (
        f"{' and '.join(closing)} close{'s' if len(closing) == 1 else ''} the gap."
        if closing
        else "Neither the other polar nor induced velocity closes the gap: the cause lies in what the model leaves out "
        "(unsteady and added-mass forces, the tail, wing folding and hand rotation, the bounded kinematics)."
    )
    return ("; ".join(parts) + ". " if parts else "") + verdict


def _fmt_ratio(r: float | None) -> str:
    return "" if r is None else f"{r:.2f}"


def render_html(obj: dict, rows: Sequence[Row], title: str) -> str:
    """The page: scorecard table, figures, and why the off rows are off."""
    esc = html.escape
    trs = []
    for r in rows:
        m = r.measurement
        cls = r.verdict.split(" ")[0]
        variants = "; ".join(f"{k}: {r.value_text(v)}" for k, v in r.variants.items())
        src = f'<a href="{esc(m.url)}">{esc(m.source)}</a>' if m.url else esc(m.source)
        trs.append(
            f"<tr class='{esc(cls)}'><td>{esc(m.quantity)}</td><td>{esc(m.measured_text())}"
            f"{' (' + esc(m.uncertainty_kind) + ')' if m.uncertainty_kind else ''}</td><td>{src}</td>"
            f"<td>{esc(r.birdsim_text)}</td><td>{_fmt_ratio(r.ratio)}</td><td>{esc(r.verdict)}</td><td>{esc(variants)}</td></tr>"
        )
    off = [r for r in rows if r.verdict.startswith(("off", "opposite"))]
    off_html = ""
    if off:
        items = "".join(f"<li>{esc(c)}</li>" for c in CAUSES)
        rows_off = "".join(
            f"<li><b>{esc(r.measurement.quantity)}</b>: measured {esc(r.measurement.measured_text())}, birdsim {esc(r.birdsim_text)}; "
            f"{esc(diagnose(r))} <i>{esc(r.measurement.note)}</i></li>"
            for r in off
        )
        off_html = (
            f"<h2>Where the model is off</h2><ul>{rows_off}</ul><p>Candidate causes (the model is not tuned to the data; "
            f"each row above is recomputed with the other polar and with induced velocity toggled to show which physics moves it):</p><ul>{items}</ul>"
        )
    mp = obj.get("min_power_speed")
    summary = (
        f"model {esc(str(obj['model']))}, bird {esc(str(obj['bird']))}, polar {esc(str(obj['polar']))}; "
        f"minimum-power speed {'none' if mp is None else f'{mp:.2f} m/s'}; trimmed speed range {esc(str(obj.get('trim_range')))} m/s; "
        f"hover {'trims' if obj.get('hover') else 'does not trim'}; "
        f"shipped table {esc(str(obj.get('table')))} (a start at each speed in its grid, and its interpolated power in the figure)"
    )
    return f"""<!doctype html>
<html><head><meta charset="utf-8"><title>{esc(title)}</title>
<style>body{{font-family:sans-serif;max-width:1200px;margin:auto}} td,th{{border:1px solid #ccc;padding:3px;font-size:13px;vertical-align:top}}
table{{border-collapse:collapse}} tr.agrees td:nth-child(6),tr.same td:nth-child(6){{background:#dfd}} tr.rough td:nth-child(6){{background:#ffd}}
tr.off td:nth-child(6),tr.opposite td:nth-child(6){{background:#fdd}}</style></head><body>
<h1>{esc(title)}</h1>
<p>{summary}.</p>
<p>Verdicts: ratio = birdsim / measured; agrees within the measurement's uncertainty or a factor {AGREE:g}, rough within {ROUGH:g}, off beyond;
bounds agree when met; trends compare the sign of the slope only; rows marked "shown" are not compared. Powers are the whole bird's
mechanical (aerodynamic) power, both wings. Every measured value and its citation come from the data file; see docs/validation.md.</p>
<table><tr><th>quantity</th><th>measured</th><th>source</th><th>birdsim</th><th>ratio</th><th>verdict</th><th>other physics</th></tr>
{"".join(trs)}</table>
{off_html}
<h2>Power curve</h2><img src="power_curve.png" alt="power curve">
<h2>Amplitude and angles</h2><img src="kinematics.png" alt="amplitude and angles against speed">
<p>The numbers behind the figures: <a href="scorecard.json">scorecard.json</a> (the object of <code>birdsim validate --json</code>).</p>
</body></html>
"""


def write_page(
    out: Path,
    obj: dict,
    rows: Sequence[Row],
    sweep: TrimSweep,
    variants: dict[str, TrimSweep],
    *,
    force: bool,
) -> Path:
    """Write the page into ``out`` (created); every file atomically.

    Args:
        out: output folder; ``obj`` the JSON object of :func:`birdsim.validation.run.validate`,
            ``rows``, ``sweep`` and ``variants`` what it computed.
        force: overwrite a page already in ``out``.
    Returns:
        The path of ``index.html``.
    Raises:
        BirdsimError: ``out`` is a file, or holds a page and ``force`` is not given.
    """
    out = Path(out)
    check_page_folder(out, force)
    title = f"birdsim against measured pigeons: {obj['bird']}, model {obj['model']}, {obj['polar']} polar"
    curve_variants = {k: v for k, v in variants.items() if len(v.points) > 2}
    figs = {
        "power_curve.png": _power_figure(
            sweep,
            rows,
            curve_variants,
            "Level flight: trimmed wingbeat's mechanical power against speed",
            obj.get("power_curve", ()),
        ),
        "kinematics.png": _kinematics_figure(
            sweep, rows, "Trimmed wingbeat: amplitude and angles against speed"
        ),
    }
    out.mkdir(parents=True, exist_ok=True)
    for name, fig in figs.items():
        save_png(fig, out / name)
    write_atomic(out / "scorecard.json", (json.dumps(obj, indent=1) + "\n").encode())
    write_atomic(out / "index.html", render_html(obj, rows, title).encode())
    return out / "index.html"


__all__ = ["CAUSES", "PAGE_FILES", "check_page_folder", "diagnose", "render_html", "write_page"]
