"""Sums and products as the C-family printer lays them out, and when each value is ready.

Vitis HLS schedules a floating-point expression as the C++ text associates it: ``a + b + c + d``
is ``((a + b) + c) + d``, three adders one after another, because the tool does not reassociate
floating-point operations (UG1399, "Optimizing Techniques and Troubleshooting Tips": floating-point
operations are not associative, so an accumulation is a chain unless the source says otherwise).
The HLS backend therefore prints every n-ary sum and product as the reduction tree its critical
path is priced with, and both sides take the tree from this module:

- :func:`pairing` is the one rule: operands are combined two at a time, always the two that are
  ready first (ties: the one printed first), each result ready one operator latency after the
  later of its two operands — the tree of least completion time for operands ready at given
  times;
- :class:`ReadyTimes` walks an expression the way :class:`~fgc_backends.cfamily.printer.
  HlsCodePrinter` prints it (:func:`mul_parts`, :func:`power_terms`: the same splits) and gives
  the cycle at which every subexpression is ready, with the operand order of the printed text;
  ``cost.kernels.critical_path`` is its largest output time, the printer asks it for the ready
  time of each operand it pairs.

With ``balanced=False`` the walker prices the flat layout instead (every sum and product a
left-to-right chain in printed order): what the text holds without trees, the native backend's.
"""

from __future__ import annotations

import heapq
from collections.abc import Sequence

import sympy as sp
from sympy.core.mul import _keep_coeff

from fgc.frontend.geometry import special

MAX_PRODUCT_POWER = 8
TRIG = (sp.sin, sp.cos, sp.tan, sp.atan, sp.atan2, sp.acos, sp.asin)
ARCTANGENTS = (sp.atan, sp.atan2, sp.acos, sp.asin)  # the table's atan2 figure, where it has one


def pairing(times: Sequence[int], latency: int) -> tuple[tuple[tuple[int, int], ...], int]:
    """The reduction tree of operands ready at ``times`` through operators of ``latency``: the
    pairs ``(a, b)`` in the order they are combined (operand ``i`` is node ``i``; the k-th pair
    makes node ``len(times) + k``; ``a`` the earlier-ready of the two) and the cycle the last
    one ends. Always the two earliest-ready nodes first, ties broken by node number: the
    deterministic tree of least completion time."""
    heap = [(t, i) for i, t in enumerate(times)]
    heapq.heapify(heap)
    pairs = []
    while len(heap) > 1:
        (ta, a), (tb, b) = heapq.heappop(heap), heapq.heappop(heap)
        pairs.append((a, b))
        heapq.heappush(heap, (max(ta, tb) + latency, len(times) + len(pairs) - 1))
    return tuple(pairs), heap[0][0]


def chain(times: Sequence[int], latency: int) -> int:
    """When a left-to-right chain of operands ready at ``times`` ends."""
    done = times[0]
    for t in times[1:]:
        done = max(done, t) + latency
    return done


def tree_text(texts: Sequence[str], pairs: Sequence[tuple[int, int]], op: str) -> str:
    """``texts`` combined by ``pairs`` (:func:`pairing`) with the binary operator ``op``: each
    inner node in parentheses, the root bare (C++ then associates exactly the tree)."""
    nodes = list(texts)
    for a, b in pairs:
        nodes.append(f"{_wrapped(nodes[a], a, len(texts))}{op}{_wrapped(nodes[b], b, len(texts))}")
    return nodes[-1]


def _wrapped(text: str, node: int, leaves: int) -> str:
    return text if node < leaves else f"({text})"


def signed_tree_text(terms: Sequence[tuple[bool, str]],
                     pairs: Sequence[tuple[int, int]]) -> tuple[bool, str]:
    """A sum of ``terms`` (each ``(negated, text)``, ``text`` without its sign) combined by
    ``pairs``: ``a + b``, ``a - b`` (``b`` negated), ``b - a`` (``a`` negated), or ``a + b``
    negated as a whole (both negated; the sign goes to the parent, where it is free). Returns
    the root's ``(negated, text)``. The operations are the flat sum's: n - 1 adders, signs
    free."""
    leaves = len(terms)
    nodes = list(terms)
    for a, b in pairs:
        (na, ta), (nb, tb) = nodes[a], nodes[b]
        ta, tb = _wrapped(ta, a, leaves), _wrapped(tb, b, leaves)
        if na and nb:
            nodes.append((True, f"{ta} + {tb}"))
        elif nb:
            nodes.append((False, f"{ta} - {tb}"))
        elif na:
            nodes.append((False, f"{tb} - {ta}"))
        else:
            nodes.append((False, f"{ta} + {tb}"))
    return nodes[-1]


def printable_power(exp) -> bool:
    """Whether b**exp prints: exp a non-zero integer or half-integer, |exp| ≤ the product bound."""
    if not exp.is_Rational or exp == 0 or abs(exp) > MAX_PRODUCT_POWER:
        return False
    return exp.is_Integer or exp.q == 2


def power_terms(exp) -> tuple[int, bool, bool]:
    """How ``b**exp`` prints (:meth:`HlsCodePrinter._print_Pow`): the copies of ``b`` in its
    product (``|exp|`` rounded down), whether a square root ``fgc_sqrt(b)`` joins them (a
    half-integer exponent) and whether the product is inverted (``T(1)/(…)``)."""
    return int(abs(exp)), not exp.is_Integer, bool(exp < 0)


def mul_parts(expr: sp.Mul) -> tuple[str, list, list, list]:
    """How a product prints (:meth:`HlsCodePrinter._print_Mul`): its sign (``"-"`` for a
    negative coefficient, printed as a unary minus), the numerator's factors (a rational
    coefficient one of them: ``x/2`` prints ``(T(0.5))*x``), the denominator's factors (each
    power with a negative rational exponent, inverted: ``x*y**-2`` prints ``x/(y*y)``) and, per
    denominator factor, whether it is printed in its own parentheses (an inverted product)."""
    c, e = expr.as_coeff_Mul()
    sign = ""
    if c < 0:
        expr = _keep_coeff(-c, e)
        sign = "-"
    numer, denom, grouped = [], [], []
    for item in expr.as_ordered_factors():
        if (item.is_commutative and item.is_Pow and item.exp.is_Rational
                and item.exp.is_negative):
            if item.exp != -1:
                denom.append(sp.Pow(item.base, -item.exp, evaluate=False))
                grouped.append(False)
            else:
                denom.append(sp.Pow(item.base, -item.exp))
                grouped.append(len(item.args[0].args) != 1 and isinstance(item.base, sp.Mul))
        else:
            numer.append(item)
    return sign, numer or [sp.S.One], denom, grouped


class ReadyTimes:
    """The cycle each subexpression of a kernel is ready, its inputs ready at 0, with operator
    ``latencies`` (kind → cycles: add, mul, div, sqrt, trig, special, and atan2 where an
    arctangent's differs from a sine's) and sums and products
    reduced as :func:`pairing`'s trees (``balanced``) or as the printed left-to-right chains.
    :meth:`assign` records an intermediate's time; calling the walker on an expression gives its
    time (remembered: a subexpression is timed once)."""

    def __init__(self, latencies, balanced: bool = True):
        self.lat = dict(latencies)
        self.balanced = balanced
        self.known: dict[sp.Symbol, int] = {}
        self._memo: dict[sp.Expr, int] = {}

    def assign(self, symbol: sp.Symbol, expr: sp.Expr) -> int:
        self.known[symbol] = t = self(expr)
        return t

    def reduce(self, times: Sequence[int], kind: str) -> int:
        """When a sum (``kind`` "add") or product ("mul") of operands ready at ``times`` ends."""
        if self.balanced:
            return pairing(times, self.lat[kind])[1]
        return chain(times, self.lat[kind])

    def __call__(self, expr) -> int:
        if expr.is_Symbol:
            return self.known.get(expr, 0)
        if expr.is_Number or not expr.args:
            return 0
        hit = self._memo.get(expr)
        if hit is None:
            hit = self._memo[expr] = self._time(expr)
        return hit

    def _time(self, expr) -> int:
        lat = self.lat
        if expr.is_Add:
            return self.reduce([self(a) for a in expr.as_ordered_terms()], "add")
        if expr.is_Mul:  # a sign is free; one divide after the numerator and denominator
            _, numer, denom, _ = mul_parts(expr)
            top = self.reduce([self(a) for a in numer], "mul")
            if not denom:
                return top
            return max(top, self.reduce([self(a) for a in denom], "mul")) + lat["div"]
        if expr.is_Pow:
            base = self(expr.base)
            if not printable_power(expr.exp):  # refused by the printer; the slowest unit
                return base + lat["special"]
            whole, root, inverse = power_terms(expr.exp)
            times = [base + lat["sqrt"]] * root + [base] * whole
            return self.reduce(times, "mul") + lat["div"] * inverse
        if isinstance(expr, special.VectorNorm):  # printed as its expansion
            return self(expr.expanded())
        args = [self(a) for a in expr.args]
        if isinstance(expr, ARCTANGENTS):
            return max(args) + lat.get("atan2", lat["trig"])
        if isinstance(expr, TRIG):
            return max(args) + lat["trig"]
        if isinstance(expr, special.GuardedQuotient):  # a divide, then a select
            return max(args) + lat["div"]
        # Lie coefficients, SO(3) log components and anything else: the slowest unit
        return max(args) + lat["special"]
