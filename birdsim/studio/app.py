"""The studio's web app (Flask): the page, the choices, flights flown on request, their
scenes and downloads. Every error is one line in JSON (``{"error": ...}``), shown in
the page; files are read only inside ``root`` (:mod:`birdsim.studio.safety`)."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

from flask import Flask, Response, jsonify, request

from birdsim.errors import BirdsimError
from birdsim.json_values import finite_or_none
from birdsim.studio.flights import FlightRequest, path_dict
from birdsim.studio.jobs import Store
from birdsim.studio.page import scene_json, static_text, view_html
from birdsim.studio.safety import inside, toml_files

#: The largest request body (a path of MAX_KEYFRAMES keyframes is a few kB).
MAX_REQUEST_BYTES = 256 * 1024
MODELS = ("base", "m1", "m2", "m3", "m4")

_PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>birdsim studio</title>
<style>{view_css}</style><style>{css}</style></head>
<body><div id="studio"></div>
<script type="application/json" id="birdsim-options">{options}</script>
<script>{view_js}</script>
<script>{js}</script></body></html>
"""


def _error(message: str, status: int = 400) -> tuple[Response, int]:
    return jsonify(error=message), status


def _shipped_birds() -> dict[str, Path]:
    from birdsim.flight.presets import MODELS_FOLDER

    return {f"shipped:{p.name}": p for p in sorted(MODELS_FOLDER.glob("*.toml"))}


def create_app(root: str | Path) -> Flask:
    """The studio for the folder ``root`` (the only folder it reads files from)."""
    from birdsim.flight.flock import preset_names as flock_presets
    from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS
    from birdsim.flight.turn_presets import TURN_PRESETS

    root = Path(root).resolve()
    app = Flask("birdsim.studio", static_folder=None)
    app.config["MAX_CONTENT_LENGTH"] = MAX_REQUEST_BYTES
    store = Store()
    app.extensions["birdsim_store"] = store

    def options() -> dict[str, Any]:
        files = toml_files(root)
        return {
            "folder": str(root),
            "birds": [*_shipped_birds(), *files],
            "models": list(MODELS),
            "default_model": DEMO_MODEL,
            # the turns fly free (bank to turn); a flock flies every bird of its file
            "presets": [*PATH_PRESETS, *TURN_PRESETS, *flock_presets()],
            "files": files,
        }

    def bird_arg(name: str | None) -> str | None:
        if not name:
            return None
        shipped = _shipped_birds()
        if name in shipped:
            return str(shipped[name])
        return str(inside(root, name, "bird file"))

    def source_arg(name: str) -> str:
        from birdsim.flight.presets import PATH_PRESETS
        from birdsim.flight.turn_presets import TURN_PRESETS

        if name in PATH_PRESETS or name in TURN_PRESETS or name in flock_presets():
            return name
        return str(inside(root, name, "manoeuvre file"))

    @app.errorhandler(BirdsimError)
    def _birdsim_error(exc: BirdsimError):
        return _error(str(exc))

    @app.errorhandler(413)
    def _too_large(_exc):
        return _error(
            f"the request is larger than {MAX_REQUEST_BYTES} bytes; allowed: a smaller path", 413
        )

    @app.get("/")
    def page():
        text = _PAGE.format(
            view_css=static_text("view.css"),
            view_js=static_text("view.js").replace("</script", "<\\/script"),
            css=static_text("studio.css"),
            options=scene_json(options()),
            js=static_text("studio.js").replace("</script", "<\\/script"),
        )
        return Response(text, mimetype="text/html")

    @app.get("/api/options")
    def api_options():
        return jsonify(options())

    @app.get("/api/path")
    def api_path():
        from birdsim.flight.flock import is_flock, load_flock
        from birdsim.flight.path_file import get_flight

        name = request.args.get("source", "")
        if is_flock(source_arg(name)):
            flock = load_flock(source_arg(name))
            return jsonify(
                path=None,
                flock=True,
                note=f"{name!r} is a flock of {flock.n_birds} birds (rule {flock.rule}): "
                "flown as its file says, every bird drawn; not edited here",
            )
        flight = get_flight(source_arg(name), turning=True)
        if getattr(flight, "is_3d", False):  # the editor's table has no y, heading, turn_rate
            return jsonify(
                path=None,
                note=f"{name!r} turns out of the vertical plane: flown as it is (attitude "
                "free, bank to turn), not edited here",
            )
        data = path_dict(flight)
        if data is None:
            return jsonify(
                path=None, note=f"{name!r} is a force schedule: flown as it is, not edited here"
            )
        return jsonify(path=data)

    @app.post("/api/fly")
    def api_fly():
        body = request.get_json(silent=True)
        if not isinstance(body, dict):
            return _error(
                "the request is not a JSON object; allowed: {source | path, bird, model, gusts, open_loop}"
            )
        gusts = body.get("gusts") or []
        if not isinstance(gusts, list) or not all(isinstance(g, str) for g in gusts):
            return _error("gusts must be a list of T0:DURATION:WX:WZ strings")
        path = body.get("path")
        if path is not None and not isinstance(path, dict):
            return _error("path must be a table of a path file (name, duration, keyframe list)")
        source = body.get("source") or ""
        if path is None and not source:
            return _error("source is missing; allowed: a preset name or a manoeuvre file")
        seconds = body.get("seconds")
        if seconds is not None and not (
            isinstance(seconds, (int, float)) and math.isfinite(seconds)
        ):
            return _error(f"seconds={seconds!r}; allowed: a finite time > 0")
        model = body.get("model") or None
        if model is not None and model not in MODELS:
            return _error(f"model {model!r} is unknown; allowed: {', '.join(MODELS)}")
        req = FlightRequest(
            None if path is not None else source_arg(str(source)),
            model=model,
            bird=bird_arg(body.get("bird")),
            path=path,
            gusts=tuple(gusts),
            open_loop=bool(body.get("open_loop", False)),
            seconds=float(seconds) if seconds is not None else None,
        )
        label = str(body.get("label") or (path or {}).get("name") or source)[:80]
        job = store.submit(req, label)
        return jsonify(job=job.id)

    @app.get("/api/job/<jid>")
    def api_job(jid: str):
        job = store.jobs.get(jid)
        if job is None:
            return _error(f"job {jid!r} is unknown", 404)
        return jsonify(state=job.state, progress=job.progress, error=job.error, flight=job.flight)

    def _flight(fid: str):
        f = store.flight(fid)
        if f is None:
            raise BirdsimError(
                f"flight {fid!r} is unknown (flights are kept while the studio runs)"
            )
        return f

    def _scene(f) -> dict:
        from birdsim.studio.scene import flight_scene

        with f.lock:
            if f.scene is None and "n_birds" in f.log:  # a flock: every bird
                from birdsim.studio.flock_flights import flock_birds
                from birdsim.studio.flock_view import flock_scene

                f.scene = flock_scene(flock_birds(f.log), title=f.label)
            if f.scene is None:
                f.scene = flight_scene(f.log, title=f.label)
        return f.scene

    @app.get("/api/flight/<fid>/scene")
    def api_scene(fid: str):
        f = _flight(fid)
        scene = dict(_scene(f))
        scene["summary"] = finite_or_none(f.summary)
        return Response(scene_json(scene), mimetype="application/json")

    @app.get("/api/flight/<fid>/download/<kind>")
    def api_download(fid: str, kind: str):
        from birdsim.studio import downloads

        f = _flight(fid)
        data = downloads.make(
            kind, f.log, lambda: view_html(_scene(f)), size=request.args.get("size", "")
        )
        suffix, mime = downloads.KINDS[kind]
        stem = re.sub(r"[^A-Za-z0-9_.-]+", "_", Path(f.label or "flight").stem).strip("_.")
        name = f"{stem or 'flight'}-{fid}{suffix}"
        return Response(
            data, mimetype=mime, headers={"Content-Disposition": f'attachment; filename="{name}"'}
        )

    return app


__all__ = ["MAX_REQUEST_BYTES", "create_app"]
