"""Prior, between, GPS and LiDAR-odometry factors."""

from __future__ import annotations

from functools import cache

from fgc.errors import DslError
from fgc.frontend.dsl import Factor, FactorType, factor
from fgc.frontend.geometry import LieGroup, Point3, Pose3
from fgc.frontend.noise import NoiseModel


@cache
def prior_factor_type(t: type[LieGroup]) -> FactorType:
    """``PriorFactor<T>``: error = prior.local(x) (GTSAM ``traits<T>::Local(prior, x)``)."""

    def prior(x: t, *, prior: t):
        return prior.local(x)

    prior.__annotations__ = {"x": t, "prior": t}
    ftype = factor(prior, name=f"PriorFactor{t.__name__}")
    ftype.gtsam_kind = ("prior", t.__name__)
    return ftype


@cache
def between_factor_type(t: type[LieGroup], name: str | None = None) -> FactorType:
    """``BetweenFactor<T>``: error = measured.local(x1.between(x2))."""

    def between(x1: t, x2: t, *, measured: t):
        return measured.local(x1.between(x2))

    between.__annotations__ = {"x1": t, "x2": t, "measured": t}
    ftype = factor(between, name=name or f"BetweenFactor{t.__name__}")
    ftype.gtsam_kind = ("between", t.__name__)
    return ftype


def _value_type(value, what: str) -> type[LieGroup]:
    if not isinstance(value, LieGroup):
        raise DslError(f"{what}: expected a geometry value (Pose3, Point2, ...), got "
                       f"{type(value).__name__}")
    return type(value)


def PriorFactor(key, prior: LieGroup, noise: NoiseModel, name: str | None = None) -> Factor:
    """Prior on variable ``key`` at value ``prior`` (its type picks the factor type)."""
    t = _value_type(prior, "PriorFactor prior")
    return prior_factor_type(t)(key, prior=prior, noise=noise, name=name)


def BetweenFactor(key1, key2, measured: LieGroup, noise: NoiseModel,
                  name: str | None = None) -> Factor:
    """Relative measurement ``measured`` ≈ x1⁻¹·x2 between ``key1`` and ``key2``."""
    t = _value_type(measured, "BetweenFactor measured")
    return between_factor_type(t)(key1, key2, measured=measured, noise=noise, name=name)


@factor(name="GPSFactor")
def gps_factor(pose: Pose3, *, position: Point3):
    """GTSAM ``GPSFactor``: error = pose.translation() − position (navigation frame)."""
    return pose.translation() - position


gps_factor.gtsam_kind = ("gps", "Pose3")


def GPSFactor(key, position, noise: NoiseModel, name: str | None = None) -> Factor:
    """Position fix of pose ``key`` (3-vector in the navigation frame)."""
    return gps_factor(key, position=Point3(position) if not isinstance(position, Point3)
                      else position, noise=noise, name=name)


lidar_odometry_factor = between_factor_type(Pose3, "LidarOdometryFactor")


def LidarOdometryFactor(key1, key2, measured: Pose3, noise: NoiseModel,
                        name: str | None = None) -> Factor:
    """LiDAR odometry between keyframes: a Pose3 between factor under its own name, so it is
    fused and reported as the LIO paper's LiDAR factor."""
    if not isinstance(measured, Pose3):
        raise DslError(f"LidarOdometryFactor measured must be a Pose3, got "
                       f"{type(measured).__name__}")
    return lidar_odometry_factor(key1, key2, measured=measured, noise=noise, name=name)
