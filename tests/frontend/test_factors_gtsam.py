"""Every built-in factor against GTSAM's factor of the same name, at random points.

Tolerance: whitened Jacobian blocks A and right-hand side b = −R·r equal GTSAM's
``factor.linearize(values)`` to ≤ 1e-9 relative to max(1, |A|max, |b|max), float64.
Points: random values anywhere on the manifold (rotations uniform in angle up to π), plus cases
whose rotations are the identity, 1e-8 and 1e-4 rad from it, and 1e-6 rad from π.
"""

from __future__ import annotations

import numpy as np
import pytest

import fgc
from fgc.frontend import noise
from fgc.frontend.factors import (
    BearingRangeFactor,
    BetweenFactor,
    CombinedImuFactor,
    GPSFactor,
    LidarOdometryFactor,
    PriorFactor,
)
from fgc.frontend.geometry import ImuBias, Point2, Point3, Pose2, Pose3, Rot2, Rot3, Vector3
from fgc.frontend.preintegration import ImuParams, PreintegratedCombinedMeasurements
from fgc.interop.to_gtsam import linearization_error

TOL = 1e-9
N_POINTS = 100
SPECIAL_ANGLES = (0.0, 1e-8, 1e-4, np.pi - 1e-6)


def _rot_at(angle: float, rng) -> Rot3:
    axis = rng.normal(size=3)
    return Rot3.Expmap(axis / np.linalg.norm(axis) * angle)


def _pose3(rng, i: int) -> Pose3:
    """Random Pose3; the first cases sit at the special angles."""
    if i < len(SPECIAL_ANGLES):
        return Pose3(_rot_at(SPECIAL_ANGLES[i], rng), rng.normal(size=3) * 3)
    return Pose3.random(rng, 3.0)


def _pose3_pair(rng, i: int) -> tuple[Pose3, Pose3]:
    """Two poses whose *relative* rotation hits the special angles in the first cases."""
    a = Pose3.random(rng, 3.0)
    if i < len(SPECIAL_ANGLES):
        return a, a.compose(_pose3(rng, i))
    return a, Pose3.random(rng, 3.0)


def _check(graph: fgc.Graph) -> None:
    err = linearization_error(graph)
    assert err <= TOL, f"max relative difference to GTSAM {err:.3e} > {TOL}"


def _noise(dim: int, rng, kind: str):
    if kind == "isotropic":
        return noise.isotropic(dim, 0.3)
    if kind == "diagonal":
        return noise.diagonal(rng.uniform(0.05, 2.0, size=dim))
    m = rng.normal(size=(dim, dim))
    return noise.covariance(m @ m.T + dim * np.eye(dim))


KINDS = ("isotropic", "diagonal", "full")


@pytest.mark.parametrize("kind", KINDS)
def test_between_pose3(kind):
    rng = np.random.default_rng(1)
    for i in range(N_POINTS):
        a, b = _pose3_pair(rng, i)
        z = _pose3(rng, i) if i < 4 else Pose3.random(rng, 3.0)
        g = fgc.Graph().add_variable("a", a).add_variable("b", b)
        g.add(BetweenFactor("a", "b", z, _noise(6, rng, kind)))
        _check(g)


@pytest.mark.parametrize("kind", KINDS)
def test_prior_pose3_and_lidar(kind):
    rng = np.random.default_rng(2)
    for i in range(N_POINTS):
        x, prior = _pose3_pair(rng, i)
        y = Pose3.random(rng, 3.0)
        g = fgc.Graph().add_variable("x", x).add_variable("y", y)
        g.add(PriorFactor("x", prior, _noise(6, rng, kind)))
        g.add(LidarOdometryFactor("x", "y", Pose3.random(rng, 1.0), _noise(6, rng, kind)))
        _check(g)


@pytest.mark.parametrize("t", [Pose2, Rot2, Rot3, Point2, Point3, ImuBias, Vector3])
def test_prior_and_between_every_type(t):
    rng = np.random.default_rng(3)
    for i in range(N_POINTS):
        a, b, z = t.random(rng, 2.0), t.random(rng, 2.0), t.random(rng, 2.0)
        if t is Rot3 and i < len(SPECIAL_ANGLES):
            b = a.compose(_rot_at(SPECIAL_ANGLES[i], rng))
            z = _rot_at(SPECIAL_ANGLES[i], rng)
        g = fgc.Graph().add_variable("a", a).add_variable("b", b)
        g.add(PriorFactor("a", z, _noise(t.dim, rng, "diagonal")))
        if t is not Vector3:  # GTSAM's Python wrapper has no BetweenFactorVector
            g.add(BetweenFactor("a", "b", z, _noise(t.dim, rng, "full")))
        _check(g)


def test_gps():
    rng = np.random.default_rng(4)
    for i in range(N_POINTS):
        g = fgc.Graph().add_variable("x", _pose3(rng, i))
        g.add(GPSFactor("x", rng.normal(size=3) * 5, _noise(3, rng, "diagonal")))
        _check(g)


def test_bearing_range_2d():
    rng = np.random.default_rng(5)
    for _ in range(N_POINTS):
        g = fgc.Graph().add_variable("x", Pose2.random(rng, 3.0))
        g.add_variable("l", Point2(rng.normal(size=2) * 5))
        g.add(BearingRangeFactor("x", "l", Rot2.fromAngle(rng.uniform(-3, 3)),
                                 rng.uniform(0.5, 8), _noise(2, rng, "diagonal")))
        _check(g)


@pytest.mark.parametrize("loss", ["huber", "cauchy"])
def test_robust_between(loss):
    rng = np.random.default_rng(6)
    robust = noise.huber if loss == "huber" else noise.cauchy
    for _ in range(N_POINTS):
        a, b = Pose3.random(rng, 3.0), Pose3.random(rng, 3.0)
        g = fgc.Graph().add_variable("a", a).add_variable("b", b)
        g.add(BetweenFactor("a", "b", Pose3.random(rng), robust(1.345, _noise(6, rng, "diagonal"))))
        _check(g)


def _random_pim(rng, mode: str) -> PreintegratedCombinedMeasurements:
    params = ImuParams.make_u(9.81, accelerometer_covariance=0.01 * np.eye(3),
                              gyroscope_covariance=1e-4 * np.eye(3),
                              integration_covariance=1e-8 * np.eye(3),
                              bias_acc_covariance=1e-6 * np.eye(3),
                              bias_omega_covariance=1e-8 * np.eye(3), error_mode=mode)
    pim = PreintegratedCombinedMeasurements(params, rng.normal(size=6) * 0.05)
    for _ in range(int(rng.integers(2, 12))):
        pim.integrate_measurement(rng.normal(size=3) * 2 + [0, 0, 9.81], rng.normal(size=3),
                                  0.01)
    return pim


# componentwise is heavy (about 15 s): logmap keeps the combined IMU factor against GTSAM by default
@pytest.mark.parametrize("mode", ["logmap", pytest.param("componentwise", marks=pytest.mark.heavy)])
def test_combined_imu(mode):
    rng = np.random.default_rng(7)
    for i in range(N_POINTS):
        pose_i, pose_j = _pose3_pair(rng, i)
        g = fgc.Graph()
        for k, v in (("xi", pose_i), ("xj", pose_j), ("vi", Vector3(rng.normal(size=3))),
                     ("vj", Vector3(rng.normal(size=3))), ("bi", ImuBias(rng.normal(size=6) * .1)),
                     ("bj", ImuBias(rng.normal(size=6) * 0.1))):
            g.add_variable(k, v)
        g.add(CombinedImuFactor("xi", "vi", "xj", "vj", "bi", "bj", _random_pim(rng, mode)))
        _check(g)


def test_imu_error_mode_is_pinned():
    """The GTSAM twin is built with the factor's own error mode, never GTSAM's default: at a
    point where the two modes' errors differ, each twin's error is its own factor's."""
    from fgc.interop.to_gtsam import to_gtsam

    rng = np.random.default_rng(8)
    pim = _random_pim(rng, "componentwise")
    pose_i, pose_j = _pose3_pair(rng, 3)
    values = (("xi", pose_i), ("xj", pose_j), ("vi", Vector3(rng.normal(size=3))),
              ("vj", Vector3(rng.normal(size=3))), ("bi", ImuBias(rng.normal(size=6) * .1)),
              ("bj", ImuBias(rng.normal(size=6) * 0.1)))
    ours, twins = [], []
    for mode, type_name in (("componentwise", "CombinedImuFactorComponentWise"),
                            ("logmap", "CombinedImuFactor")):
        g = fgc.Graph()
        for k, v in values:
            g.add_variable(k, v)
        g.add(CombinedImuFactor("xi", "vi", "xj", "vj", "bi", "bj", pim, error_mode=mode))
        assert g.factors[0].type.name == type_name
        problem = to_gtsam(g)
        ours.append(g.error())
        twins.append(problem.graph.error(problem.values))
    assert abs(ours[0] - ours[1]) > 1e-3 * max(ours)      # the two modes differ at this point
    assert np.allclose(twins, ours, rtol=1e-9, atol=0)
