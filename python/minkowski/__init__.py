"""Minkowski for Python: a 2D rigid-body physics engine with numpy in and out.

Worlds, bodies, every shape and joint kind, filters, sensors, events as structured arrays,
queries, scene files, batch arrays of body states, frames rendered headless as arrays, and
parameter sweeps on a Dask cluster. See docs/python.md.
"""

from minkowski._minkowski import *  # noqa: F401,F403
from minkowski._minkowski import (  # noqa: F401
    Error,
    InvalidArgumentError,
    SceneFileError,
    NonFiniteInputError,
    DegenerateInputError,
    StaleIdError,
    OutputError,
    GlContextError,
)

__version__ = "0.1.0"

from minkowski.sweeps import sweep  # noqa: E402,F401
