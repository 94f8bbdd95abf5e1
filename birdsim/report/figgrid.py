"""Mean forces of a whole grid of wingbeats in one batched ``evaluate_cycle`` call
(chunked to bound memory): what every map and landscape of the report is drawn from."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle

CHUNK = 8192


@dataclass(frozen=True)
class GridMeans:
    """Mean forces and power over a grid of parameter sets (arrays of the grid shape).

    ``Fx`` includes the body drag (dissertation force); ``P`` is the mean mechanical
    power of the right wing."""

    Fx: np.ndarray
    Fz: np.ndarray
    P: np.ndarray


def grid_means(
    model: str,
    params: Mapping[str, np.ndarray | float],
    speed: np.ndarray | float,
    *,
    bird: Bird | None = None,
    n: int = 32,
    check_bounds: bool = False,
) -> GridMeans:
    """Batched cycle means of every parameter set of a broadcastable grid.

    The grid is flattened and evaluated in chunks of :data:`CHUNK` sets, each one
    vectorised ``evaluate_cycle`` call.
    """
    arrays = {k: np.asarray(v, dtype=float) for k, v in params.items()}
    v = np.asarray(speed, dtype=float)
    shape = np.broadcast_shapes(v.shape, *(a.shape for a in arrays.values()))
    flat = {k: np.broadcast_to(a, shape).reshape(-1) for k, a in arrays.items()}
    vf = np.broadcast_to(v, shape).reshape(-1)
    size = vf.size
    fx, fz, p = np.empty(size), np.empty(size), np.empty(size)
    for lo in range(0, size, CHUNK):
        hi = min(lo + CHUNK, size)
        cyc = evaluate_cycle(
            model,
            {k: a[lo:hi] for k, a in flat.items()},
            vf[lo:hi],
            bird=bird,
            n=n,
            check_bounds=check_bounds,
        )
        m = cyc.mean
        fx[lo:hi], fz[lo:hi], p[lo:hi] = m.Fx, m.Fz, m.P
    return GridMeans(fx.reshape(shape), fz.reshape(shape), p.reshape(shape))


def mesh(axes: Sequence[np.ndarray]) -> list[np.ndarray]:
    """Open-mesh views (``np.ix_``) of 1-D axes: arrays that broadcast to the full grid."""
    return list(np.ix_(*[np.asarray(a, dtype=float) for a in axes]))
