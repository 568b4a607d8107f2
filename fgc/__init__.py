"""fgc — a factor-graph compiler.

Write factor graphs in Python (variables on Lie groups, factors as residual functions); fgc derives
Jacobians with sympy, schedules elimination, and emits an accelerator simulator and HLS C++.
"""

# The one-call API fgc.solve / fgc.verify (imported last, below) shares its names with the
# modules fgc/solve.py and fgc/verify.py. Both modules are loaded here, before the names are
# bound to the functions, so that a later ``from fgc.verify import ...`` finds the module loaded
# and does not rebind ``fgc.verify`` to it. Reach module contents with ``from fgc.verify import``.
import fgc.verify as _verify_module  # noqa: F401
from fgc import noise
from fgc.dsl import Factor, FactorType, Graph, Matrix, factor
from fgc.errors import DataError, DerivationError, DslError, FgcError, StructureError
from fgc.functions import acos, asin, atan, atan2, cos, exp, hypot, log, sin, sqrt, tan, tanh
from fgc.geometry import (
    ImuBias,
    Point2,
    Point3,
    Pose2,
    Pose3,
    Rot2,
    Rot3,
    Vector1,
    Vector2,
    Vector3,
    Vector6,
    Vector9,
    vector_type,
)
from fgc.solve import solve, verify  # the functions (see the comment above)

__version__ = "0.1.0"


def stream(graph, window=None, incremental=None, batch_every=None, solver=None):
    """Feed a chain's keyframes one at a time to the simulator (fixed-lag ``window`` or
    ``incremental`` K) and yield each keyframe's result (:func:`fgc.streaming.stream`)."""
    from fgc.streaming import stream as _stream

    return _stream(graph, window, incremental, batch_every, solver)


def from_gtsam(graph, values, key_names=None):
    """Convert a ``gtsam.NonlinearFactorGraph`` + ``gtsam.Values`` into an fgc Graph
    (see :func:`fgc.importer.from_gtsam`; gtsam is imported only when this is called)."""
    from fgc.importer import from_gtsam as _from_gtsam

    return _from_gtsam(graph, values, key_names)


__all__ = [
    "stream",
    "acos",
    "asin",
    "atan",
    "atan2",
    "cos",
    "exp",
    "hypot",
    "log",
    "sin",
    "sqrt",
    "tan",
    "tanh",
    "DataError",
    "DerivationError",
    "DslError",
    "Factor",
    "FactorType",
    "FgcError",
    "Graph",
    "ImuBias",
    "Matrix",
    "Point2",
    "Point3",
    "Pose2",
    "Pose3",
    "Rot2",
    "Rot3",
    "StructureError",
    "Vector1",
    "Vector2",
    "Vector3",
    "Vector6",
    "Vector9",
    "factor",
    "from_gtsam",
    "noise",
    "solve",
    "vector_type",
    "verify",
]
