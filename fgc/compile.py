"""The whole compiler, top to bottom: a Graph → a checked :class:`fgc.ir.program.Program`.

    DSL graph ─► check ─► schedule ─► fuse (+ derive, CSE) ─► storage ─► lower ─► Program

The structure (check, schedule) comes first: it needs no symbolic work, so a graph that cannot
be solved fails in milliseconds rather than after its derivations. The stages live in
``fgc/compiler/`` in the same order; the Program's types in ``fgc/ir/``.
"""

from __future__ import annotations

from dataclasses import replace

from fgc.compiler.fuse import fuse
from fgc.compiler.lower import lower
from fgc.compiler.schedule import FactorInfo, GraphStructure, VarInfo, check_structure, schedule
from fgc.compiler.storage import ChainLayout, plan_storage
from fgc.errors import DslError, StructureError
from fgc.frontend.dsl import Graph
from fgc.ir import frame
from fgc.ir.program import Program, SolverConfig, check_program


def compile_graph(graph: Graph, solver: SolverConfig | None = None, name: str = "fgc_problem",
                  max_variables: int | None = None, local_frame: bool = True,
                  robust_types: frozenset[str] = frozenset()) -> Program:
    """Compile ``graph``'s structure into a Program for ``solver`` (default options).

    Structure errors (unconstrained variable, gauge freedom, more variables than
    ``max_variables``) are raised before any symbolic or numeric work. A graph far from the
    origin gets a local frame (``Program.frame``, ``fgc.ir.frame``: what float32 needs, and the
    same for every precision so that one data file serves every design of the graph) unless
    ``local_frame`` is False (the streaming paths, whose data are assembled keyframe by keyframe
    in world coordinates). A block member is built with a robust-loss datapath
    (``MemberSpec.robust``) only when one of its factors has a robust loss, or its factor type
    is in ``robust_types`` (a stream's template window, whose later windows may hold robust
    factors the template's own factors lack).
    """
    solver = solver or SolverConfig()
    solver.check()
    limit = max_variables or len(graph.variables)
    structure = graph_structure(graph)
    check_structure(structure, max_variables=limit)              # before any numerics
    sched = schedule(structure, ordering=solver.ordering, incremental_k=solver.incremental_k,
                     batch_every=solver.batch_every, max_variables=limit)
    blocks = fuse(graph)                                          # derive + CSE per block type
    storage = plan_storage(blocks, chain_layout(graph, sched), solver.linear)
    program = lower(graph, blocks, sched, storage, solver, name, limit, robust_types)
    if local_frame:
        program = replace(program, frame=frame.choose(graph))
    check_program(program)
    return program


def graph_structure(graph: Graph) -> GraphStructure:
    """Keys, dimensions and factor key tuples of ``graph`` (keys as strings)."""
    names: dict[str, object] = {}
    for k in graph.variables:
        if str(k) in names:
            raise DslError(f"variable keys {names[str(k)]!r} and {k!r} collide as text")
        names[str(k)] = k
    if not graph.factors:
        raise StructureError("the graph has no factors")
    return GraphStructure.from_lists(
        [VarInfo(str(k), v.type.dim, v.type.__name__) for k, v in graph.variables.items()],
        [FactorInfo(f.name, tuple(str(k) for k in f.keys), f.type.residual_dim)
         for f in graph.factors])


def chain_layout(graph: Graph, sched) -> ChainLayout | None:
    """The schedule's keyframe clusters as a storage layout (slot order = graph order)."""
    if sched.structure_class != "chain":
        return None
    original = {str(k): k for k in graph.variables}
    rank = {str(k): i for i, k in enumerate(graph.variables)}
    return ChainLayout(tuple(tuple(original[k] for k in sorted(c, key=rank.__getitem__))
                             for c in sched.clusters))
