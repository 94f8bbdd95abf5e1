"""``birdsim studio``: a local web app to choose a bird, a model and a path, edit the
path's keyframes, add gusts, fly it (the code of ``birdsim fly``), watch it in 3-D with
plots linked to the timeline, compare flights side by side and download each as MP4,
USD, BVH, CSV, the log or the self-contained 3-D view (docs/studio.md).

It listens on 127.0.0.1 (this machine only) unless --host says otherwise, and reads
files only inside the folder it was started in. Needs the extra: pip install
'birdsim[studio]'."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from birdsim.errors import BirdsimError

DEFAULT_PORT = 8765
LOOPBACK = ("127.0.0.1", "localhost", "::1")


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "studio",
        help="a local web app: design, fly and watch flights in 3-D (needs birdsim[studio])",
        description=__doc__,
    )
    p.add_argument(
        "--port",
        default=str(DEFAULT_PORT),
        metavar="N",
        help=f"port, 1 to 65535 (default {DEFAULT_PORT})",
    )
    p.add_argument(
        "--host",
        default="127.0.0.1",
        help="address to listen on (default 127.0.0.1: this machine only)",
    )
    p.set_defaults(func=run)


def parse_port(raw: str) -> int:
    try:
        port = int(raw)
    except ValueError:
        raise BirdsimError(f"--port {raw!r} is not a whole number; allowed: 1 to 65535") from None
    if not 1 <= port <= 65535:
        raise BirdsimError(f"--port {raw!r} is out of range; allowed: 1 to 65535")
    return port


def make_server(host: str, port: int, root: Path):
    """The studio's HTTP server (werkzeug's threaded server), bound but not serving.

    Raises:
        BirdsimError: the extra is missing, or the port cannot be bound (one line).
    """
    try:
        from werkzeug.serving import make_server as _make_server

        from birdsim.studio.app import create_app
    except ModuleNotFoundError as exc:
        raise BirdsimError(
            f"birdsim studio needs {exc.name!r}; allowed: install the extra: pip install 'birdsim[studio]'"
        ) from None
    app = create_app(root)
    import socket

    try:
        family, _, _, _, address = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)[0]
    except (socket.gaierror, UnicodeError, OverflowError):
        raise BirdsimError(
            f"--host {host!r} is not an address; allowed: an address of this machine (default 127.0.0.1)"
        ) from None
    try:  # bind once ourselves: werkzeug would print several lines and exit on its own
        with socket.socket(family, socket.SOCK_STREAM) as probe:
            probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            probe.bind(address)
        return _make_server(host, port, app, threaded=True)
    except (OSError, SystemExit) as exc:
        in_use = getattr(exc, "errno", None) in (98, 48, 10048) or isinstance(exc, SystemExit)
        reason = (
            "is in use" if in_use else f"cannot be used ({getattr(exc, 'strerror', None) or exc})"
        )
        raise BirdsimError(
            f"--port {port} on {host} {reason}; allowed: a free port (e.g. --port {port + 1})"
        ) from None


def run(args: argparse.Namespace) -> int:
    port = parse_port(args.port)
    host = str(args.host)
    root = Path.cwd()
    if host not in LOOPBACK:
        print(
            f"birdsim studio: warning: listening on {host}: other machines can reach the studio and fly on this one",
            file=sys.stderr,
        )
    server = make_server(host, port, root)
    shown = f"[{host}]" if ":" in host else host
    print(
        f"birdsim studio: http://{shown}:{server.server_port}/ (files from {root}; Ctrl-C stops)",
        flush=True,
    )
    try:
        server.serve_forever()
    finally:
        server.server_close()
    return 0
