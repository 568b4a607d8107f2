"""Numerically robust scalar functions behind the Lie-group maps, numeric and symbolic.

Exp and Log of SO(3)/SE(3)/SE(2) and their Jacobians are polynomial in the group entries once a few
scalar coefficients of ``t = θ²`` are known:

======  ==============================  ===================  ===================
name    closed form                     value at t = 0       used by
======  ==============================  ===================  ===================
``A``   sin θ / θ                       1                    Exp
``B``   (1 − cos θ) / θ²                1/2                  Exp, Jr
``C``   (θ − sin θ) / θ³                1/6                  Jr, SE(3) Exp
``D``   1/θ² − (1 + cos θ)/(2θ sin θ)   1/12                 Jr⁻¹, SE(3) Log
======  ==============================  ===================  ===================

and their derivatives with respect to ``t`` (``A1`` … ``D1``). Each is evaluated by its Taylor
series for ``t < 4`` and by the closed form above it, so the maps stay accurate at θ = 0, 1e-8,
1e-4 and near π in float64 and float32. ``D`` is only used for θ ≤ π (the range of Log).

Symbolically each coefficient is a sympy ``Function`` with a derivative rule, so sympy's chain rule
never differentiates a singular closed form. The rotation logarithm is an opaque function
``so3_log_{x,y,z}(R00 … R22)`` whose derivative along any tangent direction dR = R·[δ]× is the exact
``Jr⁻¹(ω)·δ``; printers turn all of them into calls of the robust numeric routines below.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import sympy as sp

from fgc.errors import DerivationError
from fgc.frontend.geometry.lie_closed_forms import closed_form, horner

# Use the Taylor series for t = θ² below this (|θ| < 2 rad): the closed forms of C1, D and D1
# cancel badly for θ ≈ 1 (≈ 2e-13 relative in float64, 1e-4 in float32 for D1 at t = 1).
SERIES_BELOW = 4.0
_N_TERMS = 12


def _alternating_factorial_series(offset: int) -> list[Fraction]:
    """Coefficients c_n = (−1)^n / (2n + offset)! of a series in t = θ²."""
    return [Fraction((-1) ** n, math.factorial(2 * n + offset)) for n in range(_N_TERMS)]


# 1/θ² − (1 + cos θ)/(2 θ sin θ) = Σ d_n θ^(2n) with d_n = |B_(2n+2)| / (2n+2)! (Bernoulli
# numbers, from θ/2·cot(θ/2)). It converges for θ < 2π only, so it needs more terms than the
# factorial series to reach float64 precision at t = SERIES_BELOW.
_N_TERMS_D = 22
_D_SERIES = [
    Fraction(int(abs(b.p)), int(b.q)) / math.factorial(2 * n + 2)
    for n, b in ((n, sp.bernoulli(2 * n + 2)) for n in range(_N_TERMS_D))
]

SERIES: dict[str, list[Fraction]] = {
    "A": _alternating_factorial_series(1),
    "B": _alternating_factorial_series(2),
    "C": _alternating_factorial_series(3),
    "D": _D_SERIES,
}


def _derivative_series(coeffs: list[Fraction]) -> list[Fraction]:
    return [n * c for n, c in enumerate(coeffs)][1:]


for _name in list(SERIES):
    SERIES[_name + "1"] = _derivative_series(SERIES[_name])


_FLOAT_SERIES: dict[str, tuple[float, ...]] = {}


def _horner(name: str, t: np.ndarray) -> np.ndarray:
    coeffs = _FLOAT_SERIES.get(name)
    if coeffs is None:
        coeffs = _FLOAT_SERIES[name] = tuple(float(c) for c in reversed(SERIES[name]))
    return horner(coeffs, t)


def coefficient(name: str, t):
    """Evaluate coefficient ``name`` (A, B, C, D, A1, B1, C1, D1) at ``t = θ²``.

    ``t`` is a float or an array (float32 or float64); the result has the same shape and dtype.
    """
    arr = np.asarray(t)
    if arr.dtype.kind != "f":
        arr = arr.astype(np.float64)
    small = arr < SERIES_BELOW
    series = _horner(name, arr)
    safe = np.where(small, arr.dtype.type(SERIES_BELOW), arr)
    with np.errstate(all="ignore"):
        closed = closed_form(name, safe)  # lie_closed_forms: the simulator copies it
    out = np.where(small, series, closed).astype(arr.dtype)
    return out if out.ndim else out.dtype.type(out)


# --------------------------------------------------------------------------------------------
# numeric SO(3) log (robust at 0 and π)
# --------------------------------------------------------------------------------------------


def so3_log_numeric(r: np.ndarray) -> np.ndarray:
    """Rotation vector ω with Exp(ω) = R for a 3×3 rotation matrix (any float dtype).

    θ comes from ``atan2(sin θ, cos θ)``; the axis from the skew part when cos θ ≥ 0 and from
    the symmetric part (R + Rᵀ)/2 = cos θ·I + (1 − cos θ)·n nᵀ otherwise, so θ → π loses no digits.
    """
    r = np.asarray(r)
    dt = r.dtype.type if r.dtype.kind == "f" else np.float64
    skew = np.array([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]], dtype=dt)
    cos_t = dt(0.5) * (r[0, 0] + r[1, 1] + r[2, 2] - dt(1))
    sin_t = dt(0.5) * np.sqrt(skew @ skew)
    theta = np.arctan2(sin_t, cos_t)
    if cos_t >= 0:
        # ω = θ / (2 sin θ) · skew: θ = atan2(sin θ, cos θ) keeps its relative digits as θ → 0,
        # so the ratio does too (its limit 1 at sin θ = 0)
        return (dt(0.5) * (theta / sin_t if sin_t > 0 else dt(1))) * skew
    sym = dt(0.5) * (r + r.T) - cos_t * np.eye(3, dtype=dt)
    k = int(np.argmax(np.diag(sym)))
    axis = sym[:, k] / np.sqrt(sym[k, k] * (dt(1) - cos_t))
    axis = axis / np.sqrt(axis @ axis)
    if axis @ skew < 0:
        axis = -axis
    return (theta * axis).astype(dt)


# --------------------------------------------------------------------------------------------
# symbolic counterparts
# --------------------------------------------------------------------------------------------


class LieCoefficient(sp.Function):
    """Base of the symbolic coefficient functions of ``t = θ²`` (see the module table)."""

    nargs = 1
    coeff_name = ""
    derivative: type[LieCoefficient] | None = None

    @classmethod
    def eval(cls, t):
        if t.is_zero:
            return sp.Rational(SERIES[cls.coeff_name][0].numerator,
                               SERIES[cls.coeff_name][0].denominator)
        if isinstance(t, sp.Float):
            return sp.Float(float(coefficient(cls.coeff_name, float(t))))
        return None

    def fdiff(self, argindex=1):
        if self.derivative is None:
            raise DerivationError(
                f"second derivatives of the Lie coefficient {self.coeff_name} are not supported"
            )
        return self.derivative(self.args[0])

    def _eval_evalf(self, prec):
        val = self.args[0].evalf(prec)
        if val.is_number:
            return sp.Float(float(coefficient(self.coeff_name, float(val))), prec)
        return None


def _make_coefficient(name: str, derivative: type[LieCoefficient] | None) -> type[LieCoefficient]:
    cls = type(f"lie_{name}", (LieCoefficient,), {"coeff_name": name, "derivative": derivative})
    return cls


lie_A1 = _make_coefficient("A1", None)
lie_B1 = _make_coefficient("B1", None)
lie_C1 = _make_coefficient("C1", None)
lie_D1 = _make_coefficient("D1", None)
lie_A = _make_coefficient("A", lie_A1)
lie_B = _make_coefficient("B", lie_B1)
lie_C = _make_coefficient("C", lie_C1)
lie_D = _make_coefficient("D", lie_D1)

COEFFICIENT_FUNCTIONS: dict[str, type[LieCoefficient]] = {
    c.coeff_name: c for c in (lie_A, lie_B, lie_C, lie_D, lie_A1, lie_B1, lie_C1, lie_D1)
}


def skew_part(m: sp.Matrix) -> sp.Matrix:
    """vee of the skew-symmetric part of a 3×3 matrix: ½(m21 − m12, m02 − m20, m10 − m01)."""
    return sp.Matrix([m[2, 1] - m[1, 2], m[0, 2] - m[2, 0], m[1, 0] - m[0, 1]]) / 2


def hat_sym(w) -> sp.Matrix:
    return sp.Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


class SO3LogComponent(sp.Function):
    """Component ``axis`` of Log(R) as a function of the nine entries of R (row-major)."""

    nargs = 9
    axis = 0

    @classmethod
    def eval(cls, *entries):
        if all(e.is_number for e in entries):
            if all(e.is_Integer for e in entries):
                mat = np.array([int(e) for e in entries], dtype=np.float64).reshape(3, 3)
                if np.array_equal(mat, np.eye(3)):
                    return sp.Integer(0)
            mat = np.array([float(e) for e in entries], dtype=np.float64).reshape(3, 3)
            return sp.Float(float(so3_log_numeric(mat)[cls.axis]))
        return None

    def fdiff(self, argindex=1):
        # dω = Jr⁻¹(ω) · vee(skew(Rᵀ dR)), exact along tangent directions dR = R [δ]×.
        i, j = divmod(argindex - 1, 3)
        r = sp.Matrix(3, 3, self.args)
        m = sp.zeros(3, 3)
        m[:, j] = r[i, :].T
        omega = so3_log_symbolic(self.args)
        w = hat_sym(omega)
        t = (omega.T * omega)[0, 0]
        jr_inv = sp.eye(3) + w / 2 + lie_D(t) * (w * w)
        return (jr_inv * skew_part(m))[self.axis]


so3_log_x = type("so3_log_x", (SO3LogComponent,), {"axis": 0})
so3_log_y = type("so3_log_y", (SO3LogComponent,), {"axis": 1})
so3_log_z = type("so3_log_z", (SO3LogComponent,), {"axis": 2})
SO3_LOG_FUNCTIONS = (so3_log_x, so3_log_y, so3_log_z)


def so3_log_symbolic(entries) -> sp.Matrix:
    """Symbolic Log of a rotation given as its nine row-major entries."""
    args = tuple(entries)
    return sp.Matrix([f(*args) for f in SO3_LOG_FUNCTIONS])


def numeric_namespace() -> dict[str, object]:
    """Names → numeric callables, for ``sympy.lambdify`` and the NumPy printer."""
    ns: dict[str, object] = {}
    for name, cls in COEFFICIENT_FUNCTIONS.items():
        ns[cls.__name__] = (lambda n: lambda t: coefficient(n, t))(name)
    for axis, cls in enumerate(SO3_LOG_FUNCTIONS):
        ns[cls.__name__] = (lambda a: lambda *e: _log_entries(a, e))(axis)
    ns["GuardedQuotient"] = guarded_quotient_numeric
    ns["VectorNorm"] = vector_norm_numeric
    return ns


def _log_entries(axis: int, entries) -> np.floating:
    mat = np.array(entries)
    return so3_log_numeric(mat.reshape(3, 3))[axis]


# --------------------------------------------------------------------------------------------
# GTSAM's conventions at singular points: the norm of a zero vector, the bearing to a point
# at the observer's position
# --------------------------------------------------------------------------------------------

# GTSAM's norm2 / norm3 (behind Pose2::range, Pose3::range, distance2): at |v| ≤ NORM_TINY the
# Jacobian of |v| is the all-ones row (a fixed direction, not 0/0).
NORM_TINY = 1e-10
# GTSAM's Rot2::relativeBearing (behind Pose2::bearing): at |d| ≤ BEARING_TINY the bearing is
# the identity rotation and its Jacobian zero.
BEARING_TINY = 1e-5


def guarded_quotient_numeric(a, b, g, t, f):
    """``a / b`` where ``g > t``, else ``f`` (elementwise; no division where ``g ≤ t``)."""
    cond = np.asarray(g) > t
    if cond.ndim == 0:
        return a / b if cond else f + 0 * a
    return np.where(cond, a / np.where(cond, b, 1), f)


def vector_norm_numeric(*xs):
    """``sqrt(Σ x²)`` elementwise, in the inputs' dtype."""
    return np.sqrt(sum(x * x for x in xs))


class GuardedQuotient(sp.Function):
    """``guarded_quotient(a, b, g, t, f)``: ``a / b`` where ``g > t``, else ``f`` (``t`` and ``f``
    numbers). The one branch printed by every backend (a select: the quotient is never
    evaluated where ``g ≤ t``); it carries GTSAM's conventions at singular points, which hold
    ``f`` on a neighbourhood ``g ≤ t``, so its derivative is that of ``a / b`` where ``g > t``
    and 0 elsewhere (``g`` is a guard, not differentiated)."""

    nargs = 5

    @classmethod
    def eval(cls, a, b, g, t, f):
        if not (t.is_Number and f.is_Number):
            raise DerivationError(f"guarded_quotient needs a numeric threshold and fallback, "
                                  f"not {t}, {f}")
        if g.is_Number:
            return a / b if g > t else f
        if a.is_zero and f.is_zero:
            return sp.S.Zero
        return None

    def fdiff(self, argindex=1):
        a, b, g, t, _ = self.args
        if argindex == 1:
            return GuardedQuotient(sp.S.One, b, g, t, sp.S.Zero)
        if argindex == 2:
            return GuardedQuotient(-a, b * b, g, t, sp.S.Zero)
        return sp.S.Zero  # the guard, threshold and fallback move nothing

    def _eval_evalf(self, prec):
        vals = [x.evalf(prec) for x in self.args]
        if all(v.is_number for v in vals):
            a, b, g, t, f = vals
            return (a / b).evalf(prec) if g > t else f.evalf(prec)
        return None


class VectorNorm(sp.Function):
    """``vector_norm(x1, …, xn) = sqrt(Σ xᵢ²)`` with GTSAM's Jacobian at the zero vector
    (norm2 / norm3): ``∂/∂xᵢ = xᵢ / |x|`` where ``|x| > NORM_TINY`` and 1 elsewhere, so a range
    or distance between coincident points moves them apart instead of giving 0/0."""

    @classmethod
    def eval(cls, *xs):
        if not xs:
            raise DerivationError("vector_norm needs at least one argument")
        if all(x.is_number for x in xs):
            return sp.sqrt(sp.Add(*[x * x for x in xs]))
        return None

    def fdiff(self, argindex=1):
        return GuardedQuotient(self.args[argindex - 1], self, self, sp.Float(NORM_TINY),
                               sp.S.One)

    def _eval_is_nonnegative(self):
        return True

    def _eval_is_real(self):
        return all(x.is_real for x in self.args) or None

    def expanded(self) -> sp.Expr:
        """The plain ``sqrt(Σ xᵢ²)`` it stands for once derivatives are taken."""
        return sp.sqrt(sp.Add(*[x * x for x in self.args]))


def relative_bearing(x, y):
    """(cos, sin) of the direction of ``(x, y)``, GTSAM's ``Rot2::relativeBearing``: the
    identity (1, 0) with a zero Jacobian where ``|(x, y)| ≤ BEARING_TINY``."""
    if isinstance(x, sp.Basic) or isinstance(y, sp.Basic):
        n = VectorNorm(x, y)
        tiny = sp.Float(BEARING_TINY)
        return GuardedQuotient(x, n, n, tiny, sp.S.One), GuardedQuotient(y, n, n, tiny, sp.S.Zero)
    n = (x * x + y * y) ** 0.5
    if n > BEARING_TINY:
        return x / n, y / n
    return type(n)(1.0), type(n)(0.0)


GUARD_FUNCTIONS = (GuardedQuotient, VectorNorm)


def expand_norms(expr: sp.Expr) -> sp.Expr:
    """``expr`` with every :class:`VectorNorm` written as the square root it is (after
    differentiation, where its derivative rule has done its work)."""
    if not isinstance(expr, sp.Basic):
        return expr
    norms = expr.atoms(VectorNorm)
    while norms:  # a norm of norms: the outer one's expansion still holds the inner ones
        expr = expr.xreplace({n: n.expanded() for n in norms})
        norms = expr.atoms(VectorNorm)
    return expr
