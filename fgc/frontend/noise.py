"""Noise models: how a factor's residual is whitened, and optional robust losses.

A Gaussian noise model is stored as its square-root information matrix R (upper triangular,
RᵀR = Σ⁻¹), so the whitened residual is ``R · r``, as in GTSAM. Its *kind* fixes which entries of R
are data the accelerator reads at run time: one scalar (isotropic), the diagonal (diagonal), or the
upper triangle (full). Robust wrappers (Huber, Cauchy) reweight the whitened system like GTSAM's
``noiseModel.Robust``: rows and right-hand side are scaled by √w(‖R r‖).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from fgc.errors import DataError
from fgc.ir.codes import ROBUST_KINDS


def _finite_array(values, what: str) -> np.ndarray:
    arr = np.asarray(values, dtype=np.float64)
    if not np.all(np.isfinite(arr)):
        raise DataError(f"{what} contains a non-finite value: {arr.tolist()}")
    return arr


@dataclass(frozen=True)
class RobustLoss:
    """An M-estimator (GTSAM ``mEstimator``): ``kind`` is "huber" or "cauchy", ``k`` its width."""

    kind: str
    k: float

    def __post_init__(self):
        if self.kind not in ROBUST_KINDS:
            raise DataError(f"unknown robust loss {self.kind!r}; one of {ROBUST_KINDS}")
        if not (np.isfinite(self.k) and self.k > 0):
            raise DataError(f"robust loss {self.kind} needs a positive finite k, got {self.k}")

    def weight(self, e: float) -> float:
        """Reweighting factor w(e) for a whitened residual norm e."""
        e = abs(e)
        if self.kind == "huber":
            return 1.0 if e <= self.k else self.k / e
        return self.k * self.k / (self.k * self.k + e * e)

    def loss(self, e: float) -> float:
        """ρ(e); GTSAM's factor error is ρ(‖R r‖)."""
        e = abs(e)
        if self.kind == "huber":
            return 0.5 * e * e if e <= self.k else self.k * e - 0.5 * self.k * self.k
        return 0.5 * self.k * self.k * np.log1p(e * e / (self.k * self.k))


@dataclass(frozen=True)
class NoiseModel:
    """A Gaussian noise model (``kind`` in isotropic/diagonal/full) with optional robust loss."""

    kind: str
    sqrt_information: np.ndarray = field(compare=False, repr=False)
    robust: RobustLoss | None = None

    @property
    def dim(self) -> int:
        return self.sqrt_information.shape[0]

    def params(self) -> np.ndarray:
        """The run-time parameters of the whitening matrix, in the order derive expects."""
        r = self.sqrt_information
        if self.kind == "isotropic":
            return np.array([r[0, 0]])
        if self.kind == "diagonal":
            return np.diag(r).copy()
        return r[np.triu_indices(self.dim)].copy()

    def whiten(self, r: np.ndarray) -> np.ndarray:
        return self.sqrt_information @ r

    def error(self, r: np.ndarray) -> float:
        """GTSAM's factor error for unwhitened residual r: ½‖R r‖², or ρ(‖R r‖) if robust."""
        e = float(np.linalg.norm(self.whiten(r)))
        return 0.5 * e * e if self.robust is None else float(self.robust.loss(e))

    def with_robust(self, loss: RobustLoss) -> NoiseModel:
        return NoiseModel(self.kind, self.sqrt_information, loss)


def _information(r: np.ndarray, what: str) -> np.ndarray:
    """``r`` if every entry is finite: σ so small that 1/σ overflows is a DataError."""
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        ok = np.all(np.isfinite(r))
    if not ok or r.size == 0:
        raise DataError(f"{what}: the information (1/σ) is not finite — σ is too small")
    return r


def _dimension(dim, what: str) -> int:
    if isinstance(dim, bool) or not isinstance(dim, (int, np.integer)) or dim < 1:
        raise DataError(f"{what} needs a positive integer dimension, got {dim!r}")
    return int(dim)


def isotropic(dim: int, sigma: float) -> NoiseModel:
    """Same standard deviation ``sigma`` on every one of ``dim`` residual rows."""
    dim = _dimension(dim, "isotropic noise")
    if not (np.isfinite(sigma) and sigma > 0):
        raise DataError(f"isotropic noise needs a positive finite sigma, got {sigma}")
    with np.errstate(over="ignore"):
        r = np.eye(dim) / sigma
    return NoiseModel("isotropic", _information(r, f"isotropic noise sigma {sigma}"))


def diagonal(sigmas) -> NoiseModel:
    """Independent rows with standard deviations ``sigmas``."""
    s = _finite_array(sigmas, "diagonal noise sigmas").reshape(-1)
    if s.size == 0 or np.any(s <= 0):
        raise DataError(f"diagonal noise sigmas must be positive, got {s.tolist()}")
    with np.errstate(over="ignore", divide="ignore"):
        r = np.diag(1.0 / s)
    return NoiseModel("diagonal", _information(r, f"diagonal noise sigmas {s.tolist()}"))


def covariance(cov) -> NoiseModel:
    """Full covariance Σ (symmetric positive definite)."""
    c = _finite_array(cov, "noise covariance")
    if c.ndim != 2 or c.shape[0] != c.shape[1]:
        raise DataError(f"noise covariance must be square, got shape {c.shape}")
    if not np.allclose(c, c.T, rtol=1e-12, atol=1e-15 * np.abs(c).max()):
        raise DataError("noise covariance is not symmetric")
    try:
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            info = np.linalg.inv(np.linalg.cholesky(c))  # L⁻¹ with Σ = L Lᵀ: Σ⁻¹ = L⁻ᵀ L⁻¹
            # upper-triangular R with RᵀR = Σ⁻¹: Cholesky of the information matrix, transposed
            r = np.linalg.cholesky(_information(info.T @ info, "noise covariance")).T
    except np.linalg.LinAlgError:
        raise DataError("noise covariance is not positive definite") from None
    return NoiseModel("full", _information(r, "noise covariance"))


def sqrt_information(r) -> NoiseModel:
    """Full model from an upper-triangular square-root information matrix R (RᵀR = Σ⁻¹)."""
    m = _finite_array(r, "square-root information")
    if m.ndim != 2 or m.shape[0] != m.shape[1]:
        raise DataError(f"square-root information must be square, got shape {m.shape}")
    if np.any(np.tril(m, -1) != 0):
        m = np.linalg.cholesky(m.T @ m).T  # same information, upper-triangular factor
    if np.any(np.diag(m) <= 0):
        raise DataError("square-root information must have a positive diagonal")
    return NoiseModel("full", m)


def huber(k: float, base: NoiseModel) -> NoiseModel:
    """Huber-robustified ``base`` (GTSAM ``Robust.Create(mEstimator.Huber.Create(k), base)``)."""
    return base.with_robust(RobustLoss("huber", float(k)))


def cauchy(k: float, base: NoiseModel) -> NoiseModel:
    """Cauchy-robustified ``base``."""
    return base.with_robust(RobustLoss("cauchy", float(k)))
