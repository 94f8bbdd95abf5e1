"""The committed web bundle (birdsim/studio/static) is built from today's web/ sources:
PROVENANCE.json records a hash of them (web/build.mjs), recomputed here, so an edit of
web/ without `make web` fails; and the bundle fetches nothing at run time."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
WEB = REPO / "web"
STATIC = REPO / "birdsim" / "studio" / "static"


def sources_sha256() -> str:
    """The same hash as web/build.mjs: each file's name, then its bytes, in its order."""
    names = ["package.json", "package-lock.json", "build.mjs"]
    names += [f"src/{p.name}" for p in sorted((WEB / "src").iterdir(), key=lambda p: p.name)]
    h = hashlib.sha256()
    for name in names:
        h.update(name.encode())
        h.update((WEB / name).read_bytes())
    return h.hexdigest()


def test_bundle_is_built_from_the_sources():
    prov = json.loads((STATIC / "PROVENANCE.json").read_text())
    assert prov["sources_sha256"] == sources_sha256(), "web/ changed: run `make web`"
    lock = json.loads((WEB / "package-lock.json").read_text())["packages"]
    for name in ("three", "uplot", "esbuild"):
        assert prov["packages"][name]["version"] == lock[f"node_modules/{name}"]["version"]
        assert prov["packages"][name]["integrity"].startswith("sha512-")


def test_bundle_loads_nothing_from_the_network():
    for name in ("view.js", "studio.js", "view.css", "studio.css"):
        text = (STATIC / name).read_text()
        assert "cdn." not in text and "unpkg" not in text and "@import" not in text, name
        assert "fonts.googleapis" not in text, name
