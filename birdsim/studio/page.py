"""The self-contained 3-D view: one HTML file with the viewer's bundle, its styles and
the scene inlined (no network at all: no CDN, no fonts, no fetch).

The bundles in ``birdsim/studio/static`` are built from ``web/`` by ``make web``
(esbuild, pinned by ``web/package-lock.json``) and committed with their provenance
(``static/PROVENANCE.json``), so neither ``pip install`` nor CI needs npm.
"""

from __future__ import annotations

import html
import json
from pathlib import Path
from typing import Any

from birdsim.errors import BirdsimError

STATIC = Path(__file__).resolve().parent / "static"
#: The most bytes a view may have (issue 26: at most 3 MB for 10 s of flight at 60 fps).
MAX_VIEW_BYTES = 3_000_000

_TEMPLATE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8"><link rel="icon" href="data:,">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; img-src data: blob:">
<title>{title}</title>
<style>{css}</style>
</head>
<body>
<div id="app"></div>
<p class="bv-note">{note}</p>
<script type="application/json" id="birdsim-scene">{scene}</script>
<script>{js}</script>
</body>
</html>
"""


def static_text(name: str) -> str:
    """A built bundle (``view.js``, ``view.css``, ``studio.js``, ``studio.css``).

    Raises:
        BirdsimError: the bundle is missing (a checkout without ``make web``'s output).
    """
    path = STATIC / name
    if not path.is_file():
        raise BirdsimError(
            f"the viewer bundle {str(path)!r} is missing; allowed: a birdsim with its built web bundle (make web)"
        )
    return path.read_text(encoding="utf-8")


def scene_json(scene: dict[str, Any]) -> str:
    """The scene as compact JSON, safe inside a ``<script>`` element."""
    text = json.dumps(scene, separators=(",", ":"), allow_nan=False)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def view_html(scene: dict[str, Any]) -> str:
    """The whole page for ``scene`` (:func:`birdsim.studio.scene.flight_scene`)."""
    js = static_text("view.js").replace("</script", "<\\/script")
    tb = scene["time_base"]
    note = (
        f"birdsim view: {scene['title']} ({scene['bird']}, {scene['model']}); "
        f"playback 1x = {tb['label']}; drag to orbit, wheel to zoom, right-drag to pan; "
        "click a plot to jump there."
    )
    return _TEMPLATE.format(
        title=html.escape(f"birdsim: {scene['title']}"),
        css=static_text("view.css"),
        note=html.escape(note),
        scene=scene_json(scene),
        js=js,
    )


__all__ = ["MAX_VIEW_BYTES", "STATIC", "scene_json", "static_text", "view_html"]
