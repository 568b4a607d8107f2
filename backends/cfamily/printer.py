"""The HLS backend's sympy printer: the only place that knows C++ expression syntax.

:class:`HlsCodePrinter` prints kernel expressions for a scalar type named ``T`` (a ``typedef`` in
the emitted header: ``float``, ``double`` or ``ap_fixed<W,I>``). Every literal is wrapped as
``T(...)`` so no arithmetic silently happens in ``double`` (or in ``int``) when ``T`` is
``float``; integer powers become products, square roots and trigonometry become calls of the
``fgc_*`` wrappers in the emitted header, and fgc's special functions (``lie_A`` … ``lie_D1``,
``so3_log_x/y/z``) become calls of the inline functions emitted beside them. Symbols print only
through a caller-given table (inputs → ``in[i]``, intermediates → ``t<i>``), so no user-chosen
name ever reaches C++. Anything else is refused with :class:`UnsupportedExpressionError` before g++
could see it.

Given an operator table's latencies (``print_kernel(..., latencies=...)``, the HLS design's), every
n-ary sum and product is printed as the reduction tree the plan's critical path prices
(:mod:`fgc_backends.cfamily.trees`: one pairing rule for both), parenthesised, since Vitis does not
reassociate floating-point operations; without them the text is flat (the native backend's).
"""

from __future__ import annotations

import functools
from collections import Counter
from collections.abc import Iterable, Sequence
from typing import NamedTuple

import sympy as sp
from sympy.printing.cxx import CXX17CodePrinter
from sympy.printing.precedence import PRECEDENCE, precedence

from fgc.compiler.kernel import OP_KINDS, Kernel
from fgc.errors import FgcError
from fgc.frontend.geometry import special
from fgc_backends.cfamily.trees import MAX_PRODUCT_POWER as _MAX_PRODUCT_POWER
from fgc_backends.cfamily.trees import TRIG as _TRIG
from fgc_backends.cfamily.trees import ReadyTimes, pairing, signed_tree_text, tree_text
from fgc_backends.cfamily.trees import mul_parts as _mul_parts
from fgc_backends.cfamily.trees import power_terms as _power_terms
from fgc_backends.cfamily.trees import printable_power as _printable_power

# one C++ wrapper per function of the DSL's whitelist (fgc.frontend.functions.FUNCTIONS) and per
# function
# its derivatives introduce (sign, from Abs); tests/frontend/test_functions.py prints each
_FUNCTIONS = {sp.sin: "fgc_sin", sp.cos: "fgc_cos", sp.tan: "fgc_tan", sp.atan2: "fgc_atan2",
              sp.atan: "fgc_atan", sp.exp: "fgc_exp", sp.log: "fgc_log", sp.asin: "fgc_asin",
              sp.acos: "fgc_acos", sp.tanh: "fgc_tanh", sp.Abs: "fgc_abs", sp.sign: "fgc_sign"}


class UnsupportedExpressionError(FgcError):
    """A kernel holds an expression the HLS backend cannot print (named in the message)."""


class PrintedKernel(NamedTuple):
    """A kernel as C++ statements: ``intermediates`` are ``const T tK = …;`` lines in dependency
    order, ``outputs`` the right-hand sides of ``out[i] = …;`` (one per kernel output)."""

    intermediates: tuple[str, ...]
    outputs: tuple[str, ...]
    total_ops: int


class HlsCodePrinter(CXX17CodePrinter):
    """C++17 printer for scalar type ``T``; ``symbols`` maps every free symbol to its C++ text."""

    printmethod = "_hlscode"

    def __init__(self, symbols: dict[sp.Symbol, str], settings: dict | None = None,
                 checked: bool = False, vector: bool = False, latencies=None):
        super().__init__({"strict": True, **(settings or {})})
        self.symbol_names = dict(symbols)
        self.checked = checked  # the caller ran check_supported on everything it will print
        self.call = "v_" if vector else ""  # lane-wise versions of the functions on V
        # ``latencies`` (kind → cycles): every sum and product printed as the reduction tree
        # its critical path is priced with (trees.pairing, operands by ready time); None: flat,
        # left to right (the native backend's CPU code)
        self.ready = None if latencies is None else ReadyTimes(latencies)

    def doprint(self, expr, assign_to=None) -> str:
        """C++ text of ``expr``; refuses anything outside the whitelist (sympy's C++ printer
        would happily print ``std::abs`` and friends, in double)."""
        if not self.checked:
            check_supported([expr], "expression")
        return super().doprint(expr, assign_to)

    # -- atoms ----------------------------------------------------------------------------
    def _print_Symbol(self, expr: sp.Symbol) -> str:
        try:
            return self.symbol_names[expr]
        except KeyError:
            raise UnsupportedExpressionError(
                f"kernel uses a symbol that is neither an input nor an intermediate "
                f"({sp.srepr(expr)[:80]})") from None

    def literal(self, value: float | int) -> str:
        """A number as a ``T`` literal that reads back exactly in double (``repr``)."""
        value = float(value)
        if value != value or value in (float("inf"), float("-inf")):
            raise UnsupportedExpressionError(f"non-finite constant {value} in a kernel")
        return f"T({value!r})"

    def horner(self, coeffs: Sequence[float], var: str) -> str:
        """``c0 + var*(c1 + var*(…))`` for ascending coefficients ``coeffs``."""
        text = self.literal(coeffs[-1])
        for c in reversed(coeffs[:-1]):
            text = f"{self.literal(c)} + {var}*({text})"
        return text

    def _print_Integer(self, expr: sp.Integer) -> str:
        return f"T({int(expr)})" if int(expr) >= 0 else f"(-T({-int(expr)}))"

    def _print_Rational(self, expr: sp.Rational) -> str:
        text = self.literal(float(expr))
        return text if expr >= 0 else f"({text})"

    def _print_Float(self, expr: sp.Float) -> str:
        text = self.literal(float(expr))
        return text if expr >= 0 else f"({text})"

    def _print_NumberSymbol(self, expr) -> str:
        return self.literal(float(expr))

    _print_Pi = _print_Exp1 = _print_NumberSymbol

    def _print_Zero(self, expr) -> str:
        return "T(0)"

    def _print_One(self, expr) -> str:
        return "T(1)"

    def _print_NegativeOne(self, expr) -> str:
        return "(-T(1))"

    def _print_Half(self, expr) -> str:
        return "T(0.5)"

    # -- operations -----------------------------------------------------------------------
    def _print_Pow(self, expr: sp.Pow) -> str:
        base, exp = expr.base, expr.exp
        if not _printable_power(exp):
            raise UnsupportedExpressionError(f"the HLS backend prints only integer and "
                                             f"half-integer powers up to {_MAX_PRODUCT_POWER} "
                                             f"in magnitude, not {expr}")
        # b**(n/2) = sqrt(b) * b**((n-1)/2): one square root and a product of multiplies
        whole, root, inverse = _power_terms(exp)
        factor = self.parenthesize(base, 100)
        terms = [factor] * whole
        if root:
            terms.insert(0, f"{self.call}fgc_sqrt({self._print(base)})")
        if exp == sp.Rational(1, 2):
            return terms[0]
        if exp == -sp.Rational(1, 2):
            return f"(T(1)/{terms[0]})"
        if self.ready is None:
            product = "*".join(terms)
        else:  # the copies as a tree (trees.ReadyTimes prices the same terms)
            t = self.ready(base)
            times = [t + self.ready.lat["sqrt"]] * root + [t] * whole
            product = tree_text(terms, pairing(times, self.ready.lat["mul"])[0], "*")
        return f"({product})" if not inverse else f"(T(1)/({product}))"

    def _print_Add(self, expr: sp.Add, order=None) -> str:
        if self.ready is None:
            return super()._print_Add(expr, order)
        # the terms in sympy's printed order, each with its sign apart (a subtraction is an
        # adder, a sign free), paired by ready time (trees.pairing)
        terms, times = [], []
        for term in self._as_ordered_terms(expr, order=order):
            text = self._print(term)
            negated = text.startswith("-") and not term.is_Add
            text = text[1:] if negated else text
            if precedence(term) < precedence(expr) or term.is_Add:
                text = f"({text})"
            terms.append((negated, text))
            times.append(self.ready(term))
        negated, text = signed_tree_text(terms, pairing(times, self.ready.lat["add"])[0])
        return f"-({text})" if negated else text

    def _product(self, factors: list, texts: list[str]) -> str:
        """``texts`` (of ``factors``) multiplied: flat, or as the tree of their ready times."""
        if self.ready is None or len(texts) < 2:
            return "*".join(texts)
        times = [self.ready(f) for f in factors]
        return tree_text(texts, pairing(times, self.ready.lat["mul"])[0], "*")

    def _print_Mul(self, expr: sp.Mul) -> str:
        """``[-]a*b*…[/c | /(c*d*…)]`` as :func:`_mul_parts` splits ``expr`` (sympy's own C
        layout: a rational coefficient is a factor, a negative exponent a denominator)."""
        sign, numer, denom, grouped = _mul_parts(expr)
        prec = precedence(expr)
        if len(numer) == 1 and sign:  # unary minus binds between a product and a power
            a_str = [self.parenthesize(numer[0], 0.5 * (PRECEDENCE["Pow"] + PRECEDENCE["Mul"]))]
        else:
            a_str = [self.parenthesize(x, prec) for x in numer]
        b_str = [f"({self.parenthesize(x, prec)})" if paren else self.parenthesize(x, prec)
                 for x, paren in zip(denom, grouped, strict=True)]
        top = self._product(numer, a_str)
        if not denom:
            return sign + top
        if len(denom) == 1:
            return sign + top + "/" + b_str[0]
        return f"{sign}{top}/({self._product(denom, b_str)})"

    def _print_Function(self, expr) -> str:
        args = ", ".join(self._print(a) for a in expr.args)
        if isinstance(expr, (special.LieCoefficient, special.SO3LogComponent)):
            return f"{self.call}{type(expr).__name__}({args})"
        if isinstance(expr, special.GuardedQuotient):  # a / b where g > t, else f
            return f"{self.call}fgc_guarded_quotient({args})"
        if isinstance(expr, special.VectorNorm):
            return self._print(expr.expanded())
        for func, name in _FUNCTIONS.items():
            if isinstance(expr, func):
                return f"{self.call}{name}({args})"
        raise UnsupportedExpressionError(f"the HLS backend has no C++ for the function "
                                         f"'{type(expr).__name__}'")

    _print_sin = _print_cos = _print_tan = _print_atan2 = _print_atan = _print_Function
    _print_exp = _print_log = _print_Function
    _print_asin = _print_acos = _print_tanh = _print_Abs = _print_sign = _print_Function

    def _print_not_supported(self, expr) -> str:
        raise UnsupportedExpressionError(f"the HLS backend cannot print '{type(expr).__name__}'")

    emptyPrinter = _print_not_supported


def printed_ops(exprs: Iterable[sp.Expr], counts: Counter | None = None) -> Counter:
    """The floating-point operations of ``exprs`` as :class:`HlsCodePrinter` prints them, by
    kind (add, mul, div, sqrt, trig, special): each operator the text holds, counted from the
    same splits the printer prints from (:func:`_mul_parts`, :func:`_power_terms`). A
    subtraction is an add, a sign no operation, a product of k factors k - 1 multiplies, a
    denominator one divide (a product of several, their multiplies too), a division by a
    constant a multiply by its reciprocal, a power's base once however often it is printed
    (``(a + b)**2`` prints ``(a + b)*(a + b)``, whose repeated sum the C++ front end computes
    once, as the second reader reads it); a Lie coefficient or SO(3) logarithm component is one
    ``special`` (its body counted apart: ``fgc_backends.hls.units.special_ops``), a sine,
    cosine, tangent or inverse one ``trig``, ``fgc_guarded_quotient`` its divide."""
    counts = Counter() if counts is None else counts
    for expr in exprs:
        _printed(sp.sympify(expr), counts, 1)
    return counts


def _printed(expr, counts: Counter, times: int) -> None:
    """Add ``times`` copies of ``expr``'s printed operations to ``counts``."""
    if expr.is_Atom:
        return
    if expr.is_Add:
        counts["add"] += times * (len(expr.args) - 1)
        for arg in expr.args:
            _printed(arg, counts, times)
    elif expr.is_Mul:
        _, numer, denom, _ = _mul_parts(expr)
        counts["mul"] += times * (len(numer) - 1 + max(len(denom) - 1, 0))
        counts["div"] += times * bool(denom)
        for item in (*numer, *denom):
            _printed(item, counts, times)
    elif expr.is_Pow:
        whole, root, inverse = _power_terms(expr.exp)
        counts["mul"] += times * max(whole + root - 1, 0)
        counts["sqrt"] += times * root
        counts["div"] += times * inverse
        # the product's copies of the base are one value: the C++ front end computes a
        # repeated group once (``(a + b)*(a + b)``: one add, one multiply); a half-integer
        # power's square root takes the base as a call's argument, a second value
        _printed(expr.base, counts, times * (1 + (root and whole > 0)))
    elif isinstance(expr, special.VectorNorm):
        _printed(expr.expanded(), counts, times)
    else:
        if isinstance(expr, (special.LieCoefficient, special.SO3LogComponent)):
            counts["special"] += times
        elif isinstance(expr, special.GuardedQuotient):  # g > t ? a / b : f
            counts["div"] += times
        elif isinstance(expr, _TRIG):
            counts["trig"] += times
        for arg in expr.args:
            _printed(arg, counts, times)


@functools.lru_cache(maxsize=512)
def kernel_printed_ops(kernel: Kernel) -> tuple[tuple[str, int], ...]:
    """:func:`printed_ops` of a whole kernel as :func:`print_kernel` prints it: each assignment
    and output once, and the arguments of one rotation's SO(3) logarithm once (its three
    components are read from one ``so3_log`` call)."""
    counts: Counter = Counter()
    logs = set()
    for _, e in kernel.assignments:
        if isinstance(e, special.SO3LogComponent):
            counts["special"] += 1
            if e.args not in logs:
                logs.add(e.args)
                printed_ops(e.args, counts)
        else:
            printed_ops([e], counts)
    printed_ops(kernel.outputs, counts)
    return tuple((k, counts.get(k, 0)) for k in OP_KINDS)


def check_supported(exprs: Iterable[sp.Expr], where: str) -> None:
    """Raise :class:`UnsupportedExpressionError` naming ``where`` if any node cannot be printed.

    Checked before printing so that the error names the block and the offending function
    instead of surfacing as a g++ failure.
    """
    allowed_funcs = tuple(_FUNCTIONS) + (special.LieCoefficient, special.SO3LogComponent,
                                         *special.GUARD_FUNCTIONS)
    for expr in exprs:
        for node in sp.preorder_traversal(sp.sympify(expr)):
            if node.is_Atom or isinstance(node, (sp.Add, sp.Mul)):
                if node.is_Atom and not (node.is_Symbol or node.is_Number
                                         or isinstance(node, sp.NumberSymbol)):
                    raise UnsupportedExpressionError(
                        f"{where}: cannot print '{type(node).__name__}'")
                continue
            if isinstance(node, sp.Pow):
                if not _printable_power(node.exp):
                    raise UnsupportedExpressionError(f"{where}: unsupported power {node}")
                continue
            if not isinstance(node, allowed_funcs):
                raise UnsupportedExpressionError(f"{where}: the HLS backend has no C++ for "
                                                 f"'{type(node).__name__}'")


def print_kernel(kernel: Kernel, input_names: Sequence[str], where: str,
                 prefix: str = "t", vector: bool = False, latencies=None) -> PrintedKernel:
    """Print ``kernel`` with inputs named ``input_names`` and intermediates ``<prefix><i>``.

    ``where`` names the kernel in error messages (e.g. the block type). The three components
    ``so3_log_x/y/z`` of one rotation are assigned from a single ``so3_log`` call (one logarithm
    instead of three).

    ``vector``: every value has type ``V`` instead of ``T`` — in the emitted code, ``LANES``
    scalars side by side (a GCC/Clang vector type on the host, ``T`` itself in synthesis) — and
    functions are called as their lane-wise versions ``v_<name>``. Each lane computes exactly the
    scalar operations, so results do not depend on ``LANES``.

    ``latencies`` (operator kind → cycles, the HLS design's table): every sum and product is
    printed as the reduction tree ``cost.kernels.critical_path`` prices (:mod:`.trees`: the
    operands paired by the cycle they are ready, the inputs at 0, each intermediate when its
    statement ends), so Vitis, which does not reassociate floating-point operations, schedules
    the depth the plan prints. None: the flat left-to-right text (the native backend).
    """
    exprs = [e for _, e in kernel.assignments] + [sp.sympify(e) for e in kernel.outputs]
    check_supported(exprs, where)
    names = dict(zip(kernel.inputs, input_names, strict=True))
    names.update({x: f"{prefix}{i}" for i, (x, _) in enumerate(kernel.assignments)})
    printer = HlsCodePrinter(names, checked=True, vector=vector, latencies=latencies)
    value_type = "V" if vector else "T"
    logs: dict[tuple, str] = {}
    lines = []
    for x, e in kernel.assignments:
        if isinstance(e, special.SO3LogComponent):
            if e.args not in logs:
                logs[e.args] = f"{prefix}log{len(logs)}"
                args = ", ".join(printer.doprint(a) for a in e.args)
                lines.append(f"{value_type} {logs[e.args]}[3]; {printer.call}so3_log({args}, "
                             f"{logs[e.args]});")
            lines.append(f"const {value_type} {names[x]} = {logs[e.args]}[{e.axis}];")
        else:
            lines.append(f"const {value_type} {names[x]} = {printer.doprint(e)};")
        if printer.ready is not None:
            printer.ready.assign(x, e)
    outputs = tuple(printer.doprint(sp.sympify(e)) for e in kernel.outputs)
    return PrintedKernel(tuple(lines), outputs, sum(kernel.op_counts().values()))
