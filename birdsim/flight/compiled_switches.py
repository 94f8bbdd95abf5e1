"""Every compiled path's switch in one place: the modules whose ``ENABLED`` flag chooses
their compiled (numba) code over the numpy / Python reference they are tested against
(the compiled step loop, prescription, table lookup, bounded least squares, path curves,
attitude estimate, schedule filters (alone and with the wings' rows), error window, the
attitude loop's allocation, the held-body pose of its Jacobian measurements, a straight flight's per-sample path errors, the schedule's advance
with the steps after it, the path controller's table lookup, the pitch plan's smoothing).
Tests and benchmarks flip them together to fly the reference path."""

from __future__ import annotations

from types import ModuleType

from birdsim.flight import (
    bounded_lsq,
    fast_attitude,
    fast_command,
    fast_errors,
    fast_estimate,
    fast_hold,
    fast_interval,
    fast_loop,
    fast_path,
    fast_prescription,
    fast_schedule,
    fast_smooth,
    fast_window,
    fast_wingbeat,
)
from birdsim.tables import fast_lookup

SWITCHES: tuple[ModuleType, ...] = (
    fast_loop,
    fast_prescription,
    fast_lookup,
    bounded_lsq,
    fast_path,
    fast_estimate,
    fast_schedule,
    fast_window,
    fast_attitude,
    fast_wingbeat,
    fast_hold,
    fast_errors,
    fast_interval,
    fast_command,
    fast_smooth,
)
