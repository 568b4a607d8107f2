"""Shared machinery of the geometry types: one implementation for numbers and for symbols.

Every type stores its *storage* — a short tuple of scalars (a rotation matrix's nine entries, a
translation) — either as NumPy arrays (numeric values: initial guesses, measurements, results) or as
sympy matrices (symbolic values inside a factor's residual function). The group operations are
written once against the small helpers below, which dispatch on the kind of their arguments.
"""

from __future__ import annotations

from typing import ClassVar

import numpy as np
import sympy as sp

from fgc.errors import DataError
from fgc.frontend.geometry import special

# --------------------------------------------------------------------------------------------
# backend helpers (numbers or symbols)
# --------------------------------------------------------------------------------------------


def is_symbolic(*xs) -> bool:
    """True if any argument is a sympy object (so the result must be symbolic)."""
    return any(isinstance(x, (sp.Basic, sp.MatrixBase)) for x in xs)


def column(values, symbolic: bool, dtype=None):
    """A column vector: a sympy ``Matrix(n, 1)`` or a 1-D NumPy array (of ``dtype``, default:
    the entries' float type, so float32 inputs stay float32)."""
    if symbolic:
        return sp.Matrix([sp.sympify(v) for v in values])
    return _float_array(values, dtype).reshape(-1)


def matrix(rows, symbolic: bool, dtype=None):
    if symbolic:
        return sp.Matrix(rows)
    return _float_array(rows, dtype)


def _float_array(values, dtype) -> np.ndarray:
    arr = np.asarray(values)
    if dtype is None:
        dtype = arr.dtype if arr.dtype.kind == "f" else np.float64
    return arr.astype(dtype, copy=False)


def eye(n: int, symbolic: bool, dtype=np.float64):
    return sp.eye(n) if symbolic else np.eye(n, dtype=dtype)


def as_vector(x, n: int | None = None):
    """Normalise a vector argument (list, array, sympy matrix, geometry vector) to the backend."""
    if isinstance(x, VectorSpace):
        x = x.v
    if isinstance(x, sp.MatrixBase):
        x = x.reshape(len(x), 1)
    elif is_symbolic(*np.ravel(np.asarray(x, dtype=object))):
        x = sp.Matrix(list(np.ravel(np.asarray(x, dtype=object))))
    else:
        x = np.asarray(x)
        x = x.astype(np.float64) if x.dtype.kind != "f" else x
        x = x.reshape(-1)
    if n is not None and len(x) != n:
        raise DataError(f"expected a vector of length {n}, got length {len(x)}")
    return x


def segment(v, start: int, stop: int):
    """Entries ``start:stop`` of a vector, as a vector of the same backend."""
    return v[start:stop, :] if isinstance(v, sp.MatrixBase) else v[start:stop]


def dot(a, b):
    if isinstance(a, sp.MatrixBase) or isinstance(b, sp.MatrixBase):
        return (sp.Matrix(a).T * sp.Matrix(b))[0, 0]
    return a @ b


def sqrt(x):
    return sp.sqrt(x) if is_symbolic(x) else np.sqrt(x)


def sin(x):
    return sp.sin(x) if is_symbolic(x) else np.sin(x)


def cos(x):
    return sp.cos(x) if is_symbolic(x) else np.cos(x)


def atan2(y, x):
    return sp.atan2(y, x) if is_symbolic(y, x) else np.arctan2(y, x)


def coeff(name: str, t):
    """Robust Lie coefficient ``name`` at ``t = θ²`` (see :mod:`fgc.frontend.geometry.special`)."""
    if is_symbolic(t):
        return special.COEFFICIENT_FUNCTIONS[name](t)
    return special.coefficient(name, t)


def hat3(w):
    if isinstance(w, sp.MatrixBase):
        return special.hat_sym(w)
    dt = w.dtype
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]], dtype=dt)


def so3_exp(w):
    """Rotation matrix Exp(ω) = I + A·[ω]× + B·[ω]×² with robust A, B."""
    wx = hat3(w)
    t = dot(w, w)
    return eye(3, is_symbolic(wx), _dtype(w)) + coeff("A", t) * wx + coeff("B", t) * (wx @ wx)


def so3_log(r):
    if isinstance(r, sp.MatrixBase):
        return special.so3_log_symbolic(list(r))
    return special.so3_log_numeric(r)


def _dtype(x):
    return np.float64 if isinstance(x, sp.MatrixBase) else x.dtype


def transpose(m):
    return m.T


# --------------------------------------------------------------------------------------------
# base class
# --------------------------------------------------------------------------------------------


class LieGroup:
    """A value on a Lie group (numeric or symbolic) with GTSAM's chart conventions.

    Subclasses define ``dim`` (tangent dimension), ``storage_dim``, ``storage_names``,
    ``to_storage``/``from_storage``, ``compose``, ``inverse``, ``Expmap`` and ``Logmap``.
    ``retract(δ) = self ∘ Exp(δ)`` and ``local(y) = Log(self⁻¹ ∘ y)`` (right perturbation).
    """

    dim: ClassVar[int]
    storage_dim: ClassVar[int]
    storage_names: ClassVar[tuple[str, ...]]

    # -- storage --------------------------------------------------------------------------
    def to_storage(self) -> list:
        raise NotImplementedError

    @classmethod
    def from_storage(cls, values):
        raise NotImplementedError

    @classmethod
    def symbol(cls, prefix: str):
        """A symbolic value whose storage entries are real sympy symbols ``<prefix>__<name>``."""
        return cls.from_storage([sp.Symbol(f"{prefix}__{n}", real=True) for n in cls.storage_names])

    @property
    def symbolic(self) -> bool:
        return is_symbolic(*self.to_storage())

    def storage_array(self, dtype=np.float64) -> np.ndarray:
        if self.symbolic:
            raise DataError(f"{type(self).__name__} value is symbolic, not numeric")
        return np.asarray([float(v) for v in self.to_storage()], dtype=dtype)

    def astype(self, dtype):
        """The same numeric value with storage in ``dtype`` (e.g. ``np.float32``)."""
        return type(self).from_storage(self.storage_array(dtype))

    # -- group ----------------------------------------------------------------------------
    def compose(self, other):
        raise NotImplementedError

    def inverse(self):
        raise NotImplementedError

    @classmethod
    def identity(cls):
        raise NotImplementedError

    @classmethod
    def Expmap(cls, v):  # noqa: N802 - GTSAM's name
        raise NotImplementedError

    @classmethod
    def random(cls, rng: np.random.Generator, scale: float = 1.0):
        """A random numeric value: Exp of a tangent vector with rotation angle up to π."""
        v = rng.normal(size=cls.dim) * scale
        return cls.Expmap(v)

    @classmethod
    def Logmap(cls, x):  # noqa: N802 - GTSAM's name
        raise NotImplementedError

    def between(self, other):
        """``self⁻¹ ∘ other`` (GTSAM ``between``)."""
        return self.inverse().compose(other)

    def retract(self, delta):
        return self.compose(type(self).Expmap(as_vector(delta, self.dim)))

    def local(self, other):
        """Local coordinates of ``other`` at ``self``: ``Log(self⁻¹ ∘ other)``."""
        return type(self).Logmap(self.between(other))

    localCoordinates = local  # noqa: N815 - GTSAM's name

    def __mul__(self, other):
        if isinstance(other, LieGroup) and type(other) is type(self):
            return self.compose(other)
        return NotImplemented

    def __repr__(self) -> str:
        vals = ", ".join(str(v) for v in self.to_storage())
        return f"{type(self).__name__}.from_storage([{vals}])"


class VectorSpace(LieGroup):
    """Vectors under addition: Point2, Point3, velocities, IMU biases, ``VectorN``."""

    def __init__(self, *values):
        if len(values) == 1 and not np.isscalar(values[0]) and not isinstance(values[0], sp.Expr):
            values = values[0]
        self.v = as_vector(values, self.dim)

    def to_storage(self) -> list:
        return list(self.v)

    @classmethod
    def from_storage(cls, values):
        return cls(as_vector(values, cls.storage_dim))

    @classmethod
    def identity(cls):
        return cls(np.zeros(cls.dim))

    def compose(self, other):
        return type(self)(self.v + other.v)

    def inverse(self):
        return type(self)(-self.v)

    @classmethod
    def Expmap(cls, v):  # noqa: N802
        return cls(as_vector(v, cls.dim))

    @classmethod
    def Logmap(cls, x):  # noqa: N802
        return x.v

    def vector(self):
        return self.v

    # arithmetic that users expect of points and vectors
    def __add__(self, other):
        return type(self)(self.v + as_vector(other, self.dim))

    def __sub__(self, other):
        return type(self)(self.v - as_vector(other, self.dim))

    def __neg__(self):
        return type(self)(-self.v)

    def __rmul__(self, scalar):
        return type(self)(scalar * self.v)

    def __mul__(self, scalar):
        if isinstance(scalar, LieGroup):
            return NotImplemented
        return type(self)(self.v * scalar)

    def __getitem__(self, i):
        return self.v[i]

    def __len__(self) -> int:
        return self.dim

    def dot(self, other):
        return dot(self.v, as_vector(other, self.dim))

    def norm(self):
        """|v|; differentiated with GTSAM's convention at the zero vector (norm2 / norm3)."""
        if self.symbolic:
            return special.VectorNorm(*(self.v[i] for i in range(self.dim)))
        return sqrt(self.dot(self))

    def squared_norm(self):
        return self.dot(self)
