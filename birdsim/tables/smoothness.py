"""How smooth a table is: zig-zags and jumps of the wingbeat parameters between
neighbouring reachable cells.

A *zig-zag* is a triple of consecutive reachable (status ``ok``) cells along one axis
where some parameter goes out and back: the middle cell lies more than
:data:`ZIGZAG_RAD` (0.15 rad) away from BOTH neighbours, on the same side.  Such
triples are near-ties in a flat cost, not physics: a demand that moves smoothly
through the table makes the wingbeat wobble.  The *zig-zag share* is the fraction of
reachable triples, over every axis, that zig-zag in at least one parameter.

A parameter with no effect in a cell is skipped wherever it has none: the lag of an
idle wrist (amplitude below :data:`IDLE_WRIST_RAD`) changes nothing, so a triple in
which any of the three cells has an idle wrist ignores the lag.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

#: Out-and-back excursion (rad) of the middle cell of a triple that counts as a zig-zag.
ZIGZAG_RAD = 0.15
#: Wrist amplitude (rad) below which the wrist lag has no effect worth a parameter jump
#: (the lag's effect on the force scales with the amplitude).
IDLE_WRIST_RAD = 1e-3


def effect_mask(param_names: tuple[str, ...], params: np.ndarray) -> np.ndarray:
    """True where a parameter has an effect in a cell (same shape as ``params``):
    everything except the wrist lag of an idle wrist and the phase of an idle fold (m5).

    Args:
        param_names: the model's parameter names (last axis of ``params``).
        params: grid shape x d, radians.
    Returns:
        Boolean array of ``params``' shape.
    """
    mask = np.ones(params.shape, dtype=bool)
    if "wrist_amp" in param_names and "wrist_lag" in param_names:
        idle = params[..., param_names.index("wrist_amp")] < IDLE_WRIST_RAD
        mask[..., param_names.index("wrist_lag")] = ~idle
    if "fold_phase" in param_names:  # m5: the phase of an idle fold has no effect
        idle = (params[..., param_names.index("fold_amp")] < IDLE_WRIST_RAD) & (
            params[..., param_names.index("supination_amp")] < IDLE_WRIST_RAD
        )
        mask[..., param_names.index("fold_phase")] = ~idle
    return mask


def _shift(a: np.ndarray, axis: int, lo: int, hi: int | None) -> np.ndarray:
    index = [slice(None)] * a.ndim
    index[axis] = slice(lo, hi)
    return a[tuple(index)]


def zigzags(
    param_names: tuple[str, ...],
    params: np.ndarray,
    ok: np.ndarray,
    axis: int,
    threshold: float = ZIGZAG_RAD,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The triples along ``axis`` (indexed by their middle cell).

    Returns:
        (reachable: all three cells ok, grid shape minus 2 along ``axis``;
        zig: reachable and zig-zagging in some parameter, same shape;
        size: per triple and parameter, min(|x_m - x_a|, |x_m - x_b|) where the middle
        goes out and back (0 elsewhere and for parameters without effect), shape + (d,)).
    """
    n = params.shape[axis]
    if n < 3:
        shape = list(ok.shape)
        shape[axis] = 0
        empty = np.zeros(shape, dtype=bool)
        return empty, empty, np.zeros(tuple(shape) + (params.shape[-1],))
    a, m, b = (_shift(params, axis, s, n - 2 + s) for s in (0, 1, 2))
    eff = effect_mask(param_names, params)
    both = _shift(eff, axis, 0, n - 2) & _shift(eff, axis, 1, n - 1) & _shift(eff, axis, 2, n)
    reachable = _shift(ok, axis, 0, n - 2) & _shift(ok, axis, 1, n - 1) & _shift(ok, axis, 2, n)
    da, db = m - a, m - b
    out_and_back = (np.sign(da) == np.sign(db)) & (da != 0)
    size = np.where(
        out_and_back & both & reachable[..., None], np.minimum(np.abs(da), np.abs(db)), 0.0
    )
    zig = np.any(size > threshold, axis=-1)
    return reachable, zig, size


@dataclass(frozen=True)
class Smoothness:
    """The smoothness of one table (see the module docstring)."""

    zigzag_share: float  # zig-zag triples / reachable triples, all axes
    triples: int  # reachable triples, all axes
    zigzag_triples: int
    per_axis: dict[str, float]  # zig-zag share along each axis
    largest_jump: dict[
        str, float
    ]  # per parameter: largest |step| (rad) between reachable neighbours
    worst: list[dict[str, Any]] = field(
        default_factory=list
    )  # the largest zig-zags: where and how big

    def to_dict(self) -> dict[str, Any]:
        return {
            "zigzag_share": self.zigzag_share,
            "zigzag_rad": ZIGZAG_RAD,
            "triples": self.triples,
            "zigzag_triples": self.zigzag_triples,
            "per_axis": self.per_axis,
            "largest_jump": self.largest_jump,
            "worst": self.worst,
        }


def measure(
    param_names: tuple[str, ...],
    axes: dict[str, np.ndarray],
    params: np.ndarray,
    ok: np.ndarray,
    worst: int = 5,
    threshold: float = ZIGZAG_RAD,
) -> Smoothness:
    """Zig-zag share, largest jumps and the worst zig-zags of a table's parameters.

    Args:
        param_names: parameter names (last axis of ``params``).
        axes: the grid axes in array order ({name: values}).
        params: grid shape x d, radians.
        ok: grid shape, True where the cell is reachable.
        worst: how many of the largest zig-zags to list.
        threshold: the out-and-back excursion (rad) that counts.
    Returns:
        A :class:`Smoothness`.
    """
    names = list(axes)
    eff = effect_mask(param_names, params)
    triples = zig_count = 0
    per_axis: dict[str, float] = {}
    jumps = np.zeros(len(param_names))
    found: list[tuple[float, str, str, tuple[int, ...]]] = []
    for k, axis_name in enumerate(names):
        reachable, zig, size = zigzags(param_names, params, ok, k, threshold)
        triples += int(reachable.sum())
        zig_count += int(zig.sum())
        per_axis[axis_name] = float(zig.sum() / reachable.sum()) if reachable.sum() else 0.0
        n = params.shape[k]
        step = np.abs(_shift(params, k, 1, n) - _shift(params, k, 0, n - 1))
        pair = (
            (_shift(ok, k, 1, n) & _shift(ok, k, 0, n - 1))[..., None]
            & _shift(eff, k, 1, n)
            & _shift(eff, k, 0, n - 1)
        )
        if pair.any():
            jumps = np.maximum(
                jumps, np.where(pair, step, 0.0).reshape(-1, len(param_names)).max(axis=0)
            )
        for idx in np.argwhere(zig):
            p = int(np.argmax(size[tuple(idx)]))
            middle = tuple(int(i) for i in idx)
            middle = middle[:k] + (middle[k] + 1,) + middle[k + 1 :]
            found.append((float(size[tuple(idx)][p]), axis_name, param_names[p], middle))
    found.sort(key=lambda f: (-f[0], f[1], f[3]))
    listed = [
        {"size_rad": round(s, 4), "axis": a, "param": p, "cell": list(c)}
        | {n: float(axes[n][c[i]]) for i, n in enumerate(names)}
        for s, a, p, c in found[:worst]
    ]
    return Smoothness(
        zigzag_share=float(zig_count / triples) if triples else 0.0,
        triples=triples,
        zigzag_triples=zig_count,
        per_axis=per_axis,
        largest_jump={n: float(j) for n, j in zip(param_names, jumps)},
        worst=listed,
    )


def table_smoothness(table: Any, worst: int = 5) -> Smoothness:
    """:func:`measure` of a :class:`~birdsim.tables.lookup.LookupTable`."""
    return measure(
        tuple(table.param_names),
        dict(table.axes),
        np.asarray(table.params),
        table.status == "ok",
        worst,
    )
