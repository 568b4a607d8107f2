"""The factor datapaths' depth as Vitis would schedule the emitted text.

Each factor datapath function (``factor_<b>``: the Jacobian mode, ``factor_cost_<b>``: the cost
mode) and each state-update datapath (``retract_<k>``) is a straight list of statements:
``const T tK = <expr>;``, an SO(3) logarithm's ``T tlogK[3]; so3_log(<args>, tlogK);`` and its
outputs (``raw[i] = <expr>;``, ``half[i] = <expr>;``, ``out[i] = <expr>;``). This module reads
them back with its own parse of C++ expressions (precedence and left-to-right associativity as
the language defines them: ``a + b + c`` is ``(a + b) + c``) and schedules them as soon as their
operands are ready, each operator taking its latency in the project's operator table
(``run_hls.tcl``'s part, clock and binding: :func:`~fgc_backends.hls.reader.design.emitted_ops`).
Vitis HLS does not reassociate floating-point operations (UG1399, "Optimizing Logic
Expressions": expression balancing is off for floating-point operations unless
``config_compile -unsafe_math_optimizations``), so a function's depth is the latest of its
outputs: what its pipeline's depth is at least, whatever the ``ALLOCATION`` limits add.

Calls: ``fgc_sqrt`` a square root; ``fgc_sin`` / ``fgc_cos`` / ``fgc_tan`` one sine or cosine;
``fgc_atan2`` / ``fgc_atan`` / ``fgc_asin`` / ``fgc_acos`` an arctangent; ``fgc_exp`` /
``fgc_tanh`` an exponential, ``fgc_log`` a logarithm; ``fgc_guarded_quotient`` its divide;
``fgc_abs`` / ``fgc_sign`` a compare; a Lie coefficient (``lie_*``) or ``so3_log`` one
``special`` operator (the table's Lie coefficient: the figure the DSP reader counts them by);
``T(x)`` a cast (free); a sign free. Anything else makes the function unread (``None``): the
reader does not judge what it cannot parse.

Nothing here reads the plan: :func:`check_depths` compares the depths read with the ones a
caller says the plan prices (rule ``depth``).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable

from fgc_backends.cfamily.lint import LintIssue
from fgc_backends.hls.reader.text import strip_comments

_FUNCTION = re.compile(r"\bvoid\s+(factor(?:_cost)?_\d+|retract_\d+)\s*\(([^)]*)\)\s*\{")
_TOKEN = re.compile(r"\s*(?:(\d+\.\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?|\d+(?:[eE][-+]?\d+)?)"
                    r"|([A-Za-z_]\w*(?:\s*::\s*[A-Za-z_]\w*)*)|(\S))")
# call -> operator kind of the project's table (None: free)
_CALLS = {"fgc_sqrt": "sqrt", "fgc_sin": "sincos", "fgc_cos": "sincos", "fgc_tan": "sincos",
          "fgc_atan2": "atan2", "fgc_atan": "atan2", "fgc_asin": "atan2", "fgc_acos": "atan2",
          "fgc_exp": "exp", "fgc_tanh": "exp", "fgc_log": "log",
          "fgc_guarded_quotient": "div", "fgc_abs": "compare", "fgc_sign": "compare",
          "so3_log": "special"}
_CASTS = {"T", "L", "float", "double"}


class UnreadError(Exception):
    """A statement or expression outside what this reader parses."""


def _tokens(text: str) -> list[str]:
    out, pos = [], 0
    text = text.strip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None or m.end() == pos:
            raise UnreadError(text[pos:pos + 20])
        out.append(m.group(m.lastindex))
        pos = m.end()
    return out


class _Expr:
    """Recursive descent over one expression's tokens: :meth:`time` is when its value is
    ready, given ``ready(name)`` for a variable (an input or an earlier statement's)."""

    def __init__(self, tokens: list[str], ready: Callable[[str], int],
                 latency: Callable[[str], int]):
        self.toks, self.pos, self.ready, self.lat = tokens, 0, ready, latency

    def peek(self) -> str | None:
        return self.toks[self.pos] if self.pos < len(self.toks) else None

    def take(self, want: str | None = None) -> str:
        tok = self.peek()
        if tok is None or (want is not None and tok != want):
            raise UnreadError(f"expected {want!r}, found {tok!r}")
        self.pos += 1
        return tok

    def time(self) -> int:
        t = self.sum()
        if self.peek() is not None:
            raise UnreadError(f"trailing {self.peek()!r}")
        return t

    def sum(self) -> int:  # left to right: (a + b) - c
        t = self.product()
        while self.peek() in ("+", "-"):
            self.take()
            t = max(t, self.product()) + self.lat("add")
        return t

    def product(self) -> int:  # left to right: (a * b) / c
        t = self.unary()
        while self.peek() in ("*", "/"):
            kind = "mul" if self.take() == "*" else "div"
            t = max(t, self.unary()) + self.lat(kind)
        return t

    def unary(self) -> int:
        if self.peek() in ("-", "+"):  # a sign: free
            self.take()
            return self.unary()
        return self.primary()

    def primary(self) -> int:
        tok = self.take()
        if tok == "(":
            t = self.sum()
            self.take(")")
            return t
        if re.fullmatch(r"[\d.]\S*", tok):
            return 0
        if not re.fullmatch(r"[A-Za-z_][\w:\s]*", tok):
            raise UnreadError(tok)
        name = re.sub(r"\s+", "", tok)
        if self.peek() == "(":  # a call or a cast
            self.take()
            args = [self.sum()]
            while self.peek() == ",":
                self.take()
                args.append(self.sum())
            self.take(")")
            if name in _CASTS:
                return max(args)
            short = name.split("::")[-1]
            kind = "special" if short.startswith("lie_") else _CALLS.get(short)
            if kind is None:
                raise UnreadError(f"call of {name}")
            return max(args) + self.lat(kind)
        while self.peek() == "[":  # in[3], dat[12]: an element of an input or a log's output
            self.take()
            index = self.take()
            self.take("]")
            name = f"{name}[{index}]"
        return self.ready(name)


def function_depth(body: str, latency: Callable[[str], int]) -> int | None:
    """When the last output of a datapath function whose body is ``body`` is ready (its inputs
    ready at 0), or None when a statement is not of the forms this reader parses."""
    ready: dict[str, int] = {}
    depth = 0
    try:
        for stmt in strip_comments(body).split(";"):
            stmt = re.sub(r"^\s*#[^\n]*\n", "", stmt.strip() + "\n", flags=re.M).strip()
            if not stmt:
                continue
            m = re.fullmatch(r"const\s+\w+\s+(\w+)\s*=\s*(.+)", stmt, re.S)
            if m:
                ready[m.group(1)] = _time(m.group(2), ready, latency)
                continue
            if re.fullmatch(r"\w+\s+\w+\s*\[\s*\d+\s*\]", stmt):  # T tlog0[3]
                continue
            m = re.fullmatch(r"(so3_log)\s*\((.+),\s*(\w+)\s*\)", stmt, re.S)
            if m:  # its three components, one special operator after its arguments
                t = _time(f"{m.group(1)}({m.group(2)})", ready, latency)
                for axis in range(3):
                    ready[f"{m.group(3)}[{axis}]"] = t
                continue
            m = re.fullmatch(r"(\w+)\s*\[\s*\d+\s*\]\s*=\s*(.+)", stmt, re.S)
            if m:  # an output
                depth = max(depth, _time(m.group(2), ready, latency))
                continue
            raise UnreadError(stmt[:60])
    except UnreadError:
        return None
    return depth


def _time(expr: str, ready: dict[str, int], latency: Callable[[str], int]) -> int:
    return _Expr(_tokens(expr), lambda name: ready.get(name, 0), latency).time()


def datapath_depths(files: Iterable[tuple[str, str]],
                    latency: Callable[[str], int]) -> dict[str, int | None]:
    """Per factor datapath function of the emitted ``files`` (name → depth in cycles, None when
    unread), its operators' latencies ``latency(kind)`` (an operator table's ``op(kind)``)."""
    out: dict[str, int | None] = {}
    for _, text in files:
        code = strip_comments(text)
        for m in _FUNCTION.finditer(code):
            end = _closing(code, m.end() - 1)
            out[m.group(1)] = function_depth(code[m.end():end], latency)
    return out


def _closing(code: str, start: int) -> int:
    depth = 0
    for i in range(start, len(code)):
        depth += {"{": 1, "}": -1}.get(code[i], 0)
        if depth == 0:
            return i
    raise ValueError("unbalanced braces")


def table_latency(table) -> Callable[[str], int]:
    """``latency(kind)`` of an operator table (``emitted_ops(directory)(precision)``)."""
    return lambda kind: table.op(kind).latency


def check_depths(read: dict[str, int | None], priced: dict[str, int],
                 file: str = "<design>") -> list[LintIssue]:
    """An issue (rule ``depth``) per datapath function whose text schedules deeper than the
    depth the plan prices its loop with (``priced``: function name → cycles), and per
    function the reader could not read."""
    issues = []
    for name, plan in sorted(priced.items()):
        got = read.get(name)
        if got is None:
            issues.append(LintIssue(file, 1, "depth", f"{name}: the reader cannot read its "
                                    "depth from the text"))
        elif got > plan:
            issues.append(LintIssue(file, 1, "depth", f"{name}: the text schedules {got} "
                                    f"cycles deep, the plan prices {plan}"))
    return issues
