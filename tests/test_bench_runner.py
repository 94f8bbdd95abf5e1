"""``benchmarks/run.py``'s section names: a mistyped one is refused in one line (it used to
run nothing and exit 0); ``--help`` lists the sections."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

RUN = Path(__file__).resolve().parents[1] / "benchmarks" / "run.py"


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, str(RUN), *args], capture_output=True, text=True, timeout=60
    )


def test_unknown_section_is_one_line_exit_2() -> None:
    done = _run("tabels")
    assert done.returncode == 2
    assert done.stderr.strip().splitlines() == [done.stderr.strip()]
    assert "section 'tabels' is unknown" in done.stderr and "tables" in done.stderr
    assert done.stdout == ""


def test_help_lists_every_section() -> None:
    done = _run("--help")
    assert done.returncode == 0
    for path in RUN.parent.glob("bench_*.py"):
        assert path.stem.removeprefix("bench_") in done.stdout
