"""The structural non-zeros of one block type's rows ``[J | r]``, before and after whitening.

A block's Jacobian is sparse in a way fixed at compile time (``BlockSpec.structure``: "0", "1",
"-1" or "x" per entry, exact because derive found them symbolically), and whitening changes the
pattern only through the noise kind: an isotropic or diagonal noise scales rows, a full square-root
information R (upper triangular) makes row i the combination of rows i … of its member.

The emitted code uses the pattern at the granularity that pays on both targets: the kernel stores
only the non-zeros (the rows are zeroed first), and the Gram ``[A | b]ᵀ[A | b]`` is summed in
TILE × TILE tiles of columns, each over just the rows that touch it, skipping tiles that are zero.
Row operations themselves (whitening, gradient) stay dense over a row: unrolling them entry by
entry into straight-line code makes the linearisation of a 21 × 30 block some 70 KB of
instructions, which on a CPU is slower than the multiplications by zero it saves.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from fgc.ir.program import BlockSpec
from fgc_backends.cfamily.errors import CodegenError

ZERO, ONE, MINUS_ONE, VALUE = "0", "1", "-1", "x"
TILE = 4  # the Gram is computed in TILE × TILE tiles of columns (one SIMD register per tile row)
PANEL_TILES = 2  # at most this many tiles side by side in one panel (3 or 4: 20-60 % slower)


@dataclass(frozen=True)
class BlockPattern:
    """Structure of a block's m rows over its d tangent columns plus the right-hand side (column
    d; ``stride = d + 1``).

    ``raw[r][c]`` is the code of the Jacobian entry (the right-hand side is always "x");
    ``whitened[r][c]`` says whether the whitened entry can be non-zero; ``members`` gives each
    member's (first row, rows, noise kind) with kind 0 isotropic, 1 diagonal, 2 full.
    """

    m: int
    d: int
    raw: tuple[tuple[str, ...], ...]
    whitened: tuple[tuple[bool, ...], ...]
    members: tuple[tuple[int, int, int], ...]

    @property
    def stride(self) -> int:
        return self.d + 1

    @property
    def padded(self) -> int:
        """Row stride of the local rows: d + 1 rounded up to whole tiles."""
        return -(-self.stride // TILE) * TILE

    def rows_of(self, column: int) -> tuple[int, ...]:
        """Rows whose whitened entry in ``column`` can be non-zero."""
        return tuple(r for r in range(self.m) if self.whitened[r][column])

    def columns_of(self, row: int) -> tuple[int, ...]:
        """Columns (right-hand side included) where whitened ``row`` can be non-zero."""
        return tuple(c for c in range(self.stride) if self.whitened[row][c])

    def constant_tail(self, member: int) -> tuple[int, tuple[tuple[tuple[int, int], ...], ...]]:
        """For a full-noise member (kind 2): how many of its leading rows the whitening sums as
        whole rows, and, for each row after them, its constant entries (column, ±1). The rows
        after are the longest run at the member's end whose Jacobian entries are all 0 or ±1 (a
        bias random walk's −I, I): R_ij times such a row adds ±R_ij at a few fixed columns, so it
        needs no row of products. Other kinds, or no such rows: (rows, ())."""
        first, n, kind = self.members[member]
        dense = n
        if kind == 2:
            while dense > 0 and all(code in (ZERO, ONE, MINUS_ONE)
                                    for code in self.raw[first + dense - 1][:self.d]):
                dense -= 1
        rows = (self.raw[first + j][:self.d] for j in range(dense, n))
        entries = tuple(tuple((c, 1 if code == ONE else -1) for c, code in enumerate(row)
                              if code != ZERO) for row in rows)
        return dense, entries

    def gram_rows(self, p: int, q: int) -> tuple[int, ...]:
        """Rows contributing to entry (p, q) of [A | b]ᵀ[A | b]."""
        return tuple(r for r in range(self.m) if self.whitened[r][p] and self.whitened[r][q])

    def tiles(self) -> GramTiles:
        """The lower-triangle TILE × TILE tiles (p0, q0 ≤ p0) of the Gram that are not
        structurally zero, each with the rows that touch both of its column ranges. Two tiles
        side by side in a row of tiles (q0 and q0 + TILE) are summed as one TILE × 2·TILE panel
        over the union of their rows: twice the independent accumulators per row streamed, and
        a row that touches only one of them adds exact zeros (x + 0 = x) to the other."""
        table, rows = [], []
        for p0 in range(0, self.stride, TILE):
            touching = {}
            for q0 in range(0, p0 + 1, TILE):
                touching[q0] = [r for r in range(self.m) if any(self.whitened[r][p0:p0 + TILE])
                                and any(self.whitened[r][q0:q0 + TILE])]
            q0s = [q0 for q0 in touching if touching[q0]]
            while q0s:
                run = [q0s.pop(0)]
                while q0s and len(run) < PANEL_TILES and q0s[0] == run[-1] + TILE:
                    run.append(q0s.pop(0))
                union = sorted(set().union(*(touching[q0] for q0 in run)))
                table += [p0, run[0], len(rows), len(union), len(run)]
                rows += union
        return GramTiles(len(table) // 5, tuple(table), tuple(rows))


@dataclass(frozen=True)
class GramTiles:
    """``count`` panels as ``table`` = (p0, q0, first, rows, tiles) × count: panel t covers
    columns q0 … q0 + tiles·TILE of rows p0 … p0 + TILE and sums over rows
    ``rows[first … first + rows)``."""

    count: int
    table: tuple[int, ...]
    rows: tuple[int, ...]

    @property
    def tile_count(self) -> int:
        """How many TILE × TILE tiles the panels cover."""
        return sum(self.table[4::5])


def block_pattern(block: BlockSpec, kinds: tuple[int, ...], where: str) -> BlockPattern:
    """The pattern of ``block`` whose members have noise ``kinds`` (0, 1, 2 as above).

    Raises :class:`CodegenError` naming ``where`` if a structure code disagrees with the
    block's kernel output (a "0" that is not zero, a "±1" that is not that constant).
    """
    m, d = block.residual_dim, sum(block.variable_dims)
    raw = [[ZERO] * d + [VALUE] for _ in range(m)]
    col = 0
    for k, dim in enumerate(block.variable_dims):
        for r in range(m):
            for j in range(dim):
                raw[r][col + j] = block.structure[k][r][j]
        col += dim
    _check_against_kernel(block, raw, where)
    whitened = [[code != ZERO for code in row] for row in raw]
    members = []
    for member, kind in zip(block.members, kinds, strict=True):
        first, last = member.rows
        members.append((first, last - first, kind))
        if kind == 2:  # row i of R·J mixes rows i … last - 1 of its member
            for i in range(first, last):
                whitened[i] = [any(raw[j][c] != ZERO for j in range(i, last))
                               for c in range(d + 1)]
    return BlockPattern(m, d, tuple(tuple(r) for r in raw), tuple(tuple(r) for r in whitened),
                        tuple(members))


def _check_against_kernel(block: BlockSpec, raw: list[list[str]], where: str) -> None:
    outputs = block.kernel.kernel().outputs
    m, pos, col = block.residual_dim, block.residual_dim, 0
    for dim in block.variable_dims:
        for r in range(m):
            for j in range(dim):
                expr, code = sp.sympify(outputs[pos]), raw[r][col + j]
                pos += 1
                if code != VALUE and expr != sp.Integer(int(code)):
                    raise CodegenError(f"{where}: Jacobian entry ({r}, {col + j}) has structure "
                                         f"code {code!r} but the kernel computes {expr}")
        col += dim
