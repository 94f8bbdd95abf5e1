"""Whole-bird moments and Jacobians per second (issue 22): the compiled kernel with exact
derivatives against the numpy reference with central differences, on the m3 table."""

from __future__ import annotations

import time
from pathlib import Path

from birdsim.tables.jacobians import table_jacobians
from birdsim.tables.lookup import load_table

TABLE = Path(__file__).resolve().parent.parent / "tables" / "m3"


def main() -> None:
    table = load_table(TABLE)
    cells = table.params.size // len(table.param_names)
    table_jacobians(table)  # compile / load the kernel
    for backend in ("kernel", "numpy"):
        t0 = time.perf_counter()
        table_jacobians(table, backend=backend)
        dt = time.perf_counter() - t0
        print(
            f"moments+Jacobians {backend:6s}: {cells / dt:8.0f} cells/s ({cells} cells, {dt:.2f} s)"
        )


if __name__ == "__main__":
    main()
