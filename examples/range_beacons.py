"""The README tutorial: a robot (Pose2) drives an arc, measuring odometry and its range to two
beacons (Point2) whose positions are roughly known.

    fgc verify examples/range_beacons.py
"""

import numpy as np

import fgc
from fgc import Point2, Pose2, noise
from fgc.factors import BetweenFactor, PriorFactor


@fgc.factor
def range_to_beacon(pose: Pose2, beacon: Point2, *, measured: float):
    """Distance from the robot to a beacon, minus the measured range."""
    return [pose.range(beacon) - measured]


def build(steps: int = 20, seed: int = 0) -> fgc.Graph:
    if steps < 1:
        raise fgc.DataError(f"range_beacons: steps={steps}: steps must be at least 1")
    rng = np.random.default_rng(seed)
    graph = fgc.Graph()
    beacons = {"b0": Point2(5.0, 5.0), "b1": Point2(-5.0, 8.0)}
    for key, where in beacons.items():
        graph.add_variable(key, where)
        graph.add(PriorFactor(key, where, noise.isotropic(2, 0.01)))
    truth = [Pose2(0.0, 0.0, 0.0)]
    for _ in range(1, steps):
        truth.append(truth[-1].compose(Pose2(1.0, 0.0, 0.1)))
    for i, pose in enumerate(truth):
        graph.add_variable(f"x{i}", pose.retract(rng.normal(size=3) * 0.1))
    graph.add(PriorFactor("x0", truth[0], noise.isotropic(3, 0.01)))
    for i in range(1, steps):
        odometry_noise = noise.diagonal([0.05, 0.05, 0.02])
        graph.add(BetweenFactor(f"x{i - 1}", f"x{i}", Pose2(1.0, 0.0, 0.1), odometry_noise))
        for key, where in beacons.items():
            measured = truth[i].range(where) + rng.normal() * 0.05
            graph.add(range_to_beacon(f"x{i}", key, measured=measured,
                                      noise=noise.isotropic(1, 0.05)))
    return graph
