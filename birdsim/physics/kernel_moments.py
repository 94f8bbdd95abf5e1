"""Compiled whole-bird moments and their exact derivatives (placeholder: the numpy path
answers until the kernel lands)."""

from __future__ import annotations


def whole_bird(mx, sym, speed, climb, rate, u, bird, phases, signs):
    """None: the caller uses the numpy reference."""
    return None
