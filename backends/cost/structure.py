"""Structural non-zeros the units work on: whitened Jacobians, stacked QR matrices, L's columns.

Everything here is boolean structure derived from the Program (``BlockSpec.structure`` codes,
member noise kinds, the schedule's steps); no numbers. Whitening with a full (upper-triangular)
square-root information matrix makes whitened row i a combination of rows i…m−1 of its member;
isotropic and diagonal noise keep the Jacobian's zero pattern (as in ``fgc.compiler.storage``).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from fgc.compiler.schedule.ir import EliminationStep
from fgc.ir.program import BlockSpec, Program


def whitened_pattern(block: BlockSpec) -> tuple[np.ndarray, ...]:
    """Per block variable, the m × dim mask of whitened Jacobian entries that can be non-zero."""
    full = tuple(tuple(m.rows) for m in block.members if m.noise_kind == "full")
    return _whitened(block.structure, full)


@lru_cache(maxsize=256)
def _whitened(structure: tuple, full: tuple) -> tuple[np.ndarray, ...]:
    masks = [np.array(codes) != "0" for codes in structure]
    out = []
    for mask in masks:
        mixed = mask.copy()
        for r0, r1 in full:
            # suffix "or" over the member's rows: row i mixes rows i..r1-1
            mixed[r0:r1] = np.logical_or.accumulate(mask[r0:r1][::-1], axis=0)[::-1]
        mixed.flags.writeable = False  # shared through the cache
        out.append(mixed)
    return tuple(out)


def row_counts(block: BlockSpec) -> np.ndarray:
    """Non-zeros per whitened Jacobian row of one block instance (over all its variables)."""
    return np.sum([p.sum(axis=1) for p in whitened_pattern(block)], axis=0)


# --------------------------------------------------------------------------------------------
# Cholesky: columns of L in elimination order
# --------------------------------------------------------------------------------------------


def l_column_counts(program: Program) -> np.ndarray:
    """Structural non-zeros of each column of L (diagonal included), in elimination order.

    Frontal variable v of a step, of dimension d and parent width p, owns d columns with
    d − t + p entries (t = 0…d−1): the d×d lower triangle and d × p below it — the step's
    ``r_nonzeros``, i.e. Lᵀ = R of the same elimination.
    """
    counts = [d - t + p
              for step in program.schedule.steps
              for d, p in zip(step.frontal_dims, step.parent_dims, strict=True)
              for t in range(d)]
    return np.array(counts, dtype=np.int64)


# --------------------------------------------------------------------------------------------
# QR: the stacked matrix entering one elimination step
# --------------------------------------------------------------------------------------------


def step_columns(program: Program, step: EliminationStep) -> dict[str, range]:
    """Column range of each frontal and separator variable in the step's stacked matrix."""
    dims = {v.key: v.dim for v in program.variables}
    out, col = {}, 0
    for key in (*step.frontals, *step.separator):
        out[key] = range(col, col + dims[key])
        col += dims[key]
    return out


def stacked_pattern(program: Program, step: EliminationStep, damping: bool) -> np.ndarray:
    """Boolean rows × (frontal + separator) structure of the step's stacked matrix.

    Rows: the whitened rows of each block instance entering here, the children's new factors
    (upper-trapezoidal over the child's separator, as a QR leaves them) and, with LM
    ``damping``, one √μ row per frontal column. The right-hand side is dense and not included.
    """
    cols = step_columns(program, step)
    width = sum(len(r) for r in cols.values())
    rows = [_factor_rows(program, i, cols, width) for i in entering_blocks(program, step)]
    for child in step.children:
        rows.append(_new_factor_rows(program.schedule.steps[child], cols, width))
    if damping:
        rows.append(np.eye(step.frontal_dim, width, dtype=bool))
    return np.vstack(rows) if rows else np.zeros((0, width), dtype=bool)


def entering_blocks(program: Program, step: EliminationStep) -> list[int]:
    """Indices of block instances that enter ``step``: those whose first member factor does
    (a fused instance's rows are stacked whole, where the emitted tables put them:
    ``fgc_backends.cfamily.tables.factor_steps``), even when a later member's own variable is
    eliminated after it (a prior fused into the factor that reaches its keyframe)."""
    entering = set(step.factors)
    return [i for i, f in enumerate(program.factors) if f.factors[0] in entering]


def _factor_rows(program: Program, index: int, cols: dict, width: int) -> np.ndarray:
    spec = program.factors[index]
    block = program.blocks[spec.block]
    out = np.zeros((block.residual_dim, width), dtype=bool)
    for key, mask in zip(spec.keys, whitened_pattern(block), strict=True):
        out[:, cols[key].start:cols[key].stop] |= mask
    return out


def _new_factor_rows(child: EliminationStep, cols: dict, width: int) -> np.ndarray:
    child_cols = [c for key in child.separator for c in cols[key]]
    out = np.zeros((child.new_factor_rows, width), dtype=bool)
    for i in range(child.new_factor_rows):
        out[i, child_cols[i:]] = True
    return out
