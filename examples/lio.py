"""Paper A's LiDAR-inertial odometry chain on the KITTI data shipped in the gtsam wheel.

Keyframes sit at the GPS fixes of ``KittiGps_converted.txt`` (about 1 Hz). Between consecutive
keyframes: a ``CombinedImuFactor`` preintegrating the real KITTI IMU samples
(``KittiEquivBiasedImu.txt``) and a ``LidarOdometryFactor``; on every keyframe a ``GPSFactor``;
priors on the first pose, velocity and bias.

There is no LiDAR in the data: the LiDAR-odometry measurements are *synthesised* from a reference
trajectory — orientation from integrating the gyroscope from the initial GPS heading (the car
drives along its body x axis), position from the GPS fixes — as the relative pose between
consecutive reference keyframes, perturbed by Gaussian noise (``lidar_sigma_rot`` rad,
``lidar_sigma_pos`` m, seeded). Initial values are the same reference
poses, velocities from central differences of the GPS fixes, zero biases.

    fgc verify examples/lio.py -p N=30
"""

from __future__ import annotations

import numpy as np

import fgc
from fgc.data import example_data_file, kitti_params, read_kitti_imu
from fgc.factors import CombinedImuFactor, GPSFactor, LidarOdometryFactor, PriorFactor
from fgc.geometry import ImuBias, Pose3, Rot3, Vector3
from fgc.preintegration import PreintegratedCombinedMeasurements


def read_gps(path) -> tuple[np.ndarray, np.ndarray]:
    """``KittiGps_converted.txt``: header, then ``time,x,y,z`` rows → (times, positions)."""
    table = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    if table.shape[1] != 4:
        raise fgc.DataError(f"{path}: expected 4 comma-separated columns")
    return table[:, 0], table[:, 1:4]


def _preintegrate(log, params, t0: float, t1: float) -> PreintegratedCombinedMeasurements:
    pim = PreintegratedCombinedMeasurements(params)
    for k in np.flatnonzero((log.time > t0) & (log.time <= t1)):
        pim.integrate_measurement(log.acc[k], log.gyro[k], log.dt[k])
    if pim.num_samples == 0:
        raise fgc.DataError(f"lio: no IMU samples between GPS times {t0} and {t1}")
    return pim


def _velocities(times: np.ndarray, pos: np.ndarray) -> np.ndarray:
    return np.gradient(pos, times, axis=0)


def build(N: int = 30, first: int = 1, gps_sigma: float = 1.0,  # noqa: N803 - paper's N
          lidar_sigma_rot: float = 0.01, lidar_sigma_pos: float = 0.05, seed: int = 0,
          error_mode: str = "logmap", keyframe_dt: float | None = None) -> fgc.Graph:
    """``N`` keyframes from GPS fix ``first``: at the fixes (about 1 Hz, at most 470), or every
    ``keyframe_dt`` seconds (positions interpolated between fixes, a GPS factor only on the
    keyframe nearest each fix) — e.g. ``keyframe_dt=0.4`` gives room for N = 1000."""
    times, gps = read_gps(example_data_file("KittiGps_converted.txt"))
    t, p, fixes = _keyframes(times, gps, N, first, keyframe_dt)
    log = read_kitti_imu(example_data_file("KittiEquivBiasedImu.txt"))
    params = kitti_params(example_data_file("KittiEquivBiasedImu_metadata.txt"))
    params = params.replace(error_mode=error_mode)
    pims = [_preintegrate(log, params, t[i], t[i + 1]) for i in range(N - 1)]
    vel = _velocities(t, p)
    heading = np.arctan2(vel[0, 1], vel[0, 0])  # the car drives along its body x axis
    rots = [Rot3.RzRyRx(0.0, 0.0, heading).R]
    for pim in pims:
        rots.append(rots[-1] @ pim.delta_R_ij)
    ref = [Pose3(Rot3(r), x) for r, x in zip(rots, p, strict=True)]
    graph = fgc.Graph()
    for i in range(N):
        graph.add_variable(f"x{i}", ref[i])
        graph.add_variable(f"v{i}", Vector3(vel[i]))
        graph.add_variable(f"b{i}", ImuBias(np.zeros(6)))
    _add_factors(graph, N, pims, ref, fixes, gps_sigma, lidar_sigma_rot, lidar_sigma_pos, seed)
    return graph


def _keyframes(times, gps, n: int, first: int, dt: float | None):
    """Keyframe times, reference positions and the GPS fixes [(keyframe, position)]."""
    if n < 2:
        raise fgc.DataError(f"lio: N={n}: N must be at least 2 keyframes")
    if not 0 <= first < len(times):
        raise fgc.DataError(f"lio: first={first}: first must be a GPS fix index from 0 to "
                            f"{len(times) - 1}")
    if dt is None:
        if first + n > len(times):
            raise fgc.DataError(f"lio: N={n} keyframes from GPS fix {first} exceed the "
                                f"{len(times)} fixes in the data")
        t, p = times[first:first + n], gps[first:first + n]
        return t, p, list(enumerate(p))
    t = times[first] + dt * np.arange(n)
    if n < 2 or not dt > 0 or t[-1] > times[-1]:
        raise fgc.DataError(f"lio: N={n} keyframes every {dt} s from GPS fix {first} run past "
                            f"the data's last fix ({times[-1] - times[first]:.0f} s later)")
    p = np.stack([np.interp(t, times, gps[:, c]) for c in range(3)], axis=1)
    fixes = []
    for j in range(first, len(times)):
        k = int(round((times[j] - t[0]) / dt))
        if 0 <= k < n and abs(t[k] - times[j]) <= dt / 2:
            fixes.append((k, gps[j]))
    return t, p, fixes


def _add_factors(graph, n, pims, ref, gps, gps_sigma, sigma_rot, sigma_pos, seed) -> None:
    rng = np.random.default_rng(seed)
    graph.add(PriorFactor("x0", ref[0], fgc.noise.diagonal([0.1] * 3 + [1.0] * 3)))
    graph.add(PriorFactor("v0", graph.variables["v0"].initial, fgc.noise.isotropic(3, 1.0)))
    graph.add(PriorFactor("b0", ImuBias(np.zeros(6)), fgc.noise.isotropic(6, 0.1)))
    lidar_noise = fgc.noise.diagonal([sigma_rot] * 3 + [sigma_pos] * 3)
    for i in range(n - 1):
        graph.add(CombinedImuFactor(f"x{i}", f"v{i}", f"x{i + 1}", f"v{i + 1}", f"b{i}",
                                    f"b{i + 1}", pims[i]))
        noise = np.concatenate([rng.normal(size=3) * sigma_rot, rng.normal(size=3) * sigma_pos])
        measured = ref[i].between(ref[i + 1]).retract(noise)
        graph.add(LidarOdometryFactor(f"x{i}", f"x{i + 1}", measured, lidar_noise))
    for i, position in gps:
        graph.add(GPSFactor(f"x{i}", position, fgc.noise.isotropic(3, gps_sigma)))
