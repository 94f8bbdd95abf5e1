"""``birdsim studio`` and ``birdsim view`` on the command line: the port, the host
warning, a page written once and atomically."""

from __future__ import annotations

import socket

import pytest

from birdsim.cli import main

pytest.importorskip("flask", reason="the studio needs birdsim[studio] (flask)")


def test_port_in_use_is_one_line(capsys):
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen(1)
        port = s.getsockname()[1]
        assert main(["studio", "--port", str(port)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"--port {port} on 127.0.0.1 is in use" in err[0]


@pytest.mark.parametrize("port", ["0", "65536", "-1", "http", "8080.5"])
def test_port_out_of_range(capsys, port):
    assert main(["studio", "--port", port]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"--port {port!r}" in err[0] and "1 to 65535" in err[0]


class _Server:
    server_port = 54321

    def serve_forever(self):
        return None

    def server_close(self):
        return None


@pytest.mark.parametrize("host, warned", [("127.0.0.1", False), ("0.0.0.0", True)])
def test_other_hosts_print_a_warning(monkeypatch, capsys, host, warned):
    import birdsim.commands.studio as studio

    seen = {}

    def fake(h, p, root):
        seen.update(host=h, port=p)
        return _Server()

    monkeypatch.setattr(studio, "make_server", fake)
    assert main(["studio", "--host", host]) == 0
    out, err = capsys.readouterr()
    assert seen == {"host": host, "port": studio.DEFAULT_PORT}
    assert f"http://{host}:54321/" in out
    lines = err.strip().splitlines()
    assert (
        (len(lines) == 1 and "warning: listening on 0.0.0.0" in lines[0]) if warned else not lines
    )


def test_the_default_listens_on_loopback_only():
    from birdsim.commands.studio import make_server

    server = make_server("127.0.0.1", 0, __import__("pathlib").Path("."))
    try:
        assert server.server_address[0] == "127.0.0.1"
    finally:
        server.server_close()


def test_view_writes_one_page(tmp_path, capsys):
    out = tmp_path / "hover.html"
    assert main(["view", "hover", "--out", str(out), "--fps", "30"]) == 0
    line = capsys.readouterr().out.strip()
    assert line.startswith(f"wrote {out}") and "playback 1x = 2 wingbeats per second" in line
    text = out.read_text()
    assert text.startswith("<!DOCTYPE html>") and 'id="birdsim-scene"' in text
    assert main(["view", "hover", "--out", str(out)]) == 2  # no overwrite without --force
    assert "exists" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hover.html"]
