"""Lie-group value types (numeric and symbolic) with GTSAM 4.3 conventions, and the one
registry of them by name (:func:`type_named`): the Program stores a variable's type by name and
every backend and reader turns it back into its class here."""

import re

from fgc.errors import FgcError
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

# the named types; VectorN exists for every N ≥ 1 (vector_type)
TYPES: dict[str, type[LieGroup]] = {t.__name__: t for t in (
    Pose2, Pose3, Rot2, Rot3, Point2, Point3, ImuBias, Vector1, Vector2, Vector3, Vector6, Vector9)}
_VECTOR = re.compile(r"Vector([1-9][0-9]{0,3})")


class UnknownTypeError(FgcError):
    """A type name (from a Program, a result file or a table) that names no fgc value type."""


def type_named(name: str, dim: int | None = None) -> type[LieGroup]:
    """The value type called ``name`` (``VectorN`` for any N); with ``dim``, also checked to have
    that tangent dimension. Raises :class:`UnknownTypeError` naming the type otherwise."""
    match = _VECTOR.fullmatch(name)
    cls = vector_type(int(match.group(1))) if match else TYPES.get(name)
    if cls is None:
        raise UnknownTypeError(f"no fgc value type {name!r}; known: {', '.join(TYPES)}, VectorN")
    if dim is not None and cls.dim != dim:
        raise UnknownTypeError(f"fgc value type {name!r} has dimension {cls.dim}, not {dim}")
    return cls


__all__ = [
    "TYPES",
    "UnknownTypeError",
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
    "type_named",
    "vector_type",
]
