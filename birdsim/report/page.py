"""The report's page: ``index.html`` from the built sections (no figure code here)."""

from __future__ import annotations

import html
from collections.abc import Sequence

from birdsim.report import plots
from birdsim.report.records import Context, Section

_BADGE = {"agrees": "#2e7d32", "disagrees": "#c62828"}


def render_html(sections: Sequence[Section], ctx: Context) -> str:
    e = html.escape
    parts = [
        "<!doctype html><html><head><meta charset='utf-8'><title>birdsim report</title><style>",
        "body{font-family:sans-serif;max-width:1250px;margin:auto;padding:1em;color:#222}"
        "figure{margin:1.5em 0;border-top:1px solid #ccc;padding-top:1em}img{max-width:100%}"
        ".badge{color:#fff;padding:1px 6px;border-radius:4px;font-size:90%}"
        "li.ok::marker{content:'\\2714  ';color:#2e7d32}li.no::marker{content:'\\2718  "
        "';color:#c62828}"
        ".small{color:#555;font-size:90%}",
        "</style></head><body>",
        "<h1>birdsim: the dissertation's analysis, regenerated</h1>",
        "<p class='small'>Every figure is computed by this checkout's code (birdsim "
        f"report{' --quick: coarse grids' if ctx.res.quick else ''}); "
        f"{e(plots.FORCE_NOTE)}; angles in radians; all quantities non-dimensional (rho = omega = "
        "semispan = 1). "
        "Each figure lists the dissertation's statements about the same figure and whether our "
        "numbers bear them out.</p>",
    ]
    for sec in sections:
        parts.append(
            f"<h2>{e(sec.family.heading)}</h2><p class='small'>built in {sec.seconds:.1f} s</p>"
        )
        if sec.error:
            parts.append(f"<p><b>{e(sec.error)}</b></p>")
        for ent in sec.entries:
            colour = _BADGE.get(ent.verdict, "#ef6c00" if ent.claims else "#777")
            parts.append(
                f"<figure id='{e(ent.file)}'><h3>{e(ent.title)}</h3><img src='{e(ent.file)}' "
                f"alt='{e(ent.title)}'>"
            )
            parts.append(f"<figcaption><p>{e(ent.shows)}</p>")
            if ent.dissertation:
                parts.append(f"<p><b>Dissertation:</b> {e(ent.dissertation)}</p>")
            parts.append(
                "<p><b>Ours:</b> <span class='badge' "
                f"style='background:{colour}'>{e(ent.verdict)}</span></p>"
            )
            if ent.claims:
                parts.append(
                    "<ul>"
                    + "".join(
                        f"<li class='{'ok' if c.holds else 'no'}'>{e(c.statement)}: "
                        f"{e(c.ours)}</li>"
                        for c in ent.claims
                    )
                    + "</ul>"
                )
            if ent.note:
                parts.append(f"<p class='small'>{e(ent.note)}</p>")
            parts.append("</figcaption></figure>")
    parts.append("</body></html>")
    return "\n".join(parts)
