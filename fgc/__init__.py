"""fgc — a factor-graph compiler.

Write factor graphs in Python (variables on Lie groups, factors as residual functions); fgc derives
Jacobians with sympy, schedules elimination, and emits an accelerator simulator and HLS C++.
"""

from fgc.app.solve import solve, verify
from fgc.errors import DataError, DerivationError, DslError, FgcError, StructureError
from fgc.frontend import noise
from fgc.frontend.dsl import Factor, FactorType, Graph, Matrix, factor
from fgc.frontend.functions import (
    acos,
    asin,
    atan,
    atan2,
    cos,
    exp,
    hypot,
    log,
    sin,
    sqrt,
    tan,
    tanh,
)
from fgc.frontend.geometry import (
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
from fgc.version import __version__  # noqa: F401  (one home: fgc/version.py)

# The front end's modules keep their public names: a user writes ``from fgc.factors import
# PriorFactor`` or ``from fgc.geometry import Pose3`` (as the examples do), whatever folder the
# module lives in. This table is the only place those names exist; fgc's own code imports the
# real paths (tests/test_layout.py checks it).
PUBLIC_MODULES = {
    "geometry": "fgc.frontend.geometry",
    "factors": "fgc.frontend.factors",
    "noise": "fgc.frontend.noise",
    "preintegration": "fgc.frontend.preintegration",
    "data": "fgc.interop.gtsam_data",
    "io": "fgc.interop.datasets",
    "metrics": "fgc.app.metrics",
}


def _public_modules() -> None:
    import importlib
    import sys

    for name, path in PUBLIC_MODULES.items():
        module = importlib.import_module(path)
        sys.modules[f"{__name__}.{name}"] = module
        globals()[name] = module


_public_modules()



def stream(graph, window=None, incremental=None, batch_every=None, solver=None):
    """Feed a chain's keyframes one at a time to the simulator (fixed-lag ``window`` or
    ``incremental`` K) and yield each keyframe's result (:func:`fgc.app.streaming.stream`)."""
    from fgc.app.streaming import stream as _stream

    return _stream(graph, window, incremental, batch_every, solver)


def from_gtsam(graph, values, key_names=None):
    """Convert a ``gtsam.NonlinearFactorGraph`` + ``gtsam.Values`` into an fgc Graph
    (see :func:`fgc.interop.from_gtsam.from_gtsam`; gtsam is imported only when this is called)."""
    from fgc.interop.from_gtsam import from_gtsam as _from_gtsam

    return _from_gtsam(graph, values, key_names)


def to_gtsam_values(values, keys=None):
    """fgc values {key: value} as a ``gtsam.Values`` under the same keys (an int stays that int,
    ``"x1"`` becomes ``gtsam.Symbol('x', 1)``; see
    :func:`fgc.interop.to_gtsam.values_to_gtsam`). A solve's result has ``.gtsam_values()``."""
    from fgc.interop.to_gtsam import values_to_gtsam

    return values_to_gtsam(values, keys)


__all__ = [
    "to_gtsam_values",
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
