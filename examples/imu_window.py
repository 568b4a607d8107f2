"""Paper B's IMU state window: N states (pose, velocity, bias) joined by CombinedImuFactors built
from the real KITTI IMU log in the gtsam wheel (``KittiEquivBiasedImu.txt``), solved by LM.

There is no vision front end here, so the window is anchored by priors on the first state (pose at
the origin, velocity from ``v0``, zero bias). Initial values are the IMU dead-reckoning prediction
perturbed by ``init_noise`` (deterministic seed), so the optimiser has real work to do.

    fgc verify examples/imu_window.py -p N=20

Conditioning: with priors on the first state only, the window has an exact zero-error solution
and strongly unequal row scales (bias random-walk rows weigh ~1e6). QR handles it (fgc and GTSAM's
multifrontal QR agree to 1e-10 at N = 20, 50, 80); GTSAM's multifrontal Cholesky stalls at N ≥ 50,
and in float32 Cholesky (which squares the condition number) misses the 1 mrad / 1 cm bounds at
N ≥ 50 while float32 QR stays within 4e-5 m.
"""

from __future__ import annotations

import numpy as np

import fgc
from fgc.data import example_data_file, kitti_params, read_kitti_imu
from fgc.factors import CombinedImuFactor, PriorFactor
from fgc.geometry import ImuBias, Pose3, Rot3, Vector3
from fgc.preintegration import PreintegratedCombinedMeasurements


def _integrate(log, params, start: int, count: int) -> PreintegratedCombinedMeasurements:
    pim = PreintegratedCombinedMeasurements(params)
    for k in range(start, start + count):
        pim.integrate_measurement(log.acc[k], log.gyro[k], log.dt[k])
    return pim


def build(N: int = 20, samples_per_state: int = 10, v0: float = 8.0,  # noqa: N803 - paper's N
          init_noise: float = 0.05, error_mode: str = "logmap", seed: int = 0) -> fgc.Graph:
    if N < 2:
        raise fgc.DataError(f"imu_window: N must be at least 2, got {N}")
    log = read_kitti_imu(example_data_file("KittiEquivBiasedImu.txt"))
    params = kitti_params(example_data_file("KittiEquivBiasedImu_metadata.txt"))
    params = params.replace(error_mode=error_mode)
    if 1 + (N - 1) * samples_per_state > len(log.dt):
        raise fgc.DataError(f"imu_window: N={N} needs more IMU samples than the log has")
    rng = np.random.default_rng(seed)
    graph = fgc.Graph()
    pose, vel, bias = Pose3.identity(), np.array([v0, 0.0, 0.0]), np.zeros(6)
    pims = [_integrate(log, params, 1 + i * samples_per_state, samples_per_state)
            for i in range(N - 1)]
    for i in range(N):
        jitter = Pose3.Expmap(rng.normal(size=6) * init_noise) if i else Pose3.identity()
        graph.add_variable(f"x{i}", pose.compose(jitter))
        graph.add_variable(f"v{i}", Vector3(vel + (rng.normal(size=3) * init_noise if i else 0)))
        graph.add_variable(f"b{i}", ImuBias(bias))
        if i < N - 1:
            rot, pos, vel = pims[i].predict((pose.r.R, pose.t), vel, bias)
            pose = Pose3(Rot3(rot), pos)
    for i, pim in enumerate(pims):
        graph.add(CombinedImuFactor(f"x{i}", f"v{i}", f"x{i + 1}", f"v{i + 1}", f"b{i}",
                                    f"b{i + 1}", pim))
    graph.add(PriorFactor("x0", Pose3.identity(), fgc.noise.isotropic(6, 1e-3)))
    graph.add(PriorFactor("v0", Vector3([v0, 0.0, 0.0]), fgc.noise.isotropic(3, 1e-2)))
    graph.add(PriorFactor("b0", ImuBias(np.zeros(6)), fgc.noise.isotropic(6, 1e-2)))
    return graph
