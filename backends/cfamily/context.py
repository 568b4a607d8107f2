"""The template context both C++ backends (hls, native) share: the solver constants, tables,
block contexts, step patterns, sizes and the codes their kernels print. Each emitter adds only
its own keys (the HLS design's part, clock and testbench; the native build's host flags, SIMD
lanes and row export), so knowledge of a Program's tables lives here once."""

from __future__ import annotations

from fgc.ir.codes import NOISE_CODES, REASONS, ROBUST_CODES, STATUSES
from fgc.ir.datafile import MAGIC
from fgc.ir.program import Program
from fgc.version import __version__
from fgc_backends.cfamily.blocks import block_contexts
from fgc_backends.cfamily.names import comment
from fgc_backends.cfamily.printer import HlsCodePrinter
from fgc_backends.cfamily.retract import retract_kinds
from fgc_backends.cfamily.scalars import FIXED_POINT_FLAGS, ap_types_include, fixed_declaration
from fgc_backends.cfamily.solver import solver_context
from fgc_backends.cfamily.sparsity import TILE
from fgc_backends.cfamily.special import SERIES_BELOW, coefficient_functions
from fgc_backends.cfamily.steps import padded, step_patterns
from fgc_backends.cfamily.tables import IntTable, build_tables, factor_data_words

HEADER_TABLES = ("VAR_X_OFF", "FACTOR_DATA_OFF")


def common_context(program: Program, config, project: str, error: type[Exception],
                   unit_sets: int, vector: bool = True, latencies=None) -> dict:
    """The shared context of ``program`` emitted with ``config`` (an HlsConfig or NativeConfig)
    as ``project``; ``unit_sets`` is the order a level's steps run in (one per chain end on a
    two-ended chain), ``error`` the backend's config error (a fixed-point scalar without the
    ap_types headers); ``latencies``: the kernels' sums and products printed as that operator
    table's reduction trees (the HLS design's; ``cfamily.trees``), None flat (native)."""
    printer = HlsCodePrinter({})
    solver = solver_context(program, config, printer)
    tables = build_tables(program, damped=solver["lm"], cholesky=solver["cholesky"])
    include = [str(ap_types_include(error))] if config.is_fixed_point else []
    blocks = block_contexts(program, vector=vector, latencies=latencies)
    patterns, step_pattern = step_patterns(tables, {b.index: b.pattern for b in blocks},
                                           solver["cholesky"], solver["lm"])
    max_ld = padded(tables.constant("MAX_W") + 1)
    table = {t.name: t.values for t in tables.arrays}
    # the widest separator of any step: the back-substitution's tiled loop over separator
    # columns exists only if some separator spans a whole TILE (else g++ -Werror proves the dead
    # loop would index past xs[MAX_W])
    max_sep = max(w - f for w, f in zip(table["STEP_W"], table["STEP_F"], strict=True))
    level_width = max(len(level) for level in program.schedule.levels)
    return {
        "fgc_version": __version__, "name": project, "guard": project.upper(),
        "problem_comment": comment(program.name), "data_magic": MAGIC,
        "structure_fingerprint": program.structure_fingerprint,
        "design_fingerprint": program.fingerprint,
        "scalar": config.scalar_cxx, "fixed_point": config.is_fixed_point,
        "scalar_decl": fixed_declaration(config.scalar_cxx),
        "linear_scalar": config.linear_cxx, "mixed": config.mixed,
        "include_dirs": include,
        "cxx": config.cxx, "cxxflags": " ".join(config.cxxflags + FIXED_POINT_FLAGS
                                                 * config.is_fixed_point),
        "units": max(1, int(program.solver.units)), "cpe": max(1, int(program.solver.cpe)),
        "unit_sets": unit_sets, "structure_comment": comment(
            f"{program.schedule.structure_class} graph, {program.schedule.ordering} ordering"),
        "constants": tables.constants, "sizes": {
            **dict(tables.constants),
            "MAX_LEVEL_WIDTH": level_width,
            "MAX_STORAGE": max(v.storage_dim for v in program.variables),
            "MAX_LD": max_ld, "MAX_SEP": max_sep},
        "max_variables": program.max_variables,
        "header_tables": [t for t in tables.arrays if t.name in HEADER_TABLES],
        "tables": [t for t in tables.arrays if t.name not in HEADER_TABLES]
        + [IntTable("STEP_PATTERN", step_pattern)] * bool(patterns),
        "blocks": blocks, "patterns": patterns, "retracts": retract_kinds(program, latencies),
        "tile": TILE,
        # a generic step whose shape a pattern has is factored by that pattern's fixed routine
        # (the same operations in the same order, no new unit): the chain ends' steps
        "fixed_shapes": sorted({(p.w, p.f) for p in patterns if p.ld == max_ld}),
        "coefficients": coefficient_functions(), "series_below": printer.literal(SERIES_BELOW),
        "solver": solver, "statuses": STATUSES, "reasons": REASONS,
        "noise_codes": NOISE_CODES, "robust_codes": ROBUST_CODES,
        "max_level_width": level_width,
        "max_line_chars": 32 * max([v.storage_dim for v in program.variables] + [
            factor_data_words(program, b) for b in range(len(program.blocks))]) + 64,
    }
