"""Vector-space types: points, velocities, IMU biases and fixed-size vectors."""

from __future__ import annotations

from functools import cache

from fgc.frontend.geometry.base import VectorSpace, as_vector, column, is_symbolic, segment


class Point2(VectorSpace):
    """A 2-D point (GTSAM ``Point2``); tangent ``[x, y]``."""

    dim = storage_dim = 2
    storage_names = ("x", "y")

    def x(self):
        return self.v[0]

    def y(self):
        return self.v[1]


class Point3(VectorSpace):
    """A 3-D point (GTSAM ``Point3``); tangent ``[x, y, z]``."""

    dim = storage_dim = 3
    storage_names = ("x", "y", "z")

    def x(self):
        return self.v[0]

    def y(self):
        return self.v[1]

    def z(self):
        return self.v[2]

    def cross(self, other):
        a, b = self.v, as_vector(other, 3)
        vals = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
        return Point3(column(vals, is_symbolic(*vals)))


@cache
def vector_type(n: int) -> type[VectorSpace]:
    """The class of n-vectors (``Vector3`` for velocities, ...); one class per size."""
    if n < 1:
        raise ValueError(f"vector size must be positive, got {n}")
    names = tuple(f"v{i}" for i in range(n))
    return type(f"Vector{n}", (VectorSpace,), {"dim": n, "storage_dim": n, "storage_names": names})


Vector1 = vector_type(1)
Vector2 = vector_type(2)
Vector3 = vector_type(3)
Vector6 = vector_type(6)
Vector9 = vector_type(9)


class ImuBias(VectorSpace):
    """Constant IMU bias ``[acc (3), gyro (3)]`` (GTSAM ``imuBias.ConstantBias``)."""

    dim = storage_dim = 6
    storage_names = ("ax", "ay", "az", "gx", "gy", "gz")

    def accelerometer(self):
        return segment(self.v, 0, 3)

    def gyroscope(self):
        return segment(self.v, 3, 6)
