"""The schedule stage: graph structure → elimination :class:`Schedule`.

``schedule(structure)`` classifies the structure (chain of repeating clusters, or general), picks an
elimination ordering (two-ended on chains, fill-reducing on general graphs), builds the Bayes tree
with its parallel levels and, on request, an incremental-smoothing plan. Pure Python; it never
imports GTSAM (tests compare against GTSAM's own elimination).

Public API::

    GraphStructure, VarInfo, FactorInfo            # input
    Schedule, EliminationStep, IncrementalPlan, IncrementalUpdate   # output
    schedule(structure, ordering="auto", incremental_k=None, batch_every=None, max_variables=None)
    check_structure(structure, max_variables=None)
    check_schedule(structure, schedule)
"""

from __future__ import annotations

from collections.abc import Sequence

from fgc.compiler.schedule.check import check_schedule
from fgc.compiler.schedule.classify import Classification, classify
from fgc.compiler.schedule.elimination import eliminate, group_levels, supernodes
from fgc.compiler.schedule.incremental import plan_incremental
from fgc.compiler.schedule.ir import EliminationStep, IncrementalPlan, IncrementalUpdate, Schedule
from fgc.compiler.schedule.ordering import (
    min_degree_order,
    natural_order,
    nested_dissection_order,
    serial_groups,
    two_ended_groups,
)
from fgc.compiler.schedule.structure import (
    FactorInfo,
    GraphStructure,
    VariableGraph,
    VarInfo,
    check_structure,
)
from fgc.errors import StructureError
from fgc.ir.codes import ORDERINGS  # the one list of orderings

__all__ = [
    "ORDERINGS",
    "EliminationStep",
    "FactorInfo",
    "GraphStructure",
    "IncrementalPlan",
    "IncrementalUpdate",
    "Schedule",
    "VarInfo",
    "check_schedule",
    "check_structure",
    "schedule",
]


_CHAIN_ORDERINGS = ("serial", "two-ended")

# ``auto`` tries nested dissection on general graphs up to this many variables only: its
# bisections (Kernighan–Lin) took 20 s of a 10,000-pose graph's compile, and on large pose graphs
# (long-range loop closures, no small separators) it lost to minimum degree anyway. Ask for
# ``nested-dissection`` by name to have it at any size.
AUTO_DISSECTION_MAX_VARIABLES = 5000


def schedule(
    structure: GraphStructure,
    ordering: str | Sequence[str] = "auto",
    incremental_k: int | None = None,
    batch_every: int | Sequence[int] | None = None,
    max_variables: int | None = None,
) -> Schedule:
    """Schedule the elimination of ``structure``.

    ``ordering`` is one of :data:`ORDERINGS`: ``auto`` means two-ended on chains and the better of
    minimum degree and nested dissection on general graphs (nested dissection only when it has no
    more fill and fewer sequential levels; tried up to :data:`AUTO_DISSECTION_MAX_VARIABLES`
    variables, above which ``auto`` is minimum degree). A sequence of variable keys is a custom
    ordering (GTSAM's ``Ordering.CUSTOM``; recorded as ``"custom"``), e.g. to schedule GTSAM's
    COLAMD order. ``incremental_k`` (chains only) adds an :class:`IncrementalPlan`
    re-eliminating the newest k clusters per arrival, with batch updates at ``batch_every`` (a
    period or a list of arrival indices). ``max_variables`` bounds the structure's size (the
    compiled window).

    Structure errors (:class:`StructureError`, naming the variable, component or step) are raised
    before any numerics; ``ValueError`` for an unknown ordering or bad plan arguments. The result
    is checked with :func:`check_schedule` before it is returned.
    """
    if isinstance(ordering, str) and ordering not in ORDERINGS:
        raise ValueError(f"unknown ordering '{ordering}'; choose one of {', '.join(ORDERINGS)}")
    if batch_every is not None and incremental_k is None:
        raise ValueError(
            "batch_every needs incremental_k: batch steps belong to an incremental plan"
        )
    check_structure(structure, max_variables)
    graph = VariableGraph.of(structure)
    shape = classify(graph)
    if shape.structure_class == "general" and (
        ordering in _CHAIN_ORDERINGS or incremental_k is not None
    ):
        wanted = f"ordering '{ordering}'" if ordering in _CHAIN_ORDERINGS else "incremental_k"
        raise StructureError(f"{wanted} needs a chain structure, but this graph is general")
    if isinstance(ordering, str):
        name, steps = _eliminate_with(graph, shape, ordering)
    else:
        name, steps = "custom", eliminate(graph, supernodes(graph, _custom_order(graph, ordering)))
    plan = None
    if incremental_k is not None:
        plan = plan_incremental(len(shape.clusters), incremental_k, batch_every)
    result = Schedule(
        structure_class=shape.structure_class,
        ordering=name,
        clusters=tuple(tuple(graph.keys[v] for v in cluster) for cluster in shape.clusters),
        steps=steps,
        levels=group_levels(steps),
        incremental=plan,
    )
    check_schedule(structure, result)
    return result


def _eliminate_with(
    graph: VariableGraph, shape: Classification, ordering: str
) -> tuple[str, tuple[EliminationStep, ...]]:
    """Resolve ``ordering`` and run the symbolic elimination; returns (name, steps)."""
    if ordering == "auto" and shape.structure_class == "chain":
        ordering = "two-ended"
    if ordering in _CHAIN_ORDERINGS:
        make = two_ended_groups if ordering == "two-ended" else serial_groups
        cluster_groups = make(len(shape.clusters))
        groups = [tuple(v for c in group for v in shape.clusters[c]) for group in cluster_groups]
        plain = eliminate(graph, groups, cluster_groups)
        tuned = eliminate(graph, _order_within(graph, groups), cluster_groups)
        return ordering, tuned if _fill(tuned) < _fill(plain) else plain
    if ordering == "natural":
        return ordering, eliminate(graph, supernodes(graph, natural_order(graph)))
    by_min_degree = eliminate(graph, supernodes(graph, min_degree_order(graph)))
    if ordering == "min-degree" or (ordering == "auto"
                                    and graph.size > AUTO_DISSECTION_MAX_VARIABLES):
        return "min-degree", by_min_degree
    by_dissection = eliminate(graph, supernodes(graph, nested_dissection_order(graph)))
    if ordering == "nested-dissection" or _prefer_dissection(by_min_degree, by_dissection):
        return "nested-dissection", by_dissection
    return "min-degree", by_min_degree


def _custom_order(graph: VariableGraph, keys: Sequence[str]) -> list[int]:
    """Variable indices of a user-given key order; every variable exactly once."""
    index = {key: v for v, key in enumerate(graph.keys)}
    unknown = [key for key in keys if key not in index]
    if unknown:
        raise ValueError(f"custom ordering names unknown variable '{unknown[0]}'")
    given = set(keys)
    missing = [key for key in graph.keys if key not in given]
    if missing or len(keys) != len(set(keys)):
        problem = f"misses variable '{missing[0]}'" if missing else "repeats a variable"
        raise ValueError(f"custom ordering {problem}")
    return [index[key] for key in keys]


def _order_within(graph: VariableGraph, groups: list[tuple[int, ...]]) -> list[tuple[int, ...]]:
    """Keep the groups' order but order each group's variables by minimum degree.

    Within a keyframe the order changes only which structural zeros R keeps (e.g. a velocity that
    does not touch the next bias); constrained minimum degree with the group index as rank finds a
    good one. Used only when it saves fill, so that keyframes keep their declaration order.
    """
    rank = [0] * graph.size
    for g, group in enumerate(groups):
        for v in group:
            rank[v] = g
    order = min_degree_order(graph, rank)
    return [tuple(v for v in order if rank[v] == g) for g in range(len(groups))]


def _fill(steps: tuple[EliminationStep, ...]) -> int:
    """Structural non-zeros of R."""
    return sum(step.r_nonzeros for step in steps)


def _prefer_dissection(
    min_degree: tuple[EliminationStep, ...], dissection: tuple[EliminationStep, ...]
) -> bool:
    """Nested dissection wins only if it is no worse in fill and strictly shallower."""

    def height(steps: tuple[EliminationStep, ...]) -> int:
        return 1 + max(step.level for step in steps)

    return _fill(dissection) <= _fill(min_degree) and height(dissection) < height(min_degree)
