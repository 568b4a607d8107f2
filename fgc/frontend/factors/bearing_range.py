"""Bearing-range factor from a Pose2 to a Point2 landmark."""

from __future__ import annotations

from fgc.frontend.dsl import Factor, factor
from fgc.frontend.geometry import Point2, Pose2, Rot2
from fgc.frontend.geometry.base import column
from fgc.frontend.noise import NoiseModel


@factor(name="BearingRangeFactor2D")
def bearing_range_2d(pose: Pose2, point: Point2, *, bearing: Rot2, range: float):  # noqa: A002
    """GTSAM ``BearingRangeFactor2D``: [bearing.local(pose.bearing(point)), range(pose, point) −
    measured range]."""
    b = bearing.local(pose.bearing(point))
    return column([b[0], pose.range(point) - range], True)


bearing_range_2d.gtsam_kind = ("bearing_range", "Pose2")


def BearingRangeFactor(pose_key, point_key, bearing: Rot2, range: float,  # noqa: A002
                       noise: NoiseModel, name: str | None = None) -> Factor:
    """Bearing (a Rot2, in the pose's frame) and range from pose ``pose_key`` to a landmark."""
    return bearing_range_2d(pose_key, point_key, bearing=bearing, range=float(range),
                            noise=noise, name=name)

