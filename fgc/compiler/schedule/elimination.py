"""Symbolic elimination: from an ordering to the Bayes tree of :class:`EliminationStep` nodes.

Nothing numeric happens here; the elimination *game* on the variable graph tells, for every
variable, which later variables its conditional depends on (its separator) and which edges its
elimination adds (fill). Groups of variables eliminated as one frontal block become one step.
"""

from __future__ import annotations

from collections.abc import Sequence

from fgc.compiler.schedule.ir import EliminationStep
from fgc.compiler.schedule.structure import VariableGraph

Group = tuple[int, ...]


def elimination_game(
    graph: VariableGraph, order: Sequence[int]
) -> tuple[list[tuple[int, ...]], list[list[tuple[int, int]]]]:
    """Eliminate the variables of ``graph`` one at a time in ``order``.

    Returns, indexed like ``order``, each variable's separator (its neighbours when it is
    eliminated, sorted by elimination position) and the fill edges its elimination adds (pairs of
    variable indices, earlier-eliminated first).
    """
    position = _positions(graph.size, order)
    adjacency = [set(neighbours) for neighbours in graph.adjacency]
    separators, fills = [], []
    for v in order:
        separator = sorted(adjacency[v], key=position.__getitem__)
        fill = []
        for i, a in enumerate(separator):
            adjacency[a].discard(v)
            for b in separator[i + 1 :]:
                if b not in adjacency[a]:
                    adjacency[a].add(b)
                    adjacency[b].add(a)
                    fill.append((a, b))
        separators.append(tuple(separator))
        fills.append(fill)
    return separators, fills


def supernodes(graph: VariableGraph, order: Sequence[int]) -> list[Group]:
    """Fundamental supernodes of a variable ordering, as contiguous groups.

    The elimination tree is post-ordered first (same fill, children before parents, each subtree
    contiguous); then a variable merges with its parent when it is the parent's only child and the
    parent's separator is its own minus the parent. Merged variables share one dense frontal block
    whose R block has exactly the non-zeros of the separate conditionals, so merging changes the
    number of steps and levels, never the fill.
    """
    order = _postorder(graph, order)
    separators, _ = elimination_game(graph, order)
    sep_of = dict(zip(order, separators, strict=True))
    parent = {v: (sep[0] if sep else None) for v, sep in sep_of.items()}
    child_count = [0] * graph.size
    for p in parent.values():
        if p is not None:
            child_count[p] += 1
    groups: list[list[int]] = []
    for i, v in enumerate(order):
        previous = order[i - 1] if i else None
        if (
            previous is not None
            and parent[previous] == v
            and child_count[v] == 1
            and len(sep_of[previous]) == len(sep_of[v]) + 1
        ):
            groups[-1].append(v)
        else:
            groups.append([v])
    return [tuple(group) for group in groups]


def _postorder(graph: VariableGraph, order: Sequence[int]) -> list[int]:
    """A post-order of the elimination tree of ``order``; children in their original order."""
    separators, _ = elimination_game(graph, order)
    children: dict[int | None, list[int]] = {}
    for v, separator in zip(order, separators, strict=True):
        children.setdefault(separator[0] if separator else None, []).append(v)
    result: list[int] = []
    stack: list[tuple[int, bool]] = [(root, False) for root in reversed(children.get(None, []))]
    while stack:
        v, expanded = stack.pop()
        if expanded:
            result.append(v)
            continue
        stack.append((v, True))
        stack.extend((child, False) for child in reversed(children.get(v, [])))
    return result


def eliminate(
    graph: VariableGraph,
    groups: Sequence[Group],
    group_clusters: Sequence[tuple[int, ...]] | None = None,
) -> tuple[EliminationStep, ...]:
    """Build the Bayes tree for eliminating ``groups`` (frontal blocks) in the given order.

    ``groups`` must partition the variables; ``group_clusters`` optionally names the chain
    clusters each group holds. Returns one :class:`EliminationStep` per group, in order.
    """
    order = [v for group in groups for v in group]
    position = _positions(graph.size, order)
    var_separators, var_fills = elimination_game(graph, order)
    step_of = [0] * graph.size
    for s, group in enumerate(groups):
        for v in group:
            step_of[v] = s
    separators = [_block_separator(group, var_separators, position) for group in groups]
    parents = [step_of[sep[0]] if sep else None for sep in separators]
    factors = _assign_factors(graph, step_of, position, len(groups))
    children: list[list[int]] = [[] for _ in groups]
    for s, p in enumerate(parents):
        if p is not None:
            children[p].append(s)
    rows, new_rows = _row_counts(graph, groups, separators, factors, children)
    levels = _levels(parents)
    return tuple(
        EliminationStep(
            index=s,
            frontals=tuple(graph.keys[v] for v in group),
            frontal_dims=tuple(graph.dims[v] for v in group),
            separator=tuple(graph.keys[v] for v in separators[s]),
            separator_dims=tuple(graph.dims[v] for v in separators[s]),
            parent_dims=tuple(
                sum(graph.dims[u] for u in var_separators[position[v]]) for v in group
            ),
            factors=tuple(factors[s]),
            children=tuple(children[s]),
            rows=rows[s],
            new_factor_rows=new_rows[s],
            fill_edges=tuple(
                (graph.keys[a], graph.keys[b]) for v in group for a, b in var_fills[position[v]]
            ),
            parent=parents[s],
            level=levels[s],
            clusters=tuple(group_clusters[s]) if group_clusters else (),
        )
        for s, group in enumerate(groups)
    )


def _block_separator(
    group: Group, var_separators: list[tuple[int, ...]], position: list[int]
) -> list[int]:
    """What a block's frontals still touch when eliminated, minus the block, by position."""
    touched = {u for v in group for u in var_separators[position[v]]} - set(group)
    return sorted(touched, key=position.__getitem__)


def _positions(size: int, order: Sequence[int]) -> list[int]:
    """Inverse permutation of ``order``; rejects anything that is not a permutation."""
    position = [-1] * size
    for i, v in enumerate(order):
        if not 0 <= v < size or position[v] != -1:
            raise ValueError(f"ordering is not a permutation: variable {v} repeated or unknown")
        position[v] = i
    if len(order) != size:
        raise ValueError(f"ordering has {len(order)} variables, graph has {size}")
    return position


def _assign_factors(
    graph: VariableGraph, step_of: list[int], position: list[int], num_steps: int
) -> list[list[int]]:
    """Each factor enters the step of its first-eliminated variable (as in GTSAM)."""
    factors: list[list[int]] = [[] for _ in range(num_steps)]
    for f, members in enumerate(graph.factor_vars):
        first = min(members, key=position.__getitem__)
        factors[step_of[first]].append(f)
    return factors


def _row_counts(
    graph: VariableGraph,
    groups: Sequence[Group],
    separators: list[list[int]],
    factors: list[list[int]],
    children: list[list[int]],
) -> tuple[list[int], list[int]]:
    """Stacked rows entering each step and rows of the factor it hands on.

    After a partial QR on ``f`` frontal columns of an ``r``-row stack, the remainder has ``r - f``
    rows but rank at most ``s`` (separator columns), so it is trimmed to ``min(r - f, s)`` rows.
    Children always come before their parent in ``groups``.
    """
    rows = [0] * len(groups)
    new_rows = [0] * len(groups)
    for s, group in enumerate(groups):
        rows[s] = sum(graph.factor_dims[f] for f in factors[s])
        rows[s] += sum(new_rows[c] for c in children[s])
        frontal = sum(graph.dims[v] for v in group)
        separator = sum(graph.dims[v] for v in separators[s])
        new_rows[s] = max(0, min(rows[s] - frontal, separator))
    return rows, new_rows


def _levels(parents: Sequence[int | None]) -> list[int]:
    """Height of every step above the leaves (children come before parents)."""
    levels = [0] * len(parents)
    for s, p in enumerate(parents):
        if p is not None:
            levels[p] = max(levels[p], levels[s] + 1)
    return levels


def group_levels(steps: Sequence[EliminationStep]) -> tuple[tuple[int, ...], ...]:
    """Step indices grouped by level, leaves first."""
    height = max((step.level for step in steps), default=-1) + 1
    return tuple(tuple(s.index for s in steps if s.level == level) for level in range(height))
