"""Published figures the cost model is calibrated against, and the assumptions that tie them to it.

Paper B (docs/design.md) reports whole-solve latencies of its IMU-window accelerator (ZC706,
143 MHz, float32) and Vivado power estimates of three built designs. Paper A reports the
two-ended over serial speed-up on the LIO chain. ``tests/hls/test_cost.py`` checks the model against
them within the tolerances below; ``bench/bench_cost_model.py`` prints the comparison.

**Iterations.** Paper B replaces VINS-Fusion's Ceres back end, whose EuRoC configurations cap the
solver at ``max_num_iterations: 8`` to stay real-time; its own solver stops at k_max too. We
assume that budget is always used: 8 LM iterations, each relinearising (no rejected steps). With
:class:`CostParams`' defaults the two N = 50 points then come out within ±15 %.
"""

from __future__ import annotations

from dataclasses import dataclass

PAPER_B_ITERATIONS = 8  # VINS-Fusion's max_num_iterations on EuRoC (see module docstring)
PAPER_B_MAX_N = 80  # "the design handles at most N = 80 states"


@dataclass(frozen=True)
class LatencyPoint:
    """A published whole-solve latency: window size N, #CPE, milliseconds."""

    n: int
    cpe: int
    ms: float


@dataclass(frozen=True)
class PowerPoint:
    """A published power estimate of a built design with ``cpe`` CPEs."""

    name: str
    cpe: int
    watts: float


PAPER_B_LATENCY = (LatencyPoint(50, 5, 171.0), LatencyPoint(50, 120, 8.97))
PAPER_B_POWER = (PowerPoint("C1", 20, 2.293), PowerPoint("C2", 40, 2.956),
                 PowerPoint("C3", 80, 3.759))
PAPER_B_LINEAR_SOLVE_SHARE = 0.824  # average over designs and N
PAPER_A_TWO_ENDED_SPEEDUP = 1.6  # average, serial / two-ended

LATENCY_TOLERANCE = 0.25  # relative, per point
POWER_TOLERANCE = 0.10  # relative, per design


def relative_error(model: float, published: float) -> float:
    """(model − published) / published."""
    return (model - published) / published
