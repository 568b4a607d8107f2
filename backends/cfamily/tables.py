"""The constant tables the HLS kernel steps through: a Program's structure as integer arrays.

The accelerator is specialised to one structure, so everything that says *which* factor, variable
or column meets *where* is a compile-time table — the instruction stream of the elimination — and
the kernel's loops only do arithmetic. All index arithmetic happens here, in Python; the template
only prints the arrays.

Layout conventions shared with ``kernel.cpp.jinja``:

- variable ``v`` occupies storage words ``VAR_X_OFF[v] …`` and tangent entries ``VAR_T_OFF[v] …``;
- factor instance ``f`` (a fused block instance, ``Program.factors`` order) reads its data line at
  ``FACTOR_DATA_OFF[f]`` and writes its whitened rows ``[A | b]`` (M × (D + 1), row-major) at
  ``FACTOR_A_OFF[f]``; its local column ``c`` is column
  ``FACTOR_COLMAP[FACTOR_COLMAP_BEGIN[f] + c]`` of the elimination step it enters;
- step ``s`` has ``STEP_W[s]`` columns (frontal then separator, elimination order; the right-hand
  side is column ``STEP_W[s]``), of which the first ``STEP_F[s]`` are frontal; its column ``c`` is
  global tangent entry ``STEP_COL[STEP_COL_BEGIN[s] + c]``; its conditional (``STEP_F`` rows of
  ``STEP_W + 1``) is stored at ``STEP_COND_OFF[s]`` and the factor (QR) or update matrix
  (Cholesky) it passes to its parent, ``STEP_NF_ROWS[s]`` rows of ``STEP_W - STEP_F + 1``, at
  ``STEP_NF_OFF[s]``; separator column ``k`` lands in column ``STEP_SEPMAP[…]`` of the parent.
"""

from __future__ import annotations

from dataclasses import dataclass

from fgc.ir.program import Program


@dataclass(frozen=True)
class IntTable:
    """One ``static const int NAME[len] = {…};`` array."""

    name: str
    values: tuple[int, ...]


@dataclass(frozen=True)
class Tables:
    """All tables plus the scalar sizes (``constants``: name → value) the kernel is built for."""

    constants: tuple[tuple[str, int], ...]
    arrays: tuple[IntTable, ...]

    def constant(self, name: str) -> int:
        return dict(self.constants)[name]


def _offsets(sizes: list[int]) -> list[int]:
    out, pos = [], 0
    for s in sizes:
        out.append(pos)
        pos += s
    return out + [pos]


def factor_data_words(program: Program, block: int) -> int:
    """Numbers on one data-file line of an instance of ``block`` (see :mod:`fgc.ir.datafile`)."""
    return sum(sum(n for _, n in m.measurements) + m.noise_params + 2
               for m in program.blocks[block].members)


def factor_steps(program: Program) -> list[int]:
    """The elimination step each factor instance enters (that of its first member factor)."""
    step_of_factor = {i: s.index for s in program.schedule.steps for i in s.factors}
    return [step_of_factor[f.factors[0]] for f in program.factors]


def build_tables(program: Program, damped: bool, cholesky: bool) -> Tables:
    """Tables of ``program``; ``damped`` adds LM's √μ rows to each QR step's row count."""
    var_index = {v.key: i for i, v in enumerate(program.variables)}
    x_off = _offsets([v.storage_dim for v in program.variables])
    t_off = _offsets([v.dim for v in program.variables])
    steps = program.schedule.steps
    step_cols = [_step_columns(s, var_index, t_off) for s in steps]
    entering = factor_steps(program)
    arrays = [IntTable("VAR_X_OFF", tuple(x_off)), IntTable("VAR_T_OFF", tuple(t_off))]
    arrays += _factor_arrays(program, var_index, entering, steps, t_off)
    step_arrays, sizes = _step_arrays(program, step_cols, entering, damped, cholesky)
    arrays += step_arrays
    level_steps = [i for level in program.schedule.levels for i in level]
    arrays += [IntTable("LEVEL_BEGIN", tuple(_offsets([len(lv) for lv in
                                                        program.schedule.levels]))),
               IntTable("LEVEL_STEPS", tuple(level_steps))]
    a_words = sum(program.blocks[f.block].residual_dim * (1 + sum(
        program.blocks[f.block].variable_dims)) for f in program.factors)
    data_words = sum(factor_data_words(program, f.block) for f in program.factors)
    gram_words = sum((d + 1) * (d + 2) // 2 for d in (sum(program.blocks[f.block].variable_dims)
                                                       for f in program.factors))
    constants = (("N_VARIABLES", len(program.variables)), ("N_FACTORS", len(program.factors)),
                 ("N_STEPS", len(steps)), ("N_LEVELS", len(program.schedule.levels)),
                 ("N_X", x_off[-1]), ("N_TANGENT", t_off[-1]), ("N_DATA", data_words),
                 ("N_A", a_words), ("N_GRAM", gram_words), *sizes)
    return Tables(constants, tuple(arrays))


def _step_columns(step, var_index: dict, t_off: list[int]) -> list[int]:
    """Global tangent index of each column of ``step`` (frontals, then separator)."""
    cols = []
    for key in (*step.frontals, *step.separator):
        v = var_index[key]
        cols += range(t_off[v], t_off[v + 1])
    return cols


def _factor_arrays(program: Program, var_index: dict, entering: list[int], steps,
                   t_off: list[int]) -> list[IntTable]:
    block_of, data_off, a_off, gram_off, var_lists, colmaps = [], [], [], [], [], []
    data_pos = a_pos = gram_pos = 0
    columns_of: dict[int, dict[int, int]] = {}  # per step: global tangent index → its column
    for f, step in zip(program.factors, entering, strict=True):
        block = program.blocks[f.block]
        block_of.append(f.block)
        data_off.append(data_pos)
        a_off.append(a_pos)
        data_pos += factor_data_words(program, f.block)
        a_pos += block.residual_dim * (1 + sum(block.variable_dims))
        gram_off.append(gram_pos)
        gram_pos += (sum(block.variable_dims) + 1) * (sum(block.variable_dims) + 2) // 2
        variables = [var_index[k] for k in f.keys]
        var_lists.append(variables)
        if step not in columns_of:
            columns_of[step] = {g: c for c, g in enumerate(_step_columns(steps[step], var_index,
                                                                         t_off))}
        where = columns_of[step]
        colmaps.append([where[g] for v in variables for g in range(t_off[v], t_off[v + 1])])
    return [IntTable("FACTOR_BLOCK", tuple(block_of)),
            IntTable("FACTOR_DATA_OFF", (*data_off, data_pos)),
            IntTable("FACTOR_A_OFF", (*a_off, a_pos)),
            IntTable("FACTOR_GRAM_OFF", (*gram_off, gram_pos)),
            IntTable("FACTOR_VAR_BEGIN", tuple(_offsets([len(v) for v in var_lists]))),
            IntTable("FACTOR_VARS", tuple(v for vs in var_lists for v in vs)),
            IntTable("FACTOR_COLMAP_BEGIN", tuple(_offsets([len(c) for c in colmaps]))),
            IntTable("FACTOR_COLMAP", tuple(c for cs in colmaps for c in cs))]


def _step_arrays(program: Program, step_cols: list[list[int]], entering: list[int],
                 damped: bool, cholesky: bool) -> tuple[list[IntTable], list[tuple[str, int]]]:
    """Per-step tables, and the buffer sizes they imply."""
    steps = program.schedule.steps
    factor_rows = [0] * len(steps)
    factors_of: list[list[int]] = [[] for _ in steps]
    for f, step in enumerate(entering):
        factors_of[step].append(f)
        factor_rows[step] += program.blocks[program.factors[f].block].residual_dim
    f_cols = [s.frontal_dim for s in steps]
    widths = [len(c) for c in step_cols]
    rows, nf_rows = [0] * len(steps), [0] * len(steps)
    for s in steps:  # children come before their parent in ``steps``
        i = s.index
        rows[i] = factor_rows[i] + sum(nf_rows[c] for c in s.children) + (f_cols[i] * damped)
        sep = widths[i] - f_cols[i]
        nf_rows[i] = sep if cholesky else max(0, min(rows[i], widths[i]) - f_cols[i])
    sepmaps = [_sepmap(s, step_cols) for s in steps]
    cond_sizes = [f * (w + 1) for f, w in zip(f_cols, widths, strict=True)]
    nf_sizes = [n * (w - f + 1) for n, w, f in zip(nf_rows, widths, f_cols, strict=True)]
    arrays = [
        IntTable("STEP_F", tuple(f_cols)), IntTable("STEP_W", tuple(widths)),
        IntTable("STEP_ROWS", tuple(rows)), IntTable("STEP_NF_ROWS", tuple(nf_rows)),
        IntTable("STEP_COND_OFF", tuple(_offsets(cond_sizes)[:-1])),
        IntTable("STEP_NF_OFF", tuple(_offsets(nf_sizes)[:-1])),
        IntTable("STEP_COL_BEGIN", tuple(_offsets(widths))),
        IntTable("STEP_COL", tuple(c for cs in step_cols for c in cs)),
        IntTable("STEP_FACTOR_BEGIN", tuple(_offsets([len(fs) for fs in factors_of]))),
        IntTable("STEP_FACTORS", tuple(f for fs in factors_of for f in fs)),
        IntTable("STEP_CHILD_BEGIN", tuple(_offsets([len(s.children) for s in steps]))),
        IntTable("STEP_CHILDREN", tuple(c for s in steps for c in s.children)),
        IntTable("STEP_SEPMAP_BEGIN", tuple(_offsets([len(m) for m in sepmaps]))),
        IntTable("STEP_SEPMAP", tuple(c for m in sepmaps for c in m)),
    ]
    sizes = [("N_COND", sum(cond_sizes)), ("N_NF", max(1, sum(nf_sizes))),
             ("MAX_W", max(widths)), ("MAX_F", max(f_cols)),
             ("MAX_ROWS", max(max(rows), max(widths))), ("MAX_STEP_FACTORS",
                                                        max(len(fs) for fs in factors_of)),
             ("MAX_CHILDREN", max([len(s.children) for s in steps] + [1]))]
    return arrays, sizes


def _sepmap(step, step_cols: list[list[int]]) -> list[int]:
    """Columns of the parent step that receive ``step``'s separator columns."""
    if step.parent is None:
        return []
    where = {g: c for c, g in enumerate(step_cols[step.parent])}
    return [where[g] for g in step_cols[step.index][step.frontal_dim:]]
