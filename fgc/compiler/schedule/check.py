"""Invariant check run after the schedule stage (``check_schedule``).

A schedule may come from :func:`fgc.compiler.schedule.schedule` or from JSON; either way it must
describe a
correct elimination of *this* structure before anything is lowered from it.
"""

from __future__ import annotations

from collections import Counter

from fgc.compiler.schedule.elimination import eliminate, group_levels
from fgc.compiler.schedule.ir import Schedule
from fgc.compiler.schedule.structure import GraphStructure, VariableGraph, format_keys
from fgc.errors import StructureError

# Step fields that must agree with a fresh symbolic elimination of the same frontal groups.
_DERIVED_FIELDS = (
    "frontal_dims",
    "separator",
    "separator_dims",
    "parent_dims",
    "factors",
    "children",
    "rows",
    "new_factor_rows",
    "fill_edges",
    "parent",
    "level",
)


def check_schedule(structure: GraphStructure, schedule: Schedule) -> None:
    """Raise :class:`StructureError` unless ``schedule`` is a valid elimination of ``structure``.

    Checks: every variable is eliminated exactly once; step indices, dimensions, separators,
    parents, factor assignment, row counts, fill and levels agree with the elimination game on the
    variable graph; no step receives fewer rows than it has unknowns (structural rank deficiency);
    chain clusters partition the variables and factors touch one or two consecutive clusters; the
    incremental plan, if any, covers every cluster.
    """
    graph = VariableGraph.of(structure)
    _check_partition(graph, schedule)
    index = {key: v for v, key in enumerate(graph.keys)}
    groups = [tuple(index[key] for key in step.frontals) for step in schedule.steps]
    expected = eliminate(graph, groups, [step.clusters for step in schedule.steps])
    for step, fresh in zip(schedule.steps, expected, strict=True):
        if step.index != fresh.index:
            raise StructureError(f"step {fresh.index} is numbered {step.index}")
        for name in _DERIVED_FIELDS:
            if getattr(step, name) != getattr(fresh, name):
                raise StructureError(
                    f"step {step.index} eliminating {format_keys(step.frontals)}: {name} is "
                    f"{getattr(step, name)!r}, the elimination graph gives {getattr(fresh, name)!r}"
                )
        if step.rows < step.frontal_dim:
            raise StructureError(
                f"step {step.index} eliminating {format_keys(step.frontals)} receives {step.rows} "
                f"rows for {step.frontal_dim} unknowns: the graph is structurally rank-deficient"
            )
    if schedule.levels != group_levels(expected):
        raise StructureError("levels do not match the elimination tree's heights")
    _check_clusters(structure, schedule)


def _check_partition(graph: VariableGraph, schedule: Schedule) -> None:
    """Every variable of the graph is a frontal of exactly one step."""
    counts = Counter(schedule.order)
    unknown = sorted(set(counts) - set(graph.keys))
    if unknown:
        raise StructureError(f"the schedule eliminates unknown variable '{unknown[0]}'")
    for key in graph.keys:
        if counts[key] == 0:
            raise StructureError(f"variable '{key}' is never eliminated")
        if counts[key] > 1:
            raise StructureError(f"variable '{key}' is eliminated {counts[key]} times")


def _check_clusters(structure: GraphStructure, schedule: Schedule) -> None:
    """Chain clusters partition the variables and every factor spans <= 2 consecutive ones."""
    if schedule.structure_class == "general":
        if schedule.clusters or schedule.incremental is not None:
            raise StructureError("a general schedule has no chain clusters or incremental plan")
        return
    listed = [key for cluster in schedule.clusters for key in cluster]
    if sorted(listed) != sorted(var.key for var in structure.variables):
        raise StructureError("chain clusters do not partition the variables")
    cluster_of = {key: c for c, cluster in enumerate(schedule.clusters) for key in cluster}
    for factor in structure.factors:
        touched = sorted({cluster_of[key] for key in factor.keys})
        if touched[-1] - touched[0] > 1:
            raise StructureError(f"factor '{factor.name}' touches chain clusters {touched}")
    for step in schedule.steps:
        if any(not 0 <= c < len(schedule.clusters) for c in step.clusters):
            raise StructureError(f"step {step.index} names unknown clusters {step.clusters}")
        members = sorted(key for c in step.clusters for key in schedule.clusters[c])
        if step.clusters and members != sorted(step.frontals):
            raise StructureError(f"step {step.index}: frontals are not clusters {step.clusters}")
    if schedule.incremental is not None:
        _check_plan(schedule)


def _check_plan(schedule: Schedule) -> None:
    """One update per arriving cluster, each re-eliminating a run of clusters ending with it."""
    updates = schedule.incremental.updates if schedule.incremental else ()
    if [update.keyframe for update in updates] != list(range(len(schedule.clusters))):
        raise StructureError("the incremental plan needs one update per chain cluster")
    for update in updates:
        if update.clusters != tuple(range(update.kept, update.keyframe + 1)):
            raise StructureError(
                f"update for keyframe {update.keyframe} re-eliminates {update.clusters}, not a "
                f"run of clusters from {update.kept} to the new one"
            )
