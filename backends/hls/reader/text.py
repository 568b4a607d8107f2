"""Text scanning for the second reader: the C++ patterns it reads (declarations, pragmas,
operators, subscripts, calls), the text blanked or cut to one block's own level, and the
records a reading adds up (:class:`_Var`, :class:`_Count`)."""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass, field

from fgc_backends.hls.lint.cxx import _Function, _matching

FLOAT_TYPES = r"(?:T|L|float|double|typename\s+CFG::T|CFG::T|ap_fixed<[^<>;]*>)"


_DECL = re.compile(r"(?:^|(?<=[;{}(,]))\s*(?:static\s+)?(?:const\s+)?(?P<type>" + FLOAT_TYPES +
                   r"|int|bool|unsigned|qr_word<[^<>;]*>)\s+(?P<names>[A-Za-z_][^;{}]*?)"
                   r"\s*(?=[;)])", re.M)


_PRAGMA = re.compile(r"#\s*pragma\s+HLS\s+([^\n]*)", re.I)


_SQRT = re.compile(r"\b(?:fgc_sqrt|hls::sqrt|std::sqrt|sqrt|sqrtf|fgc_rsqrt)\s*\(")


_SPECIAL = re.compile(r"\b(?:fgc_|hls::|std::)(?:sin|cos|atan2|exp|log|log1p|tan|asin|acos|"
                      r"atan)\s*\(")


def library_calls(pattern: re.Pattern, text: str, defined) -> int:
    """Calls in ``text`` matched by ``pattern`` (:data:`_SQRT`, :data:`_SPECIAL`) of functions
    the project does not define: a project function (``fgc_sin``, a wrapper of ``std::sin``)
    is read in place, its body's call counted there, not twice."""
    return sum(1 for m in pattern.finditer(text)
               if re.sub(r"[\s(]", "", m.group(0)).split("::")[-1] not in defined)


KINDS = ("add", "mul", "div", "sqrt", "special")


_ALLOCATION_KINDS = {"fadd": "add", "dadd": "add", "fsub": "add", "dsub": "add", "fmul": "mul",
                     "dmul": "mul", "fdiv": "div", "ddiv": "div", "fsqrt": "sqrt",
                     "dsqrt": "sqrt"}


_CONTROL = re.compile(r"\bfor\s*\(|\bif\s*\(|\belse\b|#|[^\s;{}]")


_SUBSCRIPTED = re.compile(r"\b([A-Za-z_]\w*)\s*((?:\[[^\[\]]*(?:\[[^\]]*\][^\[\]]*)*\]\s*)+)"
                          r"(\s*[-+*/]?=(?!=))?")


_GLOBAL = re.compile(r"^[ \t]*(?:static\s+)?(?:const\s+)?(" + FLOAT_TYPES + r"|int|bool)\s+"
                     r"([A-Za-z_]\w*)\s*((?:\[[^\]]*\]\s*)+)(?:=[^;]*)?;", re.M)


_CALL = re.compile(r"\b([A-Za-z_]\w*)\s*(<[^;{}()=&|]*?>)?\s*\(")


@dataclass(frozen=True)
class _Var:
    """A name in scope: floating-point or not, its dimensions, the array it stands for (a
    parameter: the caller's) and where that array lives: "global" (namespace scope: ports as
    partitioned), "local" (a function's own array: Vitis's default throughput-driven automatic
    partitioning gives it the ports a pipelined loop needs, at a price in registers) or
    "stream" (an hls::stream: a FIFO per element)."""

    is_float: bool
    dims: tuple[str, ...]
    alias: str
    storage: str


@dataclass
class _Count:
    ops: Counter = field(default_factory=Counter)
    capped: dict[str, Counter] = field(default_factory=dict)  # callee -> its ops (ALLOCATION)
    accesses: Counter = field(default_factory=Counter)  # global array -> accesses
    recurrences: set[str] = field(default_factory=set)  # carried read-modify-writes
    # array or scalar that lives across iterations -> {(access, index fixed or data-dependent)}
    rw: dict[str, set[tuple[str, bool]]] = field(default_factory=dict)
    # ``ops`` / ``capped`` with the branches of an if / else chain taking the largest branch,
    # not their sum: exclusive branches share an ALLOCATION's instances (what one iteration
    # must issue through them)
    peak: Counter = field(default_factory=Counter)
    capped_peak: dict[str, Counter] = field(default_factory=dict)
    calls: Counter = field(default_factory=Counter)  # project function -> its call sites

    @classmethod
    def of(cls, ops: Counter) -> _Count:
        """Operations run unconditionally."""
        return cls(ops=Counter(ops), peak=Counter(ops))

    def add(self, other: _Count, times: int = 1) -> None:
        for k, v in other.ops.items():
            self.ops[k] += v * times
        for k, v in other.peak.items():
            self.peak[k] += v * times
        for k, v in other.calls.items():
            self.calls[k] += v * times
        for mine_of, theirs in ((self.capped, other.capped),
                                (self.capped_peak, other.capped_peak)):
            for name, c in theirs.items():
                mine = mine_of.setdefault(name, Counter())
                for k, v in c.items():
                    mine[k] += v * times
        for k, v in other.accesses.items():
            self.accesses[k] += v * times
        self.recurrences |= other.recurrences
        for k, v in other.rw.items():
            self.rw.setdefault(k, set()).update(v)


def _blank_macros(code: str) -> str:
    """``code`` with the cycle counters' invocations (``FGC_CYCLES(...)`` and the like, empty
    in synthesis) blanked, lines kept."""
    out, pos = [], 0
    for m in re.finditer(r"\bFGC_[A-Z_]+\s*\(", code):
        if m.start() < pos:
            continue
        end = _matching(code, m.end() - 1, "(", ")")
        out.append(code[pos:m.start()])
        out.append(re.sub(r"[^\n]", " ", code[m.start():end + 1]))
        pos = end + 1
    out.append(code[pos:])
    return "".join(out)


def until_fixed(pattern: str, repl: str, text: str) -> str:
    """``re.sub(pattern, repl, ...)`` applied again until nothing changes: nested groups
    (brackets within brackets) replaced innermost first."""
    while True:
        new = re.sub(pattern, repl, text)
        if new == text:
            return text
        text = new


def _own_level(text: str) -> str:
    """``text`` with every brace block inside it replaced by ';' (what its own level says)."""
    return until_fixed(r"\{[^{}]*\}", ";", text)


def _pipelined(body: str) -> bool:
    """Whether a loop body (its own level, not a nested loop's) holds a PIPELINE pragma."""
    body = _own_level(body)
    return re.search(r"#\s*pragma\s+HLS\s+PIPELINE\b(?![^\n]*\boff\b)", body, re.I) is not None


def _subscripts(index: str) -> list[str]:
    """The contents of each top-level ``[...]`` of ``index`` (``[j][at[a]]`` -> j, at[a])."""
    out, depth, start = [], 0, 0
    for i, ch in enumerate(index):
        if ch == "[":
            if depth == 0:
                start = i + 1
            depth += 1
        elif ch == "]":
            depth -= 1
            if depth == 0:
                out.append(index[start:i])
    return out


def _unit(f: _Function, unit: str | None) -> str | None:
    """The translation unit ``f`` is read in: its own file if it is a .cpp (a kernel), else
    (a header's function) the unit that reached it."""
    return f.file if f.file.endswith(".cpp") else unit


_DIRECTIVE = re.compile(r"^[ \t]*#[ \t]*(if|ifdef|ifndef|elif|else|endif|define|undef|include)\b"
                        r"([^\n]*)", re.M)


def _condition(expr: str, defined: dict[str, str]) -> bool | None:
    """The value of an ``#if`` / ``#elif`` expression of ``defined(A)``, macro names, integers,
    ``!``, ``&&``, ``||`` and parentheses under the macros ``defined`` (name -> body); None
    where it holds anything else (the reader then keeps every branch: it does not guess)."""
    expr = re.sub(r"\bdefined\s*\(\s*(\w+)\s*\)|\bdefined\s+(\w+)",
                  lambda m: " 1 " if (m.group(1) or m.group(2)) in defined else " 0 ", expr)

    def name(m: re.Match) -> str:
        body = defined.get(m.group(0), "0").strip() or "0"
        return f" {int(body)} " if re.fullmatch(r"\d+", body) else " ? "

    expr = re.sub(r"\b[A-Za-z_]\w*\b", name, expr)
    if not re.fullmatch(r"[\s\d()!&|]*", expr) or not expr.strip():
        return None
    expr = expr.replace("&&", " and ").replace("||", " or ")
    expr = re.sub(r"!(?!=)", " not ", expr)
    if re.search(r"[&|]", expr):
        return None
    try:
        return bool(eval(expr, {"__builtins__": {}}, {}))  # digits, parentheses, and/or/not
    except SyntaxError:
        return None


def wide_namespace_lines(text: str) -> set[int]:
    """The lines of ``text`` inside a namespace whose own level says ``typedef L T;`` (the
    mixed design's ``fgc::les``: there ``T`` is the linear solver's scalar ``L``)."""
    code = strip_comments(text)
    out: set[int] = set()
    for m in re.finditer(r"\bnamespace\s+\w+\s*\{", code):
        end = _matching(code, m.end() - 1, "{", "}")
        if re.search(r"(?<![\w:])typedef\s+L\s+T\s*;", _own_level(code[m.end():end])):
            first = code.count("\n", 0, m.start())
            out.update(range(first, first + code.count("\n", m.start(), end) + 1))
    return out


def compiled_view(files: list[tuple[str, str]], wide: dict[str, set[int]] | None = None
                  ) -> list[tuple[str, str]]:
    """``files`` with the text of the preprocessor branches no translation unit compiles
    blanked (lines kept). Each kernel (.cpp) is preprocessed from the top: its ``#define`` s
    and those of the headers it includes (``#include "x.h"`` of a file among ``files``) decide
    each ``#if`` / ``#ifdef`` / ``#ifndef`` / ``#elif`` / ``#else`` of the files it reaches; a
    line is kept if some inclusion compiles it. A header no kernel includes is kept whole, as is
    every branch of a condition this does not evaluate. ``wide`` (when given) receives, per
    file, the lines compiled where ``T`` is ``L`` (:func:`wide_namespace_lines`: a kernel's
    lines inside such a namespace and a header's lines an inclusion there compiles)."""
    texts = dict(files)
    kept: dict[str, set[int]] = {}
    wide = {} if wide is None else wide

    def run(name: str, defined: dict[str, str], depth: int, inside: bool = False) -> None:
        text = texts[name]
        lines = strip_comments(text).split("\n")
        raw = text.split("\n")
        mine = kept.setdefault(name, set())
        spans = wide_namespace_lines(text) if name.endswith(".cpp") else set()
        # per open #if: (the enclosing branch active, this branch active, a branch was taken)
        stack: list[tuple[bool, bool, bool]] = []
        active = True
        for i, line in enumerate(lines):
            m = _DIRECTIVE.match(line)
            word, rest = (m.group(1), m.group(2).strip()) if m else (None, "")
            if word in ("if", "ifdef", "ifndef"):
                if word == "if":
                    value = _condition(rest, defined)
                else:
                    value = (rest.split()[0] in defined) == (word == "ifdef") if rest else None
                taken = value is not False
                stack.append((active, active and taken, taken and value is not None))
                active = active and taken
                mine.add(i)
                continue
            if word in ("elif", "else") and stack:
                outer, _, done = stack[-1]
                value = True if word == "else" else _condition(rest, defined)
                now = not done and value is not False
                stack[-1] = (outer, outer and now, done or (now and value is not None))
                active = outer and now
                mine.add(i)
                continue
            if word == "endif" and stack:
                active = stack.pop()[0]
                mine.add(i)
                continue
            if not active:
                continue
            mine.add(i)
            here = inside or i in spans
            if here:
                wide.setdefault(name, set()).add(i)
            if word == "define" and rest:
                macro = re.match(r"(\w+)(\([^)]*\))?\s*(.*)", rest)
                if macro:
                    defined[macro.group(1)] = macro.group(3) if not macro.group(2) else "?"
            elif word == "undef" and rest:
                defined.pop(rest.split()[0], None)
            elif word == "include":
                target = re.search(r'"([^"]+)"', raw[i])
                child = target and target.group(1).rsplit("/", 1)[-1]
                if child in texts and depth < 32:
                    run(child, defined, depth + 1, here)

    for name, _ in files:
        if name.endswith(".cpp"):
            run(name, {}, 0)
    out = []
    for name, text in files:
        if name not in kept:
            out.append((name, text))
            continue
        lines = text.split("\n")
        out.append((name, "\n".join(line if i in kept[name] else " " * len(line)
                                    for i, line in enumerate(lines))))
    return out


def strip_comments(text: str) -> str:
    """``text`` with its comments blanked (newlines kept; strings left: an include's name)."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"', re.S)
    return pattern.sub(lambda m: m.group(0) if m.group(0).startswith('"')
                       else re.sub(r"[^\n]", " ", m.group(0)), text)
