"""The pitch row's allocation of the attitude loop: the slow moment by the wings' force
line, the fast moment by the tail (reduced units, seed body axes).

The wings' symmetric inputs (the sweep and dihedral offsets of both shoulders) move the
wingbeat-mean force line, but they move the force's swing within the wingbeat far more:
they change the periodic pitching moment that rocks the body.  Driven at the wingbeat
frequency (the one-wingbeat estimate's error follows the rocking), they pumped the
rocking of a light body: the pigeon's free cruise (pitch inertia 0.78 reduced, a quarter
of the seed bird's) grew a rocking from 5 to 68 degrees in 17 wingbeats with the pitch
swinging by +-30 degrees, and with the tail alone allocated it stayed at 8-20 degrees.
So the wings get the demand low-passed over :data:`WING_PITCH_BEATS` (first order), the
tail (whose force is steady within the wingbeat) what is left, and the wings again what
the tail cannot deliver (at hover the tail has no air): measured in docs/free-body.md
("The pigeon's attitude, fourth stage")."""

from __future__ import annotations

import math

import numpy as np

from birdsim.flight.attitude_jacobians import INPUTS
from birdsim.flight.bounded_lsq import bounded_lsq

#: Time constant (wingbeats) of the low-pass that gives the wings their share of the
#: pitch demand.  Measured (pigeon cruise / take-off / landing path RMS m, pitch deg):
#: the integral alone as the wings' share 0.0064, 3.2 / 0.021, 14.8 / 0.045, 28.2; the
#: mean over the last wingbeat 0.0062, 3.1 / 0.020, 14.6 / 0.069, 23.5; 0.25 wingbeats
#: 0.0052, 1.6 / 0.020, 14.5 / 0.037, 16.1 (the first two measured with a prototype).
WING_PITCH_BEATS = 0.25

#: the shoulders' inputs and the tail elevation's (indices into INPUTS)
_WINGS = [i for i, (_, kind, _) in enumerate(INPUTS) if kind == "shoulder"]
_TAIL = [name for name, _, _ in INPUTS].index("tail_elevation")


def _lsq(
    a: np.ndarray, b: float, lo: np.ndarray, hi: np.ndarray, lam: float
) -> tuple[np.ndarray, bool]:
    """``argmin (a u - b)^2 + lam |a|max^2 |u / s|^2`` within [lo, hi] (s the half range;
    the allocation's regularisation), one row ``a``."""
    scale = np.where(hi > lo, (hi - lo) / 2, 1.0)
    sa = a * scale
    reg = math.sqrt(lam) * max(float(np.abs(sa).max()), 1e-12)
    n = len(a)  # [sa; reg I] and [b; 0] (the same numbers as vstack / eye / concatenate)
    a_aug = np.zeros((n + 1, n))
    a_aug[0] = sa
    a_aug[1:].flat[:: n + 1] = reg
    b_aug = np.zeros(n + 1)
    b_aug[0] = b
    x, mask = bounded_lsq(a_aug, b_aug, lo / scale, hi / scale)
    return x * scale, bool(np.any(mask != 0))


def pitch_allocation(
    row: np.ndarray, demand: float, slow: float, lo: np.ndarray, hi: np.ndarray, lam: float
) -> tuple[np.ndarray, float, bool]:
    """(u (every input of :data:`INPUTS`, nonzero on the shoulders' and the tail
    elevation's), the moment missed, whether a bound bound): the shoulders' offsets
    deliver ``slow``, the tail elevation the rest of ``demand`` within its bounds, the
    shoulders what is still missing within the room they have left.  ``row``: the pitch
    row of the Jacobian (table units per rad), ``lo`` / ``hi`` the inputs' bounds; ``lam``
    the allocation's regularisation."""
    u = np.zeros(len(row))
    wings, tail = _WINGS, _TAIL
    w = [c for c in wings if hi[c] > lo[c]]
    active = False
    if w:
        u[w], active = _lsq(row[w], slow, lo[w], hi[w], lam)
    rest = demand - float(row @ u)
    if hi[tail] > lo[tail] and abs(row[tail]) > 1e-12:
        u[tail] = rest / row[tail]
        if not lo[tail] <= u[tail] <= hi[tail]:
            u[tail] = min(max(u[tail], lo[tail]), hi[tail])
            active = True
        rest -= row[tail] * u[tail]
    if w:
        more, act2 = _lsq(row[w], rest, lo[w] - u[w], hi[w] - u[w], lam)
        u[w] += more
        active = active or act2
    return u, abs(demand - float(row @ u)), active


__all__ = ["WING_PITCH_BEATS", "pitch_allocation"]
