"""Operator, access and recurrence counting: a block's statements run once, constant-bound
inner loops unrolled and the project functions it calls read in place (:class:`_Counter`)."""

from __future__ import annotations

import re
from collections import Counter

from fgc_backends.hls.lint.cxx import (
    _Function,
    _matching,
    _split_top,
    statement_end,
)
from fgc_backends.hls.reader.expr import ExpressionTyper
from fgc_backends.hls.reader.scope import _Scope
from fgc_backends.hls.reader.text import (
    _CALL,
    _CONTROL,
    _DECL,
    _SPECIAL,
    _SQRT,
    _SUBSCRIPTED,
    FLOAT_TYPES,
    _Count,
    _own_level,
    _pipelined,
    _subscripts,
    _unit,
    _Var,
    library_calls,
    until_fixed,
)

_RETURNS = re.compile(r"(?:^|[;{}])\s*return\b[^;]*;\s*$")  # a block that ends in a return


class _Counter(_Scope):
    """The operations, array accesses and carried read-modify-writes of a block
    of text run once."""
    # -- counting ----------------------------------------------------------------------------
    def count(self, text: str, scope: dict, env: dict[str, int], loop_var: str | None,
              outer: frozenset, depth: int = 0) -> _Count:
        """The operations, accesses and recurrences of ``text`` (a block's contents) run once,
        inner constant-bound loops unrolled; ``outer``: names that live across iterations of
        the pipelined loop (a read-modify-write of one of them is carried)."""
        total = _Count()
        pos, n = 0, len(text)
        taken: bool | None = None  # the last if's condition, when the template fixes it
        chain: _Count = _Count()  # the largest branch so far of the current if / else chain
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
                # the condition's floating-point operators, evaluated every iteration
                test = _Count.of(self._typer(scope).operators(header[1])) \
                    if len(header) == 3 else _Count()
                if values is None:
                    trips = self._tripcount(body, env) or 1
                    total.add(self.count(body, scope, env, loop_var, outer, depth), trips)
                    total.add(test, trips)
                    continue
                var, seq = values
                total.add(test, len(seq))
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
                chain = _Count()
                if taken is not False:
                    chain = self.count(body, scope, env, loop_var, outer, depth)
                    total.add(chain)
                    if taken is None and _RETURNS.search(_own_level(body)) and \
                            not re.match(r"\s*else\b", text[pos:]):
                        # `if (c) { ...; return; } rest`: the rest is the branch's else
                        rest = self.count(text[pos:], scope, env, loop_var, outer, depth)
                        total.add(rest)
                        _exclusive(total, chain, rest)
                        break
                continue
            if word == "else":
                body, pos = self._body(text, m.end())
                if taken is not True:  # a branch known taken: its else is never built
                    other = self.count(body, scope, env, loop_var, outer, depth)
                    total.add(other)
                    chain = _exclusive(total, chain, other)
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

    def _tripcount(self, body: str, env: dict[str, int]) -> int | None:
        m = re.match(r"\s*#\s*pragma\s+HLS\s+LOOP_TRIPCOUNT\s+max\s*=\s*([\w:]+)", body)
        return self._value(m.group(1), env) if m else None

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
        loads = set()  # (array, subscript) read in this statement
        for m in _SUBSCRIPTED.finditer(stmt):
            var = self._lookup(m.group(1), scope)
            if var is None or var.storage == "stream":
                continue
            op = (m.group(3) or "").strip()
            if var.storage == "global":
                # a word read twice in one statement (`n == 1 ? T(-bank[j][l]) : bank[j][l]`)
                # is one load: the front end merges loads of one address with no store between
                load = (var.alias, re.sub(r"\s+", "", m.group(2)))
                if op != "" or load not in loads:
                    out.accesses[var.alias] += 1 + (op not in ("", "="))
                if op == "":
                    loads.add(load)
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
            own = self._operators(stmt, scope)
        else:  # a condition, a call's arguments, an integer's initialiser: typed operands
            own = self._typer(scope).operators(stmt)
        out.ops += own
        out.peak += own
        for m in _CALL.finditer(stmt) if self.flatten else ():
            found = self.resolve(stmt, m, env)
            if found is None or depth > 24:
                continue
            out.calls[found[0].name] += 1
            close = _matching(stmt, stmt.index("(", m.end() - 1), "(", ")")
            args = _split_top(stmt[m.end():close])
            out.add(self.call(found[0], found[1], args, scope, outer, depth + 1))
        return out

    def _typer(self, scope: dict) -> ExpressionTyper:
        def is_float(name: str, indices: int) -> bool:
            var = self._lookup(name, scope)
            return var is not None and var.is_float and indices >= len(var.dims)

        return ExpressionTyper(is_float, self._float_call, self.functions)

    def _float_call(self, name: str) -> bool:
        """Whether the project function (or struct member) ``name`` returns a floating-point
        value."""
        f = self.local.get(self.where, {}).get(name) or self.functions.get(name)
        if f is None:
            if not hasattr(self, "_member_rets"):
                self._member_rets: dict[str, str] = {}
                for qual, variants in self.members.items():
                    self._member_rets.setdefault(qual.split("::")[-1], variants[0][1].ret)
            ret = self._member_rets.get(name)
        else:
            ret = f.ret
        return ret is not None and re.search(rf"\b{FLOAT_TYPES}\b", ret) is not None

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

    def _operators(self, stmt: str, scope: dict) -> Counter:
        ops: Counter = Counter()
        # a square printed as a product of two copies, (e)*(e): the compiler's front end
        # computes e once (common subexpressions of a statement are merged), so the second
        # copy's operators are not built: it is read as an operand (e may hold calls and
        # groups of its own: (sin((0.5)*c))*(sin((0.5)*c)))
        text = _merge_squares(stmt)
        # a ternary's condition (``c + h < f ? x[c + h] : L(0)``) is not the statement's
        # floating-point value: its operators are typed by their operands' declarations
        text, conditions = _ternary_conditions(text)
        typer = self._typer(scope)
        for condition in conditions:
            ops += typer.operators(condition)
        # index arithmetic is integer: drop every subscript
        text = until_fixed(r"\[[^\[\]]*\]", "", text)
        text = re.sub(r"<[^<>;()]*>", "", text)  # template arguments
        text = re.sub(r"\b\d+(?:\.\d*)?(?:[eE][-+]?\d+)?f?\b", "1", text)
        ops["sqrt"] += library_calls(_SQRT, text, self.functions)
        ops["special"] += library_calls(_SPECIAL, text, self.functions)
        compound = re.match(r"^[A-Za-z_]\w*\s*([-+*/])=", text)
        if compound:
            ops[{"+": "add", "-": "add", "*": "mul", "/": "div"}[compound.group(1)]] += 1
        body = text.split("=", 1)[1] if re.search(r"[^=!<>]=[^=]", text) else text
        body = re.sub(r"^\s*return\b", "", body)  # `return -x`: a sign, not a subtraction
        # a multiply follows an operand (``= *scale`` dereferences a pointer)
        ops["mul"] += len(re.findall(r"(?<=[\w)\]])\s*\*(?!=)", body))
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
            caller, self.scalar = self.scalar, self.scalar_of(f, inner_env)
            try:
                result = self.count(f.text, inner_scope, dict(inner_env), None,
                                    frozenset(inner_outer), depth)
            finally:
                self.returns_float = saved
                self.where = where
                self.scalar = caller
            if self.allocation(f.text):  # its own module under ALLOCATION: counted apart
                capped = _Count(accesses=result.accesses, recurrences=result.recurrences,
                                rw=result.rw, calls=result.calls)
                capped.capped = {f.name: result.ops, **result.capped}
                capped.capped_peak = {f.name: result.peak, **result.capped_peak}
                result = capped
            self.memo[key] = result
        scalar = self.scalar_of(f, inner_env)
        if scalar != self.scalar:  # a callee in another scalar (the float state update a
            # double solver's loop calls): its own operators typed as its scalar's
            return _retyped(self.memo[key], scalar or self.scalars.get("T", ""))
        return self.memo[key]


def _retyped(count: _Count, scalar: str) -> _Count:
    """``count`` with its untyped operator kinds typed ``kind:scalar`` (kinds already typed,
    a callee's own, kept)."""
    def typed(c: Counter) -> Counter:
        return Counter({(k if ":" in k else f"{k}:{scalar}"): n for k, n in c.items()})

    return _Count(ops=typed(count.ops), capped={k: typed(v) for k, v in count.capped.items()},
                  accesses=count.accesses, recurrences=count.recurrences, rw=count.rw,
                  peak=typed(count.peak),
                  capped_peak={k: typed(v) for k, v in count.capped_peak.items()},
                  calls=count.calls)


def _merge_squares(text: str) -> str:
    """``text`` with every copy after the first of a power ``(e)*(e)[*(e)…]`` (a parenthesised
    group, not a call's arguments, times the same group) read as an operand ``q``."""
    start = 0
    while (i := text.find("(", start)) >= 0:
        start = i + 1
        if i and (text[i - 1].isalnum() or text[i - 1] == "_"):
            continue  # a call's arguments
        j = _matching(text, i, "(", ")")
        after = j + 1
        while (m := _TIMES_GROUP.match(text, after)) is not None:  # (e)*(e)*(e): a cube
            k = m.end() - 1
            end = _matching(text, k, "(", ")")
            if text[i + 1:j] != text[k + 1:end]:
                break
            text = text[:k] + "q" + text[end + 1:]
            after = k + 1
    return text


_TIMES_GROUP = re.compile(r"\s*\*\s*\(")


def _exclusive(total: _Count, chain: _Count, other: _Count) -> _Count:
    """``total`` holds both branches ``chain`` (an if / else chain's largest so far) and
    ``other`` (its next branch) summed; its peak is set to hold their largest instead. Returns
    the chain's new largest branch."""
    largest = _Count(peak=chain.peak | other.peak)
    total.peak -= chain.peak & other.peak
    for name in set(chain.capped_peak) | set(other.capped_peak):
        a = chain.capped_peak.get(name, Counter())
        b = other.capped_peak.get(name, Counter())
        largest.capped_peak[name] = a | b
        total.capped_peak[name] = total.capped_peak.get(name, Counter()) - (a & b)
    return largest


def _ternary_conditions(text: str) -> tuple[str, list[str]]:
    """``text`` with the condition of every ternary ``c ? a : b`` cut out (``0`` and a mark in
    its place), and the conditions: each from the ``?`` back to the start of its operand (an
    open bracket, a ``,``, an assignment's ``=``, another ternary's ``:``)."""
    conditions = []
    while True:
        q = text.find("?")
        if q < 0:
            return text, conditions
        depth, i = 0, q - 1
        while i >= 0:
            ch = text[i]
            if ch in ")]":
                depth += 1
            elif ch in "([":
                if depth == 0:
                    break
                depth -= 1
            elif depth == 0 and _operand_starts(text, i):
                break
            i -= 1
        conditions.append(text[i + 1:q])
        text = text[:i + 1] + " 0 \x03" + text[q + 1:]


def _operand_starts(text: str, i: int) -> bool:
    """Whether ``text[i]`` (at the level of the ``?``) ends what precedes a ternary's operand:
    a ``,``, an assignment's ``=`` (not ``==``, ``<=``, ...), another ternary's ``:`` (not a
    ``::``)."""
    ch, before, after = text[i], text[i - 1:i], text[i + 1:i + 2]
    return ch == "," or (ch == "=" and after != "=" and before not in ("=", "!", "<", ">")) \
        or (ch == ":" and ":" not in (before, after))
