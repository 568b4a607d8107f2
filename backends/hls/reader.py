"""The second reader: what Vitis HLS would build from the emitted C++ text alone.

The accelerator plan says what each loop costs and the emitter prints the plan; this module
reads the printed text back without the plan and derives, per ``PIPELINE`` loop, what Vitis's
documented binding and scheduling rules (UG1399: pipelining, ``ALLOCATION``,
``ARRAY_PARTITION``, ``DEPENDENCE``) make of it:

- **operators**: the floating-point operations of one iteration, with constant-bound inner
  loops unrolled (as a pipelined loop's inner loops are) and the project functions it calls
  read in place (template arguments bound, so ``fold_partials<T, 11>`` counts its 10 adders).
  A pipelined loop is its own module: at II ``n`` it needs ``ceil(ops / n)`` instances of each
  operator kind, capped only by an ``ALLOCATION`` in the function that holds the loop or in
  the callee that holds the operations;
- **memories**: the accesses of one iteration to each array, against its ports: 2 a bank, and
  as many banks as the ``ARRAY_PARTITION`` where the array is declared (a parameter: the
  caller's array it is bound to) gives. ``ceil(accesses / (2 × banks))`` bounds the II;
- **recurrences**: an array element or scalar read and written by every iteration (a
  compound assignment whose index does not move with the pipelined loop's variable, or is
  data-dependent: read from another array) carries a dependence; without a ``DEPENDENCE ...
  inter false`` on it the II is at least the adder's latency.

:func:`read_project` returns one :class:`LoopReading` per pipelined loop; :func:`check`
compares them with the II each loop's pragma declares (the plan's) and returns
:class:`fgc_backends.hls.lint.LintIssue` s (rules ``ii_ports``, ``ii_recurrence``).
:func:`dsp_estimate` sums the operators over the module instances Vitis would make (every
call site its own instance, an unrolled call once per copy). This reader knows nothing of the
plan; where it cannot resolve something (a bound it cannot evaluate, an array it cannot find)
it does not judge rather than guess.
"""

from __future__ import annotations

import math
import re
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field, replace

from fgc_backends.hls.lint import (
    LintIssue,
    _constants,
    _evaluate,
    _Function,
    _functions,
    _line,
    _matching,
    _split_top,
    statement_end,
    strip_comments_and_strings,
    synthesis_view,
)

FLOAT_TYPES = r"(?:T|L|float|double|typename\s+CFG::T|CFG::T|ap_fixed<[^<>;]*>)"
_DECL = re.compile(r"(?:^|(?<=[;{}(,]))\s*(?:static\s+)?(?:const\s+)?(?P<type>" + FLOAT_TYPES +
                   r"|int|bool|unsigned|qr_word<[^<>;]*>)\s+(?P<names>[A-Za-z_][^;{}]*?)"
                   r"\s*(?=[;)])", re.M)
_PRAGMA = re.compile(r"#\s*pragma\s+HLS\s+([^\n]*)", re.I)
_SQRT = re.compile(r"\b(?:fgc_sqrt|hls::sqrt|std::sqrt|sqrt|sqrtf|fgc_rsqrt)\s*\(")
_SPECIAL = re.compile(r"\b(?:fgc_sin|fgc_cos|fgc_atan2|fgc_exp|fgc_log|fgc_log1p|fgc_tan|"
                      r"fgc_asin|fgc_acos|fgc_atan|hls::sin|hls::cos|std::sin|std::cos)\s*\(")
KINDS = ("add", "mul", "div", "sqrt", "special")


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

    def add(self, other: _Count, times: int = 1) -> None:
        for k, v in other.ops.items():
            self.ops[k] += v * times
        for name, c in other.capped.items():
            mine = self.capped.setdefault(name, Counter())
            for k, v in c.items():
                mine[k] += v * times
        for k, v in other.accesses.items():
            self.accesses[k] += v * times
        self.recurrences |= other.recurrences
        for k, v in other.rw.items():
            self.rw.setdefault(k, set()).update(v)


@dataclass(frozen=True)
class LoopReading:
    """One pipelined loop as the text describes it."""

    file: str
    line: int
    function: str
    label: str | None  # the FGC_CYCLES label after the loop, when there is one
    template: tuple[tuple[str, int], ...]  # the instantiation's integer template arguments
    ii: int  # the II its PIPELINE pragma declares (the plan's)
    ops: tuple[tuple[str, int], ...]  # floating-point operations of one iteration, by kind
    instances: tuple[tuple[str, int], ...]  # operator instances it needs at its II
    accesses: tuple[tuple[str, int, int], ...]  # (global array, accesses an iteration, banks)
    ii_ports: int  # the smallest II its memories' ports allow
    recurrence: tuple[str, ...]  # carried read-modify-writes without DEPENDENCE inter false
    ii_recurrence: int  # the smallest II those recurrences allow (0: none)
    ii_known: bool = True  # False: the pragma's II does not evaluate here (not judged)

    @property
    def ii_bound(self) -> int:
        return max(1, self.ii_ports, self.ii_recurrence)

    def dsp(self, dsp_of: dict[str, int]) -> int:
        return sum(n * dsp_of.get(kind, 0) for kind, n in self.instances)


_ALLOCATION_KINDS = {"fadd": "add", "dadd": "add", "fsub": "add", "dsub": "add", "fmul": "mul",
                     "dmul": "mul", "fdiv": "div", "ddiv": "div", "fsqrt": "sqrt",
                     "dsqrt": "sqrt"}
_CONTROL = re.compile(r"\bfor\s*\(|\bif\s*\(|\belse\b|#|[^\s;{}]")
_SUBSCRIPTED = re.compile(r"\b([A-Za-z_]\w*)\s*((?:\[[^\[\]]*(?:\[[^\]]*\][^\[\]]*)*\]\s*)+)"
                          r"(\s*[-+*/]?=(?!=))?")
_GLOBAL = re.compile(r"^[ \t]*(?:static\s+)?(?:const\s+)?(" + FLOAT_TYPES + r"|int|bool)\s+"
                     r"([A-Za-z_]\w*)\s*((?:\[[^\]]*\]\s*)+)(?:=[^;]*)?;", re.M)
_CALL = re.compile(r"\b([A-Za-z_]\w*)\s*(<[^;{}()=&|]*?>)?\s*\(")


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


def _own_level(text: str) -> str:
    """``text`` with every brace block inside it replaced by ';' (what its own level says)."""
    while True:
        new = re.sub(r"\{[^{}]*\}", ";", text)
        if new == text:
            return text
        text = new


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


class _Reader:
    def __init__(self, files: Iterable[tuple[str, str]], add_latency: int):
        self.files = [(name, _blank_macros(strip_comments_and_strings(synthesis_view(text))))
                      for name, text in files]
        self.functions: dict[str, _Function] = {}
        # Struct::name -> [(specialisation's template arguments or None, function)]
        self.members: dict[str, list[tuple[tuple[str, ...] | None, _Function]]] = {}
        self.defaults: dict[str, tuple[str, ...]] = {}  # struct template -> its parameters
        self.structs: set[str] = set()  # every struct's name
        # file -> its functions: a call resolves in its own file first (a kernel's functions
        # live in its .cpp's anonymous namespace: the on-chip stream design's two kernels
        # define the same names), then anywhere
        self.local: dict[str, dict[str, _Function]] = {}
        # the translation unit being read: the .cpp of the kernel function that (directly or
        # through a header's template) is being read
        self.where: str | None = None
        for name, code in self.files:
            structs = []
            for m in re.finditer(r"(?:template\s*<([^{};]*?)>\s*)?\bstruct\s+(\w+)\s*"
                                 r"(<[^{};]*>)?\s*\{", code):
                self.structs.add(m.group(2))
                structs.append((m.start(), _matching(code, m.end() - 1, "{", "}"),
                                tuple(_split_top(m.group(3)[1:-1])) if m.group(3) else None))
                if m.group(1) and not m.group(3):
                    self.defaults[m.group(2)] = tuple(_split_top(m.group(1)))
            for f in _functions(name, code):
                if f.qualname != f.name:
                    spec = [s for s in structs if s[0] < f.start < s[1]]
                    self.members.setdefault(f.qualname, []).append(
                        (spec[-1][2] if spec else None, f))
                else:
                    self.functions.setdefault(f.name, f)
                    self.local.setdefault(name, {}).setdefault(f.name, f)
        self.constants = _constants(code for _, code in self.files)
        # a kernel's own constants (two kernels in one design may give a name two values)
        self.unit_constants = {name: _constants([code]) for name, code in self.files
                               if name.endswith(".cpp")}
        self.add_latency = add_latency
        outside = "\n".join(self._outside_functions(n, c) for n, c in self.files)
        self.globals = {m.group(2): _Var(re.fullmatch(FLOAT_TYPES, m.group(1)) is not None,
                                         tuple(re.findall(r"\[([^\]]*)\]", m.group(3))),
                                         m.group(2), "global")
                        for m in _GLOBAL.finditer(outside)}

        def dims_of(name):
            return self.globals[name].dims if name in self.globals else None

        self.global_banks = self._banks(outside, {}, dims_of)
        # a global partitioned inside a function (Vitis's place for a global's pragma): a
        # pragma naming it where no parameter or local of that name hides it
        for f in self.functions.values():
            own = {p.name for p in f.params} | set(self._declarations(f.text))
            for name, banks in self._banks(f.text, {}, dims_of).items():
                if name in self.globals and name not in own:
                    self.global_banks[name] = banks
        self.bindings = self._bindings()
        self.memo: dict[tuple, _Count] = {}
        self.flatten = True  # read a callee in place (off: a function's own operations)
        self.returns_float = False  # the function being read returns a floating-point value

    # -- declarations ----------------------------------------------------------------------
    def _outside_functions(self, file: str, code: str) -> str:
        """``code`` with every function body blanked: the declarations at namespace scope."""
        chars = list(code)
        for f in _functions(file, code):
            for i in range(f.body[0], f.body[1] + 1):
                if chars[i] != "\n":
                    chars[i] = " "
        return "".join(chars)

    @staticmethod
    def _declarations(code: str) -> dict[str, tuple[bool, tuple[str, ...]]]:
        """name -> (floating-point, array dimensions) of the variables declared in ``code``."""
        out: dict[str, tuple[bool, tuple[str, ...]]] = {}
        for m in _DECL.finditer(code):
            is_float = re.fullmatch(FLOAT_TYPES, m.group("type").strip()) is not None
            for part in _split_top(m.group("names")):
                d = re.match(r"^\*?\s*([A-Za-z_]\w*)\s*((?:\[[^\]]*\]\s*)*)", part)
                if d:
                    dims = tuple(x.strip() for x in re.findall(r"\[([^\]]*)\]", d.group(2)))
                    out.setdefault(d.group(1), (is_float, dims))
        return out

    def _banks(self, code: str, env: dict[str, int], dims_of=None) -> dict[str, int | None]:
        """array -> banks from the ARRAY_PARTITION pragmas in ``code`` (None: registers, a
        complete partition of every dimension). ``complete dim=k`` (k >= 1) of an array of
        more than one dimension gives as many banks as dimension k has (``dims_of``: name ->
        its dimensions, when known)."""
        out: dict[str, int | None] = {}
        for m in _PRAGMA.finditer(code):
            words = m.group(1)
            if not words.upper().startswith("ARRAY_PARTITION"):
                continue
            var = re.search(r"variable\s*=\s*(\w+)", words)
            if not var:
                continue
            if re.search(r"\bcomplete\b", words):
                dim = re.search(r"\bdim\s*=\s*(\d+)", words)
                dims = dims_of(var.group(1)) if dims_of else None
                k = int(dim.group(1)) if dim else 0
                if k >= 1 and dims and len(dims) > 1 and k <= len(dims):
                    out[var.group(1)] = self._value(dims[k - 1], env)  # None: not known
                else:
                    out[var.group(1)] = None
            else:
                factor = re.search(r"factor\s*=\s*(\w+)", words)
                value = self._value(factor.group(1), env) if factor else None
                out[var.group(1)] = value or 1
        return out

    def _value(self, expr: str, env: dict[str, int]) -> int | None:
        word = expr.strip()
        if word in ("true", "false"):
            return int(word == "true")
        return _evaluate(expr, {**self.constants, **self.unit_constants.get(self.where, {}),
                                **env})

    def _bindings(self) -> dict[tuple[str, str], set[str]]:
        """(function, parameter) -> the names its call sites pass (their base names, resolved
        through the callers' own parameters to globals where they lead there)."""
        direct: dict[tuple[str, str], set[tuple[str, str]]] = {}
        for caller in self.functions.values():
            for m in _CALL.finditer(caller.text):
                f = self.functions.get(m.group(1))
                if f is None:
                    continue
                open_ = caller.text.index("(", m.end() - 1)
                args = _split_top(caller.text[m.end():_matching(caller.text, open_, "(", ")")])
                for param, arg in zip(f.params, args, strict=False):
                    base = re.match(r"^&?\s*([A-Za-z_]\w*)", arg)
                    if base and (param.dims or param.pointer):
                        direct.setdefault((f.name, param.name), set()).add(
                            (caller.name, base.group(1)))
        out: dict[tuple[str, str], set[str]] = {}

        def resolve(key, seen):
            names = set()
            for caller, name in direct.get(key, ()):
                if name in self.globals:
                    names.add(name)
                elif (caller, name) not in seen and any(
                        p.name == name for p in self.functions[caller].params):
                    names |= resolve((caller, name), seen | {key})
            return names

        for key in direct:
            out[key] = resolve(key, frozenset())
        return out

    def _param_var(self, f: _Function, param) -> _Var | None:
        if param.stream:
            return None
        is_float = re.search(rf"\b{FLOAT_TYPES}\b", param.type) is not None
        if not (param.dims or param.pointer):
            return _Var(is_float, (), param.name, "local")
        bound = sorted(self.bindings.get((f.name, param.name), ()))
        if bound:  # bound to a global: the first (a parameter bound to several: any one)
            return _Var(is_float, param.dims, bound[0], "global")
        return _Var(is_float, param.dims, param.name, "local")

    # -- counting ----------------------------------------------------------------------------
    def count(self, text: str, scope: dict, env: dict[str, int], loop_var: str | None,
              outer: frozenset, depth: int = 0) -> _Count:
        """The operations, accesses and recurrences of ``text`` (a block's contents) run once,
        inner constant-bound loops unrolled; ``outer``: names that live across iterations of
        the pipelined loop (a read-modify-write of one of them is carried)."""
        total = _Count()
        pos, n = 0, len(text)
        taken: bool | None = None  # the last if's condition, when the template fixes it
        while pos < n:
            m = _CONTROL.search(text, pos)
            if not m:
                break
            word = m.group(0)
            if word.startswith("for"):
                open_ = text.index("(", m.start())
                close = _matching(text, open_, "(", ")")
                header = text[open_ + 1:close].split(";")
                body, pos = self._body(text, close + 1)
                if _pipelined(body):
                    continue  # its own pipelined loop: read on its own
                values = self._iterations(header, env) if len(header) == 3 else None
                if values is None:
                    trips = self._tripcount(body, env) or 1
                    total.add(self.count(body, scope, env, loop_var, outer, depth), trips)
                    continue
                var, seq = values
                if re.search(rf"\b(?:for|if)\s*\([^)]*\b{var}\b", body):
                    for value in seq:  # the body's shape moves with the variable: unroll it
                        total.add(self.count(body, scope, {**env, var: value}, loop_var,
                                             outer, depth))
                elif seq:
                    total.add(self.count(body, scope, env, loop_var, outer, depth), len(seq))
                continue
            if word.startswith("if"):
                open_ = text.index("(", m.start())
                close = _matching(text, open_, "(", ")")
                condition = text[open_ + 1:close]
                total.add(self.statement(condition, scope, env, loop_var, outer, depth))
                body, pos = self._body(text, close + 1)
                taken = self._condition(condition, env)
                if taken is not False:
                    total.add(self.count(body, scope, env, loop_var, outer, depth))
                continue
            if word == "else":
                body, pos = self._body(text, m.end())
                if taken is not True:  # a branch known taken: its else is never built
                    total.add(self.count(body, scope, env, loop_var, outer, depth))
                taken = None
                continue
            if word == "#":
                pos = text.find("\n", m.start())
                pos = n if pos < 0 else pos
                continue
            end = statement_end(text, m.start(), blocks=True)
            total.add(self.statement(text[m.start():end], scope, env, loop_var, outer, depth))
            pos = end + 1
        return total

    def _body(self, text: str, pos: int) -> tuple[str, int]:
        """The statement or block after ``pos``: its text and the index after it."""
        while pos < len(text) and text[pos].isspace():
            pos += 1
        if pos < len(text) and text[pos] == "{":
            end = _matching(text, pos, "{", "}")
            return text[pos + 1:end], end + 1
        m = re.compile(r"\s*(?:for|if)\s*\(").match(text, pos)
        if m:  # a loop or branch without braces: up to its own statement's end
            close = _matching(text, text.index("(", pos), "(", ")")
            _, after = self._body(text, close + 1)
            return text[pos:after], after
        end = statement_end(text, pos, blocks=True)
        return text[pos:end + 1], end + 1

    def _iterations(self, header: list[str], env: dict[str, int]
                    ) -> tuple[str, list[int]] | None:
        """(variable, its values) of a loop with constant bounds, or None."""
        init = re.match(r"^(?:const\s+)?(?:int|unsigned)?\s*(\w+)\s*=\s*([^,]+)$",
                        header[0].strip())
        bound = re.match(r"^\s*(\w+)\s*(<=|<)\s*(.+)$", header[1].strip())
        if not init or not bound or bound.group(1) != init.group(1):
            return None
        var = init.group(1)
        lo, hi = self._value(init.group(2), env), self._value(bound.group(3), env)
        if lo is None or hi is None:
            return None
        hi += bound.group(2) == "<="
        step = header[2].strip()
        add = re.fullmatch(rf"(?:\+\+\s*{var}|{var}\s*\+\+|{var}\s*\+=\s*(.+))", step)
        mul = re.fullmatch(rf"{var}\s*\*=\s*(.+)", step)
        values, v = [], lo
        if add:
            inc = self._value(add.group(1), env) if add.group(1) else 1
            if not inc or inc <= 0:
                return None
            values = list(range(lo, hi, inc))
        elif mul:
            k = self._value(mul.group(1), env)
            if not k or k <= 1 or lo <= 0:
                return None
            while v < hi:
                values.append(v)
                v *= k
        else:
            return None
        return (var, values) if len(values) <= 1 << 16 else None

    def _condition(self, expr: str, env: dict[str, int]) -> bool | None:
        m = re.fullmatch(r"\s*(.+?)\s*(<=|>=|==|!=|<|>)\s*(.+?)\s*", expr)
        if not m:
            return None
        a, b = self._value(m.group(1), env), self._value(m.group(3), env)
        if a is None or b is None:
            return None
        return {"<": a < b, "<=": a <= b, ">": a > b, ">=": a >= b, "==": a == b,
                "!=": a != b}[m.group(2)]

    def _tripcount(self, body: str, env: dict[str, int]) -> int | None:
        m = re.match(r"\s*#\s*pragma\s+HLS\s+LOOP_TRIPCOUNT\s+max\s*=\s*([\w:]+)", body)
        return self._value(m.group(1), env) if m else None

    def _lookup(self, name: str, scope: dict) -> _Var | None:
        return scope.get(name) or self.globals.get(name)

    def statement(self, stmt: str, scope: dict, env: dict[str, int], loop_var: str | None,
                  outer: frozenset, depth: int) -> _Count:
        out = _Count()
        stmt = stmt.strip()
        if not stmt:
            return out
        for name, (is_float, dims) in self._declarations(stmt + ";").items():
            scope[name] = _Var(is_float, dims, name, "local")
        const = re.match(r"^(?:static\s+)?const\s+int\s+(\w+)\s*=\s*(.+)$", stmt)
        if const and "," not in const.group(2):
            value = self._value(const.group(2), env)
            if value is not None:
                env[const.group(1)] = value
        for m in _SUBSCRIPTED.finditer(stmt):
            var = self._lookup(m.group(1), scope)
            if var is None or var.storage == "stream":
                continue
            op = (m.group(3) or "").strip()
            if var.storage == "global":
                out.accesses[var.alias] += 1 + (op not in ("", "="))
            if var.alias not in outer and var.storage != "global":
                continue  # a local of this iteration: nothing carried through it
            subscripts = _subscripts(m.group(2))
            fixed = any("[" in s for s in subscripts) or loop_var is None or not any(
                re.search(rf"\b{loop_var}\b", s) for s in subscripts)
            kinds = {"": ("r",), "=": ("w",)}.get(op, ("r", "w"))
            out.rw.setdefault(var.alias, set()).update((k, fixed) for k in kinds)
        scalar = re.match(r"^([A-Za-z_]\w*)\s*([-+*/])=", stmt)
        if scalar:
            var = self._lookup(scalar.group(1), scope)
            if var is not None and var.is_float and not var.dims and \
                    scalar.group(1) in outer:
                out.recurrences.add(scalar.group(1))
        if self._float_statement(stmt, scope):
            out.ops += self._operators(stmt)
        for m in _CALL.finditer(stmt) if self.flatten else ():
            found = self.resolve(stmt, m, env)
            if found is None or depth > 24:
                continue
            close = _matching(stmt, stmt.index("(", m.end() - 1), "(", ")")
            args = _split_top(stmt[m.end():close])
            out.add(self.call(found[0], found[1], args, scope, outer, depth + 1))
        return out

    def _float_statement(self, stmt: str, scope: dict) -> bool:
        decl = _DECL.match(stmt + ";")
        if decl:
            return re.fullmatch(FLOAT_TYPES, decl.group("type").strip()) is not None
        lhs = re.match(r"^([A-Za-z_]\w*)\s*(?:\[.*?\]\s*)*[-+*/]?=(?!=)", stmt)
        if lhs:
            var = self._lookup(lhs.group(1), scope)
            return var is not None and var.is_float
        return stmt.startswith("return") and self.returns_float and \
            bool(re.search(r"[-+*/]", stmt))

    @staticmethod
    def _operators(stmt: str) -> Counter:
        ops: Counter = Counter()
        text = stmt
        while True:  # index arithmetic is integer: drop every subscript
            new = re.sub(r"\[[^\[\]]*\]", "", text)
            if new == text:
                break
            text = new
        text = re.sub(r"<[^<>;()]*>", "", text)  # template arguments
        text = re.sub(r"\b\d+(?:\.\d*)?(?:[eE][-+]?\d+)?f?\b", "1", text)
        ops["sqrt"] += len(_SQRT.findall(text))
        ops["special"] += len(_SPECIAL.findall(text))
        compound = re.match(r"^[A-Za-z_]\w*\s*([-+*/])=", text)
        if compound:
            ops[{"+": "add", "-": "add", "*": "mul", "/": "div"}[compound.group(1)]] += 1
        body = text.split("=", 1)[1] if re.search(r"[^=!<>]=[^=]", text) else text
        ops["mul"] += len(re.findall(r"(?<=[\w)\]\s])\*(?!=)", body))
        ops["div"] += len(re.findall(r"/(?!=)", body))
        ops["add"] += len(re.findall(r"(?<=[\w)\]])\s*[-+](?![-+=>])", body))
        return +ops

    def call(self, f: _Function, inner_env: dict[str, int], args: list[str], scope: dict,
             outer: frozenset, depth: int) -> _Count:
        inner_scope: dict = {}
        inner_outer = set()
        for param, arg in zip(f.params, args, strict=False):
            var = self._param_var(f, param)
            if var is None:
                continue
            base = re.match(r"^&?\s*([A-Za-z_]\w*)", arg)
            if (param.dims or param.pointer) and base:
                bound = self._lookup(base.group(1), scope)
                if bound is not None:
                    var = _Var(var.is_float, param.dims, bound.alias, bound.storage)
                    if bound.alias in outer or base.group(1) in outer:
                        inner_outer.add(bound.alias)
            inner_scope[param.name] = var
        key = (f.file, f.qualname, f.start, tuple(sorted(inner_env.items())),
               tuple(sorted((k, v.alias, v.storage) for k, v in inner_scope.items())),
               tuple(sorted(inner_outer)))
        if key not in self.memo:
            self.memo[key] = _Count()  # a call back into itself counts nothing more
            saved, self.returns_float = self.returns_float, re.search(
                rf"\b{FLOAT_TYPES}\b", f.ret) is not None
            where, self.where = self.where, _unit(f, self.where)
            try:
                result = self.count(f.text, inner_scope, dict(inner_env), None,
                                    frozenset(inner_outer), depth)
            finally:
                self.returns_float = saved
                self.where = where
            if self.allocation(f.text):  # its own module under ALLOCATION: counted apart
                capped = _Count(accesses=result.accesses, recurrences=result.recurrences,
                                rw=result.rw)
                capped.capped = {f.name: result.ops, **result.capped}
                result = capped
            self.memo[key] = result
        return self.memo[key]

    def resolve(self, text: str, m: re.Match, env: dict[str, int], file: str | None = None
                ) -> tuple[_Function, dict[str, int]] | None:
        """The function a call matched by ``_CALL`` in ``text`` runs, and its integer template
        arguments: ``f<...>(``, or ``S<...>::f(`` (a member of a struct template, its partial
        specialisation chosen where the arguments match it)."""
        owner = re.search(r"\b(\w+)\s*(<[^;{}()]*>)?\s*::\s*$", text[max(0, m.start() - 160):
                                                                     m.start()])
        struct = owner and env.get(f"type:{owner.group(1)}", owner.group(1))
        if owner and struct in self.structs:  # a member of a struct (else a namespace's)
            variants = self.members.get(f"{struct}::{m.group(1)}")
            if not variants:
                return None
            # the struct of this translation unit (each kernel defines its own LmConfig)
            variants = [v for v in variants if v[1].file == (file or self.where)] or variants
            args = _split_top(owner.group(2)[1:-1]) if owner.group(2) else []
            values = [self._value(a, env) for a in args]
            params = self.defaults.get(struct, ())
            types = self._bind_types(params, args, env)
            bound = {}
            for param, value in zip(params, values, strict=False):
                name = re.search(r"(\w+)\s*(?:=.*)?$", param)
                if name and value is not None:
                    bound[name.group(1)] = value
            for param in params[len(args):]:  # defaulted parameters, evaluated
                default = re.match(r"^\s*(?:bool|int)\s+(\w+)\s*=\s*\(?(.*?)\)?\s*$", param)
                if not default:
                    break
                value = self._value(default.group(2), {**env, **bound})
                if value is None:
                    truth = self._condition(default.group(2), {**env, **bound})
                    value = None if truth is None else int(truth)
                args.append(default.group(2))
                values.append(value)
                if value is not None:
                    bound[default.group(1)] = value
            chosen = next((f for spec, f in variants if spec is None), variants[0][1])
            for spec, f in variants:
                if spec is None or len(spec) != len(values):
                    continue
                # a specialisation's own parameters are wildcards: its arguments are read
                # with constants only
                if all(self._value(s, {}) in (None, v) or s.strip() == a.strip()
                       for s, a, v in zip(spec, args, values, strict=True)) and \
                        any(self._value(s, {}) is not None for s in spec):
                    chosen = f
                    break
            ints = [v for a, v in zip(args, values, strict=True) if v is not None]
            return chosen, {**dict(zip(chosen.template_ints, ints, strict=False)), **types}
        f = self.local.get(file or self.where, {}).get(m.group(1)) or \
            self.functions.get(m.group(1))
        if f is None:
            return None
        cenv: dict = {}
        if m.group(2):
            args = _split_top(m.group(2)[1:-1])
            params = self._template_params(f)
            cenv.update(self._bind_types(params, args, env))
            if f.template_ints:
                ints = [v for a in args if (v := self._value(a, env)) is not None]
                cenv.update(zip(f.template_ints, ints, strict=False))
        return f, cenv

    @staticmethod
    def _template_params(f: _Function) -> tuple[str, ...]:
        """The parameters of the ``template <...>`` that introduces ``f`` (none: ())."""
        start = max(f.code.rfind(c, 0, f.start) for c in ";{}")
        header = re.search(r"template\s*<([^{};]*?)>", f.code[start + 1:f.start])
        return tuple(_split_top(header.group(1))) if header else ()

    @staticmethod
    def _bind_types(params: tuple[str, ...], args: list[str], env: dict) -> dict:
        """``type:NAME`` -> the struct a class template parameter is bound to (namespaces
        dropped; a parameter passed on, the struct it is bound to)."""
        out = {}
        for param, arg in zip(params, args, strict=False):
            kind = re.match(r"^\s*(class|typename)\s+(\w+)", param)
            if kind:
                name = arg.strip().split("::")[-1].strip()
                out[f"type:{kind.group(2)}"] = env.get(f"type:{name}", name)
        return out

    @staticmethod
    def allocation(text: str) -> dict[str, int]:
        out = {}
        for m in re.finditer(r"#\s*pragma\s+HLS\s+ALLOCATION\s+operation\s+instances=(\w+)\s+"
                             r"limit=(\d+)", text, re.I):
            kind = _ALLOCATION_KINDS.get(m.group(1).lower())
            if kind:
                out[kind] = int(m.group(2))
        return out

    def function_allocation(self, text: str, env: dict[str, int]) -> dict[str, int]:
        """function name -> instances, from ``ALLOCATION function instances=<name> limit=<n>``
        pragmas in ``text`` (a template's name with or without its arguments)."""
        out = {}
        for m in re.finditer(r"#\s*pragma\s+HLS\s+ALLOCATION\s+function\s+instances=([\w:]+)"
                             r"\s*(?:<[^\n]*?>)?\s+limit=(\w+)", text, re.I):
            limit = self._value(m.group(2), env)
            if limit is not None and limit >= 0:
                out[m.group(1).split("::")[-1]] = limit
        return out

    # -- pipelined loops -------------------------------------------------------------------------
    def instantiations(self, f: _Function) -> list[dict[str, int]]:
        """The integer template arguments ``f`` is instantiated with (one binding per distinct
        instantiation; ``[{}]`` for a function that is not a template)."""
        if not f.template_ints:
            return [{}]
        seen: dict[tuple, dict[str, int]] = {}
        pattern = re.compile(rf"\b{f.name}\s*<([^;{{}}()]*?)>\s*\(")
        for caller in self.functions.values():
            for m in pattern.finditer(caller.text):
                args = [a for a in _split_top(m.group(1)) if self._value(a, {}) is not None]
                env = {name: self._value(a, {}) for name, a in
                       zip(f.template_ints, args, strict=False)}
                seen.setdefault(tuple(sorted(env.items())), env)
        return list(seen.values()) or [{}]

    def loops(self) -> list[LoopReading]:
        out = []
        for f in self.functions.values():
            for env in self.instantiations(f):
                out += self.loops_in(f, env)
        return sorted(out, key=lambda r: (r.file, r.line, r.template))

    def loops_in(self, f: _Function, env: dict[str, int]) -> list[LoopReading]:
        """The pipelined loops of ``f`` instantiated with the integer template arguments
        ``env`` (those of ``f``'s own parameters are kept)."""
        env = {k: v for k, v in env.items() if k in f.template_ints}
        code, (lo, hi) = f.code, f.body
        out = []
        for m in re.finditer(r"#\s*pragma\s+HLS\s+PIPELINE\b([^\n]*)", code[lo:hi], re.I):
            if "off" in m.group(1).lower():
                continue
            ii = re.search(r"II\s*=\s*(\w+(?:\s*::\s*\w+)*)", m.group(1))
            value = self._value(ii.group(1), env) if ii else 1
            reading = self.loop(f, lo + m.start(), value or 1, env)
            if reading is not None:
                # an II this text cannot evaluate (a configuration the design does not define)
                # is read at 1 for its operators and not judged
                out.append(reading if value else replace(reading, ii_known=False))
        return out

    def loop(self, f: _Function, pragma: int, ii: int, template: dict[str, int]
             ) -> LoopReading | None:
        where, self.where = self.where, _unit(f, self.where)
        try:
            return self._loop(f, pragma, ii, template)
        finally:
            self.where = where

    def _loop(self, f: _Function, pragma: int, ii: int, template: dict[str, int]
              ) -> LoopReading | None:
        code = f.code
        depth, open_ = 0, None
        for i in range(pragma - 1, f.body[0], -1):
            if code[i] == "}":
                depth += 1
            elif code[i] == "{":
                if depth == 0:
                    open_ = i
                    break
                depth -= 1
        if open_ is None:
            return None  # a function-level pipeline: not judged here
        header = re.search(r"\bfor\s*\(([^;]*);([^;]*);([^{]*)\)\s*$", code[f.body[0]:open_])
        if not header:
            return None
        close = _matching(code, open_, "{", "}")
        body = code[open_ + 1:close]
        var = re.search(r"(\w+)\s*=", header.group(1))
        scope: dict[str, _Var] = {}
        for p in f.params:
            v = self._param_var(f, p)
            if v is not None:
                scope[p.name] = v
        # blocks closed before the loop declare nothing that lives into it
        before = _own_level(code[f.body[0] + 1:open_])
        for name, (is_float, dims) in self._declarations(before).items():
            scope[name] = _Var(is_float, dims, name, "local")
        outer = frozenset({v.alias for v in scope.values()} | set(self.globals))
        env: dict[str, int] = dict(template)
        for c in re.finditer(r"(?:^|[;{}])\s*(?:static\s+)?const\s+int\s+(\w+)\s*=\s*([^;,]+);",
                             before):
            value = self._value(c.group(2), env)
            if value is not None:
                env[c.group(1)] = value
        count = self.count(body, scope, env, var.group(1) if var else None, outer)
        limits = self.allocation(f.text)
        instances: Counter = Counter()
        for kind, n in count.ops.items():
            need = math.ceil(n / ii)
            instances[kind] += min(need, limits[kind]) if kind in limits else need
        for name, ops in count.capped.items():
            cap = self.allocation(self.functions[name].text) if name in self.functions else {}
            for kind, n in ops.items():
                need = math.ceil(n / ii)
                instances[kind] += min(need, cap[kind]) if kind in cap else need
        def dims_here(name):
            var = scope.get(name) or self.globals.get(name)
            return var.dims if var is not None else None

        banks_here = {scope[name].alias if name in scope else name: banks
                      for name, banks in self._banks(f.text, env, dims_here).items()}
        accesses, ii_ports = [], 1
        for array, n in sorted(count.accesses.items()):
            banks = banks_here.get(array, self.global_banks.get(array, 1))
            if banks is None:
                continue  # registers
            accesses.append((array, n, banks))
            ii_ports = max(ii_ports, math.ceil(n / (2 * banks)))
        free = set(re.findall(r"DEPENDENCE\s+variable\s*=\s*(\w+)[^\n]*inter\s+false", body,
                              re.I))
        free |= {scope[name].alias for name in free if name in scope}
        # DEPENDENCE ... inter true distance=D: the element comes back D iterations later, so
        # the recurrence through the adder allows II ceil(latency / D)
        distance: dict[str, int] = {}
        for d in re.finditer(r"DEPENDENCE\b([^\n]*)", body, re.I):
            args = d.group(1)
            name = re.search(r"variable\s*=\s*(\w+)", args)
            dist = re.search(r"distance\s*=\s*(\w+(?:\s*::\s*\w+)*)", args)
            if name and dist and re.search(r"inter\s+true", args, re.I):
                value = self._value(dist.group(1), env)
                if value is not None and value > 0:
                    for n in {name.group(1), scope[name.group(1)].alias if name.group(1) in
                              scope else name.group(1)}:
                        distance[n] = value
        for alias, uses in count.rw.items():
            kinds = {k for k, _ in uses}
            if kinds == {"r", "w"} and any(fixed for _, fixed in uses):
                count.recurrences.add(alias)
        carried = tuple(sorted(r for r in count.recurrences if r not in free))
        ii_recurrence = max([0] + [math.ceil(self.add_latency / distance[r]) if r in distance
                                   else self.add_latency for r in carried])
        label = re.search(r'FGC_CYCLES\(\s*"(\w+)"', code[close:close + 400])
        return LoopReading(
            file=f.file, line=_line(code, pragma), function=f.name,
            template=tuple(sorted(template.items())),
            label=label.group(1) if label else None, ii=ii,
            ops=tuple(sorted(count.ops.items())), instances=tuple(sorted(instances.items())),
            accesses=tuple(accesses), ii_ports=ii_ports, recurrence=carried,
            ii_recurrence=ii_recurrence)


@dataclass(frozen=True)
class DesignReading:
    """The design's operators as Vitis would instantiate them: every call site its own module
    instance (an unrolled call once per copy), a pipelined loop's operators as its reading
    says, a function's sequential code at least one operator of each kind it uses (or its
    ALLOCATION limit where that is lower than its operations). A lower bound: the scheduler may
    use more in sequential code, never fewer in a pipelined loop."""

    top: str
    loops: tuple[LoopReading, ...]
    operators: tuple[tuple[str, int], ...]  # operator instances by kind, the whole design
    modules: tuple[tuple[str, int], ...]  # function -> RTL instances
    # file -> operator instances by kind of the functions defined there (their own code and
    # pipelined loops; a callee's in its own file)
    by_file: tuple[tuple[str, tuple[tuple[str, int], ...]], ...] = ()
    reached: tuple[tuple[str, str], ...] = ()  # (file, function) of what the top instantiates

    @property
    def reached_loops(self) -> tuple[LoopReading, ...]:
        """The pipelined loops of the functions the top instantiates (``loops`` also reads
        those of the headers' other functions)."""
        mine = set(self.reached)
        return tuple(r for r in self.loops if (r.file, r.function) in mine)

    def dsp(self, dsp_of: dict[str, int], files: Iterable[str] | None = None) -> int:
        """DSP of the whole design, or of the functions defined in ``files``."""
        if files is None:
            return sum(n * dsp_of.get(kind, 0) for kind, n in self.operators)
        wanted = set(files)
        return sum(n * dsp_of.get(kind, 0) for file, ops in self.by_file if file in wanted
                   for kind, n in ops)


def _unit(f: _Function, unit: str | None) -> str | None:
    """The translation unit ``f`` is read in: its own file if it is a .cpp (a kernel), else
    (a header's function) the unit that reached it."""
    return f.file if f.file.endswith(".cpp") else unit


def _design(reader: _Reader, top: str) -> DesignReading:
    # the pipelined loops of each function as the design instantiates it (a template reached
    # through a struct's member, cpe_cascade<CFG, K>::run calling cpe<CFG, K>, with K bound
    # there); the loops of functions the top never reaches as their own call sites bind them
    readings: dict[tuple, list[LoopReading]] = {}

    def loops_of(f: _Function, env: dict[str, int], unit: str | None) -> list[LoopReading]:
        key = (f.file, f.start, tuple(sorted((k, v) for k, v in env.items()
                                             if k in f.template_ints)), unit)
        if key not in readings:
            reader.where = unit
            readings[key] = reader.loops_in(f, env)
        return readings[key]

    operators: Counter = Counter()
    modules: Counter = Counter()
    visited: set[tuple[str, str]] = set()
    by_file: dict[str, Counter] = {}

    def own(f: _Function, env: dict[str, int], unit: str | None) -> Counter:
        reader.flatten = False
        reader.where = unit
        reader.returns_float = re.search(rf"\b{FLOAT_TYPES}\b", f.ret) is not None
        try:
            count = reader.count(f.text, {p.name: v for p in f.params
                                          if (v := reader._param_var(f, p)) is not None},
                                 dict(env), None, frozenset())
        finally:
            reader.flatten = True
        limits = reader.allocation(f.text)
        return Counter({k: min(limits.get(k, 1), n) for k, n in count.ops.items() if n})

    def visit(f: _Function, env: dict[str, int], mult: int, depth: int,
              unit: str | None = None) -> None:
        if depth > 400 or mult == 0:  # a template recursion (a cascade of 80 CPEs) is deep
            return
        modules[f.qualname] += mult
        seq: Counter = Counter()  # the sequential code's operators, its INLINE callees' merged
        walk(f, env, mult, depth, seq, unit)
        here = by_file.setdefault(f.file, Counter())
        for kind, n in seq.items():
            operators[kind] += n * mult
            here[kind] += n * mult

    def walk(f: _Function, env: dict[str, int], mult: int, depth: int, seq: Counter,
             unit: str | None) -> None:
        """``f``'s code into the module being read: its sequential operators into ``seq``
        (an INLINE callee's join its caller's: one RTL body), its pipelined loops' and its
        other callees' instances apart."""
        visited.add((f.file, f.name))
        unit = _unit(f, unit)
        for kind, n in own(f, env, unit).items():
            seq[kind] = max(seq[kind], n)
        here = by_file.setdefault(f.file, Counter())
        for r in loops_of(f, env, unit):
            for kind, n in r.instances:
                operators[kind] += n * mult
                here[kind] += n * mult
        # ALLOCATION function instances=g limit=n in f: f's call sites of g share n instances
        left = dict(reader.function_allocation(f.text, env))
        for callee, cenv, times in calls(f.text, env, unit):
            if callee.name in left:
                times = min(times, left[callee.name])
                left[callee.name] -= times
            if callee.inline and depth <= 400:
                walk(callee, cenv, mult * times, depth + 1, seq, unit)
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
    visit(reader.functions[top], {}, 1, 0)
    reached = {(file, name) for file, name in visited}
    loops = sorted({*(r for rs in readings.values() for r in rs),
                    *(r for r in reader.loops() if (r.file, r.function) not in reached)},
                   key=lambda r: (r.file, r.line, r.template))
    return DesignReading(top, tuple(loops), tuple(sorted(operators.items())),
                         tuple(sorted(modules.items())),
                         tuple(sorted((file, tuple(sorted(c.items())))
                                      for file, c in by_file.items())),
                         tuple(sorted(reached)))


def read_design(files: Iterable[tuple[str, str]], top: str, add_latency: int
                ) -> DesignReading:
    """The whole design under ``top`` as Vitis would instantiate it (:class:`DesignReading`)."""
    return _design(_Reader(files, add_latency), top)


def read_project(files: Iterable[tuple[str, str]], add_latency: int) -> list[LoopReading]:
    """Every pipelined loop of the synthesised ``files`` ((name, text) pairs) as Vitis would
    bind and schedule it; ``add_latency``: the adder's stages (a carried sum's II)."""
    return _Reader(files, add_latency).loops()


def check(readings: Iterable[LoopReading]) -> list[LintIssue]:
    """A loop whose declared II is below what its memories or recurrences allow."""
    issues = []
    for r in readings:
        if not r.ii_known:
            continue
        args = ", ".join(f"{k}={v}" for k, v in r.template)
        where = f"'{r.label or r.function}' (in {r.function}{f'<{args}>' if args else ''})"
        if r.ii_ports > r.ii:
            worst = max(r.accesses, key=lambda a: math.ceil(a[1] / (2 * a[2])))
            issues.append(LintIssue(r.file, r.line, "ii_ports", f"loop {where} declares II={r.ii}"
                                    f" but array '{worst[0]}' takes {worst[1]} accesses an "
                                    f"iteration through {2 * worst[2]} ports: II >= "
                                    f"{r.ii_ports}"))
        if r.ii_recurrence > r.ii:
            issues.append(LintIssue(r.file, r.line, "ii_recurrence", f"loop {where} declares "
                                    f"II={r.ii} but reads and writes "
                                    f"{', '.join(repr(x) for x in r.recurrence)} every "
                                    "iteration without 'DEPENDENCE inter false': II >= "
                                    f"{r.ii_recurrence}"))
    # one issue per loop and rule (the instantiations of a template share the text)
    seen, out = set(), []
    for issue in issues:
        if (issue.file, issue.line, issue.rule) not in seen:
            seen.add((issue.file, issue.line, issue.rule))
            out.append(issue)
    return out


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
