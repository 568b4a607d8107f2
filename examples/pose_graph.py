"""Pose-graph SLAM from a g2o/TORO file (Pose2 or Pose3), anchored by a prior on the first pose.

    fgc verify examples/pose_graph.py                         # w100.graph (TORO, Pose2)
    fgc verify examples/pose_graph.py -p dataset=pose3example.txt
    fgc verify examples/pose_graph.py -p dataset=path/to/my.g2o

``dataset`` is a path or the name of a file in the gtsam wheel's example data.
"""

from __future__ import annotations

import numpy as np

import fgc
from fgc.data import example_data_file
from fgc.factors import PriorFactor
from fgc.io import read_pose_graph


def build(dataset: str = "w100.graph", prior_sigma: float = 1e-3,
          init: str = "odometry") -> fgc.Graph:
    """Any file GTSAM's load2D/load3D read (fgc.io refuses what it cannot represent);
    ``init`` (odometry | chordal) seeds variables the file gives no vertex for."""
    graph = read_pose_graph(example_data_file(dataset), init=init)
    first = next(iter(graph.variables.values()))
    dim = first.type.dim
    graph.add(PriorFactor(first.key, first.initial, fgc.noise.isotropic(dim, prior_sigma)))
    return graph


if __name__ == "__main__":
    g = build()
    print(g, "initial error", round(g.error(), 3), np.__name__)
