"""numba's cache folder is keyed by the sources of birdsim's numba modules
(birdsim/numba_cache.py): an edit of any of them (not only of the caller's own file,
which is all numba checks) moves the cache, and the user's NUMBA_CACHE_DIR wins."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from birdsim.numba_cache import cache_folder, sources_digest

ROOT = Path(__file__).resolve().parents[1]


def _tree(tmp_path: Path) -> Path:
    pkg = tmp_path / "pkg"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "caller.py").write_text("import numba\nfrom pkg.sub.helper import h\n")
    (pkg / "sub" / "helper.py").write_text("import numba\nh = numba.njit(lambda x: x + 1)\n")
    (pkg / "plain.py").write_text("X = 1\n")
    return pkg


def test_an_edit_of_a_helper_module_moves_the_cache_and_a_plain_module_does_not(
    tmp_path: Path,
) -> None:
    pkg = _tree(tmp_path)
    before = sources_digest(pkg)
    (pkg / "plain.py").write_text("X = 2\n")  # no numba: not part of the key
    assert sources_digest(pkg) == before
    (pkg / "sub" / "helper.py").write_text("import numba\nh = numba.njit(lambda x: x + 2)\n")
    assert sources_digest(pkg) != before  # the caller's file is untouched


def test_the_folder_is_under_the_user_cache(tmp_path: Path, monkeypatch) -> None:
    pkg = _tree(tmp_path)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    assert cache_folder(pkg) == tmp_path / "cache" / "birdsim" / "numba" / sources_digest(pkg)


def _cache_dir_in_child(env: dict[str, str]) -> str:
    code = "import birdsim, numba; print(numba.config.CACHE_DIR)"
    out = subprocess.run(
        [sys.executable, "-c", code], env=env, cwd=ROOT, capture_output=True, text=True
    )
    assert out.returncode == 0, out.stderr
    return out.stdout.strip()


def test_importing_birdsim_points_numba_there_unless_the_user_chose(tmp_path: Path) -> None:
    env = {k: v for k, v in os.environ.items() if "NUMBA_CACHE_DIR" not in k}
    env["XDG_CACHE_HOME"] = str(tmp_path / "cache")
    env["PYTHONPATH"] = str(ROOT)
    ours = _cache_dir_in_child(env)
    assert ours == str(tmp_path / "cache" / "birdsim" / "numba" / sources_digest())
    # a parent's folder of other sources (inherited with its marker) is re-keyed
    stale = str(tmp_path / "other-sources")
    inherited = _cache_dir_in_child(
        env | {"NUMBA_CACHE_DIR": stale, "BIRDSIM_NUMBA_CACHE_DIR": stale}
    )
    assert inherited == ours
    users = str(tmp_path / "mine")
    assert _cache_dir_in_child(env | {"NUMBA_CACHE_DIR": users}) == users
