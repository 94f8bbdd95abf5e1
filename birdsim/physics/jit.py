"""The JIT used by the fused kernels: numba's ``njit`` with an on-disk cache, or None.

numba is a dependency, but a machine where it is missing (or broken) still runs: then
``numba`` is None, ``jit`` leaves functions as plain Python (never called: the kernels
report themselves unavailable and the numpy path runs).
"""

from __future__ import annotations

try:
    import numba
    from numba import njit
except Exception:  # pragma: no cover - exercised through kernel._disable in the tests
    numba = None

if numba is not None:
    # fused multiply-add and no signed zeros only: NaN and infinity checks stay (no
    # 'nnan'/'ninf'), exact libm functions (no 'afn')
    _FAST = {"contract", "nsz"}
    jit = njit(cache=True, nogil=True, error_model="numpy", fastmath=_FAST)
    #: the same, for a helper that a kernel's inner loop calls: inlined at numba's IR
    #: level (a call per strip and sample would cost the gradient kernel up to 45 %)
    jit_inline = njit(cache=True, nogil=True, error_model="numpy", fastmath=_FAST, inline="always")
else:  # pragma: no cover

    def jit(f):
        return f

    jit_inline = jit
