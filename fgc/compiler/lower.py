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
          solver: SolverConfig, name: str, max_variables: int,
          robust_types: frozenset[str] = frozenset()) -> Program:
    """Assemble the Program; block types are numbered in order of first appearance. A member
    is flagged robust (:attr:`MemberSpec.robust`) when a factor of it in ``graph`` has a robust
    loss or its factor type is in ``robust_types``."""
    types: dict[str, int] = {}
    specs: list[BlockSpec] = []
    instances = []
    robust: list[list[bool]] = []  # per block type, per member: some factor has a robust loss
    for b in blocks:
        if b.type.key not in types:
            types[b.type.key] = len(specs)
            specs.append(_block_spec(b, graph))
            robust.append([False] * len(b.factors))
        flags = robust[types[b.type.key]]
        for k, f in enumerate(b.factors):
            flags[k] = flags[k] or f.noise.robust is not None or f.type.name in robust_types
        instances.append(BlockInstance(types[b.type.key], tuple(str(k) for k in b.keys),
                                    tuple(b.indices)))
    specs = [dataclasses.replace(s, members=tuple(
        dataclasses.replace(m, robust=r) for m, r in zip(s.members, flags, strict=True)))
        for s, flags in zip(specs, robust, strict=True)]
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
