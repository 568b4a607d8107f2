"""Structure classification: is the graph a chain of repeating clusters, or general?

A *chain* is an ordered sequence of variable clusters C_0 … C_{m-1} such that every factor touches
one cluster or two consecutive clusters, and the clusters repeat one pattern (the multiset of
variable types of a keyframe). On a LIO graph the clusters are the keyframes {x_j, v_j, b_j}.

How clusters are found (all deterministic, ties broken by declaration order; a disconnected graph
is general):

1. **Supervariables.** Variables with identical *closed* neighbourhoods in the variable graph
   (``N[v] = {v} ∪ adj(v)``) are indistinguishable for elimination — minimum-degree codes merge
   them for the same reason. With a combined IMU factor on (x_j, v_j, b_j, x_j+1, v_j+1, b_j+1) the
   three variables of a keyframe are exactly such twins. (A twin class with repeated types, as
   on a two-keyframe chain, is split into one group per repetition.)
2. **Level structure.** A breadth-first layering of the supervariable graph from a
   pseudo-peripheral node (George & Liu) puts every edge inside a layer or between consecutive
   layers. A factor's variables are pairwise adjacent, so each factor spans at most two
   consecutive layers: the layers always form a valid cluster sequence. Starting from an end of the
   chain makes the layers as small as possible.
3. **Repetition test.** The layering is a chain when every interior layer has the same type
   signature and the two end layers hold a subset of it (a chain may start or stop mid-keyframe,
   e.g. with a separate bias-between factor the layers become {b_j-1, x_j, v_j}). Otherwise the
   graph is general: loop closures make layers grow and shrink irregularly.
4. **Alignment.** When the end layers are partial, every variable type is tried shifted by -1, 0 or
   +1 layers; the first shift that leaves every cluster a full copy of the pattern and every
   factor within two consecutive clusters is taken. This turns {b_j-1, x_j, v_j} back into
   keyframes {x_j, v_j, b_j}.
5. **Keyframe test.** A cluster must look like a keyframe: either it holds one variable of each
   type, or (e.g. a pose with its own landmarks) its variables are tied together by factors; the
   end clusters are exempt, since the last bias of a chain is often tied only to the previous one.
   This rejects the layerings of loops: a ring's layers {x_i, x_n-i} hold two unrelated poses.
"""

from __future__ import annotations

import itertools
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Literal

from fgc.compiler.schedule.structure import VariableGraph, connected_components

StructureClass = Literal["chain", "general"]

# Alignment tries 3**T type shifts; beyond this many variable types it is skipped.
_MAX_TYPES_TO_ALIGN = 6


@dataclass(frozen=True)
class Classification:
    """The structure class and, for chains, the clusters in chain order (variable indices).

    Cluster 0 holds the first-declared variable, so on a chain declared in time order cluster 0 is
    the oldest keyframe. ``clusters`` is empty for general graphs.
    """

    structure_class: StructureClass
    clusters: tuple[tuple[int, ...], ...]


def classify(graph: VariableGraph) -> Classification:
    """Classify ``graph`` as a chain of repeating clusters or as general (see module docstring)."""
    if len(connected_components(graph)) != 1:
        return Classification("general", ())
    groups = supervariables(graph)
    quotient = _quotient_adjacency(graph, groups)
    best: list[tuple[int, ...]] | None = None
    for start in _layering_starts(quotient):
        layers = bfs_layers(quotient, start)
        if not _repeats(graph, groups, layers):
            continue
        clusters = _align(graph, [tuple(sorted(v for g in ly for v in groups[g])) for ly in layers])
        if _keyframe_like(graph, clusters) and (best is None or len(clusters) > len(best)):
            best = clusters
    if best is None:
        return Classification("general", ())
    if best[-1][0] < best[0][0]:
        best.reverse()
    return Classification("chain", tuple(best))


def supervariables(graph: VariableGraph) -> list[tuple[int, ...]]:
    """Group variables with identical closed neighbourhoods; groups ordered by first member.

    A twin class holding several variables of one type is split so that its k-th variable of
    every type goes to sub-group k: on a two-keyframe chain all six variables are twins, but they
    are still two keyframes.
    """
    by_neighbourhood: dict[tuple[int, ...], list[int]] = {}
    for v in range(graph.size):
        closed = tuple(sorted((v, *graph.adjacency[v])))
        by_neighbourhood.setdefault(closed, []).append(v)
    groups = []
    for members in by_neighbourhood.values():
        seen: Counter[tuple[str, int]] = Counter()
        split: dict[int, list[int]] = {}
        for v in members:
            kind = (graph.type_names[v], graph.dims[v])
            split.setdefault(seen[kind], []).append(v)
            seen[kind] += 1
        groups += [tuple(group) for group in split.values()]
    return sorted(groups)


def _quotient_adjacency(graph: VariableGraph, groups: list[tuple[int, ...]]) -> list[list[int]]:
    """Adjacency between supervariables (sorted lists of group indices)."""
    group_of = [0] * graph.size
    for g, members in enumerate(groups):
        for v in members:
            group_of[v] = g
    adjacency: list[set[int]] = [set() for _ in groups]
    for v in range(graph.size):
        adjacency[group_of[v]].update(group_of[u] for u in graph.adjacency[v])
    return [sorted(found - {g}) for g, found in enumerate(adjacency)]


def bfs_layers(adjacency: list[list[int]], start: int) -> list[list[int]]:
    """Breadth-first level structure from ``start``; each layer sorted."""
    seen = {start}
    layers = [[start]]
    while True:
        nxt = sorted({u for v in layers[-1] for u in adjacency[v] if u not in seen})
        if not nxt:
            return layers
        seen.update(nxt)
        layers.append(nxt)


def pseudo_peripheral_node(adjacency: list[list[int]], nodes: list[int]) -> int:
    """George–Liu: a node of (nearly) maximal eccentricity among ``nodes`` (a connected set).

    Starts at a minimum-degree node and jumps to a minimum-degree node of the last BFS layer while
    the eccentricity grows.
    """
    node = min(nodes, key=lambda v: (len(adjacency[v]), v))
    depth = len(bfs_layers(adjacency, node))
    while True:
        last = bfs_layers(adjacency, node)[-1]
        candidate = min(last, key=lambda v: (len(adjacency[v]), v))
        candidate_depth = len(bfs_layers(adjacency, candidate))
        if candidate_depth <= depth:
            return node
        node, depth = candidate, candidate_depth


def _layering_starts(adjacency: list[list[int]]) -> list[int]:
    """Candidate chain ends: a pseudo-peripheral node and the nodes farthest from it.

    One BFS start is not enough: on a chain whose last keyframe is only weakly attached (a lone
    bias-between factor) the pseudo-peripheral node sits on that end and its layering does not
    repeat, while the layering from the other end does.
    """
    start = pseudo_peripheral_node(adjacency, list(range(len(adjacency))))
    return [start, *bfs_layers(adjacency, start)[-1]]


def _repeats(graph: VariableGraph, groups: list[tuple[int, ...]], layers: list[list[int]]) -> bool:
    """True when interior layers share one type signature and the end layers fit inside it."""
    signatures = [_signature(graph, (v for g in layer for v in groups[g])) for layer in layers]
    if len(signatures) >= 3:
        pattern = signatures[1]
        if any(sig != pattern for sig in signatures[1:-1]):
            return False
    else:
        pattern = max(signatures, key=lambda sig: sum(sig.values()))
    return signatures[0] <= pattern and signatures[-1] <= pattern


def _keyframe_like(graph: VariableGraph, clusters: list[tuple[int, ...]]) -> bool:
    """One variable per type, or every interior cluster connected by factors (module docstring)."""
    pattern = max((_signature(graph, c) for c in clusters), key=lambda sig: sum(sig.values()))
    if all(count == 1 for count in pattern.values()):
        return True
    for cluster in clusters[1:-1]:
        members = set(cluster)
        reached, stack = {cluster[0]}, [cluster[0]]
        while stack:
            v = stack.pop()
            fresh = [u for u in graph.adjacency[v] if u in members and u not in reached]
            reached.update(fresh)
            stack.extend(fresh)
        if len(reached) != len(members):
            return False
    return True


def _signature(graph: VariableGraph, members: Iterable[int]) -> Counter[tuple[str, int]]:
    """Multiset of (type name, dimension) of the variables ``members``."""
    return Counter((graph.type_names[v], graph.dims[v]) for v in members)


def _align(graph: VariableGraph, clusters: list[tuple[int, ...]]) -> list[tuple[int, ...]]:
    """Shift whole variable types by one cluster so that every cluster is a full pattern copy.

    Returns ``clusters`` unchanged when they already are, or when no shift works.
    """
    pattern = max((_signature(graph, c) for c in clusters), key=lambda sig: sum(sig.values()))
    if all(_signature(graph, c) == pattern for c in clusters):
        return clusters
    kinds = sorted(pattern)
    if len(kinds) > _MAX_TYPES_TO_ALIGN:
        return clusters
    layer_of = {v: i for i, cluster in enumerate(clusters) for v in cluster}
    for shifts in itertools.product((0, -1, 1), repeat=len(kinds)):
        shift = dict(zip(kinds, shifts, strict=True))
        moved = {v: i + shift[(graph.type_names[v], graph.dims[v])] for v, i in layer_of.items()}
        low, high = min(moved.values()), max(moved.values())
        candidate = [tuple(sorted(v for v in moved if moved[v] == i)) for i in range(low, high + 1)]
        if all(_signature(graph, c) == pattern for c in candidate) and all(
            max(moved[v] for v in members) - min(moved[v] for v in members) <= 1
            for members in graph.factor_vars
        ):
            return candidate
    return clusters
