"""``make bench``: every ``benchmarks/bench_*.py`` in one run, with the machine noted
(``python benchmarks/run.py tables core``: only those sections).

Each bench module exposes ``main() -> None`` and prints its own lines: ratios measured
side by side in this run, and absolute figures.
"""

from __future__ import annotations

import importlib.util
import os
import platform
import sys
import time
from pathlib import Path


def machine() -> str:
    cpu = platform.processor() or "unknown cpu"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    import numpy

    return (
        f"{platform.node()} | {cpu} | {os.cpu_count()} cores | Python {platform.python_version()} | "
        f"numpy {numpy.__version__} | {time.strftime('%Y-%m-%d %H:%M')}"
    )


def load() -> str:
    """The 1-, 5- and 15-minute load averages (the machine is shared: the figures of a
    loaded run are lower, the ratios side by side much less so)."""
    try:
        one, five, fifteen = os.getloadavg()
    except OSError:
        return "load average unknown"
    return f"load average {one:.2f}, {five:.2f}, {fifteen:.2f}"


def main(argv: list[str]) -> int:
    here = Path(__file__).parent
    paths = sorted(here.glob("bench_*.py"))
    names = [path.stem.removeprefix("bench_") for path in paths]
    wanted = set(argv)
    if wanted & {"-h", "--help"}:
        print(f"usage: python benchmarks/run.py [SECTION ...]; sections: {', '.join(names)}")
        return 0
    for bad in sorted(wanted - set(names)):
        print(
            f"benchmarks/run.py: section {bad!r} is unknown; allowed: none (all) or any of "
            f"{', '.join(names)}",
            file=sys.stderr,
        )
        return 2
    print(f"machine: {machine()}")
    for path, name in zip(paths, names):
        if wanted and name not in wanted:
            continue
        print(f"\n== {name} == ({load()})", flush=True)
        spec = importlib.util.spec_from_file_location(path.stem, path)
        module = importlib.util.module_from_spec(spec)
        assert spec.loader is not None
        spec.loader.exec_module(module)
        module.main()
        print(f"({load()} at the end of {name})", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
