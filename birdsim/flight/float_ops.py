"""numpy's elementwise operations on one Python float, the same bits without numpy's
array machinery (a 0-d array and a ufunc call cost microseconds; the control update
makes a few of them per step)."""

from __future__ import annotations


def clip_float(x: float, lo: float, hi: float) -> float:
    """``float(np.clip(x, lo, hi))`` for floats, as numpy computes it: ``x`` kept where it
    equals a bound (the sign of a zero kept), a NaN ``x`` or bound propagated."""
    x, lo, hi = float(x), float(lo), float(hi)
    if x != x or lo != lo:
        return x if x != x else lo
    if hi != hi:
        return hi
    x = lo if x < lo else x
    return hi if x > hi else x


__all__ = ["clip_float"]
