"""Table builds on Dask (birdsim/tables/cluster.py): scheduler parsing, one-line errors
(bad spec, dask missing, no scheduler), and (slow) a local:2 cluster that builds the same
table bitwise as the local pool, also when one worker process is killed mid-build."""

from __future__ import annotations

import os
import signal
import socket
import sys
import threading
import time

import pytest

from birdsim.cli import main
from birdsim.errors import BirdsimError
from birdsim.tables.build import BuildConfig, Grid, build_table
from birdsim.tables.cluster import dask_executor, parse_scheduler


@pytest.mark.parametrize(
    "spec, want",
    [
        ("local:2", (None, 2)),
        ("tcp://10.0.0.5:8786", ("tcp://10.0.0.5:8786", None)),
        (" local:1 ", (None, 1)),
    ],
)
def test_scheduler_specs(spec, want):
    s = parse_scheduler(spec)
    assert (s.address, s.local_workers) == want


@pytest.mark.parametrize(
    "spec",
    ["local:0", "local:-1", "local:x", "local:1000", "tcp://host", "host:8786", "", "udp://a:1"],
)
def test_bad_scheduler_specs_are_one_line(spec):
    with pytest.raises(BirdsimError, match=r"--dask .* is invalid; allowed: "):
        parse_scheduler(spec)


def test_dask_not_installed_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)  # import distributed -> ImportError
    with pytest.raises(
        BirdsimError,
        match=r"--dask needs dask.distributed, which is not installed; allowed: pip install 'birdsim\[cluster\]'",
    ):
        with dask_executor("local:1"):
            pass


def test_cli_dask_errors_before_any_work(tmp_path, capsys, monkeypatch):
    out = tmp_path / "t.npz"
    for argv, message in (
        (["--dask", "local:0"], "--dask 'local:0' is invalid"),
        (["--dask", "local:2", "--jobs", "2"], "--jobs 2 with --dask 'local:2'"),
    ):
        assert (
            main(["tables", "build", "--model", "base", "--out", str(out), "--quiet", *argv]) == 2
        )
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1 and message in err, err
    monkeypatch.setitem(sys.modules, "distributed", None)
    assert (
        main(
            [
                "tables",
                "build",
                "--model",
                "base",
                "--out",
                str(out),
                "--quiet",
                "--dask",
                "local:1",
            ]
        )
        == 2
    )
    assert "birdsim[cluster]" in capsys.readouterr().err
    assert not any(tmp_path.iterdir())


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_a_scheduler_that_does_not_answer_is_one_line_within_the_timeout():
    pytest.importorskip("distributed")
    address = f"tcp://127.0.0.1:{_free_port()}"
    t0 = time.perf_counter()
    with pytest.raises(BirdsimError, match=f"--dask '{address}': no scheduler answered within 2 s"):
        with dask_executor(address, connect_timeout=2.0):
            pass
    assert time.perf_counter() - t0 < 8


GRID = Grid.parse("Fx=-0.25|0|0.25,Fz=-0.5|-0.25|0,V=0|0.3|0.6|0.9")


@pytest.mark.slow
def test_local2_cluster_builds_the_same_table_even_when_a_worker_dies(tmp_path):
    pytest.importorskip("distributed")
    from birdsim.tables.cluster import worker_pids

    cfg = BuildConfig("m1", GRID)
    local = build_table(cfg, jobs=2)
    with dask_executor("local:2") as ex:
        same = build_table(cfg, executor=ex)
        pids = worker_pids(ex)
        result: dict = {}

        def run() -> None:
            result["table"] = build_table(cfg, executor=ex, checkpoint_dir=tmp_path / "ck")

        thread = threading.Thread(target=run)
        thread.start()
        client = ex._client
        deadline = time.time() + 60
        while time.time() < deadline and not any(client.processing().values()):
            time.sleep(0.05)
        busy = next(w for w, tasks in client.processing().items() if tasks)
        os.kill(pids[busy], signal.SIGKILL)  # one worker process dies mid-task
        thread.join(timeout=600)
        assert not thread.is_alive()
    for t in (same, result["table"]):
        for name in ("params", "cost", "achieved", "status_code", "evaluations"):
            assert getattr(t, name).tobytes() == getattr(local, name).tobytes(), name
    assert not (tmp_path / "ck").exists()
