"""emit: a Program → a native CPU project (solver, header, C entry points, Makefile).

The native backend is a CPU program, not a hardware design: the solver's C++ (``<name>.h``,
``<name>.cpp``: the top function ``<name>_top`` and ``<name>_probe``) runs on the host, with
SIMD lanes (GCC vector types) and host-only paths; ``native_<name>.cpp`` gives it C entry points
for ctypes and the ``Makefile`` builds ``lib<name>.so`` with the host's ISA but no fused
multiply-add, checking the library for any. There is no testbench and no synthesis script.

Everything a template places is computed here or printed by the C-family printer
(:mod:`fgc_backends.cfamily.printer`, shared with the HLS backend for now); user text reaches the
files only through :mod:`fgc_backends.cfamily.names`. Limits are checked first, so a Program the
backend cannot build fails here with a :class:`NativeConfigError`, never in g++.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from fgc.ir.program import Program
from fgc_backends.cfamily import limits, sources
from fgc_backends.cfamily.context import common_context
from fgc_backends.cfamily.lint import lint_host_files
from fgc_backends.cfamily.names import identifier
from fgc_backends.cfamily.printer import HlsCodePrinter
from fgc_backends.cfamily.retract import local_kinds
from fgc_backends.cfamily.scalars import (
    check_fixed_constants,
    kernel_constants,
)
from fgc_backends.cfamily.tables import IntTable
from fgc_backends.native.config import NativeConfig, NativeConfigError

# the central-difference step of the stream's re-expression Jacobian (fgc_local_jacobian), the
# simulator's (Chain.local_jacobian)
JACOBIAN_STEP = float(np.sqrt(np.finfo(np.float64).eps) * 10)

# template → emitted file name ({name} is the project identifier)
FILES = (("kernel.h.jinja", "{name}.h"), ("kernel.cpp.jinja", "{name}.cpp"),
         ("native.cpp.jinja", "native_{name}.cpp"), ("Makefile.jinja", "Makefile"))
SOLVER_FILES = ("kernel.h.jinja", "kernel.cpp.jinja")  # the files whose constants T must hold


@dataclass(frozen=True)
class NativeProject:
    """An emitted native project: its folder, identifier and files (template order)."""

    directory: Path
    name: str
    files: tuple[Path, ...]
    config: NativeConfig

    @property
    def library(self) -> Path:
        """Where ``make native`` puts the shared library."""
        return self.directory / f"lib{self.name}.so"


_LITERAL = re.compile(r"\(?-?T\([-+0-9.eE]+\)\)?")


def is_constant_literal(expr: str) -> bool:
    """Whether a printed kernel output is a plain constant of T (``T(1)``, ``(-T(1))``): a
    scalar, not a V, so the kernel stores it as it is."""
    return _LITERAL.fullmatch(expr) is not None


def emit(program: Program, out_dir: str | Path, config: NativeConfig | None = None,
         name: str | None = None) -> NativeProject:
    """Write the native project of ``program`` into ``out_dir`` (created if needed).

    ``name`` (default: the Program's name) is sanitised into the project identifier used for
    file names and the top function ``<name>_top``. Emitting the same Program twice gives
    byte-identical files. Every file is checked to allocate nothing and use no STL container
    (:func:`fgc_backends.cfamily.lint.lint_host_files`, host rules).
    """
    config = for_program(program, config or NativeConfig())
    config.check()
    check_limits(program, config)
    project = identifier(name or program.name)
    context = _context(program, config, project)
    env = sources.environment(config.template_dir())
    env.tests["constant_literal"] = is_constant_literal
    texts = {}
    for template, pattern in FILES:
        file_name = pattern.format(name=project)
        texts[template, file_name] = env.get_template(template).render(
            **context, template=template, file_name=file_name)
    # before anything is written: a constant outside ap_fixed<W,I> would saturate silently
    check_fixed_constants(config.scalar_cxx, kernel_constants(
        (file_name, text) for (template, file_name), text in texts.items()
        if template in SOLVER_FILES), NativeConfigError,
        hint="a smaller constant (SolverConfig.lambda_upper_bound, fgc --lambda-upper-bound, "
             "bounds LM's damping)")
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for (_, file_name), text in texts.items():
        path = out / file_name
        path.write_text(text)
        paths.append(path)
    shared = sources.copy_headers(out / "include")  # fgc_lm.h: LM control, shared with HLS
    issues = lint_host_files([p for p in paths + shared if p.suffix in (".cpp", ".h")])
    if issues:
        listing = "\n".join(str(i) for i in issues[:20])
        raise NativeConfigError(f"internal error: the native project '{project}' allocates or "
                                f"uses STL containers:\n{listing}")
    return NativeProject(out, project, tuple(paths), config)


def for_program(program: Program, config: NativeConfig) -> NativeConfig:
    """``config`` with the linear solver's scalar the Program asks for (the mixed design)."""
    return limits.for_program(program, config)


def check_limits(program: Program, config: NativeConfig) -> None:
    """Raise :class:`NativeConfigError` if ``program`` exceeds what ``config`` can build."""
    limits.check_limits(program, config, NativeConfigError, "the native backend", "NativeConfig")


def lanes(config: NativeConfig) -> int | None:
    """Instances per block evaluation: ``config.lanes``; 1 for fixed point; else None, which
    the emitted code decides at compile time: one vector register of the scalar type, 64 bytes
    where the build has AVX-512 and 32 otherwise (8 or 4 doubles)."""
    if config.is_fixed_point:
        return 1
    return config.lanes




def postorder(program: Program) -> tuple[int, ...]:
    """The elimination steps in postorder: each root's subtree depth first, children in the
    order they enter their parent, every step right after its last child's subtree."""
    steps = program.schedule.steps
    order: list[int] = []
    for root in (s.index for s in steps if s.parent is None):
        stack = [(root, 0)]
        while stack:
            s, k = stack.pop()
            children = steps[s].children
            if k < len(children):
                stack.append((s, k + 1))
                stack.append((children[k], 0))
            else:
                order.append(s)
    return tuple(order)


def update_stack(program: Program, order: tuple[int, ...]) -> tuple[tuple[int, ...], int]:
    """Where each Cholesky step's update matrix (sw (sw + 1) entries, sw its separator's
    dimension) goes when the steps run in ``order`` (a postorder) and the update matrices form a
    stack: a step's children are the top of the stack when it runs, so it writes its own over
    them once it has assembled them. Returns (offset per step, the stack's largest size)."""
    steps = program.schedule.steps
    offset, top, peak = [0] * len(steps), 0, 1
    for s in order:
        children = steps[s].children
        if children:
            top = offset[children[0]]
        offset[s] = top
        top += steps[s].separator_dim * (steps[s].separator_dim + 1)
        peak = max(peak, top)
    return tuple(offset), peak


def _context(program: Program, config: NativeConfig, project: str) -> dict:
    # the steps of a level run in the order of the HLS design's unit sets (one per chain end on
    # a two-ended chain), so the two builds eliminate in one order and agree bit for bit
    unit_sets = 2 if program.schedule.ordering == "two-ended" else 1
    context = common_context(program, config, project, NativeConfigError, unit_sets=unit_sets)
    blocks = context["blocks"]
    host_lanes = lanes(config)
    row_words = [len(b.instances) * b.m * b.stride for b in blocks]  # fgc_rows' layout
    # the incremental stream's host work (fgc_kept_walk, fgc_local_jacobian) in a double build:
    # the stream's host arithmetic is double, whatever another build's scalar
    stream_host = config.scalar_cxx == "double"
    # a CPU has one unit set: Cholesky eliminates the tree in postorder instead of level by level,
    # so a child's update matrix is read by its parent while it is still in cache (level order
    # wrote every leaf's first: on sphere2500.txt 30 MB stored and read back from memory per
    # factorisation). A step's numbers depend only on its children's, so they are the same bits.
    # The update matrices then form a stack (NF_STACK_OFF): 6 MB at its largest there, not 60.
    post = unit_sets == 1 and program.solver.linear == "cholesky"
    nf_stack = 0
    if post:
        order = postorder(program)
        offsets, nf_stack = update_stack(program, order)
        context["tables"] = [*context["tables"], IntTable("POST_STEPS", order),
                             IntTable("NF_STACK_OFF", offsets)]
    return context | {
        "postorder": post, "nf_stack": nf_stack,
        "stream_host": stream_host,
        "locals": local_kinds(program) if stream_host else (),
        "jacobian_step": HlsCodePrinter({}).literal(JACOBIAN_STEP),
        "rows_offsets": [sum(row_words[:i]) for i in range(len(blocks))],
        "n_rows": sum(row_words),
        "cpu_program": True,
        "host_flags": " ".join(config.host_flags),
        "fma_check": "-mno-fma" in config.host_flags,
        "lanes": host_lanes, "laned": host_lanes != 1, "lanes_auto": host_lanes is None,
    }
