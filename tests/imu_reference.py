"""Pure-NumPy reference of GTSAM 4.3's ``CombinedImuFactor`` error, plus a KITTI IMU log reader.

This file is the *spec* fgc's symbolic IMU factor implements: every formula is a short composition
of Exp / Log / Jr⁻¹ / matrix products, and ``tests/frontend/test_preintegration.py`` checks it
against ``gtsam.CombinedImuFactor.unwhitenedError`` (and ``evaluateError``) to 1e-9 in both of
GTSAM 4.3's error modes (``ImuFactorErrorMode.Logmap``, the default, and
``ImuFactorErrorMode.ComponentWise``). ``docs/imu.md`` has the same formulas in math notation.

The error is unwhitened, 15 rows: [rotation (3), position (3), velocity (3), bias_acc (3),
bias_gyro (3)]. GTSAM whitens it with ``pim.residual_covariance()``.
"""

from __future__ import annotations

import numpy as np

from fgc.frontend.geometry import so3
from fgc.frontend.preintegration import PreintegratedCombinedMeasurements


def predicted_state(
    rot_i: np.ndarray, p_i: np.ndarray, v_i: np.ndarray, bias_i: np.ndarray,
    pim: PreintegratedCombinedMeasurements,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """X̂_j = (R̂_j, p̂_j, v̂_j) predicted from state i = (R_i = rot_i, p_i, v_i) with bias_i.

    [θ, Δp, Δv] = ζ + H_a·(b_a,i − b̂_a) + H_g·(b_g,i − b̂_g)      (first-order bias correction)
    R̂_j = R_i·Exp(θ)
    p̂_j = p_i + Δt·v_i + ½Δt²·g + R_i·Δp
    v̂_j = v_i + Δt·g + R_i·Δv
    """
    delta_b = np.asarray(bias_i, dtype=np.float64) - pim.bias_hat
    zeta = (pim.preintegrated + pim.preintegrated_H_bias_acc @ delta_b[:3]
            + pim.preintegrated_H_bias_omega @ delta_b[3:])
    theta, delta_p, delta_v = zeta[:3], zeta[3:6], zeta[6:]
    dt, g = pim.delta_t_ij, pim.params.n_gravity
    rot_hat = rot_i @ so3.exp(theta)
    p_hat = p_i + dt * v_i + 0.5 * dt * dt * g + rot_i @ delta_p
    v_hat = v_i + dt * g + rot_i @ delta_v
    return rot_hat, p_hat, v_hat


def combined_imu_error(
    rot_i: np.ndarray, p_i: np.ndarray, v_i: np.ndarray,
    rot_j: np.ndarray, p_j: np.ndarray, v_j: np.ndarray,
    bias_i: np.ndarray, bias_j: np.ndarray,
    pim: PreintegratedCombinedMeasurements, mode: str = "logmap",
) -> np.ndarray:
    """GTSAM 4.3 ``CombinedImuFactor`` unwhitened error (15,) at poses (R, p), velocities v and
    biases [acc, gyro] of keyframes i and j.

    With X̂_j from :func:`predicted_state`, φ = Log(R_jᵀ·R̂_j), e_p = R_jᵀ(p̂_j − p_j) and
    e_v = R_jᵀ(v̂_j − v_j):

    - ``mode="componentwise"`` (``ImuFactorErrorMode.ComponentWise``, = ``Legacy`` for the tangent
      preintegration; GTSAM ≤ 4.2's error):  r = [φ, e_p, e_v, b_i − b_j]
    - ``mode="logmap"`` (``ImuFactorErrorMode.Logmap``, 4.3's default; r = SE_2(3) Log(X_j⁻¹·X̂_j)):
      r = [φ, Jl⁻¹(φ)·e_p, Jl⁻¹(φ)·e_v, b_i − b_j]  with Jl⁻¹(φ) = Jr⁻¹(−φ).
    """
    rot_hat, p_hat, v_hat = predicted_state(rot_i, p_i, v_i, bias_i, pim)
    phi = so3.log(rot_j.T @ rot_hat)
    e_p = rot_j.T @ (p_hat - p_j)
    e_v = rot_j.T @ (v_hat - v_j)
    if mode == "logmap":
        jl_inv = so3.right_jacobian_inv(-phi)
        e_p, e_v = jl_inv @ e_p, jl_inv @ e_v
    elif mode != "componentwise":
        raise ValueError(f"mode must be 'logmap' or 'componentwise', got {mode!r}")
    e_bias = np.asarray(bias_i, dtype=np.float64) - np.asarray(bias_j, dtype=np.float64)
    return np.concatenate([phi, e_p, e_v, e_bias])


# The KITTI IMU log reader lives in fgc.data (examples use it too); re-exported for the tests.
from fgc.interop.gtsam_data import ImuLog, kitti_params, read_kitti_imu  # noqa: E402, F401
