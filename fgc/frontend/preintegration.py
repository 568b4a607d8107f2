"""IMU preintegration (GTSAM 4.3's tangent-space ``PreintegratedCombinedMeasurements``), in NumPy.

A sequence of accelerometer / gyroscope samples between two keyframes i and j is summarised by the
9-vector ζ = [θ, p, v] (rotation vector, position, velocity increments in the body frame at i),
its Jacobians with respect to the accelerometer and gyroscope bias, and a 15×15 covariance over
[θ, p, v, b_acc, b_gyro]. The update equations, the bias correction, the prediction and the two
residual charts of GTSAM 4.3's ``CombinedImuFactor`` are written down in ``docs/imu.md``.

fgc never calls GTSAM here; ``tests/frontend/test_preintegration.py`` checks every quantity
against GTSAM 4.3.0 on the KITTI IMU log shipped in the gtsam wheel.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from fgc.errors import DataError
from fgc.frontend.geometry import so3
from fgc.frontend.geometry.special import coefficient

ERROR_MODES = ("logmap", "componentwise")
"""Residual charts of GTSAM 4.3's ``ImuFactorErrorMode``: ``Logmap`` (its default) and
``ComponentWise``. GTSAM's third value, ``Legacy``, equals ``ComponentWise`` for the tangent
preintegration."""


def _vector(name: str, value: ArrayLike, size: int) -> np.ndarray:
    """A finite read-only float64 copy of ``value`` with shape (size,), else DataError."""
    arr = np.array(value, dtype=np.float64)
    if arr.shape != (size,):
        raise DataError(f"{name} must be a {size}-vector, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise DataError(f"{name} must be finite, got {arr}")
    arr.setflags(write=False)
    return arr


def _covariance3(name: str, value: ArrayLike) -> np.ndarray:
    """A read-only float64 copy of a 3×3 covariance; DataError unless finite, symmetric, PSD."""
    arr = np.array(value, dtype=np.float64)
    if arr.shape != (3, 3):
        raise DataError(f"{name} must be a 3×3 matrix, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise DataError(f"{name} must be finite, got {arr.tolist()}")
    scale = max(float(np.abs(arr).max()), np.finfo(np.float64).tiny)
    if np.abs(arr - arr.T).max() > 1e-12 * scale:
        raise DataError(f"{name} must be symmetric, got {arr.tolist()}")
    if np.linalg.eigvalsh(arr).min() < -1e-12 * scale:
        raise DataError(f"{name} must be positive semi-definite, got {arr.tolist()}")
    arr.setflags(write=False)
    return arr


def _identity3() -> np.ndarray:
    return np.eye(3)


@dataclass(frozen=True, eq=False)
class ImuParams:
    """Preintegration parameters, GTSAM's ``PreintegrationCombinedParams`` (SI units).

    Covariances are continuous-time densities (σ² per Hz), as in GTSAM; the defaults (identity)
    are GTSAM's. Arrays are stored as read-only float64 copies; ``eq=False`` because element-wise
    array comparison has no single truth value (compare fields explicitly).

    ``omega_coriolis`` may be ``None`` or zero: GTSAM 4.3 integrates a rotating Earth exactly when
    it is non-zero, which fgc does not model, so a non-zero value is a DataError, as is any
    ``body_P_sensor`` (the IMU must be the body frame). 4.3 no longer has ``biasAccOmegaInt``.
    ``error_mode`` picks the ``CombinedImuFactor`` residual chart, one of :data:`ERROR_MODES`.
    """

    n_gravity: np.ndarray
    accelerometer_covariance: np.ndarray = field(default_factory=_identity3)
    gyroscope_covariance: np.ndarray = field(default_factory=_identity3)
    integration_covariance: np.ndarray = field(default_factory=_identity3)
    bias_acc_covariance: np.ndarray = field(default_factory=_identity3)
    bias_omega_covariance: np.ndarray = field(default_factory=_identity3)
    omega_coriolis: np.ndarray | None = None
    body_P_sensor: Any = None
    error_mode: str = "logmap"

    def __post_init__(self) -> None:
        set_ = object.__setattr__  # the dataclass is frozen; normalise fields once, here
        set_(self, "n_gravity", _vector("ImuParams.n_gravity", self.n_gravity, 3))
        for name in ("accelerometer_covariance", "gyroscope_covariance", "integration_covariance",
                     "bias_acc_covariance", "bias_omega_covariance"):
            set_(self, name, _covariance3(f"ImuParams.{name}", getattr(self, name)))
        if self.omega_coriolis is not None:
            omega = _vector("ImuParams.omega_coriolis", self.omega_coriolis, 3)
            if np.any(omega != 0.0):
                raise DataError("ImuParams.omega_coriolis: a rotating navigation frame is not "
                                f"supported (got {omega.tolist()}); use None")
            set_(self, "omega_coriolis", omega)
        if self.body_P_sensor is not None:
            raise DataError("ImuParams.body_P_sensor is not supported: express the IMU samples in "
                            "the body frame and leave body_P_sensor as None")
        if self.error_mode not in ERROR_MODES:
            raise DataError(f"ImuParams.error_mode must be one of {ERROR_MODES}, "
                            f"got {self.error_mode!r}")

    @classmethod
    def make_u(cls, g: float = 9.81, **fields: Any) -> ImuParams:
        """Z-up navigation frame (ENU): gravity (0, 0, −g). GTSAM's ``MakeSharedU``."""
        return cls(n_gravity=np.array([0.0, 0.0, -g]), **fields)

    @classmethod
    def make_d(cls, g: float = 9.81, **fields: Any) -> ImuParams:
        """Z-down navigation frame (NED): gravity (0, 0, +g). GTSAM's ``MakeSharedD``."""
        return cls(n_gravity=np.array([0.0, 0.0, g]), **fields)

    def replace(self, **changes: Any) -> ImuParams:
        """A copy with some fields changed (validated again)."""
        return dataclasses.replace(self, **changes)


# ------------------------------------------------------------------------------------------------
# one tangent-space integration step (pure functions)
# ------------------------------------------------------------------------------------------------


def _inv_dexp_times_derivative(theta: np.ndarray, w: np.ndarray) -> np.ndarray:
    """∂(Jr⁻¹(θ)·w)/∂θ for Jr⁻¹(θ) = I + ½[θ]× + D(t)[θ]×², t = θᵀθ.

    With [θ]×²w = θ(θᵀw) − t·w the three terms differentiate to −½[w]×,
    D(t)·((θᵀw)I + θwᵀ − 2wθᵀ) and 2D'(t)·([θ]×²w)θᵀ.
    """
    t = float(theta @ theta)
    d, d1 = coefficient("D", t), coefficient("D1", t)
    tw = float(theta @ w)
    double_cross = theta * tw - t * w
    return (-0.5 * so3.hat(w)
            + d * (tw * np.eye(3) + np.outer(theta, w) - 2.0 * np.outer(w, theta))
            + 2.0 * d1 * np.outer(double_cross, theta))


def tangent_step(
    zeta: np.ndarray, acc: np.ndarray, omega: np.ndarray, dt: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Advance ζ = [θ, p, v] by one bias-corrected sample; GTSAM's ``UpdatePreintegrated``.

    Returns (ζ⁺, A, B, C): A = ∂ζ⁺/∂ζ (9×9), B = ∂ζ⁺/∂acc, C = ∂ζ⁺/∂omega (9×3 each), all at ζ.
    The body rate is pulled back to the tangent space at θ (θ̇ = Jr⁻¹(θ)·ω), so the θ update is
    exact for constant ω; position and velocity use the acceleration rotated by Exp(θ).
    """
    theta, pos, vel = zeta[:3], zeta[3:6], zeta[6:]
    rot = so3.exp(theta)
    jr_inv = so3.right_jacobian_inv(theta)
    a_nav = rot @ acc
    half_dt2 = 0.5 * dt * dt
    zeta_next = np.concatenate([theta + dt * (jr_inv @ omega),
                                pos + dt * vel + half_dt2 * a_nav,
                                vel + dt * a_nav])
    a_nav_h_theta = -rot @ so3.hat(acc) @ so3.right_jacobian(theta)  # ∂(Exp(θ)·a)/∂θ
    a_mat = np.eye(9)
    a_mat[:3, :3] += dt * _inv_dexp_times_derivative(theta, omega)
    a_mat[3:6, :3] = half_dt2 * a_nav_h_theta
    a_mat[3:6, 6:] = dt * np.eye(3)
    a_mat[6:, :3] = dt * a_nav_h_theta
    b_mat = np.zeros((9, 3))
    b_mat[3:6] = half_dt2 * rot
    b_mat[6:] = dt * rot
    c_mat = np.zeros((9, 3))
    c_mat[:3] = dt * jr_inv
    return zeta_next, a_mat, b_mat, c_mat


def propagate_covariance(
    cov: np.ndarray, a_mat: np.ndarray, b_mat: np.ndarray, c_mat: np.ndarray, dt: float,
    params: ImuParams,
) -> np.ndarray:
    """One step of the 15×15 covariance over [θ, p, v, b_acc, b_gyro]: F·Σ·Fᵀ + Q.

    F = [[A, B, C], [0, I₆]] (the bias columns carry the measurement Jacobians, so bias
    uncertainty flows into ζ as measurement noise does); Q = B·(Σ_a/dt)·Bᵀ + C·(Σ_g/dt)·Cᵀ plus
    dt·Σ_int on the position block and dt·Σ_bias on the bias blocks (discretised densities).
    """
    f_mat = np.eye(15)
    f_mat[:9, :9] = a_mat
    f_mat[:9, 9:12] = b_mat
    f_mat[:9, 12:] = c_mat
    q_mat = np.zeros((15, 15))
    q_mat[:9, :9] = (b_mat @ (params.accelerometer_covariance / dt) @ b_mat.T
                     + c_mat @ (params.gyroscope_covariance / dt) @ c_mat.T)
    q_mat[3:6, 3:6] += dt * params.integration_covariance
    q_mat[9:12, 9:12] = dt * params.bias_acc_covariance
    q_mat[12:, 12:] = dt * params.bias_omega_covariance
    return f_mat @ cov @ f_mat.T + q_mat


# ------------------------------------------------------------------------------------------------
# the preintegrator
# ------------------------------------------------------------------------------------------------


def _readonly(arr: np.ndarray) -> np.ndarray:
    out = arr.copy()
    out.setflags(write=False)
    return out


class PreintegratedCombinedMeasurements:
    """Preintegrated IMU samples between two keyframes, with bias random walk (GTSAM's class).

    ``bias_hat`` (6-vector [acc, gyro]) is the bias the samples are corrected with while
    integrating; :meth:`bias_corrected_delta` corrects ζ to first order for another bias.
    All returned arrays are read-only copies.

    Zero-length interval (no sample integrated, also right after :meth:`reset_integration`):
    ζ = 0, Δt = 0 and the covariance is zero, so :meth:`predict` returns the state at i
    unchanged, but :meth:`residual_covariance` raises DataError — a factor over no samples
    has no finite whitening (GTSAM silently builds a σ = 0 noise model instead).
    """

    def __init__(self, params: ImuParams, bias_hat: ArrayLike | None = None) -> None:
        if not isinstance(params, ImuParams):
            raise DataError(f"params must be an ImuParams, got {type(params).__name__}")
        self._params = params
        self.reset_integration(np.zeros(6) if bias_hat is None else bias_hat)

    def reset_integration(self, bias_hat: ArrayLike | None = None) -> None:
        """Forget all samples; optionally set a new ``bias_hat`` (GTSAM's
        ``resetIntegration`` / ``resetIntegrationAndSetBias``)."""
        if bias_hat is not None:
            self._bias_hat = _vector("bias_hat", bias_hat, 6)
        self._zeta = np.zeros(9)
        self._h_bias_acc = np.zeros((9, 3))
        self._h_bias_omega = np.zeros((9, 3))
        self._cov = np.zeros((15, 15))
        self._delta_t = 0.0
        self._num_samples = 0
        self._samples: list[tuple[np.ndarray, np.ndarray, float]] = []

    def integrate_measurement(self, acc: ArrayLike, gyro: ArrayLike, dt: float) -> None:
        """Add one sample: accelerometer (m/s², body frame), gyroscope (rad/s), period dt (s).

        Raises DataError naming the sample (its index since the last reset) if a value is not
        finite or dt ≤ 0.
        """
        where = f"IMU sample {self._num_samples}"
        acc_v = _vector(f"{where}: accelerometer", acc, 3)
        gyro_v = _vector(f"{where}: gyroscope", gyro, 3)
        dt = float(dt)
        if not np.isfinite(dt) or dt <= 0.0:
            raise DataError(f"{where}: dt must be finite and > 0, got {dt}")
        zeta, a_mat, b_mat, c_mat = tangent_step(
            self._zeta, acc_v - self._bias_hat[:3], gyro_v - self._bias_hat[3:], dt)
        # The bias Jacobians and the covariance are advanced with A, B, C taken at the old ζ.
        self._h_bias_acc = a_mat @ self._h_bias_acc - b_mat
        self._h_bias_omega = a_mat @ self._h_bias_omega - c_mat
        self._cov = propagate_covariance(self._cov, a_mat, b_mat, c_mat, dt, self._params)
        self._zeta = zeta
        self._delta_t += dt
        self._num_samples += 1
        self._samples.append((acc_v, gyro_v, dt))

    # -- read-only state ------------------------------------------------------------------------

    @property
    def params(self) -> ImuParams:
        return self._params

    @property
    def num_samples(self) -> int:
        """Samples integrated since the last reset."""
        return self._num_samples

    @property
    def samples(self) -> tuple[tuple[np.ndarray, np.ndarray, float], ...]:
        """The raw samples (acc, gyro, dt) integrated since the last reset, in order; lets the
        GTSAM bridge re-integrate them with GTSAM for an independent check."""
        return tuple(self._samples)

    @property
    def delta_t_ij(self) -> float:
        """Total integrated time Δt (s)."""
        return self._delta_t

    @property
    def bias_hat(self) -> np.ndarray:
        """Bias used while integrating, [acc, gyro] (6,)."""
        return self._bias_hat

    @property
    def preintegrated(self) -> np.ndarray:
        """ζ = [θ, p, v] (9,) at ``bias_hat``; GTSAM's ``preintegrated()``."""
        return _readonly(self._zeta)

    @property
    def preintegrated_H_bias_acc(self) -> np.ndarray:
        """∂ζ/∂b_acc (9×3)."""
        return _readonly(self._h_bias_acc)

    @property
    def preintegrated_H_bias_omega(self) -> np.ndarray:
        """∂ζ/∂b_gyro (9×3)."""
        return _readonly(self._h_bias_omega)

    @property
    def delta_R_ij(self) -> np.ndarray:
        """ΔR = Exp(θ) (3×3)."""
        return so3.exp(self._zeta[:3])

    @property
    def delta_p_ij(self) -> np.ndarray:
        """Δp (3,), body frame at i, without gravity."""
        return _readonly(self._zeta[3:6])

    @property
    def delta_v_ij(self) -> np.ndarray:
        """Δv (3,), body frame at i, without gravity."""
        return _readonly(self._zeta[6:])

    @property
    def preint_meas_cov(self) -> np.ndarray:
        """Σ over [θ, p, v, b_acc, b_gyro] (15×15); GTSAM's ``preintMeasCov()``."""
        return _readonly(self._cov)

    # -- derived quantities ---------------------------------------------------------------------

    def residual_covariance(self) -> np.ndarray:
        """The 15×15 covariance GTSAM 4.3's ``CombinedImuFactor`` whitens its error with.

        J·Σ·Jᵀ with J = blockdiag(Jr(θ), ΔRᵀ, ΔRᵀ, −I₆): the chart change from the additive
        [θ, p, v] of Σ to the factor's [rotation, position, velocity] residual (the same for both
        error modes; they agree to first order at zero error), and −I₆ because the bias residual
        is b_i − b_j. Raises DataError on a zero-length interval (Σ = 0).
        """
        if self._num_samples == 0:
            raise DataError("residual_covariance: no IMU samples integrated (zero-length "
                            "interval); the covariance is zero and cannot whiten a factor")
        theta = self._zeta[:3]
        rot_t = so3.exp(theta).T
        jac = np.zeros((15, 15))
        jac[:3, :3] = so3.right_jacobian(theta)
        jac[3:6, 3:6] = rot_t
        jac[6:9, 6:9] = rot_t
        jac[9:, 9:] = -np.eye(6)
        return jac @ self._cov @ jac.T

    def bias_corrected_delta(self, bias: ArrayLike) -> np.ndarray:
        """ζ corrected to first order for ``bias`` ([acc, gyro], 6): ζ + H_a·δb_a + H_g·δb_g.

        δb = bias − bias_hat. Returns the 9-vector [θ, p, v]; GTSAM's ``biasCorrectedDelta``.
        """
        delta = _vector("bias", bias, 6) - self._bias_hat
        return self._zeta + self._h_bias_acc @ delta[:3] + self._h_bias_omega @ delta[3:]

    def predict(
        self, pose_i: tuple[ArrayLike, ArrayLike], vel_i: ArrayLike, bias_i: ArrayLike
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The state at j predicted from the state at i: returns (R_j, p_j, v_j).

        ``pose_i`` is (R_i 3×3, p_i 3), ``vel_i`` the navigation-frame velocity, ``bias_i``
        the 6-vector [acc, gyro]. With [θ, Δp, Δv] = bias_corrected_delta(bias_i) and g the
        gravity vector: R_j = R_i·Exp(θ), p_j = p_i + Δt·v_i + ½Δt²·g + R_i·Δp,
        v_j = v_i + Δt·g + R_i·Δv (GTSAM's ``predict``).
        """
        rot_i = np.asarray(pose_i[0], dtype=np.float64)
        if rot_i.shape != (3, 3):
            raise DataError(f"predict: R_i must be 3×3, got shape {rot_i.shape}")
        p_i = _vector("predict: p_i", pose_i[1], 3)
        v_i = _vector("predict: vel_i", vel_i, 3)
        zeta = self.bias_corrected_delta(bias_i)
        dt, g = self._delta_t, self._params.n_gravity
        rot_j = rot_i @ so3.exp(zeta[:3])
        p_j = p_i + dt * v_i + 0.5 * dt * dt * g + rot_i @ zeta[3:6]
        v_j = v_i + dt * g + rot_i @ zeta[6:]
        return rot_j, p_j, v_j
