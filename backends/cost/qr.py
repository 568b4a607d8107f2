"""Partial-QR elimination and back-substitution (paper A).

A partial-QR block is one Evaluate unit, which turns a column into a Householder vector
(‖x‖² by a dot product, √, α, τ = 1/(α·v₀)), and n_u time-multiplexed Update units, which apply
it to the remaining columns (w = vᵀa, then a −= τ·w·v, both streamed through one MAC lane).
The next column's Evaluate starts as soon as the Update units have updated that column, so it
overlaps the rest of the current Update.

Which entries are worked on comes from a structural simulation of the Householder sweep over
the step's stacked matrix (:func:`householder_sweep`): a column's reflector involves only rows
with a structural non-zero there and touches only columns some of those rows reach (plus the
right-hand side); entries known to stay zero are never computed.

A step eliminates its frontal columns and then triangularises the separator part into the new
factor (``new_factor_rows`` rows) handed to its parent. Steps of one schedule level run on
``min(qr_unit_sets, widest level)`` sets of QR + back-substitution blocks — two for a
two-ended chain — and levels run one after another.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from fgc.compiler.schedule.ir import EliminationStep
from fgc.ir.program import Program

from .params import CostParams, OperatorTable
from .structure import stacked_pattern
from .timing import dot_cycles, makespan


@dataclass(frozen=True)
class QrTiming:
    """Cycles of the QR path for one linear solve."""

    sets: int  # QR + back-substitution unit sets instantiated
    step_cycles: tuple[int, ...]  # partial QR of each schedule step
    backsub_step_cycles: tuple[int, ...]
    factorization: int  # all steps, level by level
    back_substitution: int
    reflections: int  # Householder columns computed (r ≥ 2 rows)
    update_macs: int  # multiply-adds done by the Update units


def householder_sweep(pattern: np.ndarray, columns: int) -> list[tuple[int, int]]:
    """(active rows, updated columns incl. right-hand side) of each reflection of a sweep.

    Column k's reflector combines the rows not yet used as pivots with a non-zero in column k;
    afterwards all of them share the union of their patterns right of k, the pivot row keeps
    column k and leaves (it is a row of R), the others have a zero there. Columns with fewer
    than two active rows need no reflection and are skipped.
    """
    nz = pattern.copy()
    free = np.ones(nz.shape[0], dtype=bool)
    out = []
    for k in range(min(columns, nz.shape[1])):
        active = np.flatnonzero(free & nz[:, k])
        if active.size == 0:
            continue
        union = nz[active, k + 1:].any(axis=0)
        nz[np.ix_(active, np.arange(k + 1, nz.shape[1]))] = union
        nz[active[1:], k] = False
        free[active[0]] = False
        if active.size >= 2:
            out.append((int(active.size), int(union.sum()) + 1))
    return out


def step_cycles(sweep: list[tuple[int, int]], units: int, ops: OperatorTable,
                params: CostParams) -> int:
    """Cycles of one partial QR: Evaluate of column k + 1 overlaps the Update of column k."""
    if not sweep:
        return 0
    evaluate = [_evaluate(r, ops, params) for r, _ in sweep] + [0]
    total = evaluate[0]
    for k, (rows, cols) in enumerate(sweep):
        first = _column_update(rows, ops, params)  # column k + 1 is updated first
        stream = 2 * math.ceil(rows / params.update_lanes)  # dot then axpy through one lane
        update = math.ceil(cols / units) * stream + (first - stream)
        total += max(update, first + evaluate[k + 1])
    return total


def _evaluate(rows: int, ops: OperatorTable, params: CostParams) -> int:
    # ‖x‖², √, α = −sign(x₀)‖x‖, v₀ = x₀ − α, τ = 1/(α·v₀)
    norm = dot_cycles(rows, params.evaluate_lanes, ops)
    return norm + ops.sqrt.latency + ops.add.latency + ops.mul.latency + ops.div.latency


def _column_update(rows: int, ops: OperatorTable, params: CostParams) -> int:
    # w = vᵀa; τ·w; a −= (τw)·v streamed through multiply and subtract
    dot = dot_cycles(rows, params.update_lanes, ops)
    axpy = math.ceil(rows / params.update_lanes) + ops.mul.latency + ops.add.latency
    return dot + ops.mul.latency + axpy


def backsub_cycles(step: EliminationStep, ops: OperatorTable, params: CostParams) -> int:
    """Back-substitution of one step's conditional: its rows of R, last row first.

    A row's dot product over the already-solved entries streams at ``backsub_lanes`` a cycle;
    only the newest solved entry is on the dependency chain (multiply, add, then a multiply by
    1/R_ii, which the Evaluate unit produced during the QR).
    """
    chain = 2 * ops.mul.latency + ops.add.latency
    total = 0
    for d, p in zip(step.frontal_dims, step.parent_dims, strict=True):
        for t in range(d):
            total += max(math.ceil((d - t - 1 + p) / params.backsub_lanes), chain)
    return total + dot_cycles(step.separator_dim, params.backsub_lanes, ops)


def qr_timing(program: Program, ops: OperatorTable, params: CostParams) -> QrTiming:
    """Partial QR of every step and back-substitution, scheduled over the unit sets."""
    sched = program.schedule
    damping = program.solver.method == "lm"  # LM appends √μ·I rows per frontal column
    sweeps = [householder_sweep(stacked_pattern(program, s, damping),
                                s.frontal_dim + s.new_factor_rows) for s in sched.steps]
    units = program.solver.units
    qr = tuple(step_cycles(sw, units, ops, params) for sw in sweeps)
    bs = tuple(backsub_cycles(s, ops, params) for s in sched.steps)
    sets = max(1, min(params.qr_unit_sets, max(len(level) for level in sched.levels)))
    factorization = sum(makespan([qr[i] for i in level], sets) for level in sched.levels)
    back = sum(makespan([bs[i] for i in level], sets) for level in sched.back_substitution)
    macs = sum(2 * r * c for sw in sweeps for r, c in sw)
    return QrTiming(sets, qr, bs, factorization, back, sum(len(sw) for sw in sweeps), macs)
