"""birdsim: physics-based animation of flapping bird flight (MuJoCo + blade-element aerodynamics)."""

from .aero import Polar, RoboflyPolar, SeedPolar
from .bird import Bird
from .cycle import Cycle, MeanForces, evaluate_cycle
from .errors import BirdsimError, ParameterError, UnknownModelError
from .kinematics import MODELS, get_model
from .tables import LookupTable, load_table

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
