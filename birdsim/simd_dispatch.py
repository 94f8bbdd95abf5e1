"""numpy's SIMD dispatch: which of its compiled math paths this process runs.

numpy's wheels carry each ufunc's inner loops for several CPU generations and pick one
at import by the CPU (``numpy._core._multiarray_umath.__cpu_dispatch__``, the features
it was built to dispatch; ``__cpu_features__``, the ones this CPU has).  Where the CPU
has AVX-512 (numpy 2.4 names the group ``X86_V4``), ``np.exp`` and ``np.arctan2`` of
float64 run numpy's own AVX-512 code and differ from the C library's in the last bit
(measured: 4.6 % and 7.8 % of 200 000 random arguments, docs/performance.md); on an
AVX2 CPU they run the C library's and agree with it bit for bit.  Like OpenBLAS's
kernels (:mod:`birdsim.blas_kernel`) this decides where nearly tied optima fall, so a
table records the dispatch it was built under (``numpy_simd`` in its provenance) and
the bitwise rebuild tests run only under the same one (docs/tables.md).
"""

from __future__ import annotations

#: The dispatch the shipped tables without a ``numpy_simd`` record were built under:
#: with AVX-512 (their build machines' ``np.exp`` differed from the C library's, which
#: only numpy's AVX-512 exp does; the rebuild tests passed there).
UNRECORDED_SIMD = ["X86_V4"]


def numpy_simd() -> list[str]:
    """numpy's dispatched CPU features that this process's CPU has, in numpy's order."""
    from numpy._core import _multiarray_umath as umath

    found = umath.__cpu_features__
    return [f for f in umath.__cpu_dispatch__ if found.get(f, False)]


def has_avx512(features: list[str]) -> bool:
    """True where a dispatch list includes numpy's AVX-512 paths (any name of them)."""
    return any(f == "X86_V4" or f.startswith("AVX512") for f in features)


def same_simd(built: list[str] | None, here: list[str]) -> bool:
    """Whether a table built under ``built`` (None: unrecorded) runs the same math paths
    here: the whole list where it was recorded, AVX-512 or not where it was not."""
    if built is None:
        return has_avx512(UNRECORDED_SIMD) == has_avx512(here)
    return list(built) == list(here)


__all__ = ["UNRECORDED_SIMD", "has_avx512", "numpy_simd", "same_simd"]
