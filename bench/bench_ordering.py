"""Elimination orderings: fgc's schedule against GTSAM's COLAMD, fill measured by GTSAM.

For each graph the fill of both orderings is measured the same way: linearise the graph at its
initial values (with a prior on the first pose), ``eliminateSequential`` in the ordering, and count
the structural non-zeros of R over the Bayes net's conditionals (d(d+1)/2 + d·s per conditional of
frontal dimension d and parent dimension s). Sequential levels are the Bayes-tree heights fgc
computes for both orderings. Times: fgc's whole ``schedule()`` call against ``Ordering.Colamd``.

Run:  python bench/bench_ordering.py [--large]   (--large adds w10000.graph)

The helpers here (``load_*``, ``structure_from_gtsam``, ``gtsam_fill``) are reused by
``tests/compiler/test_schedule.py``.
"""

from __future__ import annotations

import argparse
import time
from dataclasses import dataclass

import gtsam
import numpy as np

from fgc.compiler.schedule import GraphStructure, schedule

_PRIOR_SIGMA = 0.1


@dataclass(frozen=True)
class Problem:
    """A GTSAM graph with initial values (prior on the first pose already added)."""

    name: str
    graph: gtsam.NonlinearFactorGraph
    values: gtsam.Values


def load_w100() -> Problem:
    """GTSAM's ``w100.graph`` (Pose2, Manhattan world with loop closures)."""
    return _with_prior("w100", *gtsam.load2D(gtsam.findExampleDataFile("w100.graph")), is3d=False)


def load_w10000() -> Problem:
    """GTSAM's ``w10000.graph`` (10 000 Pose2 poses)."""
    path = gtsam.findExampleDataFile("w10000.graph")
    return _with_prior("w10000", *gtsam.load2D(path), is3d=False)


def load_pose3example() -> Problem:
    """GTSAM's ``pose3example.txt`` (g2o, Pose3)."""
    path = gtsam.findExampleDataFile("pose3example.txt")
    return _with_prior("pose3example", *gtsam.readG2o(path, True), is3d=True)


def random_pose_graph(num_poses: int = 400, closure_rate: float = 0.15, seed: int = 7) -> Problem:
    """A seeded Pose2 odometry chain with random loop closures to any earlier pose."""
    rng = np.random.default_rng(seed)
    noise = gtsam.noiseModel.Isotropic.Sigma(3, 0.1)
    graph, values = gtsam.NonlinearFactorGraph(), gtsam.Values()
    for i in range(num_poses):
        values.insert(i, gtsam.Pose2(*rng.normal(size=3)))
        if i:
            graph.add(gtsam.BetweenFactorPose2(i - 1, i, gtsam.Pose2(1.0, 0.0, 0.1), noise))
        if i > 3 and rng.random() < closure_rate:
            j = int(rng.integers(0, i - 2))
            graph.add(gtsam.BetweenFactorPose2(j, i, gtsam.Pose2(*rng.normal(size=3)), noise))
    return _with_prior(f"random{num_poses}", graph, values, is3d=False)


def pose_chain(num_poses: int = 1000, seed: int = 3) -> Problem:
    """A Pose2 odometry chain without loop closures (fgc schedules it two-ended)."""
    rng = np.random.default_rng(seed)
    noise = gtsam.noiseModel.Isotropic.Sigma(3, 0.1)
    graph, values = gtsam.NonlinearFactorGraph(), gtsam.Values()
    for i in range(num_poses):
        values.insert(i, gtsam.Pose2(*rng.normal(size=3)))
        if i:
            graph.add(gtsam.BetweenFactorPose2(i - 1, i, gtsam.Pose2(1.0, 0.0, 0.1), noise))
    return _with_prior(f"chain{num_poses}", graph, values, is3d=False)


def _with_prior(
    name: str, graph: gtsam.NonlinearFactorGraph, values: gtsam.Values, is3d: bool
) -> Problem:
    """Anchor the first pose so the linear system has no gauge freedom."""
    first = min(values.keys())
    if is3d:
        noise = gtsam.noiseModel.Isotropic.Sigma(6, _PRIOR_SIGMA)
        graph.add(gtsam.PriorFactorPose3(first, values.atPose3(first), noise))
    else:
        noise = gtsam.noiseModel.Isotropic.Sigma(3, _PRIOR_SIGMA)
        graph.add(gtsam.PriorFactorPose2(first, values.atPose2(first), noise))
    return Problem(name, graph, values)


def structure_from_gtsam(problem: Problem) -> GraphStructure:
    """fgc's view of a GTSAM graph: keys as decimal strings, dims from the tangent spaces."""
    zero = problem.values.zeroVectors()
    variables = []
    for key in sorted(problem.values.keys()):
        dim = int(zero.at(key).size)
        variables.append((str(key), dim, f"Pose{2 if dim == 3 else 3}"))
    factors = []
    for i in range(problem.graph.size()):
        factor = problem.graph.at(i)
        if factor is None:
            continue
        keys = tuple(map(str, factor.keys()))
        factors.append((f"{type(factor).__name__}_{i}", keys, int(factor.dim())))
    return GraphStructure.from_lists(variables, factors)


def colamd_keys(problem: Problem) -> list[str]:
    """GTSAM's COLAMD ordering of the graph, as fgc keys."""
    ordering = gtsam.Ordering.ColamdNonlinearFactorGraph(problem.graph)
    return [str(ordering.at(i)) for i in range(ordering.size())]


def gtsam_fill(problem: Problem, keys: list[str]) -> int:
    """Structural non-zeros of R from GTSAM's own sequential elimination in ``keys`` order."""
    ordering = gtsam.Ordering()
    for key in keys:
        ordering.push_back(int(key))
    bayes_net = problem.graph.linearize(problem.values).eliminateSequential(ordering)
    total = 0
    for i in range(bayes_net.size()):
        conditional = bayes_net.at(i)
        d = conditional.R().shape[0]
        total += d * (d + 1) // 2 + d * conditional.S().shape[1]
    return total


@dataclass(frozen=True)
class Row:
    """One line of the result table."""

    graph: str
    variables: int
    factors: int
    ordering: str
    fill_ours: int
    fill_colamd: int
    levels_ours: int
    levels_colamd: int
    ms_ours: float
    ms_colamd: float

    @property
    def ratio(self) -> float:
        """Our fill over COLAMD's (both measured by GTSAM)."""
        return self.fill_ours / self.fill_colamd


def compare(problem: Problem, ordering: str = "auto") -> Row:
    """Schedule ``problem`` with fgc and with COLAMD; measure both fills with GTSAM."""
    structure = structure_from_gtsam(problem)
    start = time.perf_counter()
    ours = schedule(structure, ordering)
    ms_ours = 1e3 * (time.perf_counter() - start)
    start = time.perf_counter()
    colamd = colamd_keys(problem)
    ms_colamd = 1e3 * (time.perf_counter() - start)
    theirs = schedule(structure, colamd)
    return Row(
        graph=problem.name,
        variables=len(structure.variables),
        factors=len(structure.factors),
        ordering=ours.ordering,
        fill_ours=gtsam_fill(problem, list(ours.order)),
        fill_colamd=gtsam_fill(problem, colamd),
        levels_ours=ours.num_sequential_steps,
        levels_colamd=theirs.num_sequential_steps,
        ms_ours=ms_ours,
        ms_colamd=ms_colamd,
    )


def main() -> None:
    """Print the comparison table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--large", action="store_true", help="also run w10000.graph")
    args = parser.parse_args()
    problems = [
        load_w100(),
        load_pose3example(),
        random_pose_graph(),
        random_pose_graph(1000),
        pose_chain(),
    ]
    if args.large:
        problems.append(load_w10000())
    schedule(structure_from_gtsam(random_pose_graph(80)))  # warm-up: lazy imports, first calls
    header = (
        f"{'graph':<13}{'vars':>6}{'factors':>8}  {'ordering':<24}{'fill ours':>10}"
        f"{'fill colamd':>12}{'ratio':>7}{'levels ours/colamd':>20}{'ms ours':>9}{'ms colamd':>10}"
    )
    print(header)
    print("-" * len(header))
    for problem in problems:
        for ordering in ("auto", "min-degree", "nested-dissection"):
            r = compare(problem, ordering)
            name = f"auto: {r.ordering}" if ordering == "auto" else r.ordering
            print(
                f"{r.graph:<13}{r.variables:>6}{r.factors:>8}  {name:<24}{r.fill_ours:>10}"
                f"{r.fill_colamd:>12}{r.ratio:>7.3f}{f'{r.levels_ours}/{r.levels_colamd}':>20}"
                f"{r.ms_ours:>9.1f}{r.ms_colamd:>10.2f}"
            )


if __name__ == "__main__":
    main()
