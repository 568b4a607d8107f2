"""fgc — a factor-graph compiler.

Write factor graphs in Python (variables on Lie groups, factors as residual functions); fgc derives
Jacobians with sympy, schedules elimination, and emits an accelerator simulator and HLS C++.
"""

from fgc import noise
from fgc.dsl import Factor, FactorType, Graph, Matrix, factor
from fgc.errors import DataError, DerivationError, DslError, FgcError, StructureError
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

__version__ = "0.1.0"

__all__ = [
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
    "noise",
    "vector_type",
]
