"""A path's quintic curves evaluated in compiled code (issue 27: the control update's
Python), bitwise as :func:`birdsim.flight.path_curves.eval_extrapolated` evaluates them.

``eval_extrapolated`` calls scipy's ``PPoly`` three times (value, first and second
derivative) on the clipped times and continues the curve on its end tangent outside the
knots: six ``PPoly`` calls per 2-D path sample, some 40 us each, most of it argument
handling.  :func:`curve_values` does the same in one numba call per curve: scipy's
interval search (``x[i] <= t < x[i + 1]``, the last interval closed on the right) and
its polynomial evaluation (``_ppoly.evaluate_poly1``: ``res + c[K - 1 - k] * z * f`` with
``z = s**(k - nu)`` built by repeated products and ``f`` the derivative's falling
factorial), with the same floating-point operations in the same order, then the same
clip, tangent and zero acceleration outside.  So the numbers are scipy's to the bit
(``tests/test_fast_path.py``).  Where the knots are not strictly increasing and finite,
or numba is missing, :func:`curve_values` returns None and the caller keeps scipy.
"""

from __future__ import annotations

import numpy as np
from scipy.interpolate import PPoly

from birdsim.physics.jit import numba

#: the compiled evaluation is used where it applies (False: scipy's PPoly, the reference)
ENABLED = True


def _poly(c, i, s, nu):
    """scipy's ``evaluate_poly1``: derivative ``nu`` of the local polynomial ``i`` at
    ``s`` (coefficients highest power first)."""
    kk = c.shape[0]
    res = 0.0
    z = 1.0
    for kp in range(kk):
        if nu == 0:
            prefactor = 1.0
        else:
            if kp < nu:
                continue
            prefactor = 1.0
            for k in range(kp, kp - nu, -1):
                prefactor *= k
        res = res + c[kk - kp - 1, i] * z * prefactor
        if kp < kk - 1 and kp >= nu:
            z *= s
    return res


def _values(c, x, t, out):
    """``out[0, j], out[1, j], out[2, j]``: value, slope and second derivative at
    ``t[j]``, continued on the end tangent outside ``[x[0], x[-1]]``."""
    n = x.shape[0]
    t0, t1 = x[0], x[n - 1]
    for j in range(t.shape[0]):
        tj = t[j]
        tc = tj
        if tc < t0:  # np.clip(t, t0, t1) = min(max(t, t0), t1)
            tc = t0
        if tc > t1:
            tc = t1
        if not (t0 <= tc <= t1):  # NaN: scipy's interval -1
            out[0, j] = out[1, j] = out[2, j] = np.nan
            continue
        if tc == t1:
            i = n - 2
        else:
            lo, hi = 0, n - 2
            while lo < hi:  # the last i with x[i] <= tc
                mid = (lo + hi + 1) // 2
                if x[mid] <= tc:
                    lo = mid
                else:
                    hi = mid - 1
            i = lo
        s = tc - x[i]
        y = _poly(c, i, s, 0)
        v = _poly(c, i, s, 1)
        a = _poly(c, i, s, 2)
        if tj < t0 or tj > t1:
            a = 0.0
        out[0, j] = y + v * (tj - tc)
        out[1, j] = v
        out[2, j] = a


if numba is not None:
    _poly = numba.njit(cache=True)(_poly)
    values_kernel = numba.njit(cache=True)(_values)
else:  # pragma: no cover
    values_kernel = None

_PACKED: dict[int, tuple] = {}


def _packed(pp: PPoly) -> tuple | None:
    """(c (K, n) float, x (n + 1,)) of a 1-D ``pp``, or None where the compiled
    evaluation does not apply (kept per curve)."""
    hit = _PACKED.get(id(pp))
    if hit is not None and hit[0] is pp:
        return hit[1]
    c, x = np.asarray(pp.c), np.asarray(pp.x)
    ok = (
        c.ndim == 2
        and c.dtype == np.float64
        and x.dtype == np.float64
        and x.shape[0] == c.shape[1] + 1
        and bool(np.all(np.isfinite(x)))
        and bool(np.all(np.diff(x) > 0))
    )
    out = (np.ascontiguousarray(c), np.ascontiguousarray(x)) if ok else None
    if len(_PACKED) > 256:
        _PACKED.clear()
    _PACKED[id(pp)] = (pp, out)
    return out


def curve_values(pp: PPoly, t: np.ndarray) -> np.ndarray | None:
    """(3, t.size): :func:`birdsim.flight.path_curves.eval_extrapolated` of ``pp`` at
    the flattened ``t`` (float64), or None where it does not apply."""
    if not ENABLED or values_kernel is None:
        return None
    packed = _packed(pp)
    if packed is None:
        return None
    flat = np.ascontiguousarray(t, dtype=float).reshape(-1)
    out = np.empty((3, flat.shape[0]))
    values_kernel(packed[0], packed[1], flat, out)
    return out


def path_curves(path) -> tuple | None:
    """(c, x) of a straight path's x curve and then its z curve, packed for
    :data:`values_kernel`, or None where they are not evaluated here (switched off, not
    a FlightPath's own curves: a speed-form path's track, a side component)."""
    if not ENABLED or values_kernel is None:
        return None
    curves = [getattr(path, k, False) for k in ("_x", "_z", "_y", "_track")]
    if any(c is False for c in curves) or curves[2] is not None or curves[3] is not None:
        return None
    px, pz = _packed(curves[0]), _packed(curves[1])
    return None if px is None or pz is None else (*px, *pz)


__all__ = ["ENABLED", "curve_values", "path_curves", "values_kernel"]
