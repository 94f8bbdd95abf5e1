"""``python -m birdsim`` runs the same command line as the ``birdsim`` script."""

from __future__ import annotations

import subprocess
import sys


def test_python_m_birdsim_is_the_cli() -> None:
    """A user's mistake through ``python -m`` gets the CLI's one-line error and exit 2."""
    done = subprocess.run(
        [sys.executable, "-m", "birdsim", "fly", "nosuch"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 2
    assert "manoeuvre 'nosuch' is unknown" in done.stderr
    assert "Traceback" not in done.stderr
    assert len(done.stderr.strip().splitlines()) == 1
