"""Elimination orderings.

Chain orderings work on clusters and return *groups*: tuples of cluster indices eliminated as one
frontal block, in a valid sequential order.

- ``serial``: C_0, C_1, …, C_m-1 (the root is the newest cluster).
- ``two-ended``: C_0 and C_m-1 together, then C_1 and C_m-2, … towards the middle. The root is the
  middle cluster, or the two middle clusters as one block when m is even (eliminating them one
  after the other would add a step without saving any fill). Sequential steps: ceil(m / 2).

General orderings work on variables and return a permutation of variable indices:

- ``min-degree``: minimum *weighted* external degree (sum of neighbour dimensions, so a 6-dim
  pose neighbour weighs twice a 3-dim point), exact elimination-graph update, ties by
  declaration order. Optionally constrained: a variable with a lower constraint rank is always
  eliminated first (the CAMD idea), which nested dissection uses to keep separators last.
- ``nested-dissection``: recursive bisection (BFS halves refined by Kernighan–Lin, edge cut turned
  into a vertex separator by a minimum vertex cover); separators are eliminated after the parts
  they split, and constrained minimum degree on the whole graph orders everything within that
  rule, so fill towards the boundary is accounted for. Shallower trees, so more steps run in
  parallel, usually at some cost in fill; poor on graphs without small separators (random
  long-range loop closures).
- ``natural``: declaration order (GTSAM's ``Ordering.Natural``).
"""

from __future__ import annotations

import heapq
from collections.abc import Sequence

import networkx as nx

from fgc.compiler.schedule.classify import bfs_layers, pseudo_peripheral_node
from fgc.compiler.schedule.structure import VariableGraph

# Nested dissection stops splitting parts at or below this many variables.
_DISSECTION_LEAF_SIZE = 16


def serial_groups(num_clusters: int) -> list[tuple[int, ...]]:
    """Cluster groups of the serial chain ordering C_0 → C_m-1."""
    return [(c,) for c in range(num_clusters)]


def two_ended_groups(num_clusters: int) -> list[tuple[int, ...]]:
    """Cluster groups of the two-ended chain ordering, ends first, root in the middle."""
    groups: list[tuple[int, ...]] = []
    lo, hi = 0, num_clusters - 1
    while hi - lo >= 2:
        groups += [(lo,), (hi,)]
        lo, hi = lo + 1, hi - 1
    groups.append(tuple(range(lo, hi + 1)))
    return groups


def natural_order(graph: VariableGraph) -> list[int]:
    """Declaration order."""
    return list(range(graph.size))


def min_degree_order(graph: VariableGraph, rank: Sequence[int] | None = None) -> list[int]:
    """Minimum weighted-degree ordering of all variables of ``graph``.

    ``rank`` (optional, one int per variable) constrains the order: variables of a lower rank are
    eliminated before any of a higher rank. Returns a permutation of ``range(graph.size)``.
    """
    rank = rank if rank is not None else [0] * graph.size
    adjacency = [set(neighbours) for neighbours in graph.adjacency]
    degree = [sum(graph.dims[u] for u in adjacency[v]) for v in range(graph.size)]
    heap = [(rank[v], degree[v], v) for v in range(graph.size)]
    heapq.heapify(heap)
    eliminated = [False] * graph.size
    order = []
    while heap:
        _, deg, v = heapq.heappop(heap)
        if eliminated[v] or deg != degree[v]:
            continue  # stale heap entry: v's degree changed after it was pushed
        eliminated[v] = True
        order.append(v)
        neighbours = sorted(adjacency[v])
        clique = set(neighbours)
        for u in neighbours:
            adjacency[u].discard(v)
            added = clique - adjacency[u]
            added.discard(u)
            adjacency[u] |= added
            # the same sum as over the whole new neighbourhood, kept up to date by difference
            degree[u] += sum(graph.dims[w] for w in added) - graph.dims[v]
            heapq.heappush(heap, (rank[u], degree[u], u))
    return order


def nested_dissection_order(graph: VariableGraph) -> list[int]:
    """Nested-dissection ordering: parts before their separators, deepest separators first.

    Each variable gets a rank: 0 for the leaves of the dissection, and for a separator found at
    depth d the rank ``max_depth - d + 1``, so outer separators come last. Constrained minimum
    degree then orders all variables within those ranks.
    """
    separator_depth: dict[int, int] = {}
    parts = [(list(range(graph.size)), 0)]
    while parts:
        part, depth = parts.pop()
        if len(part) <= _DISSECTION_LEAF_SIZE:
            continue
        separator, pieces = _bisect(graph, part)
        separator_depth.update((v, depth) for v in separator)
        parts.extend((piece, depth + 1) for piece in pieces)
    deepest = max(separator_depth.values(), default=0)
    rank = [0] * graph.size
    for v, depth in separator_depth.items():
        rank[v] = deepest - depth + 1
    return min_degree_order(graph, rank)


def _bisect(graph: VariableGraph, part: list[int]) -> tuple[list[int], list[list[int]]]:
    """Split ``part`` by a small vertex separator.

    Start from the two halves of a BFS order from a pseudo-peripheral node, refine the edge cut by
    Kernighan–Lin (networkx, fixed seed), and turn the cut edges into a vertex separator by a
    minimum vertex cover of the bipartite cut graph (König), as multilevel partitioners do.
    Returns ``(separator, pieces)``: the separator and the connected components left without it;
    both empty when ``part`` cannot be split (e.g. a clique).
    """
    sub = nx.Graph()
    sub.add_nodes_from(part)
    members = set(part)
    sub.add_edges_from((v, u) for v in part for u in graph.adjacency[v] if u in members and v < u)
    pieces = [sorted(c) for c in nx.connected_components(sub)]
    if len(pieces) > 1:  # already disconnected: no separator needed
        return [], sorted(pieces)
    adjacency = {v: sorted(sub.adj[v]) for v in part}
    local = {v: i for i, v in enumerate(part)}
    local_adj = [[local[u] for u in adjacency[v]] for v in part]
    start = pseudo_peripheral_node(local_adj, list(range(len(part))))
    bfs = [part[i] for layer in bfs_layers(local_adj, start) for i in layer]
    half = set(bfs[: len(bfs) // 2])
    left, right = nx.algorithms.community.kernighan_lin_bisection(
        sub, partition=(half, members - half), seed=0
    )
    cut = nx.Graph((a, b) for a, b in sub.edges() if (a in left) != (b in left))
    if cut.number_of_edges() == 0:
        return [], []
    top = {v for v in cut if v in left}
    cover = nx.bipartite.to_vertex_cover(cut, nx.bipartite.hopcroft_karp_matching(cut, top), top)
    sub.remove_nodes_from(cover)
    pieces = sorted(sorted(c) for c in nx.connected_components(sub))
    if len(pieces) < 2:
        return [], []
    return sorted(cover), pieces
