"""The design-level reading: every module instance Vitis would make under the top, their
operators summed (:class:`DesignReading`), and the check that the plan prices at least
that DSP (:func:`check_dsp`)."""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from fgc_backends.cfamily.lint import LintIssue
from fgc_backends.cost.operators import OperatorTable
from fgc_backends.hls.lint.cxx import (
    _Function,
    _matching,
)
from fgc_backends.hls.reader.loops import LoopReading, _Reader
from fgc_backends.hls.reader.text import _CALL, FLOAT_TYPES, KINDS, _pipelined, _unit


@dataclass(frozen=True)
class DesignReading:
    """The design's operators as Vitis would instantiate them: every call site its own module
    instance (an unrolled call once per copy), a pipelined loop's operators as its reading
    says, a function's sequential code at least one operator of each kind it uses (or its
    ALLOCATION limit where that is lower than its operations). A lower bound: the scheduler may
    use more in sequential code, never fewer in a pipelined loop. A module whose scalar ``T`` is
    not the accelerator's (a mixed design's linear solver, T = L = double) counts its operators
    as ``kind:double`` (:func:`typed`), priced in that type's table (:func:`dsp_table`)."""

    top: str
    loops: tuple[LoopReading, ...]
    operators: tuple[tuple[str, int], ...]  # operator instances by kind, the whole design
    modules: tuple[tuple[str, int], ...]  # function -> RTL instances
    # file -> operator instances by kind of the functions defined there (their own code and
    # pipelined loops; a callee's in its own file)
    by_file: tuple[tuple[str, tuple[tuple[str, int], ...]], ...] = ()
    reached: tuple[tuple[str, str], ...] = ()  # (file, function) of what the top instantiates
    # (translation unit: the kernel .cpp that reached it, file) -> operator instances by kind
    # (a header's functions apart per kernel that instantiates them)
    by_unit: tuple[tuple[str, str, tuple[tuple[str, int], ...]], ...] = ()

    @property
    def reached_loops(self) -> tuple[LoopReading, ...]:
        """The pipelined loops of the functions the top instantiates (``loops`` also reads
        those of the headers' other functions)."""
        mine = set(self.reached)
        return tuple(r for r in self.loops if (r.file, r.function) in mine)

    def dsp(self, dsp_of: dict[str, int], files: Iterable[str] | None = None) -> int:
        """DSP of the whole design, or of the functions defined in ``files``."""
        if files is None:
            return sum(n * _dsp(dsp_of, kind) for kind, n in self.operators)
        wanted = set(files)
        return sum(n * _dsp(dsp_of, kind) for file, ops in self.by_file if file in wanted
                   for kind, n in ops)

    def unit_dsp(self, dsp_of: dict[str, int], unit: str, files: Iterable[str] | None = None,
                 exclude: Iterable[str] = ()) -> int:
        """DSP of what translation unit ``unit`` (a kernel's .cpp) instantiates: its own
        functions and the headers' it reaches (those defined in ``files`` only, when given;
        none defined in ``exclude``)."""
        wanted = None if files is None else set(files)
        skip = set(exclude)
        return sum(n * _dsp(dsp_of, kind) for u, file, ops in self.by_unit
                   if u == unit and (wanted is None or file in wanted) and file not in skip
                   for kind, n in ops)


def _design(reader: _Reader, top: str, unit: str | None = None) -> DesignReading:
    """The design under ``top``; ``unit``: the translation unit a header function ``top`` is
    read in (the kernel .cpp whose functions its calls reach first)."""
    # the pipelined loops of each function as the design instantiates it (a template reached
    # through a struct's member, cpe_cascade<CFG, K>::run calling cpe<CFG, K>, with K bound
    # there); the loops of functions the top never reaches as their own call sites bind them
    readings: dict[tuple, list[LoopReading]] = {}

    def loops_of(f: _Function, env: dict[str, int], unit: str | None) -> list[LoopReading]:
        scalar = reader.scalar_of(f, env)
        key = (f.file, f.start, tuple(sorted((k, v) for k, v in env.items()
                                             if k in f.template_ints)), unit, scalar)
        if key not in readings:
            reader.where = unit
            reader.scalar = scalar
            try:
                readings[key] = reader.loops_in(f, env)
            finally:
                reader.scalar = ""
        return readings[key]

    working = reader.scalars.get("T")  # the accelerator's scalar: its kinds stay untyped
    operators: Counter = Counter()
    modules: Counter = Counter()
    visited: set[tuple[str, str]] = set()
    by_file: dict[str, Counter] = {}
    by_unit: dict[tuple[str, str], Counter] = {}

    def own(f: _Function, env: dict[str, int], unit: str | None) -> Counter:
        reader.flatten = False
        reader.where = unit
        reader.scalar = reader.scalar_of(f, env)
        reader.returns_float = re.search(rf"\b{FLOAT_TYPES}\b", f.ret) is not None
        try:
            count = reader.count(f.text, {p.name: v for p in f.params
                                          if (v := reader._param_var(f, p)) is not None},
                                 dict(env), None, frozenset())
        finally:
            reader.flatten = True
            reader.scalar = ""
        limits = reader.allocation(f.text)
        return Counter({k: min(limits.get(k.split(":")[0], 1), n) for k, n in count.ops.items()
                        if n})

    def visit(f: _Function, env: dict[str, int], mult: int, depth: int,
              unit: str | None = None) -> None:
        if depth > 400 or mult == 0:  # a template recursion (a cascade of 80 CPEs) is deep
            return
        modules[f.qualname] += mult
        seq: Counter = Counter()  # the sequential code's operators, its INLINE callees' merged
        walk(f, env, mult, depth, seq, unit)
        here = by_file.setdefault(f.file, Counter())
        mine = by_unit.setdefault((_unit(f, unit) or f.file, f.file), Counter())
        for kind, n in seq.items():
            operators[kind] += n * mult
            here[kind] += n * mult
            mine[kind] += n * mult

    def walk(f: _Function, env: dict[str, int], mult: int, depth: int, seq: Counter,
             unit: str | None, scope: dict[str, int] | None = None) -> None:
        """``f``'s code into the module being read: its sequential operators into ``seq``
        (an INLINE callee's join its caller's: one RTL body), its pipelined loops' and its
        other callees' instances apart. ``scope``: the module's ``ALLOCATION function``
        budgets left (an INLINE callee's calls are the module's: they draw on the same)."""
        visited.add((f.file, f.name))
        unit = _unit(f, unit)
        scalar = reader.scalar_of(f, env)  # "" : the accelerator's T; else "double", ...
        for kind, n in own(f, env, unit).items():
            kind = typed(kind, scalar, working)
            seq[kind] = max(seq[kind], n)
        here = by_file.setdefault(f.file, Counter())
        mine = by_unit.setdefault((unit or f.file, f.file), Counter())
        for r in loops_of(f, env, unit):
            for kind, n in r.instances:
                kind = typed(kind, scalar, working)
                operators[kind] += n * mult
                here[kind] += n * mult
                mine[kind] += n * mult
        # ALLOCATION function instances=g limit=n in f: the module's call sites of g (f's own
        # and its INLINE callees') share n instances
        left = {} if scope is None else scope
        left.update(reader.function_allocation(f.text, env))
        for callee, cenv, times in calls(f.text, env, unit):
            cenv = {**cenv, "scalar:caller": scalar}  # a template on T takes the caller's
            if callee.name in left:
                times = min(times, left[callee.name])
                left[callee.name] -= times
            if callee.inline and depth <= 400:
                walk(callee, cenv, mult * times, depth + 1, seq, unit, left)
            else:
                visit(callee, cenv, mult * times, depth + 1, unit)

    def calls(text: str, env: dict[str, int], file: str):
        pos = 0
        while pos < len(text):
            m = re.compile(r"\bfor\s*\(|" + _CALL.pattern).search(text, pos)
            if not m:
                return
            if m.group(0).startswith("for") and m.group(0).rstrip("( ").strip() == "for":
                open_ = text.index("(", m.start())
                close = _matching(text, open_, "(", ")")
                header = text[open_ + 1:close].split(";")
                body, pos = reader._body(text, close + 1)
                if _pipelined(body):
                    continue  # its calls are read in the loop's reading
                values = reader._iterations(header, env) if len(header) == 3 else None
                unrolled = re.match(r"\s*\{?\s*#\s*pragma\s+HLS\s+UNROLL\s*(?:\n|$)", body)
                if unrolled and values:
                    var, seq = values
                    for value in seq:
                        yield from calls(body, {**env, var: value}, file)
                else:
                    yield from ((c, e, 1) for c, e, _ in calls(body, env, file))
                continue
            pos = m.end()
            found = reader.resolve(text, m, env, file)
            if found is not None:
                yield found[0], found[1], 1

    if top not in reader.functions:
        raise KeyError(top)
    visit(reader.functions[top], {}, 1, 0, unit)
    reached = {(file, name) for file, name in visited}
    loops = sorted({*(r for rs in readings.values() for r in rs),
                    *(r for r in reader.loops() if (r.file, r.function) not in reached)},
                   key=lambda r: (r.file, r.line, r.template))
    return DesignReading(top, tuple(loops), tuple(sorted(operators.items())),
                         tuple(sorted(modules.items())),
                         tuple(sorted((file, tuple(sorted(c.items())))
                                      for file, c in by_file.items())),
                         tuple(sorted(reached)),
                         tuple(sorted((u, file, tuple(sorted(c.items())))
                                      for (u, file), c in by_unit.items() if c)))


def typed(kind: str, scalar: str, working: str | None = None) -> str:
    """An operator kind of a module whose scalar is ``scalar`` ("": the accelerator's): the
    kind itself, or ``kind:scalar`` (``add:double``: a mixed design's linear solver); a kind
    already typed (a callee's in its own scalar) is kept, the ``working`` scalar's dropped."""
    if ":" not in kind:
        kind = f"{kind}:{scalar}" if scalar else kind
    return kind.split(":")[0] if working and kind.endswith(f":{working}") else kind


def dsp_table(ops_of: Callable[[str], OperatorTable], precision: str) -> dict[str, int]:
    """DSP of one operator of each kind :class:`DesignReading` counts: the accelerator's
    (``precision``'s table) by kind, and each C++ scalar's own (``add:double``, ``mul:float``)
    for the modules typed otherwise (``ops_of(precision)``: a part's operator table)."""
    out = {k: ops_of(precision).op(k).dsp for k in KINDS}
    for scalar, prec in (("float", "float32"), ("double", "float64")):
        out.update({typed(k, scalar): ops_of(prec).op(k).dsp for k in KINDS})
    return out


def _dsp(dsp_of: dict[str, int], kind: str) -> int:
    """One operator's DSP: a typed kind (``add:double``) by its own figure where ``dsp_of``
    has one (:func:`dsp_table`), else by its kind's (one table: the old callers')."""
    return dsp_of[kind] if kind in dsp_of else dsp_of.get(kind.split(":")[0], 0)


def read_design(files: Iterable[tuple[str, str]], top: str, add_latency: int
                ) -> DesignReading:
    """The whole design under ``top`` as Vitis would instantiate it (:class:`DesignReading`)."""
    return _design(_Reader(files, add_latency), top)


def check_dsp(design: DesignReading, plan_dsp: int, dsp_of: dict[str, int],
              file: str = "<design>") -> list[LintIssue]:
    """An issue when the plan prices fewer DSP than the operators the text instantiates."""
    needed = design.dsp(dsp_of)
    if needed <= plan_dsp:
        return []
    worst = sorted(design.loops, key=lambda r: -r.dsp(dsp_of))[:3]
    named = ", ".join(f"'{r.label or r.function}' {r.dsp(dsp_of)}" for r in worst)
    return [LintIssue(file, 1, "dsp_bound", f"the plan prices {plan_dsp} DSP but the text "
                      f"instantiates at least {needed} (operators {dict(design.operators)}; "
                      f"largest pipelined loops: {named})")]


# config_op's Vitis operators -> (operator kind, precision) of the operator table
_VITIS_KINDS = {"fadd": ("add", "float32"), "fsub": ("add", "float32"),
                "fmul": ("mul", "float32"), "dadd": ("add", "float64"),
                "dsub": ("add", "float64"), "dmul": ("mul", "float64")}
_CONFIG_OP = re.compile(r"^[ \t]*config_op[ \t]+(\w+)((?:[ \t]+-\w+(?:[ \t]+[^\s-][^\s]*)?)*)"
                        r"[ \t]*$", re.M)


def tcl_binding(tcl: str) -> dict[str, tuple[tuple[str, str], ...]]:
    """The operators' binding a Vitis script sets (``config_op <op> -impl X``), per precision:
    ``{"float32": (("add", "fabric"),), ...}`` in canonical form (``operators.normalise_bind``).
    A kind's operators bound differently (fadd fabric, fsub fulldsp) count at the one of fewer
    DSP (the reader's figures are a lower bound); ``-impl all`` (the tool's choice) or none, and
    operators the table does not price (fdiv, fexp, ...) are the default binding. An
    implementation the table does not know raises ``ValueError``."""
    from fgc_backends.cost import operators

    chosen: dict[tuple[str, str], set[str]] = {}
    for m in _CONFIG_OP.finditer(tcl):
        op, options = m.group(1), m.group(2)
        impl = re.search(r"-impl[ \t]+(\w+)", options)
        if op not in _VITIS_KINDS or impl is None or impl.group(1) == "all":
            continue
        kind, precision = _VITIS_KINDS[op]
        if impl.group(1) not in operators.IMPLEMENTATIONS[kind]:
            raise ValueError(f"config_op {op} -impl {impl.group(1)}: the operator table prices "
                             f"{', '.join(operators.IMPLEMENTATIONS[kind])} for {kind}")
        chosen.setdefault((kind, precision), set()).add(impl.group(1))
    out: dict[str, list] = {}
    for (kind, precision), impls in sorted(chosen.items()):
        base = operators.table(precision)
        cheapest = min(sorted(impls), key=lambda i: operators.implementations(base)[kind][i].dsp)
        out.setdefault(precision, []).append((kind, cheapest))
    return {p: operators.normalise_bind(tuple(b)) for p, b in out.items()}


def emitted_ops(directory) -> Callable[[str], OperatorTable]:
    """The operator tables an emitted project's ``run_hls.tcl`` asks for, read from its text
    alone: its part (``set_part``), clock (``create_clock -period``) and operators' binding
    (``config_op``, :func:`tcl_binding`): ``ops_of(precision)`` for :func:`dsp_table`."""
    from pathlib import Path

    from fgc_backends.cost import operators
    from fgc_backends.hls.target import Target

    tcl = (Path(directory) / "run_hls.tcl").read_text()
    part = re.search(r"^\s*set_part\s+\{?([\w-]+)\}?", tcl, re.M)
    period = re.search(r"^\s*create_clock\s+-period\s+([0-9.]+)", tcl, re.M)
    if part is None or period is None:
        raise ValueError(f"{Path(directory) / 'run_hls.tcl'}: no set_part or create_clock")
    family = Target(part.group(1)).family
    clock = 1000.0 / float(period.group(1))
    binding = tcl_binding(tcl)
    return lambda precision: operators.bound(operators.table(precision, family, clock),
                                             binding.get(precision, ()))


def emitted_files(directory) -> tuple[list[tuple[str, str]], str]:
    """The synthesised files of an emitted HLS project folder ((name, text) pairs: the kernel,
    its header and the unit headers) and its synthesis top (``set_top`` in run_hls.tcl)."""
    from pathlib import Path

    directory = Path(directory)
    tcl = (directory / "run_hls.tcl").read_text()
    top = re.search(r"^\s*set_top\s+(\w+)", tcl, re.M)
    if top is None:
        raise ValueError(f"{directory / 'run_hls.tcl'}: no set_top")
    files = []
    for path in sorted(directory.glob("*.cpp")) + sorted(directory.glob("*.h")) + \
            sorted((directory / "include").glob("*.h")):
        if not path.name.startswith("tb_"):
            files.append((path.name, path.read_text()))
    return files, top.group(1)
