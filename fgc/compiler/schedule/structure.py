"""The schedule stage's input: a factor graph's structure, without any numbers.

:class:`GraphStructure` lists the variables (key, tangent dimension, type name) and the factors
(name, variable keys, residual rows). It is all the elimination scheduler needs: which variables
meet in which factors and how large every block is. :func:`check_structure` rejects structures that
no numerics could solve (unconstrained variables, gauge freedom, too many variables) and names the
offending variable or component.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from fgc.compiler.schedule.serialize import JsonDataclass
from fgc.errors import StructureError

# How many keys an error message lists before it abbreviates a component.
_MAX_KEYS_IN_MESSAGE = 8


@dataclass(frozen=True)
class VarInfo(JsonDataclass):
    """One variable: its ``key``, tangent-space ``dim`` and ``type_name`` (e.g. ``"Pose3"``)."""

    key: str
    dim: int
    type_name: str


@dataclass(frozen=True)
class FactorInfo(JsonDataclass):
    """One factor: its ``name``, the ``keys`` of the variables it touches, its residual ``dim``."""

    name: str
    keys: tuple[str, ...]
    dim: int

    def __post_init__(self) -> None:
        # Accept any sequence of keys but store a tuple, so the factor stays hashable and equal
        # to its JSON round trip.
        object.__setattr__(self, "keys", tuple(self.keys))


@dataclass(frozen=True)
class GraphStructure(JsonDataclass):
    """A factor graph's structure: variables in declaration order, then factors.

    Declaration order matters: it breaks ties wherever the scheduler has a free choice, and on a
    chain the cluster holding the first-declared variable is the oldest keyframe. Construction
    rejects malformed input (duplicate keys, unknown keys, non-positive dimensions) with a
    :class:`StructureError` naming the item.
    """

    variables: tuple[VarInfo, ...]
    factors: tuple[FactorInfo, ...]

    def __post_init__(self) -> None:
        object.__setattr__(self, "variables", tuple(self.variables))
        object.__setattr__(self, "factors", tuple(self.factors))
        _check_well_formed(self)

    @classmethod
    def from_lists(
        cls,
        variables: Iterable[VarInfo | tuple[str, int, str]],
        factors: Iterable[FactorInfo | tuple[str, Sequence[str], int]],
    ) -> GraphStructure:
        """Build a structure from ``(key, dim, type_name)`` and ``(name, keys, dim)`` tuples.

        Already-built :class:`VarInfo` / :class:`FactorInfo` objects are accepted as they are.
        """
        var_infos = tuple(v if isinstance(v, VarInfo) else VarInfo(*v) for v in variables)
        factor_infos = tuple(f if isinstance(f, FactorInfo) else FactorInfo(*f) for f in factors)
        return cls(var_infos, factor_infos)


def _check_well_formed(structure: GraphStructure) -> None:
    """Raise :class:`StructureError` on input no graph could have (checked at construction)."""
    declared: set[str] = set()
    for var in structure.variables:
        if not isinstance(var.key, str) or not var.key:
            raise StructureError(f"variable key {var.key!r} must be a non-empty string")
        if var.key in declared:
            raise StructureError(f"variable '{var.key}' is declared twice")
        if not isinstance(var.dim, int) or var.dim < 1:
            raise StructureError(f"variable '{var.key}' has dimension {var.dim!r}; need >= 1")
        declared.add(var.key)
    for factor in structure.factors:
        if not isinstance(factor.dim, int) or factor.dim < 1:
            raise StructureError(f"factor '{factor.name}' has {factor.dim!r} rows; need >= 1")
        if not factor.keys:
            raise StructureError(f"factor '{factor.name}' touches no variable")
        for key in factor.keys:
            if key not in declared:
                raise StructureError(
                    f"factor '{factor.name}' refers to undeclared variable '{key}'"
                )
        if len(set(factor.keys)) != len(factor.keys):
            raise StructureError(f"factor '{factor.name}' lists a variable twice: {factor.keys}")


@dataclass(frozen=True)
class VariableGraph:
    """Index-based view of a structure used inside the scheduler (not part of the IR).

    Variables are numbered in declaration order; ``adjacency[v]`` holds the variables sharing a
    factor with ``v``, sorted. Working on integers keeps every iteration order deterministic.
    """

    keys: tuple[str, ...]
    dims: tuple[int, ...]
    type_names: tuple[str, ...]
    adjacency: tuple[tuple[int, ...], ...]
    factor_vars: tuple[tuple[int, ...], ...]
    factor_dims: tuple[int, ...]

    @classmethod
    def of(cls, structure: GraphStructure) -> VariableGraph:
        """Index the variables of ``structure`` and build its variable adjacency."""
        index = {var.key: i for i, var in enumerate(structure.variables)}
        factor_vars = tuple(tuple(index[k] for k in f.keys) for f in structure.factors)
        neighbours: list[set[int]] = [set() for _ in structure.variables]
        for members in factor_vars:
            for v in members:
                neighbours[v].update(members)
        for v, found in enumerate(neighbours):
            found.discard(v)
        return cls(
            keys=tuple(var.key for var in structure.variables),
            dims=tuple(var.dim for var in structure.variables),
            type_names=tuple(var.type_name for var in structure.variables),
            adjacency=tuple(tuple(sorted(found)) for found in neighbours),
            factor_vars=factor_vars,
            factor_dims=tuple(f.dim for f in structure.factors),
        )

    @property
    def size(self) -> int:
        """Number of variables."""
        return len(self.keys)


def connected_components(graph: VariableGraph) -> list[list[int]]:
    """Connected components of the variable graph, each sorted, ordered by smallest member."""
    seen = [False] * graph.size
    components = []
    for start in range(graph.size):
        if seen[start]:
            continue
        seen[start] = True
        stack, members = [start], []
        while stack:
            v = stack.pop()
            members.append(v)
            for u in graph.adjacency[v]:
                if not seen[u]:
                    seen[u] = True
                    stack.append(u)
        components.append(sorted(members))
    return components


def check_structure(structure: GraphStructure, max_variables: int | None = None) -> None:
    """Reject a structure that cannot be solved, before any numerics run.

    Raises :class:`StructureError` naming the offending item when the structure is empty, has more
    than ``max_variables`` variables, has variables no factor constrains, or has a connected
    component without a unary (prior-like) factor, which leaves a gauge freedom.
    """
    count = len(structure.variables)
    if count == 0:
        raise StructureError("the structure has no variables")
    if max_variables is not None and count > max_variables:
        raise StructureError(
            f"the structure has {count} variables, more than max_variables={max_variables}"
        )
    constrained = {key for factor in structure.factors for key in factor.keys}
    loose = [var.key for var in structure.variables if var.key not in constrained]
    if len(loose) == 1:
        raise StructureError(f"variable '{loose[0]}' is not constrained by any factor")
    if loose:
        names = ", ".join(f"'{key}'" for key in loose)
        raise StructureError(f"variables {names} are not constrained by any factor")
    _check_gauge(structure)


def _check_gauge(structure: GraphStructure) -> None:
    """Every connected component needs a unary factor, or it can move freely as a whole."""
    graph = VariableGraph.of(structure)
    anchored = {members[0] for members in graph.factor_vars if len(members) == 1}
    for component in connected_components(graph):
        if anchored.isdisjoint(component):
            names = format_keys([graph.keys[v] for v in component])
            raise StructureError(f"component {names} has no prior: gauge freedom")


def format_keys(keys: Sequence[str]) -> str:
    """``{x5, x6}`` for error messages; long lists are abbreviated with their size."""
    if len(keys) <= _MAX_KEYS_IN_MESSAGE:
        return "{" + ", ".join(keys) + "}"
    head = ", ".join(keys[: _MAX_KEYS_IN_MESSAGE - 1])
    return "{" + f"{head}, ..., {keys[-1]}" + "}" + f" ({len(keys)} variables)"
