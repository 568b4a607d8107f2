"""A synthesisability lint for emitted C++ (a conservative subset of what Vitis HLS accepts).

Rules, checked on code with comments and string literals blanked out:

- ``alloc``: no dynamic allocation (``new``, ``delete``, ``malloc``, ``calloc``, ``realloc``,
  ``free``);
- ``stl``: no STL containers or strings (``std::vector``, ``<map>``, …);
- ``recursion``: no function that can reach itself through calls within the file;
- ``unbounded``: no ``while``/``do``/``goto`` and no ``for`` without a condition;
- ``tripcount``: every ``for`` loop compares its variable with a compile-time bound (integer
  literals and ALL_CAPS constants) or opens its body with ``#pragma HLS LOOP_TRIPCOUNT``.

The testbench and the native backend's files run only on the host, so they are checked for
``alloc`` and ``stl`` only (``synthesis=False``).

**Semantic rules** (:func:`semantic_issues`, on the synthesised files of a project together; a
deliberately small C-like parser: function definitions and their parameters, calls, pragmas,
``for`` loops, ``constexpr``/``#define`` integer constants):

- ``dataflow``: the block holding ``#pragma HLS DATAFLOW`` (a function body or a loop body) holds
  only declarations of local channels (no initialiser), HLS pragmas, unconditional calls of
  ``void`` functions defined in the project, and fully unrolled (``#pragma HLS UNROLL`` without a
  factor) constant-bound loops of such calls: no ``if``/``return``/assignment, no used return
  value;
- ``channel``: each array, pointer, reference or ``hls::stream`` passed to the calls of a
  DATAFLOW block is written by at most one call and read by at most one; the direction comes
  from the callee's parameter (streams: ``.write(``/``.read(`` in its body; ``const``: a read;
  others: assigned → written, used otherwise → read; passed on → the inner callee's use). One
  that is both written and read in the block (by two or more calls) must be written by one call
  and read by a *different, later* one: a channel read before it is written (a feedback through
  it between invocations of the region) or read and written by the same call is an issue. A
  memory that a single call alone reads and writes (an Update unit's bank) is that process's
  own, not a channel;
- ``pointer``: no pointer variable or parameter is reassigned (``=``, ``+=``, ``++``…) after its
  initialisation, and no function returns a pointer;
- ``function_pointer``: no function pointer (declarator ``(*f)(…)``), and no function defined in
  the project passed as a template argument;
- ``partition``: an ``ARRAY_PARTITION`` factor is at most the partitioned dimension (sizes from
  the files' integer constants; an array whose size cannot be resolved, a template parameter,
  is not judged);
- ``pipeline``: a ``PIPELINE`` loop (or function) holds only loops with constant bounds (start
  and end), which HLS unrolls completely;
- ``dsp``: Σ over ``#pragma HLS ALLOCATION operation instances=<op> limit=<n>`` of n × the DSP of
  one ``<op>`` (:mod:`fgc_backends.cost.operators`, by precision: ``f…``/``d…`` names, else the
  project's scalar) is at most the part's DSP count (``hls/target.py``; each function is counted
  as one hardware instance);
- ``synthesis_macro``: no ``__SYNTHESIS__`` in a synthesised file (C simulation must compile the
  code that is synthesised).
"""

from __future__ import annotations

import re
import warnings
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from fgc.errors import FgcError
from fgc_backends.cfamily.lint import (  # the host rules, shared with the native backend
    LintIssue,
    host_issues,
    line_of,
    strip_comments_and_strings,
    synthesis_view,
    views,
)


class HlsLintError(FgcError):
    """Emitted C++ breaks a synthesisability rule (each issue names file, line and rule)."""


_UNBOUNDED = re.compile(r"\b(while|do|goto)\b")
_FOR = re.compile(r"\bfor\s*\(")
_BOUND = re.compile(r"^\s*\w+\s*(<|<=|>|>=)\s*([A-Z0-9_+\-*/() ]+)\s*$")
_CONSTANT = re.compile(r"^[A-Z0-9_+\-*/() ]+$")
_DEFINITION = re.compile(r"\b([A-Za-z_]\w*)\s*\(([^;{}]*)\)\s*(const\s*)?\{")
_CALL = re.compile(r"\b([A-Za-z_]\w*)\s*(<[^<>;]*>)?\s*\(")
_KEYWORDS = {"if", "for", "while", "switch", "return", "sizeof", "do", "catch"}


def lint_source(text: str, file: str = "<source>", synthesis: bool = True) -> list[LintIssue]:
    """All rule violations in one C++ source text."""
    # pragmas stay visible to the trip-count rule, but their words are not code
    code, plain = views(text)
    issues = host_issues(code, plain, file)
    if synthesis:
        issues += [LintIssue(file, _line(plain, m.start()), "unbounded",
                             f"'{m.group(1)}' has no bounded trip count")
                   for m in _UNBOUNDED.finditer(plain)]
        issues += _loops(code, file)
        issues += _recursion(plain, file)
    return sorted(issues, key=lambda i: (i.line, i.rule))


_line = line_of


def _matching(text: str, start: int, open_: str, close: str) -> int:
    """Index of the bracket closing the one at ``start``."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] == open_:
            depth += 1
        elif text[i] == close:
            depth -= 1
            if depth == 0:
                return i
    return len(text) - 1


def _loops(code: str, file: str) -> list[LintIssue]:
    issues = []
    for m in _FOR.finditer(code):
        close = _matching(code, m.end() - 1, "(", ")")
        parts = code[m.end():close].split(";")
        line = _line(code, m.start())
        if len(parts) != 3 or not parts[1].strip():
            issues.append(LintIssue(file, line, "unbounded", "for loop without a condition"))
            continue
        # fgc::N_X and a unit's CFG::MAX_ROWS are constants
        bound = _BOUND.match(re.sub(r"\b(?:[a-z_]\w*|CFG)::", "", parts[1]))
        if bound and _CONSTANT.match(bound.group(2)) and re.search(r"[A-Z0-9]", bound.group(2)):
            continue
        body = code[close + 1:close + 400].lstrip()
        if body.startswith("{") and re.match(r"\{\s*#\s*pragma\s+HLS\s+LOOP_TRIPCOUNT\b", body):
            continue
        issues.append(LintIssue(file, line, "tripcount", f"loop bound '{parts[1].strip()}' is "
                                "not constant and the body has no LOOP_TRIPCOUNT pragma"))
    return issues


def _recursion(code: str, file: str) -> list[LintIssue]:
    bodies: dict[str, tuple[int, str]] = {}
    for m in _DEFINITION.finditer(code):
        name = m.group(1)
        if name in _KEYWORDS:
            continue
        # a constexpr helper (fgc_cycles.h's ceil_log2) is evaluated by the compiler on the
        # constants it is given: no recursion is left for synthesis
        if re.search(r"\bconstexpr\b[^;{}]*$", code[max(0, m.start() - 120):m.start() + 1]):
            continue
        end = _matching(code, m.end() - 1, "{", "}")
        bodies.setdefault(name, (_line(code, m.start()), code[m.end():end]))
    # a call qualified through a template argument list (``unit<CFG, U + 1>::run(``) is a
    # compile-time recursion over a constant, closed by a specialisation: each instance is a
    # different function, which HLS instantiates (the unit headers' process networks)
    calls = {name: {c.group(1) for c in _CALL.finditer(body)
                    if not re.search(r">\s*::\s*$", body[:c.start()])} & bodies.keys()
             for name, (_, body) in bodies.items()}
    issues = []
    for name in sorted(bodies):
        if _reaches(calls, name):
            issues.append(LintIssue(file, bodies[name][0], "recursion",
                                    f"function '{name}' can call itself"))
    return issues


def _reaches(calls: dict[str, set[str]], start: str) -> bool:
    seen, stack = set(), list(calls[start])
    while stack:
        f = stack.pop()
        if f == start:
            return True
        if f not in seen:
            seen.add(f)
            stack.extend(calls.get(f, ()))
    return False


def lint_files(paths: Iterable[Path], synthesis: bool = True) -> list[LintIssue]:
    """Issues of every file in ``paths``."""
    return [i for p in paths for i in lint_source(Path(p).read_text(), Path(p).name, synthesis)]


class HlsFitWarning(UserWarning):
    """An emitted design is well formed but does not fit its part (the ``dsp`` rule)."""


def lint_project(project, synthesised: Iterable[Path], strict: bool = True) -> list[LintIssue]:
    """Lint an emitted project: full rules on ``synthesised`` files, allocation/STL rules on the
    rest, and the semantic rules (:func:`semantic_issues`) on the synthesised files together;
    raise :class:`HlsLintError` listing every issue. With ``strict=False`` semantic issues do not
    raise; they are returned. The ``dsp`` rule (the ALLOCATION limits imply more DSP than the
    part has) never raises: such a design is still a correct program whose C simulation checks
    the numbers (a double LIO design, say), so it is emitted with an :class:`HlsFitWarning` and
    the issue is returned; synthesis would not fit it."""
    synthesised = [Path(p) for p in synthesised]
    host = [p for p in project.files if p.suffix in (".cpp", ".h") and p not in synthesised]
    issues = lint_files(synthesised) + lint_files(host, synthesis=False)
    config = getattr(project, "config", None)
    semantic = semantic_issues([(p.name, synthesis_view(p.read_text())) for p in synthesised],
                               part=getattr(config, "part", None),
                               scalar=getattr(config, "scalar_cxx", None))
    fit = [i for i in semantic if i.rule == "dsp"]
    for i in fit:
        warnings.warn(f"{project.name}: {i.message}: the design does not fit its part",
                      HlsFitWarning, stacklevel=3)
    raised = issues + [i for i in semantic if i.rule != "dsp"] if strict else issues
    if raised:
        listing = "\n".join(str(i) for i in raised[:20])
        more = f"\n… and {len(raised) - 20} more" if len(raised) > 20 else ""
        raise HlsLintError(f"emitted project '{project.name}' is not synthesisable:\n{listing}"
                           f"{more}")
    return semantic


# --------------------------------------------------------------------------------------------
# semantic rules
# --------------------------------------------------------------------------------------------

SEMANTIC_RULES = ("dataflow", "channel", "pointer", "function_pointer", "partition", "pipeline",
                  "dsp", "synthesis_macro")
# Vitis HLS operation names of ALLOCATION → (operator kind, precision or None: the scalar's)
ALLOCATION_OPS = {
    "fadd": ("add", "float32"), "fsub": ("add", "float32"), "dadd": ("add", "float64"),
    "dsub": ("add", "float64"), "fmul": ("mul", "float32"), "dmul": ("mul", "float64"),
    "fdiv": ("div", "float32"), "ddiv": ("div", "float64"), "fsqrt": ("sqrt", "float32"),
    "dsqrt": ("sqrt", "float64"), "frsqrt": ("recip_sqrt", "float32"),
    "drsqrt": ("recip_sqrt", "float64"), "fexp": ("exp", "float32"), "dexp": ("exp", "float64"),
    "flog": ("log", "float32"), "dlog": ("log", "float64"), "add": ("add", None),
    "sub": ("add", None), "mul": ("mul", None), "div": ("div", None),
}
_KEYWORDS_ALL = _KEYWORDS | {"else", "case", "default", "break", "continue", "new", "delete"}
_CONSTEXPR = re.compile(r"\b(?:static\s+)?(?:inline\s+)?(?:constexpr|const)\s+(?:unsigned\s+)?"
                        r"(?:int|long|short|std::size_t|size_t|unsigned)\s+([A-Za-z_]\w*)\s*="
                        r"\s*([^;{}]+);")
_DEFINE = re.compile(r"^[ \t]*#\s*define\s+([A-Za-z_]\w*)[ \t]+([^\n]+)$", re.M)
_PRAGMA = re.compile(r"#\s*pragma\s+HLS\s+([^\n]*)", re.I)
_FN_POINTER = re.compile(r"\(\s*\*\s*(\w*)\s*\)\s*\(")
_POINTER_DECL = re.compile(r"(?:^|(?<=[;{}])|(?<=for\()|(?<=for \())\s*(?:const\s+)?"
                           r"[A-Za-z_][\w:]*(?:<[^;<>]*>)?\s*(?:const\s*)?\*\s*(?:const\s+)?"
                           r"([A-Za-z_]\w*)\s*(?=[=;,)\[])", re.M)


@dataclass(frozen=True)
class _Param:
    name: str
    type: str
    dims: tuple[str, ...]

    @property
    def stream(self) -> bool:
        return "stream" in self.type and "<" in self.type

    @property
    def const(self) -> bool:
        return re.search(r"\bconst\b", self.type) is not None

    @property
    def pointer(self) -> bool:
        return "*" in self.type

    @property
    def channel(self) -> bool:
        """Passes storage, not a value: an array, pointer, reference or stream."""
        return bool(self.dims) or self.pointer or "&" in self.type or self.stream


@dataclass(frozen=True)
class _Function:
    name: str
    ret: str
    params: tuple[_Param, ...]
    file: str
    code: str  # the file's code (comments/strings blanked)
    start: int  # of the definition
    body: tuple[int, int]  # indices of '{' and its '}'
    qualname: str = ""  # Struct::name for a member of a struct or class
    template_ints: tuple[str, ...] = ()  # int template parameters (of it and its struct)

    @property
    def inline(self) -> bool:
        return re.match(r"\s*#\s*pragma\s+HLS\s+INLINE\s*(?:\n|$)", self.text, re.I) is not None

    @property
    def text(self) -> str:
        return self.code[self.body[0] + 1:self.body[1]]


def _split_top(text: str, sep: str = ",") -> list[str]:
    """``text`` split at ``sep`` outside (), [], {}, <>."""
    parts, depth, cur = [], 0, []
    for ch in text:
        if ch in "([{<":
            depth += 1
        elif ch in ")]}>":
            depth -= 1
        if ch == sep and depth == 0:
            parts.append("".join(cur))
            cur = []
        else:
            cur.append(ch)
    parts.append("".join(cur))
    return [p.strip() for p in parts if p.strip()]


def _params(text: str) -> tuple[_Param, ...]:
    out = []
    for part in _split_top(text):
        part = part.split("=")[0].strip()
        if part in ("void", "...") or _FN_POINTER.search(part):
            continue
        m = re.match(r"^(.*?)([A-Za-z_]\w*)\s*((?:\[[^\]]*\]\s*)*)$", part, re.S)
        if not m or not m.group(1).strip():
            continue
        dims = tuple(d.strip() for d in re.findall(r"\[([^\]]*)\]", m.group(3)))
        out.append(_Param(m.group(2), " ".join(m.group(1).split()), dims))
    return tuple(out)


def _functions(file: str, code: str) -> list[_Function]:
    """Top-level function definitions of one file (``code``: comments/strings blanked)."""
    out, pos = [], 0
    structs = []  # (name, '{', '}', int template parameters)
    for m in re.finditer(r"(template\s*<([^{};]*?)>\s*)?\b(?:struct|class)\s+([A-Za-z_]\w*)"
                         r"[^;{}()]*\{", code):
        brace = m.end() - 1
        ints = tuple(re.findall(r"\bint\s+([A-Za-z_]\w*)", m.group(2) or ""))
        structs.append((m.group(3), brace, _matching(code, brace, "{", "}"), ints))
    for m in _DEFINITION.finditer(code):
        if m.start() < pos or m.group(1) in _KEYWORDS_ALL:
            continue
        start = max(code.rfind(c, 0, m.start()) for c in ";{}")
        prefix = code[start + 1:m.start()]
        prefix = "\n".join(line for line in prefix.splitlines()
                           if not line.strip().startswith("#"))
        header = re.match(r"^\s*template\s*<([^{};]*?)>", prefix.strip())
        ints = tuple(re.findall(r"\bint\s+([A-Za-z_]\w*)", header.group(1))) if header else ()
        prefix = re.sub(r"^\s*template\s*<[^{};]*?>\s*(?=[A-Za-z_])", "", prefix.strip())
        ret = re.sub(r"\b(inline|static|constexpr|extern)\b", "", prefix).strip()
        if not ret or "=" in ret or "(" in ret or ret.endswith(("::", ".")):
            continue  # a constructor-like call or an expression, not a definition
        brace = m.end() - 1
        end = _matching(code, brace, "{", "}")
        owner = [st for st in structs if st[1] < m.start() < st[2]]
        qualname = f"{owner[-1][0]}::{m.group(1)}" if owner else m.group(1)
        ints += owner[-1][3] if owner else ()
        out.append(_Function(m.group(1), " ".join(ret.split()), _params(m.group(2)), file, code,
                             m.start(), (brace, end), qualname, ints))
        pos = end
    return out


def _constants(codes: Iterable[str]) -> dict[str, int]:
    """Integer constants (``constexpr``/``const`` ints, ``#define``) resolved to values."""
    raw: dict[str, str] = {}
    for code in codes:
        for m in _CONSTEXPR.finditer(code):
            # `const int A = 4, B = 9;`: every declarator (split outside brackets)
            first, *rest = _split_top(m.group(2))
            raw.setdefault(m.group(1), first)
            for part in rest:
                more = re.fullmatch(r"\s*([A-Za-z_]\w*)\s*=\s*(.+?)\s*", part, re.S)
                if more:
                    raw.setdefault(more.group(1), more.group(2))
        for m in _DEFINE.finditer(code):
            raw.setdefault(m.group(1), m.group(2))
    values: dict[str, int] = {}
    for _ in range(8):  # constants defined from constants
        for name, expr in raw.items():
            if name not in values:
                value = _evaluate(expr, values)
                if value is not None:
                    values[name] = value
    return values


def _evaluate(expr: str, values: dict[str, int]) -> int | None:
    """The integer value of ``expr`` (literals, known names, + - * / % ( )), or None."""
    text = re.sub(r"\b[A-Za-z_]\w*::", "", expr).strip()
    text = re.sub(r"\b(\d+)[uUlL]*\b", r"\1", text)

    def name(m):
        return str(values[m.group(0)]) if m.group(0) in values else "?"

    text = re.sub(r"\b[A-Za-z_]\w*\b", name, text)
    if not re.fullmatch(r"[0-9+\-*/%() ]+", text):
        return None
    try:
        return int(eval(text.replace("/", "//"), {"__builtins__": {}}, {}))  # noqa: S307
    except (SyntaxError, ZeroDivisionError, TypeError, ValueError):
        return None


def _is_constant(expr: str) -> bool:
    text = re.sub(r"\b\w+::", "", expr).strip()  # fgc::N_X, CFG::N_UNITS are constants
    return bool(text) and _CONSTANT.match(text) is not None


def _for_header(code: str, start: int) -> tuple[list[str], int, int] | None:
    """(init, condition, step), index after ')', of the ``for`` at ``start``."""
    open_ = code.index("(", start)
    close = _matching(code, open_, "(", ")")
    parts = code[open_ + 1:close].split(";")
    if len(parts) != 3:
        return None
    return [p.strip() for p in parts], open_, close + 1


def _constant_bounds(header: list[str]) -> bool:
    """Whether a ``for`` header starts and ends at compile-time constants."""
    init = re.match(r"^(?:const\s+)?(?:unsigned\s+)?(?:int|long|short|size_t|std::size_t|"
                    r"unsigned)?\s*\w+\s*=\s*(.+)$", header[0])
    bound = _BOUND.match(re.sub(r"\b\w+::", "", header[1]))
    return bool(init and _is_constant(init.group(1)) and bound and _is_constant(bound.group(2)))


def statement_end(code: str, pos: int, blocks: bool = False) -> int:
    """Index of the ';' ending the C++ statement that starts at ``pos``: the first ';' outside
    (), [] and {} (an initializer list or a lambda's body nests), or the '}' closing the block
    the statement is in; ``len(code)`` if there is neither. ``blocks``: a '{' or '}' outside
    () and [] ends the statement too (the second reader's scan, which reads a block's
    statements one by one and its blocks apart). The one C++ statement scanner of the lint and
    the second reader (backends/hls/reader.py)."""
    depth = 0
    for i in range(pos, len(code)):
        ch = code[i]
        if ch in "{}" and blocks and depth <= 0:
            return i
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            if ch == "}" and depth == 0:
                return i
            depth -= 1
        elif ch == ";" and depth <= 0:
            return i
    return len(code)


def _enclosing_block(code: str, pos: int) -> tuple[int, int]:
    """The '{' … '}' block that contains ``pos``."""
    depth = 0
    for i in range(pos - 1, -1, -1):
        if code[i] == "}":
            depth += 1
        elif code[i] == "{":
            if depth == 0:
                return i, _matching(code, i, "{", "}")
            depth -= 1
    return 0, len(code)


class _Checker:
    def __init__(self, files: list[tuple[str, str]], part: str | None, scalar: str | None):
        self.files = [(name, strip_comments_and_strings(text)) for name, text in files]
        self.functions: dict[str, _Function] = {}
        self.macros: set[str] = set()
        for name, code in self.files:
            for f in _functions(name, code):
                self.functions.setdefault(f.name, f)
                self.functions.setdefault(f.qualname, f)
            self.macros |= set(re.findall(r"^[ \t]*#\s*define\s+([A-Za-z_]\w*)\(", code, re.M))
        self.inlining: set[str] = set()
        self.constants = _constants(code for _, code in self.files)
        self.part, self.scalar = part, scalar
        self.issues: list[LintIssue] = []

    def add(self, file: str, code: str, pos: int, rule: str, message: str) -> None:
        self.issues.append(LintIssue(file, _line(code, pos), rule, message))

    def run(self) -> list[LintIssue]:
        for name, code in self.files:
            for m in re.finditer(r"\b__SYNTHESIS__\b", code):
                self.add(name, code, m.start(), "synthesis_macro", "'__SYNTHESIS__' in a "
                         "synthesised file: C simulation would not compile the synthesised code")
            self.pointers(name, code)
            for m in _PRAGMA.finditer(code):
                words = m.group(1).split()
                kind = words[0].upper() if words else ""
                if kind == "DATAFLOW":
                    self.dataflow(name, code, m.start(), m.end())
                elif kind == "PIPELINE" and "off" not in (w.lower() for w in words[1:]):
                    self.pipeline(name, code, m.start())
                elif kind == "ARRAY_PARTITION":
                    self.partition(name, code, m.start(), m.group(1))
        self.dsp()
        return sorted(self.issues, key=lambda i: (i.file, i.line, i.rule, i.message))

    # -- pointers and function pointers -------------------------------------------------------
    def pointers(self, file: str, code: str) -> None:
        for f in self.functions.values():
            if f.file != file:
                continue
            if f.ret.endswith("*") or re.search(r"\*\s*$", code[f.start - 2:f.start]):
                self.add(file, code, f.start, "pointer", f"function '{f.name}' returns a "
                         f"pointer ('{f.ret}')")
            names = {p.name for p in f.params if p.pointer}
            names |= {m.group(1) for m in _POINTER_DECL.finditer(code[f.body[0]:f.body[1]])}
            for pname in names:
                pattern = (rf"(?<![\w.>])\b{pname}\s*(?:(?<![=!<>])=(?!=)|\+=|-=|\+\+|--)|"
                           rf"(?:\+\+|--)\s*\b{pname}\b")
                for m in re.finditer(pattern, code[f.body[0]:f.body[1]]):
                    at = f.body[0] + m.start()
                    if not self._is_declaration(code, at):
                        self.add(file, code, at, "pointer", f"pointer '{pname}' in '{f.name}' is "
                                 "reassigned (HLS needs each pointer bound to one object)")
        for m in _FN_POINTER.finditer(code):
            self.add(file, code, m.start(), "function_pointer", "function pointer "
                     f"'{m.group(1) or '(*)'}' (HLS cannot synthesise indirect calls)")
        for m in re.finditer(r"\b([A-Za-z_]\w*)\s*<([^<>;{}]*)>\s*\(", code):
            for arg in _split_top(m.group(2)):
                name = arg.lstrip("&").strip()
                if name in self.functions and m.group(1) not in ("static_cast", "reinterpret_cast"):
                    self.add(file, code, m.start(), "function_pointer", f"function '{name}' "
                             f"passed as a template argument of '{m.group(1)}' (a function "
                             "pointer)")

    @staticmethod
    def _is_declaration(code: str, at: int) -> bool:
        """Whether the name at ``at`` is being declared (``T* name =``) or written through
        (``*name =``), not reassigned."""
        before = code[max(0, at - 120):at]
        return re.search(r"\*\s*(?:const\s+)?$", before) is not None

    # -- dataflow ------------------------------------------------------------------------------
    def dataflow(self, file: str, code: str, pragma: int, after: int) -> None:
        lo, hi = _enclosing_block(code, pragma)
        calls: list[tuple[int, str, list[str], dict[str, int], str]] = []
        self._region(file, code, lo + 1, hi, calls, {}, pragma)
        # per channel: (call index in region order, process label, its uses) of every access
        access: dict[str, list[tuple[int, str, frozenset[str]]]] = {}
        for order, (pos, callee, args, loop, where) in enumerate(calls):
            f = self.functions.get(callee)
            if f is None:
                continue
            for index, (arg, param) in enumerate(zip(args, f.params, strict=False)):
                if not param.channel:
                    continue
                base = re.match(r"^&?\s*([A-Za-z_]\w*)", arg)
                if not base:
                    continue
                key = base.group(1)
                subscript = arg[base.end():].strip()
                # an unrolled loop makes one process per iteration: an argument indexed by the
                # loop's variable is another channel each time, any other the same channel
                copies = 1
                index_value = _evaluate(subscript[1:-1], self.constants) if \
                    re.fullmatch(r"\[[^\[\]]*\]", subscript) else None
                if index_value is not None:  # a constant element: its own channel
                    key = f"{key}[{index_value}]"
                for v, trips in loop.items():
                    if subscript and re.search(rf"\b{v}\b", subscript):
                        key = f"{base.group(1)}{subscript}"  # one element per copy
                    else:
                        copies *= trips
                uses = frozenset(self.uses(f, param, set()))
                label = f"{callee} (line {_line(where, pos)}, argument {index + 1})"
                labels = [label] if copies == 1 else [f"{label} x{copies}#{c}"
                                                      for c in range(copies)]
                access.setdefault(key, []).extend((order, lb, uses) for lb in labels)
            # file-scope arrays a process reaches are channels too (issue 18's shared COND/NF)
            for g, uses in sorted(self.global_uses(f, set()).items()):
                label = f"{callee} (line {_line(where, pos)}, global)"
                copies = 1
                for trips in loop.values():
                    copies *= trips
                labels = [label] if copies == 1 else [f"{label} x{copies}#{c}"
                                                      for c in range(copies)]
                access.setdefault(g, []).extend((order, lb, frozenset(uses)) for lb in labels)
        # a whole array passed to one process overlaps each element another one takes
        bases = {k.split("[")[0] for k in access if "[" in k}
        for key in [k for k in access if "[" in k]:
            access[key] = access[key] + access.get(key.split("[")[0], [])
        for base in bases:
            access.pop(base, None)  # reported through its elements
        for key, entries in sorted(access.items()):
            self._channel(file, code, pragma, key, entries)

    def _channel(self, file, code, pragma, key, entries) -> None:
        """UG1399's canonical form for one channel of a DATAFLOW region: at most one writer and
        one reader; a channel both written and read in the region is written by one process and
        read by another, later one (no feedback through it, no process reading and writing it).
        A memory that one process alone reads and writes is that process's own, no channel."""
        def name(label):
            return label.split("#")[0]

        writers = [(o, lb) for o, lb, u in entries if "write" in u]
        readers = [(o, lb) for o, lb, u in entries if "read" in u]
        for what, who in (("written", writers), ("read", readers)):
            if len(who) > 1:
                names = [name(lb) for _, lb in who]
                self.add(file, code, pragma, "channel", f"'{key}' is {what} by "
                         f"{len(who)} processes of the DATAFLOW region: "
                         f"{', '.join(sorted(set(names), key=names.index))} "
                         "(one producer and one consumer per channel)")
        processes = {lb for _, lb, _ in entries}
        if not writers or not readers or len(processes) == 1:
            return
        for _, lb, u in entries:
            if {"read", "write"} <= u:
                self.add(file, code, pragma, "channel", f"'{key}' is read and written by the "
                         f"same process {name(lb)} while another process of the DATAFLOW "
                         "region also uses it (a channel has one writer and a different reader)")
                return
        first_write = min(o for o, _ in writers)
        early = [(o, lb) for o, lb in readers if o <= first_write]
        if early:
            writer = next(lb for o, lb in writers if o == first_write)
            self.add(file, code, pragma, "channel", f"'{key}' is read by {name(early[0][1])} "
                     f"before {name(writer)} writes it in the DATAFLOW region: a feedback "
                     "through the channel (the writer must come first; pass data between "
                     "invocations through two buffers that alternate)")

    def _region(self, file, code, lo, hi, calls, loop, pragma) -> None:
        pos = lo
        while pos < hi:
            m = re.compile(r"\S").search(code, pos, hi)
            if not m:
                return
            pos = m.start()
            if code.startswith("#", pos):
                end = code.find("\n", pos)
                pos = hi if end < 0 else end + 1
                continue
            word = re.match(r"[A-Za-z_]\w*", code[pos:hi])
            w = word.group(0) if word else ""
            if w == "for":
                header = _for_header(code, pos)
                if header is None:
                    self.add(file, code, pos, "dataflow", "a for loop in a DATAFLOW region")
                    return
                parts, _, after = header
                body_at = re.compile(r"\S").search(code, after, hi)
                body_lo = body_at.start() if body_at else hi
                if code.startswith("{", body_lo):
                    body_hi = _matching(code, body_lo, "{", "}")
                    inner = (body_lo + 1, body_hi)
                else:
                    body_hi = statement_end(code, body_lo)
                    inner = (body_lo, body_hi + 1)
                unrolled = re.match(r"\s*#\s*pragma\s+HLS\s+UNROLL\s*(?:\n|$)",
                                    code[inner[0]:inner[1]], re.I)
                if not (unrolled and _constant_bounds(parts)):
                    self.add(file, code, pos, "dataflow", "a loop around processes of a "
                             f"DATAFLOW region ('for ({'; '.join(parts)})') that is not a fully "
                             "unrolled constant-bound loop")
                var = re.search(r"(\w+)\s*=\s*(.+)$", parts[0])
                bound = _BOUND.match(re.sub(r"\b[a-z_]\w*::", "", parts[1]))
                first = _evaluate(var.group(2), self.constants) if var else None
                last = _evaluate(bound.group(2), self.constants) if bound else None
                trips = 1
                if first is not None and last is not None and bound.group(1) in ("<", "<="):
                    trips = max(1, last - first + (bound.group(1) == "<="))
                self._region(file, code, inner[0], inner[1], calls,
                             {**loop, (var.group(1) if var else "?"): trips}, pragma)
                pos = body_hi + 1
                continue
            if w in ("if", "else", "while", "do", "switch", "return", "goto", "break",
                     "continue"):
                self.add(file, code, pos, "dataflow", f"'{w}' in a DATAFLOW region: only "
                         "channel declarations and unconditional calls of void functions")
                if w in ("if", "while", "switch"):  # the guarded statements are checked too
                    open_ = code.index("(", pos)
                    pos = _matching(code, open_, "(", ")") + 1
                elif w in ("else", "do"):
                    pos += len(w)
                else:
                    pos = statement_end(code, pos) + 1
                continue
            if code.startswith("{", pos):
                end = _matching(code, pos, "{", "}")
                self._region(file, code, pos + 1, end, calls, loop, pragma)
                pos = end + 1
                continue
            end = min(statement_end(code, pos), hi)
            self._statement(file, code, pos, code[pos:end].strip(), calls, loop)
            pos = end + 1

    def _statement(self, file, code, pos, text, calls, loop) -> None:
        if not text:
            return
        call = re.fullmatch(r"((?:::)?(?:[A-Za-z_]\w*\s*(?:<[^;()]*?>)?\s*::\s*)*[A-Za-z_]\w*)"
                            r"\s*(?:<[^;()]*?>)?\s*\((.*)\)", text, re.S)
        if call and call.group(1) not in _KEYWORDS_ALL:
            parts = re.sub(r"<[^;()]*?>|\s", "", call.group(1)).strip(":").split("::")
            name = "::".join(parts[-2:])
            f = self.functions.get(name) or self.functions.get(parts[-1])
            if parts[-1] in self.macros and f is None:
                return  # a function-like macro (instrumentation): not judged
            if f is not None and f.inline and f.ret == "void":
                # an inlined helper (a template recursion over units): its calls are processes
                # of this region, its int template parameters index one copy each
                if f.qualname not in self.inlining:
                    self.inlining.add(f.qualname)
                    self._region(f.file, f.code, f.body[0] + 1, f.body[1], calls,
                                 {**loop, **{t: 1 for t in f.template_ints}}, None)
                    self.inlining.discard(f.qualname)
                return
            if f is None:
                self.add(file, code, pos, "dataflow", f"call of '{name}' in a DATAFLOW region: "
                         "its definition is not in the project, so it cannot be checked void")
            elif f.ret != "void":
                self.add(file, code, pos, "dataflow", f"process '{name}' returns '{f.ret}': "
                         "DATAFLOW processes must be void functions")
            calls.append((pos, f.qualname if f else name, _split_top(call.group(2)), loop,
                          code))
            return
        declaration = re.fullmatch(r"(?:static\s+)?[A-Za-z_][\w:]*(?:\s*<[^;=]*>)?\s+"
                                   r"[A-Za-z_]\w*\s*(?:\[[^\]=;]*\]\s*)*(?:\(\s*\))?", text, re.S)
        constant = re.fullmatch(r"(?:static\s+)?(?:const|constexpr)\s+(?:unsigned\s+)?"
                                r"(?:int|long|short|unsigned|bool)\s+[A-Za-z_]\w*\s*=\s*(.+)",
                                text, re.S)
        enum = re.fullmatch(r"enum\s*\w*\s*\{[^{}]*\}", text)
        constant = constant and _evaluate(constant.group(1), self.constants) is not None
        if declaration or enum or constant:
            return  # a channel, or an integer constant (no computation, no process)
        inner = [m for m in re.finditer(r"\b([A-Za-z_]\w*)\s*(?:<[^;()]*?>)?\s*\(", text)
                 if m.group(1) not in _KEYWORDS_ALL]
        if inner:
            self.add(file, code, pos, "dataflow", f"'{' '.join(text.split())[:60]}' in a "
                     "DATAFLOW region uses a process's return value or computes: only "
                     "channel declarations and unconditional calls of void functions")
            for m in inner:
                f = self.functions.get(m.group(1))
                if f is not None and f.ret != "void":
                    self.add(file, code, pos, "dataflow", f"process '{f.name}' returns "
                             f"'{f.ret}': DATAFLOW processes must be void functions")
                if f is not None:
                    open_ = text.index("(", m.start())
                    close = _matching(text, open_, "(", ")")
                    calls.append((pos, f.name, _split_top(text[open_ + 1:close]), loop, code))
        else:
            self.add(file, code, pos, "dataflow", f"'{' '.join(text.split())[:60]}' in a "
                     "DATAFLOW region: only channel declarations (no initialiser) and "
                     "unconditional calls of void functions")

    def globals_(self) -> dict[str, bool]:
        """File-scope arrays of the project: name → whether declared ``const``."""
        if not hasattr(self, "_globals"):
            found: dict[str, bool] = {}
            for _, code in self.files:
                # function bodies cut to "{}" in one pass: blanking them to spaces left long
                # runs of whitespace the declaration pattern's \s* rescanned from every line
                # start (quadratic: 9 s of a LIO design's lint)
                parts, at = [], 0
                for lo, hi in sorted(f.body for f in self.functions.values() if f.code is code):
                    if lo < at:  # a body inside one already cut
                        continue
                    parts += [code[at:lo], "{}"]
                    at = hi + 1
                blanked = re.sub(r"[ \t]*\n\s*", "\n", "".join(parts) + code[at:])
                for m in re.finditer(r"(?:^|[;}])\s*((?:static\s+|const\s+|constexpr\s+)*)"
                                     r"[A-Za-z_][\w:]*(?:<[^;<>]*>)?\s+([A-Za-z_]\w*)\s*\[",
                                     blanked, re.M):
                    found.setdefault(m.group(2), bool(re.search(r"const", m.group(1))))
            self._globals = found
        return self._globals

    def global_uses(self, f: _Function, seen: set) -> dict[str, set[str]]:
        """The non-const file-scope arrays ``f`` (and what it calls) reads and writes."""
        if f.name in seen:
            return {}
        seen = seen | {f.name}
        local = {p.name for p in f.params}
        local |= set(re.findall(r"[\w>]\s+([A-Za-z_]\w*)\s*\[", f.text))
        out: dict[str, set[str]] = {}
        for g, const in self.globals_().items():
            if const or g in local or not re.search(rf"\b{g}\b", f.text):
                continue
            assign = (rf"(?<![\w.>])\b{g}\s*(?:\[[^\]]*\]\s*)*(?:\.\s*\w+\s*)*"
                      r"(=(?!=)|[-+*/|&^]=|\+\+|--)")
            uses = set()
            for m in re.finditer(assign, f.text):
                uses |= {"write"} if m.group(1) == "=" else {"write", "read"}
            if re.search(rf"\b{g}\b", re.sub(assign, " ", f.text)):
                uses.add("read")  # read, or passed on (conservatively: both)
                if re.search(rf"[(,]\s*{g}\s*[,)]", f.text):
                    uses.add("write")
            out[g] = uses
        for m in re.finditer(r"\b([A-Za-z_]\w*)\s*(?:<[^;()]*?>)?\s*\(", f.text):
            callee = self.functions.get(m.group(1))
            if callee is not None and callee.name != f.name:
                for g, uses in self.global_uses(callee, seen).items():
                    out.setdefault(g, set()).update(uses)
        return out

    def uses(self, f: _Function, param: _Param, seen: set) -> set[str]:
        """How ``f`` uses its parameter ``param``: a subset of {"read", "write"}; an argument
        passed on to another function of the project counts as that function's use."""
        if (f.name, param.name) in seen:
            return set()
        seen = seen | {(f.name, param.name)}
        body, name, out = f.text, re.escape(param.name), set()
        # passed on: the callee's use, and the occurrence is blanked for the direct analysis
        for m in re.finditer(r"\b([A-Za-z_]\w*)\s*(?:<[^;()]*?>)?\s*\(", f.text):
            callee = self.functions.get(m.group(1))
            if callee is None:
                continue
            open_ = f.text.index("(", m.start())
            close = _matching(f.text, open_, "(", ")")
            offset = open_ + 1
            for arg, inner in zip(_split_top(f.text[open_ + 1:close]), callee.params,
                                  strict=False):
                at = f.text.find(arg, offset)
                offset = at + len(arg) if at >= 0 else offset
                if inner.channel and re.fullmatch(rf"&?\s*{name}", arg) and at >= 0:
                    out |= self.uses(callee, inner, seen)
                    body = body[:at] + " " * len(arg) + body[at + len(arg):]
        if param.stream:
            out |= {m.group(1) for m in re.finditer(
                rf"\b{name}\s*(?:\[[^\]]*\]\s*)*\.\s*(write|read)(?:_nb)?\s*\(", body)}
        elif param.const:
            if re.search(rf"\b{name}\b", body):
                out.add("read")
        else:
            assign = (rf"(?<![\w.>])\b{name}\s*(?:\[[^\]]*\]\s*)*(?:\.\s*\w+\s*)*"
                      r"(=(?!=)|[-+*/|&^]=|\+\+|--)")
            for m in re.finditer(assign, body):
                out.add("write")
                if m.group(1) != "=":
                    out.add("read")
            if re.search(rf"\b{name}\b", re.sub(assign, " ", body)):
                out.add("read")
        return out

    # -- pipeline -------------------------------------------------------------------------------
    def pipeline(self, file: str, code: str, pragma: int) -> None:
        lo, hi = _enclosing_block(code, pragma)
        for m in _FOR.finditer(code, lo + 1, hi):
            header = _for_header(code, m.start())
            if header is None:
                continue
            parts = header[0]
            if not _constant_bounds(parts):
                self.add(file, code, m.start(), "pipeline", f"loop 'for ({'; '.join(parts)})' "
                         f"inside the PIPELINE at line {_line(code, pragma)} has a variable "
                         "bound: a pipelined loop may hold only constant-bound loops (HLS "
                         "unrolls them completely)")

    # -- partition ------------------------------------------------------------------------------
    def partition(self, file: str, code: str, pragma: int, text: str) -> None:
        options = dict(re.findall(r"(\w+)\s*=\s*([\w:]+)", text))
        var, factor = options.get("variable"), options.get("factor")
        if not var or factor is None:
            return
        factor_value = _evaluate(factor, self.constants)
        dims = self._dimensions(code, pragma, var)
        if dims is None or factor_value is None:
            return
        dim = int(options.get("dim", "1"))
        checked = range(len(dims)) if dim == 0 else [dim - 1]
        for d in checked:
            if d >= len(dims):
                self.add(file, code, pragma, "partition", f"ARRAY_PARTITION of '{var}' dim="
                         f"{dim}: the array has {len(dims)} dimension(s)")
                continue
            size = _evaluate(dims[d], self.constants)
            if size is not None and factor_value > size:
                self.add(file, code, pragma, "partition", f"ARRAY_PARTITION of '{var}': factor "
                         f"{factor_value} exceeds dimension {d + 1} of size {size} "
                         f"('{dims[d]}')")

    def _dimensions(self, code: str, pragma: int, var: str) -> list[str] | None:
        """The declared dimensions of ``var`` seen from ``pragma``: the enclosing function's
        parameters and locals first, then file scope."""
        decl = re.compile(rf"[\w>*&]\s+{re.escape(var)}\s*((?:\[[^\]]*\]\s*)+)")
        for f in self.functions.values():
            if f.code is code and f.body[0] <= pragma <= f.body[1]:
                for p in f.params:
                    if p.name == var:
                        return list(p.dims) or None
                m = decl.search(code, f.body[0], f.body[1])
                if m:
                    return re.findall(r"\[([^\]]*)\]", m.group(1))
        for _, other in self.files:
            m = decl.search(other)
            if m:
                return re.findall(r"\[([^\]]*)\]", m.group(1))
        return None

    # -- DSP budget -----------------------------------------------------------------------------
    def dsp(self) -> None:
        if not self.part:
            return
        from fgc_backends.hls.target import Target, device_of

        device = device_of(self.part)
        if device is None:
            return

        default = "float64" if self.scalar == "double" else "float32"
        total, parts, first = 0, [], None
        for name, code in self.files:
            for m in _PRAGMA.finditer(code):
                text = m.group(1)
                if not re.match(r"ALLOCATION\b", text, re.I) or not re.search(
                        r"\boperation\b", text):
                    continue
                options = dict(re.findall(r"(\w+)\s*=\s*(\w+)", text))
                op, limit = options.get("instances"), _evaluate(options.get("limit", ""),
                                                                 self.constants)
                if op not in ALLOCATION_OPS or limit is None:
                    continue
                kind, precision = ALLOCATION_OPS[op]
                dsp = Target(self.part).ops(precision or default).op(kind).dsp
                total += limit * dsp
                parts.append(f"{op} {limit}x{dsp}")
                first = first or (name, code, m.start())
        if first and total > device.dsp:
            self.add(*first, "dsp", f"the ALLOCATION limits imply {total} DSP "
                     f"({', '.join(parts)}), more than the {device.dsp} of part "
                     f"{self.part}")


def semantic_issues(files: Iterable[tuple[str, str]], part: str | None = None,
                    scalar: str | None = None) -> list[LintIssue]:
    """Semantic-rule issues of synthesised C++ ``files`` ((name, text) pairs, read together so
    that calls across a header and its source resolve). ``part``/``scalar`` set the DSP budget
    and the precision of ALLOCATION operation names without one."""
    return _Checker(list(files), part, scalar).run()
