"""Hessian/gradient (HGC) and the Cholesky linear-equation solver (paper B).

**HGC.** H = JᵀJ and g = Jᵀr accumulate factor by factor: a row of a block's whitened Jacobian
with c structural non-zeros contributes c(c+1)/2 products to H's lower triangle and c to g, on
``hgc_lanes`` multiply-accumulate lanes. It consumes the factor block's output as a stream, so
only the part of it that outlasts the factor block adds to an iteration.

**Cascade.** #CPE Cholesky process elements in a chain, each an Evaluate module (l_jj = √s_jj,
l_ij = s_ij / l_jj) and an Update module (s_ik −= l_ij·l_kj), streaming the stored lower triangle
of [H | g] to the next CPE through a FIFO. A round computes #CPE columns; ⌈n / #CPE⌉ rounds. The
augmented column g makes the cascade do Lz = g on the way (z_j = g_j / l_jj, g_i −= l_ij z_j).
A round cannot be shorter than its stream, nor than the cascade depth — the next round's first
column has to pass every CPE of this one (√, ÷, ×, − each); the last round drains the cascade.

**Back-solve.** Lᵀδ = z, last column first, ``solve_lanes`` MACs a cycle; only the newest
solved entry is on the dependency chain.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass

import numpy as np

from fgc.ir.program import Program

from .params import CostParams, OperatorTable
from .structure import l_column_counts, row_counts
from .timing import dot_cycles


@dataclass(frozen=True)
class CholeskyTiming:
    """Cycles of the Cholesky path for one linear solve (HGC per relinearisation)."""

    hgc_macs: int
    hgc_stream: int  # cycles to stream all products through the lanes (with fill)
    rounds: int
    stream_words: tuple[int, ...]  # words streamed per round
    cpe_latency: int  # one CPE's depth
    factorization: int  # the cascade, Lz = g included
    back_substitution: int  # Lᵀδ = z


def hgc_macs(program: Program) -> int:
    """Multiply-adds of H's lower triangle and g over all block instances."""
    per_block = []
    for block in program.blocks:
        c = row_counts(block)
        per_block.append(int(np.sum(c * (c + 1) // 2 + c)))
    counts = Counter(f.block for f in program.factors)
    return sum(per_block[b] * m for b, m in counts.items())


def hgc_stream(macs: int, ops: OperatorTable, params: CostParams) -> int:
    """Cycles for ``macs`` products on the HGC lanes, plus the read-add-write into H."""
    return math.ceil(macs / params.hgc_lanes) + ops.mul.latency + 2 * ops.add.latency


def round_words(program: Program, params: CostParams) -> tuple[int, ...]:
    """Words streamed through the cascade in each round (``CostParams.cholesky_stream``)."""
    counts = l_column_counts(program) + 1  # + the column's entry of g
    n, cpe = counts.size, program.solver.cpe
    starts = range(0, n, cpe)
    if params.cholesky_stream == "whole":
        return tuple(int(counts.sum()) for _ in starts)
    if params.cholesky_stream == "dense":  # trailing m × m lower triangle, zeros included
        return tuple((n - s) * (n - s + 1) // 2 + (n - s) for s in starts)
    suffix = np.concatenate([np.cumsum(counts[::-1])[::-1], [0]])
    return tuple(int(suffix[s]) for s in starts)


def cascade_cycles(words: tuple[int, ...], n: int, cpe: int, cpe_latency: int,
                   words_per_cycle: int) -> int:
    """Cycles of all rounds: each lasts max(stream, cascade depth); the last one drains."""
    total = 0
    for r, w in enumerate(words):
        depth = min(cpe, n - r * cpe) * cpe_latency
        stream = math.ceil(w / words_per_cycle)
        total += stream + depth if r == len(words) - 1 else max(stream, depth)
    return total


def backsolve_cycles(program: Program, ops: OperatorTable, params: CostParams) -> int:
    """Lᵀδ = z: per column max(its stream, the one-entry dependency chain)."""
    chain = 2 * ops.mul.latency + ops.add.latency
    counts = l_column_counts(program) - 1  # off-diagonal entries
    per_column = np.maximum(np.ceil(counts / params.solve_lanes), chain)
    return int(per_column.sum()) + dot_cycles(int(counts.max(initial=0)), params.solve_lanes, ops)


def cholesky_timing(program: Program, ops: OperatorTable, params: CostParams) -> CholeskyTiming:
    """HGC, cascade and triangular solves of one Cholesky solve."""
    macs = hgc_macs(program)
    cpe_latency = ops.path_latency(params.cpe_ops)  # √, ÷, ×, − in a chain
    words = round_words(program, params)
    n = int(l_column_counts(program).size)
    cascade = cascade_cycles(words, n, program.solver.cpe, cpe_latency,
                             params.cpe_words_per_cycle)
    return CholeskyTiming(macs, hgc_stream(macs, ops, params), len(words), words, cpe_latency,
                          cascade, backsolve_cycles(program, ops, params))
