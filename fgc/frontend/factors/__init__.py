"""Built-in factors, each with the meaning of GTSAM's factor of the same name.

Constructors read like GTSAM's Python API: ``BetweenFactor("x1", "x2", Pose3(...), noise)``.
Each factor type also knows how to build its GTSAM twin (:func:`fgc.interop.to_gtsam.to_gtsam`).
"""

from fgc.frontend.factors.basic import BetweenFactor, GPSFactor, LidarOdometryFactor, PriorFactor
from fgc.frontend.factors.bearing_range import BearingRangeFactor
from fgc.frontend.factors.imu import CombinedImuFactor, combined_imu_factor_type

__all__ = [
    "BearingRangeFactor",
    "BetweenFactor",
    "CombinedImuFactor",
    "GPSFactor",
    "LidarOdometryFactor",
    "PriorFactor",
    "combined_imu_factor_type",
]
