"""Helpers of the browser tests: Debian's chromium driven by Playwright for Python through
its executable path (Playwright's own browser download is never used), WebGL through
SwiftShader; the studio served from a thread on a free port of 127.0.0.1."""

from __future__ import annotations

import tempfile
import threading
from pathlib import Path

CHROMIUM = Path("/usr/bin/chromium")
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--enable-unsafe-swiftshader",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--disable-quic",
]


def skip_reason() -> str | None:
    """Why the browser tests cannot run here, or None."""
    try:
        import flask  # noqa: F401
        import playwright.sync_api  # noqa: F401
    except ImportError as exc:
        return f"{exc.name} is not installed (make setup installs birdsim[test,studio])"
    if not CHROMIUM.is_file():
        return (
            f"{CHROMIUM} is missing (scripts/setup_browser.sh installs Debian's chromium as root)"
        )
    return None


def launch(playwright, viewport=(1280, 800), **kw):
    """A fresh persistent context (its own --user-data-dir) of the system chromium."""
    profile = tempfile.mkdtemp(prefix="birdsim-chromium-")
    return playwright.chromium.launch_persistent_context(
        profile,
        executable_path=str(CHROMIUM),
        args=FLAGS,
        headless=True,
        viewport={"width": viewport[0], "height": viewport[1]},
        **kw,
    )


class ServerThread:
    """The studio app on 127.0.0.1, port chosen by the system, served from a thread."""

    def __init__(self, root: Path):
        from birdsim.commands.studio import make_server

        self.server = make_server("127.0.0.1", 0, root)  # the CLI's own server
        self.app = self.server.app
        self.url = f"http://127.0.0.1:{self.server.server_port}/"
        self.thread = threading.Thread(target=self.server.serve_forever, daemon=True)
        self.thread.start()

    @property
    def store(self):
        return self.app.extensions["birdsim_store"]

    def stop(self) -> None:
        self.server.shutdown()
        self.server.server_close()
