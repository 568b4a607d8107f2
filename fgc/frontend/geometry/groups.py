"""Rotation and pose groups with GTSAM 4.3 conventions, numeric or symbolic.

Tangent orders: Rot2 ``[θ]``, Pose2 ``[vx, vy, ω]`` (GTSAM's), Rot3 ``[ω]``, Pose3 ``[ω, v]``.
``retract`` is the full Expmap for every type, ``local(a, b) = Logmap(a⁻¹ b)``.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from fgc.errors import DataError
from fgc.frontend.geometry import special
from fgc.frontend.geometry.base import (
    LieGroup,
    as_vector,
    atan2,
    coeff,
    column,
    cos,
    dot,
    eye,
    hat3,
    is_symbolic,
    matrix,
    segment,
    sin,
    so3_exp,
    so3_log,
)
from fgc.frontend.geometry.vectors import Point2, Point3


def _point_vector(p, n: int):
    return p.v if isinstance(p, (Point2, Point3)) else as_vector(p, n)


class Rot2(LieGroup):
    """Planar rotation stored as ``(cos θ, sin θ)``."""

    dim = 1
    storage_dim = 2
    storage_names = ("c", "s")

    def __init__(self, c, s):
        self.c, self.s = c, s

    @classmethod
    def fromAngle(cls, theta):  # noqa: N802 - GTSAM's name
        return cls(cos(theta), sin(theta))

    def theta(self):
        return atan2(self.s, self.c)

    def matrix(self):
        return matrix([[self.c, -self.s], [self.s, self.c]], is_symbolic(self.c, self.s))

    def to_storage(self) -> list:
        return [self.c, self.s]

    @classmethod
    def from_storage(cls, values):
        c, s = values
        return cls(c, s)

    @classmethod
    def identity(cls):
        return cls(1.0, 0.0)

    def compose(self, other):
        return Rot2(self.c * other.c - self.s * other.s, self.s * other.c + self.c * other.s)

    def inverse(self):
        return Rot2(self.c, -self.s)

    @classmethod
    def Expmap(cls, v):  # noqa: N802
        return cls.fromAngle(as_vector(v, 1)[0])

    @classmethod
    def Logmap(cls, x):  # noqa: N802
        return column([x.theta()], x.symbolic)

    def rotate(self, p):
        v = _point_vector(p, 2)
        return Point2(self.matrix() @ v)

    def unrotate(self, p):
        v = _point_vector(p, 2)
        return Point2(self.matrix().T @ v)


class Pose2(LieGroup):
    """SE(2) pose: rotation ``r`` and translation ``t``; storage ``[x, y, c, s]``."""

    dim = 3
    storage_dim = 4
    storage_names = ("x", "y", "c", "s")

    def __init__(self, x, y=None, theta=None, *, r: Rot2 | None = None):
        if r is not None:
            self.t, self.r = as_vector(x, 2), r
        else:
            self.t = as_vector([x, y], 2)
            self.r = Rot2.fromAngle(theta)

    def to_storage(self) -> list:
        return [*self.t, self.r.c, self.r.s]

    @classmethod
    def from_storage(cls, values):
        x, y, c, s = values
        return cls(as_vector([x, y], 2), r=Rot2(c, s))

    @classmethod
    def identity(cls):
        return cls(0.0, 0.0, 0.0)

    @classmethod
    def random(cls, rng: np.random.Generator, scale: float = 1.0):
        return cls(*(rng.normal(size=2) * scale), rng.uniform(-np.pi, np.pi))

    def x(self):
        return self.t[0]

    def y(self):
        return self.t[1]

    def theta(self):
        return self.r.theta()

    def rotation(self) -> Rot2:
        return self.r

    def translation(self) -> Point2:
        return Point2(self.t)

    def compose(self, other):
        return Pose2(self.t + self.r.matrix() @ other.t, r=self.r.compose(other.r))

    def inverse(self):
        rinv = self.r.inverse()
        return Pose2(-(rinv.matrix() @ self.t), r=rinv)

    @classmethod
    def Expmap(cls, v):  # noqa: N802
        v = as_vector(v, 3)
        w = v[2]
        a, wb = coeff("A", w * w), w * coeff("B", w * w)
        t = matrix([[a, -wb], [wb, a]], is_symbolic(*v)) @ segment(v, 0, 2)
        return cls(t, r=Rot2.fromAngle(w))

    @classmethod
    def Logmap(cls, x):  # noqa: N802
        w = x.theta()
        a, wb = coeff("A", w * w), w * coeff("B", w * w)
        det = a * a + wb * wb
        vinv = matrix([[a, wb], [-wb, a]], x.symbolic) / det
        uv = vinv @ x.t
        return column([uv[0], uv[1], w], x.symbolic)

    def transformFrom(self, p):  # noqa: N802 - GTSAM's name
        return Point2(self.t + self.r.matrix() @ _point_vector(p, 2))

    def transformTo(self, p):  # noqa: N802 - GTSAM's name
        return Point2(self.r.matrix().T @ (_point_vector(p, 2) - self.t))

    def bearing(self, p) -> Rot2:
        """Bearing to a point in this pose's frame, as a Rot2 (GTSAM ``Pose2.bearing``)."""
        d = self.transformTo(p).v
        return Rot2(*special.relative_bearing(d[0], d[1]))

    def range(self, p):
        """Distance to a point (GTSAM ``Pose2.range``: its norm's Jacobian at coincident points,
        :class:`~fgc.frontend.geometry.special.VectorNorm`)."""
        d = _point_vector(p, 2) - self.t
        return special.VectorNorm(d[0], d[1]) if is_symbolic(*d) else float(np.sqrt(d @ d))


class Rot3(LieGroup):
    """SO(3) rotation stored as its row-major 3×3 matrix."""

    dim = 3
    storage_dim = 9
    storage_names = tuple(f"R{i}{j}" for i in range(3) for j in range(3))

    def __init__(self, r):
        if isinstance(r, sp.MatrixBase):
            self.R = sp.Matrix(r).reshape(3, 3)
        elif is_symbolic(*np.ravel(np.asarray(r, dtype=object))):
            self.R = sp.Matrix(3, 3, list(np.ravel(np.asarray(r, dtype=object))))
        else:
            arr = np.asarray(r)
            self.R = (arr if arr.dtype.kind == "f" else arr.astype(np.float64)).reshape(3, 3)

    def matrix(self):
        return self.R

    def to_storage(self) -> list:
        return list(self.R) if self.symbolic else list(self.R.reshape(-1))

    @property
    def symbolic(self) -> bool:
        return isinstance(self.R, sp.MatrixBase)

    @classmethod
    def from_storage(cls, values):
        return cls(values if is_symbolic(*values) else np.asarray(values).reshape(3, 3))

    @classmethod
    def identity(cls):
        return cls(np.eye(3))

    @classmethod
    def RzRyRx(cls, x, y, z):  # noqa: N802 - GTSAM's name
        """Rotation from roll x, pitch y, yaw z (GTSAM ``Rot3.RzRyRx``)."""
        rz = so3_exp(as_vector([0.0, 0.0, z], 3))
        ry = so3_exp(as_vector([0.0, y, 0.0], 3))
        rx = so3_exp(as_vector([x, 0.0, 0.0], 3))
        return cls(rz @ ry @ rx)

    def compose(self, other):
        return Rot3(self.R @ other.R)

    def inverse(self):
        return Rot3(self.R.T)

    @classmethod
    def Expmap(cls, v):  # noqa: N802
        return cls(so3_exp(as_vector(v, 3)))

    @classmethod
    def Logmap(cls, x):  # noqa: N802
        return so3_log(x.R)

    @classmethod
    def random(cls, rng: np.random.Generator, scale: float = 1.0):
        """Uniform random axis, angle uniform in [0, π] (``scale`` is ignored)."""
        axis = rng.normal(size=3)
        return cls.Expmap(axis / np.linalg.norm(axis) * rng.uniform(0.0, np.pi))

    def rotate(self, p):
        return Point3(self.R @ _point_vector(p, 3))

    def unrotate(self, p):
        return Point3(self.R.T @ _point_vector(p, 3))


class Pose3(LieGroup):
    """SE(3) pose: rotation ``R`` and translation ``t``; storage ``[R (row-major), t]``."""

    dim = 6
    storage_dim = 12
    storage_names = Rot3.storage_names + ("tx", "ty", "tz")

    def __init__(self, r: Rot3 | None = None, t=None):
        self.r = r if r is not None else Rot3.identity()
        self.t = as_vector(t if t is not None else np.zeros(3), 3)

    def to_storage(self) -> list:
        return [*self.r.to_storage(), *self.t]

    @classmethod
    def from_storage(cls, values):
        values = list(values)
        if len(values) != 12:
            raise DataError(f"Pose3 storage has 12 entries, got {len(values)}")
        return cls(Rot3.from_storage(values[:9]), as_vector(values[9:], 3))

    @classmethod
    def identity(cls):
        return cls()

    def rotation(self) -> Rot3:
        return self.r

    @classmethod
    def random(cls, rng: np.random.Generator, scale: float = 1.0):
        """Uniformly random rotation, translation ~ N(0, scale²)."""
        return cls(Rot3.random(rng), rng.normal(size=3) * scale)

    def translation(self) -> Point3:
        return Point3(self.t)

    def matrix(self):
        out = eye(4, self.symbolic)
        out[0:3, 0:3] = self.r.R
        out[0:3, 3] = self.t
        return out

    def compose(self, other):
        return Pose3(self.r.compose(other.r), self.t + self.r.R @ other.t)

    def inverse(self):
        rt = self.r.R.T
        return Pose3(Rot3(rt), -(rt @ self.t))

    @classmethod
    def Expmap(cls, v):  # noqa: N802
        v = as_vector(v, 6)
        w, u = segment(v, 0, 3), segment(v, 3, 6)
        wx = hat3(w)
        t = dot(w, w)
        jl = eye(3, is_symbolic(*v), _float_dtype(v)) + coeff("B", t) * wx
        jl = jl + coeff("C", t) * (wx @ wx)
        return cls(Rot3(so3_exp(w)), jl @ u)

    @classmethod
    def Logmap(cls, x):  # noqa: N802
        w = so3_log(x.r.R)
        wx = hat3(w)
        t = dot(w, w)
        jl_inv = eye(3, x.symbolic, _float_dtype(x.t)) - wx / 2 + coeff("D", t) * (wx @ wx)
        u = jl_inv @ x.t
        if x.symbolic:
            return sp.Matrix.vstack(w, u)
        return np.concatenate([w, u])

    def transformFrom(self, p):  # noqa: N802 - GTSAM's name
        return Point3(self.t + self.r.R @ _point_vector(p, 3))

    def transformTo(self, p):  # noqa: N802 - GTSAM's name
        return Point3(self.r.R.T @ (_point_vector(p, 3) - self.t))

    def range(self, p):
        """Distance to a point (GTSAM ``Pose3.range``: the norm of the world-frame difference,
        with norm3's all-ones Jacobian at coincident points,
        :class:`~fgc.frontend.geometry.special.VectorNorm`)."""
        d = _point_vector(p, 3) - self.t
        return special.VectorNorm(*d) if is_symbolic(*d) else float(np.sqrt(d @ d))


def _float_dtype(v):
    return np.float64 if isinstance(v, sp.MatrixBase) else v.dtype
