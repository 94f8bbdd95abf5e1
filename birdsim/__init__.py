"""birdsim: physics-based animation of flapping bird flight (MuJoCo + blade-element aerodynamics)."""

# first, before numpy loads OpenBLAS: its kernels pinned (birdsim/blas_kernel.py)
import birdsim.blas_kernel  # noqa: F401  isort: skip

# then, before any kernel compiles or loads: numba's cache keyed by the sources
import birdsim.numba_cache  # noqa: F401  isort: skip
from birdsim.errors import BirdsimError, ParameterError, UnknownModelError
from birdsim.physics.aero import Polar, RoboflyPolar, SeedPolar
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import Cycle, MeanForces, evaluate_cycle
from birdsim.physics.kinematics import MODELS, get_model
from birdsim.tables.lookup import LookupTable, load_table

__version__ = "0.1.0"

__all__ = [
    "Bird",
    "BirdsimError",
    "Cycle",
    "MODELS",
    "MeanForces",
    "ParameterError",
    "Polar",
    "RoboflyPolar",
    "SeedPolar",
    "UnknownModelError",
    "evaluate_cycle",
    "get_model",
    "load_table",
    "LookupTable",
]
