"""Locating the example data files that ship inside the gtsam wheel (without importing gtsam)."""

from __future__ import annotations

import importlib.util
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from fgc.errors import DataError
from fgc.frontend.preintegration import ImuParams


def gtsam_data_dir() -> Path:
    spec = importlib.util.find_spec("gtsam")
    if spec is None or not spec.submodule_search_locations:
        raise DataError("the gtsam package is not installed; its wheel carries the example data")
    return Path(next(iter(spec.submodule_search_locations))) / "Data"


def example_data_file(name: str) -> Path:
    """Path of ``name``: an existing path as given, else a file of the gtsam wheel's data."""
    p = Path(name)
    if p.is_file():
        return p
    candidate = gtsam_data_dir() / name
    if candidate.is_file() and candidate.resolve().parent == gtsam_data_dir().resolve():
        return candidate
    raise DataError(f"data file {name!r} not found (neither a path nor in gtsam's example data)")


# ------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ImuLog:
    """IMU samples: time (N,), dt (N,), acc (N, 3) m/s², gyro (N, 3) rad/s."""

    time: np.ndarray
    dt: np.ndarray
    acc: np.ndarray
    gyro: np.ndarray


def read_kitti_imu(path: str | Path) -> ImuLog:
    """Read ``KittiEquivBiasedImu.txt``: a header line, then rows ``time dt ax ay az wx wy wz``.

    The first row has no predecessor (its dt field is the absolute time); callers skip it.
    """
    table = np.loadtxt(path, skiprows=1, ndmin=2)
    if table.shape[1] != 8:
        raise DataError(f"{path}: expected 8 columns, got {table.shape[1]}")
    return ImuLog(time=table[:, 0], dt=table[:, 1], acc=table[:, 2:5], gyro=table[:, 5:8])


def kitti_params(metadata_path: str | Path, g: float = 9.8) -> ImuParams:
    """ImuParams from ``KittiEquivBiasedImu_metadata.txt`` (header line, then one row of 12
    numbers: body pose (6), σ_acc, σ_gyro, σ_int, σ_bias_acc, σ_bias_gyro, mean dt), as GTSAM's
    ``IMUKittiExampleGPS.py`` uses them (Z-up, g = 9.8). The body pose must be zero."""
    row = np.loadtxt(metadata_path, skiprows=1, ndmin=1)
    if row.shape != (12,) or np.any(row[:6] != 0.0):
        raise DataError(f"{metadata_path}: expected 12 numbers with a zero body pose")
    sigma_acc, sigma_gyro, sigma_int, sigma_bias_acc, sigma_bias_gyro = row[6:11]
    eye = np.eye(3)
    return ImuParams.make_u(
        g,
        accelerometer_covariance=sigma_acc**2 * eye,
        gyroscope_covariance=sigma_gyro**2 * eye,
        integration_covariance=sigma_int**2 * eye,
        bias_acc_covariance=sigma_bias_acc**2 * eye,
        bias_omega_covariance=sigma_bias_gyro**2 * eye,
    )
