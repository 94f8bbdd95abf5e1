"""What a flight returns (:func:`birdsim.flight.freeflight.fly`): its per-sample arrays
in reduced units and what produced them."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from birdsim.flight.controller import Gains
from birdsim.physics.bird import Bird


@dataclass
class FlightResult:
    """Per log sample arrays (reduced units) and what produced them."""

    arrays: dict[str, np.ndarray]
    bird: Bird
    model: str
    param_names: tuple[str, ...]
    gains: Gains
    open_loop: bool
    projection_max: float
    meta: dict[str, Any] = field(default_factory=dict)


__all__ = ["FlightResult"]
