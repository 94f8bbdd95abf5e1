"""The numbers behind the report's figures (pure numpy, no matplotlib).

Every function here evaluates the physics core (``evaluate_cycle``) on a whole grid of
parameter sets in one batched call (chunked to bound memory), or reads the polar
directly.  ``birdsim/report/plots.py`` draws these arrays; ``birdsim/report/claims.py`` compares
them with what the dissertation printed.  Forces are the dissertation's force (right
wing + body drag, seed earth axes, Fz < 0 is up) unless a name says otherwise.

The numbers live in :mod:`figgrid` (grid means), :mod:`figwing` (thrust, wrist, paths)
and :mod:`figsearch` (landscapes, speed sweeps, optimisers); this module gathers them
(the figure families read them as ``fd.NAME``).
"""

from __future__ import annotations

from birdsim.report.figgrid import CHUNK, GridMeans, grid_means, mesh
from birdsim.report.figsearch import (
    CostFunction,
    Landscape,
    OptimiserRun,
    SpeedSweep,
    landscape,
    optimiser_run,
    speed_sweep,
    test_function_f,
    test_function_g,
)
from birdsim.report.figwing import (
    WRIST_STUDY,
    ControlPointPaths,
    WristOptimum,
    control_point_paths,
    thrust_coefficient,
    wrist_activity,
    wrist_optimum,
    wrist_upward_force,
)

__all__ = [
    "CHUNK",
    "WRIST_STUDY",
    "ControlPointPaths",
    "CostFunction",
    "GridMeans",
    "Landscape",
    "OptimiserRun",
    "SpeedSweep",
    "WristOptimum",
    "control_point_paths",
    "grid_means",
    "landscape",
    "mesh",
    "optimiser_run",
    "speed_sweep",
    "test_function_f",
    "test_function_g",
    "thrust_coefficient",
    "wrist_activity",
    "wrist_optimum",
    "wrist_upward_force",
]
