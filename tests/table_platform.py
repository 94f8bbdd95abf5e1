"""The rebuild tests' platform check: a table rebuilds bit for bit only on the OpenBLAS
kernels and numpy SIMD paths it was built on (birdsim/blas_kernel.py,
birdsim/simd_dispatch.py); elsewhere those tests skip, saying why."""

from __future__ import annotations

import pytest

from birdsim.blas_kernel import blas_kernels
from birdsim.simd_dispatch import numpy_simd, same_simd

#: Tables built before their provenance recorded the OpenBLAS kernels were built on
#: SkylakeX kernels (an AVX-512 Xeon choosing them itself): they rebuild bitwise with
#: OPENBLAS_CORETYPE=SkylakeX and up to 1.47 rad apart on Haswell's (birdsim/blas_kernel.py).
UNRECORDED_KERNELS = ["SkylakeX"]


def same_platform(t) -> None:
    """Skip, saying why, where this process's OpenBLAS runs other kernels, or numpy other
    SIMD paths (birdsim/simd_dispatch.py), than the table was built on: the rebuild is
    then not expected to be bitwise (a branch can flip)."""
    built = t.meta.get("blas_kernels", UNRECORDED_KERNELS)
    here = blas_kernels()
    if here != built:
        pytest.skip(f"table built on OpenBLAS kernels {built}, this process runs {here}")
    simd = t.meta.get("numpy_simd")
    if not same_simd(simd, numpy_simd()):
        pytest.skip(
            f"table built under numpy's SIMD dispatch {simd or 'unrecorded (AVX-512)'}, "
            f"this process runs {numpy_simd()}"
        )
