"""A Pose2 loop: n poses on a circle of radius 3 m, noisy odometry closing the loop, a prior on
pose 0; the fixed-point example (tests/native/test_native_fixed.py, bench/bench_fixed.py).

    fgc run examples/pose2_loop.py --backend native --scalar "ap_fixed<64,35>"
    python bench/bench_fixed.py      # ap_fixed<40,16> with LM's damping bound lowered to 1e4

(``--scalar "ap_fixed<40,16>"`` is refused: LM's default damping bound 1e10 does not fit it.)
"""

import numpy as np

import fgc
from fgc import Pose2, noise
from fgc.factors import BetweenFactor, PriorFactor


def build(n: int = 8, seed: int = 5) -> fgc.Graph:
    rng = np.random.default_rng(seed)
    truth = [Pose2(3 * np.cos(2 * np.pi * i / n), 3 * np.sin(2 * np.pi * i / n),
                   2 * np.pi * i / n + np.pi / 2) for i in range(n)]
    graph = fgc.Graph()
    for i, pose in enumerate(truth):
        graph.add_variable(i, pose.retract(0.1 * rng.standard_normal(3)))
    graph.add(PriorFactor(0, truth[0], noise.isotropic(3, 0.1)))
    for i in range(n):
        j = (i + 1) % n
        measured = truth[i].between(truth[j]).retract(0.05 * rng.standard_normal(3))
        graph.add(BetweenFactor(i, j, measured, noise.diagonal([0.2, 0.2, 0.1])))
    return graph
