"""lower: fused blocks + schedule + storage plan + solver configuration → :class:`Program`."""

from __future__ import annotations

import dataclasses
import hashlib
from collections.abc import Sequence

from fgc.compiler.cache import cached, source_digest
from fgc.compiler.fuse import BlockType, FactorBlock
from fgc.compiler.schedule import Schedule
from fgc.compiler.storage import StoragePlan
from fgc.frontend.dsl import Graph, storage_dim
from fgc.ir.program import (
    BlockInstance,
    BlockSpec,
    KernelText,
    MemberSpec,
    Program,
    SolverConfig,
    VariableSpec,
)


def lower(graph: Graph, blocks: Sequence[FactorBlock], sched: Schedule, storage: StoragePlan,
          solver: SolverConfig, name: str, max_variables: int) -> Program:
    """Assemble the Program; block types are numbered in order of first appearance."""
    types: dict[str, int] = {}
    specs: list[BlockSpec] = []
    instances = []
    for b in blocks:
        if b.type.key not in types:
            types[b.type.key] = len(specs)
            specs.append(_block_spec(b, graph))
        instances.append(BlockInstance(types[b.type.key], tuple(str(k) for k in b.keys),
                                    tuple(b.indices)))
    variables = tuple(VariableSpec(str(k), v.type.__name__, v.type.dim, v.type.storage_dim,
                                   isinstance(k, int))
                      for k, v in graph.variables.items())
    return Program(name, variables, tuple(specs), tuple(instances), sched, storage, solver,
                   max_variables)


def _block_spec(b: FactorBlock, graph: Graph) -> BlockSpec:
    members = []
    for m, f in zip(b.type.members, b.factors, strict=True):
        sizes = {a.name: storage_dim(a.type) for a in f.type.measurements}
        members.append(MemberSpec(m.name, tuple(m.rows), m.noise_kind, len(m.noise_symbols),
                                  tuple((n, sizes[n]) for n in m.measurement_names),
                                  tuple(m.positions)))
    ops = b.type.ops
    ops_unshared, kernel, cost_kernel = _lowered_kernels(b.type)
    return BlockSpec(
        name=b.type.name,
        variable_types=tuple(v.type_name for v in b.type.variables),
        variable_dims=tuple(v.dim for v in b.type.variables),
        members=tuple(members),
        residual_dim=b.type.residual_dim,
        structure=b.type.structure,
        ops_unshared=ops_unshared,
        ops_before=dataclasses.asdict(ops.jacobian_before),
        ops_after=dataclasses.asdict(ops.jacobian_after),
        ops_cost=dataclasses.asdict(ops.cost_after),
        kernel=kernel,
        cost_kernel=cost_kernel,
    )


_LOWERED: dict[str, tuple[dict, KernelText, KernelText]] = {}


def _lowered_kernels(t: BlockType) -> tuple[dict, KernelText, KernelText]:
    """A block type's op counts without sharing and its two kernels as text. Both walk every
    expression (≈0.6 s of a warm LIO compile), so they are memoised and cached on disk beside
    the fused kernels, keyed by the block type and the code that computes them."""
    if t.key not in _LOWERED:
        h = hashlib.sha256(t.key.encode())
        h.update(source_digest("compiler/lower.py", "ir/program.py", "compiler/kernel.py"))
        _LOWERED[t.key] = cached(("lower", t.name), h.hexdigest(), lambda: (
            t.kernel.op_counts_unshared(), KernelText.of(t.kernel), KernelText.of(t.cost_kernel)),
            tuple)
    return _LOWERED[t.key]
