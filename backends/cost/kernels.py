"""The factor block: critical-path latency of a kernel and pipelined timing of its instances.

A kernel (``BlockSpec.kernel`` / ``cost_kernel``) is a list of small sympy assignments. Its
latency is the longest path through that DAG with each operator's latency; its initiation
interval (II) under operator sharing is max over kinds of ⌈ops × ii / instances⌉ in the factor
block's pool. M instances of a block type take latency + (M − 1)·II cycles.
"""

from __future__ import annotations

import heapq
import math
from collections import Counter
from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

from fgc.frontend.geometry import special
from fgc.ir.program import BlockSpec, KernelText, Program

from .params import KINDS, CostParams, OperatorCounts, OperatorTable
from .structure import whitened_pattern

_TRIG = (sp.sin, sp.cos, sp.tan, sp.atan, sp.atan2, sp.acos, sp.asin)


@dataclass(frozen=True)
class BlockTiming:
    """One block type in one mode: pipeline latency, II, instance count and total cycles."""

    name: str
    instances: int
    latency: int
    ii: int
    cycles: int


def critical_path(text: KernelText, ops: OperatorTable, balanced: bool = True) -> int:
    """Cycles from the kernel's inputs to its last output (longest DAG path)."""
    return _critical_path(text, _latencies(ops), balanced)


def _latencies(ops: OperatorTable) -> tuple[tuple[str, int], ...]:
    return tuple((kind, ops.cost(kind).latency) for kind in KINDS)


@lru_cache(maxsize=64)
def _critical_path(text: KernelText, latencies: tuple, balanced: bool) -> int:
    lat = dict(latencies)
    kernel = text.kernel()
    ready: dict[sp.Symbol, int] = {}  # inputs are ready at 0 (absent from the dict)
    for symbol, expr in kernel.assignments:
        ready[symbol] = _ready(expr, ready, lat, balanced)
    return max((_ready(e, ready, lat, balanced) for e in kernel.outputs), default=0)


def _ready(expr: sp.Expr, ready: dict, lat: dict, balanced: bool) -> int:
    """Cycle at which ``expr`` is available, given when its symbols are."""
    if expr.is_Symbol:
        return ready.get(expr, 0)
    if expr.is_Number or not expr.args:
        return 0
    if expr.is_Mul:
        return _mul_ready(expr, ready, lat, balanced)
    args = [_ready(a, ready, lat, balanced) for a in expr.args]
    if expr.is_Add:
        return _reduce(args, lat["add"], balanced)
    if expr.is_Pow:
        return _pow_ready(expr, args[0], lat, balanced)
    if isinstance(expr, _TRIG):
        return max(args) + lat["trig"]
    if isinstance(expr, special.GuardedQuotient):  # a divide, then a select
        return max(args) + lat["div"]
    # Lie coefficients, SO(3) log components and anything unknown: the slowest unit.
    return max(args) + lat["special"]


def _reduce(times: list[int], latency: int, balanced: bool) -> int:
    """Completion of an associative reduction of operands ready at ``times``."""
    if len(times) == 1:
        return times[0]
    if not balanced:  # a left-to-right chain
        done = times[0]
        for t in times[1:]:
            done = max(done, t) + latency
        return done
    heap = list(times)  # always combine the two earliest-ready operands (optimal tree)
    heapq.heapify(heap)
    while len(heap) > 1:
        a, b = heapq.heappop(heap), heapq.heappop(heap)
        heapq.heappush(heap, max(a, b) + latency)
    return heap[0]


def _mul_ready(expr: sp.Mul, ready: dict, lat: dict, balanced: bool) -> int:
    # A sign (−1 factor) is free; a constant denominator is a multiply by its reciprocal;
    # other denominators are multiplied together, then one divide.
    num, den = sp.fraction(expr)
    num_times = [_ready(a, ready, lat, balanced) for a in sp.Mul.make_args(num)
                 if a not in (sp.S.NegativeOne, sp.S.One)]
    if den.is_Number and den != 1:
        num_times.append(0)
    top = _reduce(num_times or [0], lat["mul"], balanced)
    if den.is_Number:
        return top
    den_times = [_ready(a, ready, lat, balanced) for a in sp.Mul.make_args(den)]
    return max(top, _reduce(den_times, lat["mul"], balanced)) + lat["div"]


def _pow_ready(expr: sp.Pow, base: int, lat: dict, balanced: bool) -> int:
    e = expr.exp
    if e == sp.Rational(1, 2):
        return base + lat["sqrt"]
    if e == -sp.Rational(1, 2):
        return base + lat["sqrt"] + lat["div"]
    if e.is_Integer:
        squarings = math.ceil(math.log2(abs(int(e)))) if abs(int(e)) > 1 else 0
        return base + squarings * lat["mul"] + (lat["div"] if e < 0 else 0)
    return base + lat["special"]


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
