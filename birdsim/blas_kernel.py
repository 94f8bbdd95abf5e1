"""OpenBLAS's kernels pinned, so that a table rebuilds bit for bit on another x86-64 CPU.

numpy's and scipy's wheels carry OpenBLAS built for every CPU (DYNAMIC_ARCH): at load it
picks its kernels by the CPU it finds (SkylakeX on an AVX-512 Intel Xeon) unless
``OPENBLAS_CORETYPE`` names them (this workplace's machines set ``Haswell``).  SLSQP's
small linear algebra then differs in the last bits, and where two optima are nearly
tied a cell lands on the other branch: tables built on SkylakeX kernels, rerun one V
slice each on Haswell kernels, had 42-46 of m4's 78 recorded cells off by up to 1.47 rad
and 10 of seed-m3's 334 by up to 0.11 rad; on SkylakeX kernels again every cell came out
bitwise equal (docs/performance.md).  So birdsim pins the Haswell kernels, which every
x86-64 CPU with AVX2 and FMA runs (Intel since 2013, AMD since 2015), and the shipped
tables are built on them; each table records the kernels it was built on
(``blas_kernels`` in its provenance).

The pin must happen before OpenBLAS loads, that is before numpy is first imported: this
module does it on import, and ``birdsim/__init__.py`` imports it first.  A value the
user set is kept; where numpy was imported before birdsim the pin cannot act, and
:func:`blas_kernels` says which kernels run.
"""

from __future__ import annotations

import os
import platform

#: The kernels the shipped tables were built on, and the CPU flags they need.
KERNEL = "Haswell"
REQUIRED_FLAGS = frozenset({"avx2", "fma"})


def cpu_flags(cpuinfo: str = "/proc/cpuinfo") -> frozenset[str]:
    """The CPU's feature flags (Linux; empty where /proc/cpuinfo does not exist)."""
    try:
        with open(cpuinfo, encoding="utf-8", errors="replace") as fh:
            for line in fh:
                if line.startswith("flags"):
                    return frozenset(line.split(":", 1)[1].split())
    except OSError:
        pass
    return frozenset()


def pin_blas_kernel(flags: frozenset[str] | None = None) -> str | None:
    """Set ``OPENBLAS_CORETYPE`` to :data:`KERNEL` on an x86-64 CPU that can run it,
    unless it is set already; the value in effect (None: OpenBLAS chooses)."""
    flags = cpu_flags() if flags is None else flags
    if platform.machine().lower() in ("x86_64", "amd64") and REQUIRED_FLAGS <= flags:
        os.environ.setdefault("OPENBLAS_CORETYPE", KERNEL)
    return os.environ.get("OPENBLAS_CORETYPE")


def blas_kernels() -> list[str]:
    """The kernels (architecture names) of every OpenBLAS loaded in this process."""
    from threadpoolctl import threadpool_info

    return sorted(
        {
            str(i.get("architecture"))
            for i in threadpool_info()
            if i.get("internal_api") == "openblas"
        }
    )


pin_blas_kernel()

__all__ = ["KERNEL", "REQUIRED_FLAGS", "blas_kernels", "cpu_flags", "pin_blas_kernel"]
