"""GTSAM's twins of fgc's built-in factors: one table, read by the exporter
(:mod:`fgc.interop.to_gtsam`, fgc → GTSAM) and the importer (:mod:`fgc.interop.from_gtsam`,
GTSAM → fgc), so the two directions cannot disagree on which factors have a native twin.

Keys are fgc variable type names; ``"Vector"`` stands for every vector space (``Vector1`` …,
GTSAM's dynamic-size ``PriorFactorVector`` / ``BetweenFactorVector``). Values are GTSAM class
names (looked up on the ``gtsam`` module only when a conversion runs).
"""

from __future__ import annotations

PRIOR = {"Pose3": "PriorFactorPose3", "Pose2": "PriorFactorPose2", "Rot3": "PriorFactorRot3",
         "Rot2": "PriorFactorRot2", "Point3": "PriorFactorPoint3", "Point2": "PriorFactorPoint2",
         "ImuBias": "PriorFactorConstantBias", "Vector": "PriorFactorVector"}
BETWEEN = {"Pose3": "BetweenFactorPose3", "Pose2": "BetweenFactorPose2",
           "Rot3": "BetweenFactorRot3", "Rot2": "BetweenFactorRot2",
           "Point3": "BetweenFactorPoint3", "Point2": "BetweenFactorPoint2",
           "ImuBias": "BetweenFactorConstantBias", "Vector": "BetweenFactorVector"}
# (pose type, target type) → GTSAM RangeFactor<pose, target>
RANGE = {("Pose2", "Point2"): "RangeFactor2D", ("Pose3", "Point3"): "RangeFactor3D",
         ("Pose2", "Pose2"): "RangeFactorPose2", ("Pose3", "Pose3"): "RangeFactorPose3"}
GPS = "GPSFactor"
BEARING_RANGE = "BearingRangeFactor2D"
COMBINED_IMU = "CombinedImuFactor"


def table_key(type_name: str) -> str:
    """The twin tables' key for an fgc variable type: vector spaces share ``"Vector"``."""
    if type_name.startswith("Vector") and type_name[6:].isdigit():
        return "Vector"
    return type_name
