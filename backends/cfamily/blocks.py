"""Per block type: the data layout and printed kernels the kernel template places.

A factor block (paper A's factor block, paper B's EJCC) has two modes on shared arithmetic:
residual + Jacobian (``jacobian_<b>``, writing each instance's ``[J | r]`` rows) and residual +
cost (``cost_<b>``, writing each member's ½‖W r‖²). Both evaluate ``LANES`` instances side by side
(printed with ``vector=True``: one SIMD operation per assignment on a CPU).
Everything here is offsets and sizes; C++ syntax comes from the printer.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import sympy as sp

from fgc.compiler.kernel import Kernel, drop_dead
from fgc.ir.codes import NOISE_CODES
from fgc.ir.program import BlockSpec, Program
from fgc_backends.cfamily.names import comment
from fgc_backends.cfamily.printer import PrintedKernel, print_kernel
from fgc_backends.cfamily.sparsity import ZERO, BlockPattern, GramTiles, block_pattern


@dataclass(frozen=True)
class VarSlot:
    """Variable ``k`` of a block: storage words at ``in_off`` of the kernel input, tangent
    columns ``col … col + dim`` of the block's rows."""

    k: int
    storage: int
    in_off: int
    dim: int
    col: int


@dataclass(frozen=True)
class MemberSlot:
    """One member factor: rows ``r0 … r0 + rows``, its noise and where its data sits.

    ``*_data`` offsets are into the instance's data-file line; ``meas_in`` / ``noise_in`` into the
    Jacobian / cost kernel's input array.
    """

    r0: int
    rows: int
    kind: int
    n_params: int
    meas_words: int
    meas_data: int
    meas_in: int
    noise_data: int
    noise_in: int
    robust_data: int
    dense: int = 0  # full noise: leading rows whitened as whole rows (the rest: ``tail``)
    robust: bool = True  # a robust loss possible (MemberSpec.robust): reweight / robust_loss
    tail: tuple[tuple[int, int, int, tuple[tuple[int, int], ...]], ...] = ()


@dataclass(frozen=True)
class BlockContext:
    index: int
    comment: str
    m: int  # residual rows
    d: int  # tangent columns; rows are stored with stride d + 1 (right-hand side last)
    n_in: int
    n_cost_in: int
    variables: tuple[VarSlot, ...]
    members: tuple[MemberSlot, ...]
    instances: tuple[int, ...]
    jacobian: PrintedKernel
    jacobian_targets: tuple[tuple[int, str], ...]  # (local index of [J | r], expression)
    cost: PrintedKernel  # outputs: each member's ½‖W r‖²
    pattern: BlockPattern
    tiles: GramTiles

    @property
    def n_x_in(self) -> int:
        """Kernel inputs that come from x (the variables' storage, first in the input array);
        the measurements and noise parameters follow."""
        return sum(v.storage for v in self.variables)

    @property
    def padded(self) -> int:
        """Row stride of the local rows (whole Gram tiles)."""
        return self.pattern.padded

    @property
    def stride(self) -> int:
        return self.d + 1


def block_contexts(program: Program, vector: bool = True,
                   latencies=None) -> tuple[BlockContext, ...]:
    """A :class:`BlockContext` per block type of ``program``; ``vector``: kernels printed on V
    (the CPU design's lanes), else on the scalar T (the dataflow accelerator); ``latencies``:
    their sums and products printed as the reduction trees of that operator table
    (``print_kernel``; the HLS design's), None flat (the native backend's)."""
    index = {v.key: i for i, v in enumerate(program.variables)}
    out = []
    for b, block in enumerate(program.blocks):
        instances = tuple(j for j, f in enumerate(program.factors) if f.block == b)
        first = program.factors[instances[0]]
        storage = [program.variables[index[k]].storage_dim for k in first.keys]
        out.append(_block(b, block, tuple(storage), instances, vector, latencies))
    return tuple(out)


# One context per distinct block: printing its kernel and checking its sparsity is most of an
# emit's time, and an emit asks twice (the shared context and the accelerator plan), a test
# module many times over. The key holds every BlockSpec field _build_block reads (the op-count
# dicts it does not read are unhashable); the context is frozen.
_BLOCKS: dict[tuple, BlockContext] = {}


def _block(b: int, block: BlockSpec, storage: tuple[int, ...], instances: tuple[int, ...],
           vector: bool = True, latencies=None) -> BlockContext:
    key = (b, block.name, block.variable_types, block.variable_dims, block.members,
           block.residual_dim, block.structure, block.kernel, block.cost_kernel, storage,
           instances, vector, latencies)
    hit = _BLOCKS.get(key)
    if hit is None:
        if len(_BLOCKS) >= 256:
            _BLOCKS.clear()
        hit = _BLOCKS[key] = _build_block(b, block, storage, instances, vector, latencies)
    return hit


def _build_block(b: int, block: BlockSpec, storage: tuple[int, ...],
                 instances: tuple[int, ...], vector: bool, latencies=None) -> BlockContext:
    variables, pos, col = [], 0, 0
    for k, (s, dim) in enumerate(zip(storage, block.variable_dims, strict=True)):
        variables.append(VarSlot(k, s, pos, dim, col))
        pos, col = pos + s, col + dim
    members, data, meas_in = [], 0, pos
    n_in = pos + sum(n for m in block.members for _, n in m.measurements)
    noise_in = n_in
    for m in block.members:
        words = sum(n for _, n in m.measurements)
        members.append(MemberSlot(m.rows[0], m.rows[1] - m.rows[0], NOISE_CODES[m.noise_kind],
                                  m.noise_params, words, data, meas_in, data + words, noise_in,
                                  data + words + m.noise_params, robust=m.robust))
        data += words + m.noise_params + 2
        meas_in += words
        noise_in += m.noise_params
    where = f"block type {b} ({comment(block.name)})"
    pattern = block_pattern(block, tuple(m.kind for m in members), where)
    members = [_with_tail(slot, *pattern.constant_tail(k)) for k, slot in enumerate(members)]
    kernel = block.kernel.kernel()
    jacobian = print_kernel(kernel, _input_names(len(kernel.inputs), pos), where,
                            vector=vector, latencies=latencies)
    targets = _targets(pattern, variables, jacobian.outputs)
    return BlockContext(b, comment(block.name), block.residual_dim, col, n_in, noise_in,
                        tuple(variables), tuple(members), instances, jacobian, targets,
                        _cost(block, where, pos, vector, latencies), pattern, pattern.tiles())


def _with_tail(slot: MemberSlot, dense: int, entries) -> MemberSlot:
    """``slot`` with its whitening split at ``dense``: ``tail`` lists, for each whitened row i
    and constant row j ≥ max(i, dense) in row order, (i, j, R_ij's parameter index, j's
    constant entries), the order the whole-row loop would add them in."""
    n, tail = slot.rows, []
    for i in range(n if entries else 0):
        base = i * n - (i * (i - 1)) // 2 - i  # R row-major upper triangle: R_ij at base + j
        for j in range(max(i, dense), n):
            tail.append((i, j, base + j, entries[j - dense]))
    return dataclasses.replace(slot, dense=dense, tail=tuple(tail))


def _targets(pattern: BlockPattern, variables: list[VarSlot], outputs: tuple[str, ...]):
    """Kernel outputs (residual, then each variable's m × dim Jacobian) → the local rows
    [J | r] (stride ``pattern.padded``); structural zeros are not stored (the rows start zeroed)."""
    m, stride = pattern.m, pattern.padded
    targets = [(i * stride + pattern.d, outputs[i]) for i in range(m)]
    pos = m
    for v in variables:
        for r in range(m):
            for j in range(v.dim):
                if pattern.raw[r][v.col + j] != ZERO:
                    targets.append((r * stride + v.col + j, outputs[pos]))
                pos += 1
    return tuple(sorted(targets))


def _input_names(n: int, n_x: int) -> list[str]:
    """The kernels' inputs in C++: x's storage from ``in``, the data (measurements, noise
    parameters) from ``dat``, which on the host points straight at the block's laned data."""
    return [f"in[{i}]" if i < n_x else f"dat[{i - n_x}]" for i in range(n)]


def _cost(block: BlockSpec, where: str, n_x: int, vector: bool = True,
          latencies=None) -> PrintedKernel:
    """The cost kernel reduced to the members' ½‖W r‖² (robust losses are applied in C++)."""
    kernel = cost_outputs_kernel(block.cost_kernel.kernel(), block.residual_dim,
                                 len(block.members))
    return print_kernel(kernel, _input_names(len(kernel.inputs), n_x), where + " cost",
                        vector=vector, latencies=latencies)


def cost_outputs_kernel(full: Kernel, m: int, n: int) -> Kernel:
    """Cost kernel ``full`` (of a block type with ``m`` residual rows and ``n`` members) as
    the C-family backends print it: the members' ½‖W r‖² outputs alone (the residual's outputs
    dropped) and the assignments they use."""
    outputs = tuple(sp.sympify(e) for e in full.outputs[m:m + n])
    return Kernel(full.inputs, drop_dead(full.assignments, outputs), outputs)
