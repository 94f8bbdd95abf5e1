"""Batches of flights (``birdsim fly A B ...``, ``--batch``, ``--jobs``, ``--dask``;
birdsim/flight/batch.py): every executor flies the same flights bit for bit (the two
fresh workers of a pool here; (slow) a Dask local:2 cluster against the pool), a failed
entry is one
line naming it while the others are written, bad input is one line and exit 2."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

from birdsim.cli import main
from birdsim.flight.batch import FlightJob, local_executor, run_batch
from birdsim.json_values import finite_or_none

SECONDS = 0.6  # 0.12 wingbeat of the seed bird (period 5): short, the whole loop runs


def _jobs() -> list[FlightJob]:
    return [
        FlightJob(0, "cruise", "m3", seconds=SECONDS),
        FlightJob(1, "hover", "m3", seconds=SECONDS),
        FlightJob(2, "cruise", "m4", attitude="free", seconds=SECONDS, gusts=("0:1:0.1:0.05",)),
    ]


def _text(info: dict) -> str:
    return json.dumps(finite_or_none(info), sort_keys=True, default=str)


def _same(a: list[dict], b: list[dict], labels: bool = True) -> None:
    assert not labels or [r["label"] for r in a] == [r["label"] for r in b]
    for ra, rb in zip(a, b):
        assert ra["arrays"].keys() == rb["arrays"].keys()
        for k, v in ra["arrays"].items():
            assert np.array_equal(v, rb["arrays"][k]), k
        # NaN (no figure after the start of so short a flight) equals NaN here
        assert _text(ra["info"]) == _text(rb["info"])


def _pool(n: int, jobs: list[FlightJob]) -> list[dict]:
    pool = local_executor(n)
    try:
        return run_batch(jobs, pool)
    finally:
        pool.shutdown()


@pytest.mark.slow  # two worker processes start (~14 s at load 6); the failed-entry test runs a pool by default
def test_the_workers_of_a_pool_fly_the_same_flights_bitwise():
    """Each flight twice on a pool of two fresh workers (the copies land on either)."""
    jobs = _jobs()[1:]
    twice = jobs + [dataclasses.replace(j, index=j.index + 10) for j in jobs]
    res = _pool(2, twice)
    _same(res[:2], res[2:], labels=False)
    assert res[1]["info"]["wingbeats"] > 0.1


def test_a_failed_entry_is_one_line_and_the_others_are_written(tmp_path, capsys):
    batch = tmp_path / "flights.txt"
    batch.write_text("cruise  # the first\n\nmissing.toml\nhover\n")
    out = tmp_path / "logs"
    code = main(["fly", "--batch", str(batch), "--out", str(out), "--jobs", "1"]
                + ["--seconds", str(SECONDS), "--quiet"])  # fmt: skip
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2
    assert len(err) == 1 and "entry 1" in err[0] and "missing.toml" in err[0]
    assert sorted(p.name for p in out.iterdir()) == ["000-cruise.npz", "002-hover.npz"]
    # nothing overwritten without --force: refused before flying
    code = main(["fly", "cruise", "hover", "--out", str(out), "--seconds", str(SECONDS)])
    assert code == 2
    assert "000-cruise.npz" in capsys.readouterr().err


@pytest.mark.parametrize(
    "argv, words",
    [
        (["cruise", "hover", "--jobs", "0"], "--jobs '0' is invalid"),
        (["cruise", "hover", "--out", "x.npz"], "is a .npz file; allowed: a folder"),
        (["--batch", "/nonexistent/list.txt"], "cannot be read"),
        (["cruise", "--dask", "local:1", "--jobs", "2"], "allowed: one of them"),
        (["cruise", "--dask", "udp://x:1"], "--dask 'udp://x:1' is invalid"),
        ([], "no MANOEUVRE"),
    ],
)
def test_bad_batch_input_is_one_line(argv, words, capsys):
    assert main(["fly", *argv, "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0]


@pytest.mark.slow
def test_dask_flies_the_local_pools_flights_bitwise():
    pytest.importorskip("distributed")
    from birdsim.tables.cluster import dask_executor

    local = _pool(2, _jobs())
    with dask_executor("local:2") as executor:
        remote = run_batch(_jobs(), executor)
    _same(local, remote)
