"""Lie-group value types (numeric and symbolic) with GTSAM 4.3 conventions."""

from fgc.frontend.geometry.base import LieGroup, VectorSpace
from fgc.frontend.geometry.groups import Pose2, Pose3, Rot2, Rot3
from fgc.frontend.geometry.vectors import (
    ImuBias,
    Point2,
    Point3,
    Vector1,
    Vector2,
    Vector3,
    Vector6,
    Vector9,
    vector_type,
)

__all__ = [
    "ImuBias",
    "LieGroup",
    "Point2",
    "Point3",
    "Pose2",
    "Pose3",
    "Rot2",
    "Rot3",
    "Vector1",
    "Vector2",
    "Vector3",
    "Vector6",
    "Vector9",
    "VectorSpace",
    "vector_type",
]
