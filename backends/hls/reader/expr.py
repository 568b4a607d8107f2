"""Floating-point operators of an expression outside a floating-point statement: an ``if`` or
loop condition, a ternary's condition, a call's arguments (``out.write(tau * s)``), the
initialiser of an integer or boolean, the ``return`` of a function that does not return a
floating-point value. A floating-point statement (``T x = ...``, ``x[i] += ...``) counts every
operator of its right-hand side (:meth:`_Counter._operators`); here each operator is typed by
its operands, as C's usual arithmetic conversions do: ``*`` / ``/`` / ``+`` / ``-`` is a
floating-point operator when either operand is floating-point (a float variable or array, a
float literal, a cast to a float type, a float-returning call). Comparisons and logical
operators yield integers (a float compare binds no DSP); a ternary builds both branches.
An operand the reader cannot type (a struct member, a stream's read) is taken as an integer: a
lower bound, like the rest of the reader."""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Callable

from fgc_backends.hls.reader.text import (
    _SPECIAL,
    _SQRT,
    FLOAT_TYPES,
    library_calls,
    until_fixed,
)

_FLOAT, _INT = "\x01F", "\x01I"  # a group already read: floating-point or not
_INDEX = "\x02"  # a subscript (x[i][j]: x and two marks)
# a call (its name, qualified or a member: vin.read, CFG::root), a cast T(x) or parentheses,
# innermost first
_GROUP = re.compile(r"((?<![\w.])(?:[A-Za-z_]\w*\s*(?:\.|::|->)\s*)*[A-Za-z_]\w*\s*)?"
                    r"\(([^()]*)\)")
_NUMBER = re.compile(r"(?<![\w.])(\d+\.\d*|\.\d+|\d+)([eE][-+]?\d+)?([fF]|[uUlL]*)(?![\w.])")
_LVALUE = re.compile(r"^[\w.\s\x02]*?(?:[-+*/%&|^]|<<|>>)?=(?!=)")  # `[const bool] x =`, `k +=`
_NOT_CALLS = {"if", "for", "while", "switch", "return", "sizeof"}


def _split(text: str, ops: str) -> tuple[list[str], list[str]]:
    """``text`` split at the binary operators ``ops`` (a regex alternation) at its own level
    (groups are already placeholders): the operands and the operators between them. An
    operator is binary when an operand ends just before it (``a - b``, not ``-b`` or ``a * -b``).
    """
    parts, seps, last = [], [], 0
    for m in re.finditer(ops, text):
        before = text[last:m.start()].rstrip()
        if not before or before[-1] in "+-*/%<>=!&|?:^~,":
            continue  # unary, or the second character of another operator
        parts.append(text[last:m.start()])
        seps.append(m.group(0))
        last = m.end()
    parts.append(text[last:])
    return parts, seps


class ExpressionTyper:
    """Types and counts an expression's floating-point operators. ``is_float(name, indices)``:
    whether a variable subscripted ``indices`` times is a floating-point value (an array named
    without all its subscripts is a pointer: ``raw + 480`` is address arithmetic);
    ``float_call(name)``: whether a function named so returns a floating-point value;
    ``defined``: the project's function names (a square root or special function the project
    defines is counted where its body is read, not where it is called)."""

    def __init__(self, is_float: Callable[[str, int], bool],
                 float_call: Callable[[str], bool | None], defined=frozenset()):
        self.is_float = is_float
        self.float_call = float_call
        self.defined = defined  # the project's functions (read in place where called)

    def operators(self, expr: str) -> Counter:
        ops: Counter = Counter()
        # index arithmetic is integer: each subscript becomes a mark on its name
        text = until_fixed(r"\[[^\[\]]*\]", _INDEX, expr)
        text = re.sub(r"(?<=\w)<[^<>;()]*>(?=\s*[(:])", "", text)  # template arguments
        text = re.sub(r"^\s*return\b", "", text)
        ops["sqrt"] += library_calls(_SQRT, text, self.defined)
        ops["special"] += library_calls(_SPECIAL, text, self.defined)
        text = _NUMBER.sub(lambda m: _FLOAT if m.group(2) or "." in m.group(1) or
                           m.group(3) in ("f", "F") else "1", text)
        while True:  # innermost groups first: calls, casts, parentheses
            m = _GROUP.search(text)
            if not m:
                break
            name = re.sub(r"\s+", "", m.group(1) or "")
            is_float = False
            for arg in m.group(2).split(","):
                f, o = self._typed(arg)
                ops += o
                is_float = is_float or f
            short = re.split(r"\.|::|->", name)[-1]
            if short and short not in _NOT_CALLS:
                is_float = re.fullmatch(FLOAT_TYPES, name) is not None or \
                    re.fullmatch(FLOAT_TYPES, short) is not None or \
                    _SQRT.match(name + "(") is not None or \
                    _SPECIAL.match(name + "(") is not None or bool(self.float_call(short))
            text = text[:m.start()] + (_FLOAT if is_float else _INT) + text[m.end():]
        for part in text.split(","):  # declarators; an initialiser's right-hand side
            ops += self._typed(_LVALUE.sub("", part, count=1))[1]
        return +ops

    def _typed(self, text: str) -> tuple[bool, Counter]:
        """(floating-point, operators) of a flat expression (no parentheses left)."""
        ops: Counter = Counter()
        text = re.sub(r"\b[A-Za-z_]\w*\s*::\s*", "", text).strip()  # CFG::EPS: EPS
        if "?" in text:  # c ? a : b (right-associative: the first '?' is the outermost)
            cond, rest = text.split("?", 1)
            f, o = self._typed(cond)
            ops += o
            is_float = False
            for b in rest.split(":", 1):
                f, o = self._typed(b)
                ops += o
                is_float = is_float or f
            return is_float, ops
        parts, seps = _split(text, r"&&|\|\||==|!=|<=|>=|<<|>>|<|>|&|\||\^")
        if seps:  # comparisons and logic: integers (a float compare binds no DSP)
            for p in parts:
                ops += self._typed(p)[1]
            return False, ops
        return self._arith(text, ops)

    def _arith(self, text: str, ops: Counter) -> tuple[bool, Counter]:
        terms, adds = _split(text, r"[-+]")
        acc = None
        for i, term in enumerate(terms):
            factors, muls = _split(term, r"[*/%]")
            f_acc = self._atom(factors[0])
            for op, factor in zip(muls, factors[1:], strict=True):
                f = self._atom(factor)
                if op != "%" and (f_acc or f):
                    ops["mul" if op == "*" else "div"] += 1
                f_acc = f_acc or f
            if i == 0:
                acc = f_acc
            else:
                if acc or f_acc:
                    ops["add"] += 1
                acc = acc or f_acc
        return bool(acc), ops

    def _atom(self, text: str) -> bool:
        word = text.strip().lstrip("-+!~ ").strip()
        if word == _FLOAT:
            return True
        if word == _INT or not word:
            return False
        name = re.fullmatch(r"([A-Za-z_]\w*)\s*(\x02*)", word)
        return bool(name) and self.is_float(name.group(1), len(name.group(2)))
