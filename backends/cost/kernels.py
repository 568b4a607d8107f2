"""The factor block: critical-path latency of a kernel and pipelined timing of its instances.

A kernel (``BlockSpec.kernel`` / ``cost_kernel``) is a list of small sympy assignments. Its
latency is the longest path through that DAG with each operator's latency; its initiation
interval (II) under operator sharing is max over kinds of ⌈ops × ii / instances⌉ in the factor
block's pool. M instances of a block type take latency + (M − 1)·II cycles.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

from fgc.ir.program import BlockSpec, KernelText, Program
from fgc_backends.cfamily.trees import ReadyTimes

from .params import KINDS, CostParams, OperatorCounts, OperatorTable
from .structure import whitened_pattern


@dataclass(frozen=True)
class BlockTiming:
    """One block type in one mode: pipeline latency, II, instance count and total cycles."""

    name: str
    instances: int
    latency: int
    ii: int
    cycles: int


def critical_path(text: KernelText, ops: OperatorTable, balanced: bool = True) -> int:
    """Cycles from the kernel's inputs to its last output (longest DAG path), every sum and
    product the reduction tree the HLS printer prints (``balanced``; ``cfamily.trees``) or a
    left-to-right chain in printed order."""
    return _critical_path(text, _latencies(ops), balanced)


def kernel_latencies(ops: OperatorTable) -> tuple[tuple[str, int], ...]:
    """``ops``' latency per kind, as :func:`critical_path` and the HLS printer's reduction trees
    (``cfamily.printer.print_kernel``'s ``latencies``) take them."""
    atan2 = ops.atan2 or ops.trig  # an arctangent: its own figure where the table has one
    return tuple((kind, ops.cost(kind).latency) for kind in KINDS) + (("atan2", atan2.latency),)


_latencies = kernel_latencies


@lru_cache(maxsize=64)
def _critical_path(text: KernelText, latencies: tuple, balanced: bool) -> int:
    # the walker of the printed layout (cfamily.trees): with ``balanced`` every sum and product
    # the tree the HLS printer prints (the two earliest-ready operands first), else the flat
    # text's left-to-right chains
    kernel = text.kernel()
    ready = ReadyTimes(latencies, balanced)
    for symbol, expr in kernel.assignments:
        ready.assign(symbol, expr)
    return max((ready(sp.sympify(e)) for e in kernel.outputs), default=0)


# --------------------------------------------------------------------------------------------
# pipelined timing of the block types
# --------------------------------------------------------------------------------------------


def initiation_interval(op_counts: dict, pool: OperatorCounts, ops: OperatorTable,
                        block: str = "") -> int:
    """Cycles between two instances of a kernel with ``op_counts`` on a shared ``pool``."""
    ii = 1
    for kind, count in op_counts.items():
        if not count:
            continue
        units = getattr(pool, kind)
        if units < 1:
            raise ValueError(f"block '{block}' needs {kind} operators but the factor pool "
                             f"has none (CostParams.factor_pool.{kind})")
        ii = max(ii, math.ceil(count * ops.cost(kind).ii / units))
    return ii


def block_timings(program: Program, ops: OperatorTable, params: CostParams,
                  mode: str) -> tuple[BlockTiming, ...]:
    """Timing of every block type in ``mode`` ("jacobian" or "cost") on the factor block.

    Block types run one after another, each as a pipeline over its instances. In Jacobian mode
    on the QR path the block also writes its stored A/b words, ``factor_store_ports`` a cycle.
    """
    counts = Counter(f.block for f in program.factors)
    out = []
    for index, block in enumerate(program.blocks):
        text, op_counts = ((block.kernel, block.ops_after) if mode == "jacobian"
                           else (block.cost_kernel, block.ops_cost))
        ii = initiation_interval(op_counts, params.factor_pool, ops, block.name)
        if mode == "jacobian" and program.solver.linear == "qr":
            ii = max(ii, math.ceil(stored_words(block) / params.factor_store_ports))
        latency = max(critical_path(text, ops, params.balanced_reductions), ii)
        m = counts.get(index, 0)
        cycles = latency + (m - 1) * ii if m else 0
        out.append(BlockTiming(block.name, m, latency, ii, cycles))
    return tuple(out)


def stored_words(block: BlockSpec) -> int:
    """Words of one instance's whitened Jacobian and residual that are not structural zeros."""
    return int(sum(p.sum() for p in whitened_pattern(block))) + block.residual_dim


def used_pool(program: Program, pool: OperatorCounts) -> OperatorCounts:
    """``pool`` without the operator kinds no kernel of ``program`` uses."""
    used = {kind for b in program.blocks for counts in (b.ops_after, b.ops_cost)
            for kind, n in counts.items() if n}
    return OperatorCounts(**{kind: n if kind in used else 0 for kind, n in pool.items()})


def factor_pool_ops(program: Program) -> int:
    """Operations of all kernels mapped onto the pool (sizes its operand multiplexers)."""
    return sum(sum(b.ops_after.values()) + sum(b.ops_cost.values()) for b in program.blocks)
