"""The result of one wingbeat evaluation: :class:`Cycle` (histories and means of the
right wing), :class:`MeanForces` and :class:`PanelMeans` (what the fused kernel
returns), and the cycle mean.  Built by :func:`birdsim.physics.cycle.evaluate_cycle`.

Forces follow docs/design.md's "which force": the histories are those of ONE wing (the
right) in seed earth axes; ``mean`` adds the body drag (X and, when climbing, Z) to the
wing's mean; ``whole_bird_mean`` is two mirrored wings plus the body.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np


@dataclass(frozen=True)
class _Histories:
    force_earth: np.ndarray  # B x K x N x 3
    power: np.ndarray  # B x K x N
    joint_power: dict[str, np.ndarray]  # group -> B x N
    cp_position: np.ndarray  # B x K x N x 3
    cp_velocity: np.ndarray  # B x K x N x 3


@dataclass(frozen=True)
class MeanForces:
    """Cycle means (arrays of the batch shape).  Fx includes the body drag."""

    Fx: np.ndarray
    Fy: np.ndarray
    Fz: np.ndarray
    P: np.ndarray

    def as_dict(self) -> dict[str, float]:
        return {k: float(getattr(self, k)) for k in ("Fx", "Fy", "Fz", "P")}


@dataclass(frozen=True)
class PanelMeans:
    """Cycle means per panel, as a fused kernel returns them (no histories)."""

    force_earth: np.ndarray  # B x K x 3, seed earth axes, no body drag
    power: np.ndarray  # B x K
    joint_power: dict[str, np.ndarray]  # group -> B


@dataclass(frozen=True)
class Cycle:
    """Histories over one wingbeat (N samples) of the right wing, per panel and in total.

    Shapes: ``B`` is the batch shape of the parameters, N the samples, K the panels.
    The histories are computed on first access (by the numpy reference path) when the
    means came from the fused kernel; the means never need them.
    """

    model: str
    speed: np.ndarray  # B
    params: dict[str, np.ndarray]  # each B
    time: np.ndarray  # N
    endpoint: bool
    panel_names: tuple[str, ...]
    body_drag_x: np.ndarray = field(repr=False)  # B, seed earth X
    climb: np.ndarray = field(repr=False)  # B, vertical speed relative to the air, up
    body_drag_z: np.ndarray = field(repr=False)  # B, seed earth Z (0 at climb = 0)
    histories: Callable[[], "_Histories"] = field(repr=False, compare=False)
    panel_means: PanelMeans | None = field(default=None, repr=False, compare=False)

    @cached_property
    def _hist(self) -> "_Histories":
        return self.histories()

    @property
    def panel_force_earth(self) -> np.ndarray:
        """B x K x N x 3, seed earth axes (no body drag)."""
        return self._hist.force_earth

    @property
    def panel_power(self) -> np.ndarray:
        """B x K x N, -F . v_flap (positive: the wing works on the air)."""
        return self._hist.power

    @property
    def joint_power(self) -> dict[str, np.ndarray]:
        """Group (shoulder, wrist) -> B x N power history."""
        return self._hist.joint_power

    @property
    def cp_position_body(self) -> np.ndarray:
        """B x K x N x 3 (first strip element), body axes."""
        return self._hist.cp_position

    @property
    def cp_velocity_body(self) -> np.ndarray:
        """B x K x N x 3 flapping velocity, body axes."""
        return self._hist.cp_velocity

    @cached_property
    def joint_power_mean(self) -> dict[str, np.ndarray]:
        """Group -> cycle-mean power (B)."""
        if self.panel_means is not None:
            return self.panel_means.joint_power
        return {g: cycle_mean(v, axis=-1) for g, v in self.joint_power.items()}

    @property
    def force_earth(self) -> np.ndarray:
        """Right-wing force history, B x N x 3 (no body drag)."""
        return self.panel_force_earth.sum(axis=-3)

    @property
    def power(self) -> np.ndarray:
        """Mechanical power history of the right wing, B x N."""
        return self.panel_power.sum(axis=-2)

    @property
    def Fx(self) -> np.ndarray:
        return self.force_earth[..., 0]

    @property
    def Fy(self) -> np.ndarray:
        return self.force_earth[..., 1]

    @property
    def Fz(self) -> np.ndarray:
        return self.force_earth[..., 2]

    @property
    def P(self) -> np.ndarray:
        return self.power

    @cached_property
    def mean(self) -> MeanForces:
        """The dissertation's force: right wing + body drag; mean power of the right wing."""
        f, p = self._wing_mean
        return MeanForces(f[..., 0] + self.body_drag_x, f[..., 1], f[..., 2] + self.body_drag_z, p)

    @cached_property
    def _wing_mean(self) -> tuple[np.ndarray, np.ndarray]:
        """Right-wing mean force (B x 3, no body drag) and power (B)."""
        if self.panel_means is not None:
            return self.panel_means.force_earth.sum(axis=-2), self.panel_means.power.sum(axis=-1)
        return cycle_mean(self.force_earth, axis=-2), cycle_mean(self.power, axis=-1)

    @cached_property
    def panel_mean(self) -> dict[str, MeanForces]:
        """Per-panel means (no body drag)."""
        if self.panel_means is not None:
            f, p = self.panel_means.force_earth, self.panel_means.power
        else:
            f = cycle_mean(self.panel_force_earth, axis=-2)
            p = cycle_mean(self.panel_power, axis=-1)
        return {
            name: MeanForces(f[..., k, 0], f[..., k, 1], f[..., k, 2], p[..., k])
            for k, name in enumerate(self.panel_names)
        }

    @cached_property
    def whole_bird_mean(self) -> MeanForces:
        """Two mirrored wings plus body drag: ``(2 Fx_wing + Dx, 0, 2 Fz_wing + Dz)``, power 2 P."""
        m = self.mean
        wing_x = m.Fx - self.body_drag_x  # exactly today's arithmetic at climb = 0
        wing_z = self._wing_mean[0][..., 2]
        return MeanForces(
            2.0 * wing_x + self.body_drag_x,
            np.zeros_like(m.Fy),
            2.0 * wing_z + self.body_drag_z,
            2.0 * m.P,
        )


def cycle_mean(x: np.ndarray, axis: int = -1) -> np.ndarray:
    """Mean over the time axis: the plain mean of the samples.  On the periodic grid
    (N samples on [0, T)) this is the exact periodic (trapezoidal) mean; on the
    appendix grid (t = 0 and t = T both sampled) it counts the end point twice,
    exactly as the dissertation's ``mean`` over ``0:dt:T``."""
    return np.mean(x, axis=axis)
