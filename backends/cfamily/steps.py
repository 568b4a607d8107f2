"""Elimination steps that share a shape, specialised into fixed-size routines.

On a chain every interior step looks the same: the same width W and frontal size F, the same
block types entering with the same column maps, one child with the same separator map. A
*step pattern* is all of that; the steps of a pattern that occurs at least twice (the most
frequent first, at most ``MAX_PATTERNS``) run a routine compiled for it: W, F and the row count
are compile-time constants, and the scatter of the entering Grams (Cholesky) or rows (QR) and of
the children's update matrices / new factors into the frontal matrix is a list of moves over
their structural non-zeros — no index table is read, no zero is added. Every other step runs the
generic table-driven routine.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from fgc_backends.cfamily.sparsity import TILE, BlockPattern
from fgc_backends.cfamily.tables import Tables

MAX_PATTERNS = 8


@dataclass(frozen=True)
class StepPattern:
    """One specialised step shape.

    ``moves`` are (row, column, operand, index): the frontal matrix entry (row, column) takes
    ``operand[index]`` (Cholesky: added; QR: assigned into a zeroed matrix, at ``row``). Operand
    k < ``n_factors`` is the k-th entering factor's Gram (Cholesky, packed lower) or rows [A | b]
    (QR); the others are the children's update matrices / new factors, in table order. Column
    ``w`` is the right-hand side.
    """

    index: int
    w: int
    f: int
    rows: int
    n_factors: int
    n_children: int
    steps: tuple[int, ...]
    moves: tuple[tuple[int, int, int, int], ...]
    plan: tuple[int, ...]  # QR: per Householder column, the count and rows it reflects

    @property
    def operands_used(self) -> tuple[int, ...]:
        """The operands some move reads, ascending: only these get a pointer in the emitted
        routine (a child whose new factor has no structural non-zero here reads nothing, and an
        unused pointer fails ``-Werror=unused-variable``)."""
        return tuple(sorted({k for _, _, k, _ in self.moves}))

    @property
    def ld(self) -> int:
        """Row length of the frontal matrix: w + 1 padded to whole tiles."""
        return padded(self.w + 1)


def padded(n: int) -> int:
    """``n`` rounded up to whole tiles."""
    return -(-n // TILE) * TILE


def step_patterns(tables: Tables, patterns: dict[int, BlockPattern], cholesky: bool,
                  damped: bool = True) -> tuple[tuple[StepPattern, ...], tuple[int, ...]]:
    """The specialised patterns and, per step, its pattern's index (-1: the generic routine).

    ``patterns`` maps each block type to its :class:`BlockPattern`; ``damped``: QR steps end
    with LM's damping rows.
    """
    t = {a.name: a.values for a in tables.arrays}
    n_steps = len(t["STEP_W"])
    keys = [_key(t, s) for s in range(n_steps)]
    counts = Counter(keys)
    chosen = [k for k, n in sorted(counts.items(), key=lambda kv: (-kv[1], keys.index(kv[0])))
              if n >= 2][:MAX_PATTERNS]
    index = {k: i for i, k in enumerate(chosen)}
    of_step = tuple(index.get(k, -1) for k in keys)
    out = []
    for i, key in enumerate(chosen):
        steps = tuple(s for s in range(n_steps) if of_step[s] == i)
        moves = _moves(t, steps[0], patterns, cholesky)
        w, f, rows, factors, children = key
        plan = () if cholesky else householder_plan(rows, w, f, moves, damped)
        out.append(StepPattern(i, w, f, rows, len(factors), len(children), steps, moves, plan))
    return tuple(out), of_step


def _key(t: dict, s: int) -> tuple:
    """Everything the specialised code of step ``s`` depends on."""
    factors = tuple((t["FACTOR_BLOCK"][fac], _colmap(t, fac))
                    for fac in t["STEP_FACTORS"][t["STEP_FACTOR_BEGIN"][s]:
                                                 t["STEP_FACTOR_BEGIN"][s + 1]])
    children = tuple((t["STEP_W"][c] - t["STEP_F"][c], t["STEP_NF_ROWS"][c], _sepmap(t, c))
                     for c in t["STEP_CHILDREN"][t["STEP_CHILD_BEGIN"][s]:
                                                 t["STEP_CHILD_BEGIN"][s + 1]])
    return t["STEP_W"][s], t["STEP_F"][s], t["STEP_ROWS"][s], factors, children


def _colmap(t: dict, fac: int) -> tuple[int, ...]:
    return tuple(t["FACTOR_COLMAP"][t["FACTOR_COLMAP_BEGIN"][fac]:
                                    t["FACTOR_COLMAP_BEGIN"][fac + 1]])


def _sepmap(t: dict, c: int) -> tuple[int, ...]:
    return tuple(t["STEP_SEPMAP"][t["STEP_SEPMAP_BEGIN"][c]:t["STEP_SEPMAP_BEGIN"][c + 1]])


def _moves(t: dict, s: int, patterns: dict[int, BlockPattern], cholesky: bool):
    w, _, _, factors, children = _key(t, s)
    moves, row = [], 0
    for k, (block, cm) in enumerate(factors):
        pattern = patterns[block]
        d = pattern.d
        full = [*cm, w]  # the block's right-hand side lands in column w
        if cholesky:  # Gram entry (p, q), q <= p, into the upper triangle
            for p in range(d + 1):
                for q in range(p + 1):
                    if (p, q) != (d, d) and pattern.gram_rows(p, q):
                        a, b = sorted((full[p], full[q]))
                        moves.append((a, b, k, p * (p + 1) // 2 + q))
        else:  # whitened rows, structural non-zeros only
            for r in range(pattern.m):
                moves += [(row + r, full[c], k, r * (d + 1) + c) for c in pattern.columns_of(r)]
            row += pattern.m
    for j, (sc, nf_rows, sepmap) in enumerate(children):
        k = len(factors) + j
        full = [*sepmap, w]
        if cholesky:  # the child's update matrix: upper triangle and reduced gradient
            for a in range(sc):
                for b in range(a, sc + 1):
                    lo, hi = sorted((full[a], full[b]))
                    moves.append((lo, hi, k, a * (sc + 1) + b))
        else:  # the child's new factor: upper-trapezoidal rows
            for r in range(nf_rows):
                moves += [(row + r, full[c], k, r * (sc + 1) + c) for c in range(r, sc + 1)]
            row += nf_rows
    return tuple(moves)


def householder_plan(m: int, w: int, f: int, moves, damped: bool) -> tuple[int, ...]:
    """Per Householder column j of a QR step: the rows that can be non-zero in it (pivot row j
    first, then ascending), found by running the reflections on the structure — a reflection
    fills every row it touches with the union of their patterns. Rows that are numerically
    zero there are harmless (their v_i is 0), so the plan replaces the scan exactly."""
    nz = [[False] * (w + 1) for _ in range(m)]
    for r, c, _, _ in moves:
        nz[r][c] = True
    if damped:
        for j in range(f):
            nz[m - f + j][j] = True
    plan = []
    for j in range(min(m, w + 1)):
        active = [i for i in range(j, m) if i == j or nz[i][j]]
        union = [any(nz[i][c] for i in active) for c in range(w + 1)]
        for i in active:
            nz[i][j + 1:] = union[j + 1:]
            nz[i][j] = i == j
        plan += [len(active), *active]
    return tuple(plan)
