"""Small timing formulas shared by the linear-solver units."""

from __future__ import annotations

import heapq
import math
from collections.abc import Sequence

from .params import OperatorTable


def dot_cycles(length: int, lanes: int, ops: OperatorTable) -> int:
    """Latency of a length-``length`` dot product on ``lanes`` pipelined multiply-add lanes.

    Products stream at ``lanes`` a cycle into interleaved partial sums (so a floating-point
    adder of latency L_add still accepts one product a cycle), then a tree of adders folds the
    partial sums: ⌈length/lanes⌉ + L_mul + L_add·(1 + ⌈log₂ min(length, lanes·L_add)⌉).
    """
    if length <= 0:
        return 0
    partials = max(1, min(length, lanes * ops.add.latency))
    tree = math.ceil(math.log2(partials)) if partials > 1 else 0
    return math.ceil(length / lanes) + ops.mul.latency + ops.add.latency * (1 + tree)


def makespan(durations: Sequence[int], sets: int) -> int:
    """Cycles to run independent jobs on ``sets`` identical units (longest job first)."""
    if not durations:
        return 0
    loads = [0] * max(1, sets)
    for d in sorted(durations, reverse=True):
        heapq.heapreplace(loads, loads[0] + d)
    return max(loads)
