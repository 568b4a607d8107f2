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
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import NamedTuple

import sympy as sp
from sympy.printing.cxx import CXX17CodePrinter

from fgc.compiler.kernel import Kernel
from fgc.errors import FgcError
from fgc.frontend.geometry import special

# one C++ wrapper per function of the DSL's whitelist (fgc.frontend.functions.FUNCTIONS) and per
# function
# its derivatives introduce (sign, from Abs); tests/frontend/test_functions.py prints each
_FUNCTIONS = {sp.sin: "fgc_sin", sp.cos: "fgc_cos", sp.tan: "fgc_tan", sp.atan2: "fgc_atan2",
              sp.atan: "fgc_atan", sp.exp: "fgc_exp", sp.log: "fgc_log", sp.asin: "fgc_asin",
              sp.acos: "fgc_acos", sp.tanh: "fgc_tanh", sp.Abs: "fgc_abs", sp.sign: "fgc_sign"}
_MAX_PRODUCT_POWER = 8


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
                 checked: bool = False, vector: bool = False):
        super().__init__({"strict": True, **(settings or {})})
        self.symbol_names = dict(symbols)
        self.checked = checked  # the caller ran check_supported on everything it will print
        self.call = "v_" if vector else ""  # lane-wise versions of the functions on V

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
        whole = int(abs(exp))  # whole multiplies: |n/2| rounded down
        factor = self.parenthesize(base, 100)
        terms = [factor] * whole
        if not exp.is_Integer:
            terms.insert(0, f"{self.call}fgc_sqrt({self._print(base)})")
        if exp == sp.Rational(1, 2):
            return terms[0]
        if exp == -sp.Rational(1, 2):
            return f"(T(1)/{terms[0]})"
        product = "*".join(terms)
        return f"({product})" if exp > 0 else f"(T(1)/({product}))"

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


def _printable_power(exp) -> bool:
    """Whether b**exp prints: exp a non-zero integer or half-integer, |exp| ≤ the product bound."""
    if not exp.is_Rational or exp == 0 or abs(exp) > _MAX_PRODUCT_POWER:
        return False
    return exp.is_Integer or exp.q == 2


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
                 prefix: str = "t", vector: bool = False) -> PrintedKernel:
    """Print ``kernel`` with inputs named ``input_names`` and intermediates ``<prefix><i>``.

    ``where`` names the kernel in error messages (e.g. the block type). The three components
    ``so3_log_x/y/z`` of one rotation are assigned from a single ``so3_log`` call (one logarithm
    instead of three).

    ``vector``: every value has type ``V`` instead of ``T`` — in the emitted code, ``LANES``
    scalars side by side (a GCC/Clang vector type on the host, ``T`` itself in synthesis) — and
    functions are called as their lane-wise versions ``v_<name>``. Each lane computes exactly the
    scalar operations, so results do not depend on ``LANES``.
    """
    exprs = [e for _, e in kernel.assignments] + [sp.sympify(e) for e in kernel.outputs]
    check_supported(exprs, where)
    names = dict(zip(kernel.inputs, input_names, strict=True))
    names.update({x: f"{prefix}{i}" for i, (x, _) in enumerate(kernel.assignments)})
    printer = HlsCodePrinter(names, checked=True, vector=vector)
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
    outputs = tuple(printer.doprint(sp.sympify(e)) for e in kernel.outputs)
    return PrintedKernel(tuple(lines), outputs, sum(kernel.op_counts().values()))
