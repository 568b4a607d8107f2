"""Numeric SO(3) helpers on NumPy arrays (float32 or float64, the input's dtype is kept).

GTSAM conventions: ``exp(ω)`` is the matrix exponential of ``hat(ω)``; ``right_jacobian(ω)`` is
Jr(ω) with Exp(ω + δ) ≈ Exp(ω)·Exp(Jr(ω)·δ); ``right_jacobian_inv`` is its inverse.
"""

from __future__ import annotations

import numpy as np

from fgc.frontend.geometry.special import coefficient, so3_log_numeric


def _dtype(x: np.ndarray):
    x = np.asarray(x)
    return x.dtype.type if x.dtype.kind == "f" else np.float64


def hat(w) -> np.ndarray:
    """3×3 skew-symmetric matrix of a 3-vector: hat(w) @ v == cross(w, v)."""
    w = np.asarray(w)
    dt = _dtype(w)
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]], dtype=dt)


def vee(m) -> np.ndarray:
    """Inverse of :func:`hat` (reads the lower-triangle entries of a skew matrix)."""
    m = np.asarray(m)
    return np.array([m[2, 1], m[0, 2], m[1, 0]], dtype=_dtype(m))


def exp(w) -> np.ndarray:
    """Exp: rotation vector → rotation matrix (Rodrigues with robust coefficients)."""
    w = np.asarray(w, dtype=_dtype(w))
    wx = hat(w)
    t = w @ w
    return np.eye(3, dtype=w.dtype) + coefficient("A", t) * wx + coefficient("B", t) * (wx @ wx)


def log(r) -> np.ndarray:
    """Log: rotation matrix → rotation vector with |ω| ≤ π (robust at 0 and near π)."""
    return so3_log_numeric(np.asarray(r))


def right_jacobian(w) -> np.ndarray:
    """Jr(ω) = I − B(θ²)·[ω]× + C(θ²)·[ω]×²."""
    w = np.asarray(w, dtype=_dtype(w))
    wx = hat(w)
    t = w @ w
    return np.eye(3, dtype=w.dtype) - coefficient("B", t) * wx + coefficient("C", t) * (wx @ wx)


def right_jacobian_inv(w) -> np.ndarray:
    """Jr⁻¹(ω) = I + ½[ω]× + D(θ²)·[ω]×² (valid for |ω| < 2π)."""
    w = np.asarray(w, dtype=_dtype(w))
    wx = hat(w)
    t = w @ w
    return np.eye(3, dtype=w.dtype) + 0.5 * wx + coefficient("D", t) * (wx @ wx)
