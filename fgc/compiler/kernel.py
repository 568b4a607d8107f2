"""Straight-line kernels: residual and Jacobians as a list of small assignments.

Differentiating a residual's expression tree directly makes sympy expand shared subterms into
millions of operations. Instead the residual is first split by common-subexpression elimination into
assignments ``xᵢ = eᵢ`` (each small), and Jacobians are built by forward-mode differentiation over
that list: ``dxᵢ/dδ = Σₐ ∂eᵢ/∂a · da/dδ``, seeded at the variables' storage symbols with
``∂storage/∂δ``. Cost and size stay linear in the number of assignments, and the result is already
the shape hardware wants: shared intermediates feeding residual and Jacobian (the "common term"
module of the papers).
"""

from __future__ import annotations

import functools
import keyword
from collections import Counter
from dataclasses import dataclass

import numpy as np
import sympy as sp
from sympy.printing.numpy import NumPyPrinter

from fgc.frontend.geometry import special


@dataclass(frozen=True)
class Kernel:
    """Inputs, assignments in dependency order, and output expressions (over both)."""

    inputs: tuple[sp.Symbol, ...]
    assignments: tuple[tuple[sp.Symbol, sp.Expr], ...]
    outputs: tuple[sp.Expr, ...]

    def op_counts(self) -> dict[str, int]:
        """Operations by kind (add, mul, div, sqrt, trig, special) over the whole kernel."""
        return dict(_op_counts(self))  # a copy: callers may change theirs

    def op_counts_unshared(self) -> dict[str, int]:
        """Operations if nothing were shared: every intermediate recomputed at each use, i.e.
        each output evaluated as its own expression tree (what CSE saves is the difference)."""
        inlined: dict[sp.Symbol, Counter] = {}
        for x, e in self.assignments:
            inlined[x] = _tree_counts(e, inlined)
        total: Counter = Counter()
        for e in self.outputs:
            total.update(_tree_counts(sp.sympify(e), inlined))
        return {k: total.get(k, 0) for k in OP_KINDS}


OP_KINDS = ("add", "mul", "div", "sqrt", "trig", "special")


@functools.lru_cache(maxsize=512)
def _op_counts(kernel: Kernel) -> tuple[tuple[str, int], ...]:
    """Counted once per kernel (the plan and the reports ask for the same kernels' counts)."""
    counts: Counter = Counter()
    for _, e in kernel.assignments:
        _count_ops(e, counts)
    for e in kernel.outputs:
        _count_ops(e, counts)
    return tuple((k, counts.get(k, 0)) for k in OP_KINDS)


def _tree_counts(expr: sp.Expr, inlined: dict) -> Counter:
    own: Counter = Counter()
    _count_ops(expr, own)
    for node in sp.preorder_traversal(expr):
        if node in inlined:
            own.update(inlined[node])
    return own


def _count_ops(expr: sp.Expr, counts: Counter) -> None:
    for node in sp.preorder_traversal(expr):
        if node.is_Add:
            counts["add"] += len(node.args) - 1
        elif node.is_Mul:
            nums, dens = sp.fraction(node)
            n_factors = len(sp.Mul.make_args(nums)) + (len(sp.Mul.make_args(dens)) - 1)
            counts["mul"] += max(n_factors - 1, 0)
            if dens != 1:
                counts["div"] += 1
        elif node.is_Pow:
            _count_pow(node, counts)
        elif isinstance(node, (sp.sin, sp.cos, sp.tan, sp.atan2, sp.atan, sp.acos, sp.asin)):
            counts["trig"] += 1
        elif isinstance(node, (special.LieCoefficient, special.SO3LogComponent)):
            counts["special"] += 1
        elif isinstance(node, special.GuardedQuotient):  # a compare, a divide and a select
            counts["add"] += 1
            counts["div"] += 1


def _count_pow(node: sp.Pow, counts: Counter) -> None:
    base_exp = node.exp
    if base_exp == sp.Rational(1, 2) or base_exp == -sp.Rational(1, 2):
        counts["sqrt"] += 1
        if base_exp < 0:
            counts["div"] += 1
    elif base_exp.is_Integer and base_exp < 0:
        counts["div"] += 1
        counts["mul"] += max(int(-base_exp) - 1, 0)
    elif base_exp.is_Integer:
        counts["mul"] += int(base_exp) - 1
    else:
        counts["special"] += 1


# --------------------------------------------------------------------------------------------
# building kernels
# --------------------------------------------------------------------------------------------


def jacobian_kernel(residual: sp.Matrix, seeds: list[tuple[sp.Symbol, dict[int, sp.Expr]]],
                    n_tangent: int, prefix: str = "_t") -> tuple[Kernel, int]:
    """A kernel whose outputs are the residual then the Jacobian (row-major, m × n_tangent).

    ``seeds`` maps input storage symbols to their sparse derivative {tangent column: expr}.
    Returns the kernel and the residual dimension m.
    """
    symbols = sp.numbered_symbols(prefix, real=True)
    replacements, reduced = sp.cse(list(residual), symbols=symbols, order="none")
    deriv: dict[sp.Symbol, dict[int, sp.Expr]] = {s: dict(d) for s, d in seeds}
    calls = {e: x for x, e in replacements if isinstance(e, sp.Function)}
    dsyms = sp.numbered_symbols(f"{prefix}d", real=True)
    out: list[tuple[sp.Symbol, sp.Expr]] = []
    for x, e in replacements:
        out.append((x, e))
        dx = _forward(e, deriv, calls)
        deriv[x] = {}
        for col, de in sorted(dx.items()):
            if de.is_Atom:
                deriv[x][col] = de
            else:
                sym = next(dsyms)
                out.append((sym, de))
                deriv[x][col] = sym
    jac_entries = []
    for e in reduced:
        dr = _forward(e, deriv, calls)
        jac_entries.extend(dr.get(c, sp.Integer(0)) for c in range(n_tangent))
    inputs = tuple(s for s, _ in seeds)
    # the norms' derivative rule (GTSAM's convention at 0) is used; they are square roots now
    expand = special.expand_norms
    kernel = Kernel(inputs, tuple((x, expand(e)) for x, e in out),
                    tuple(expand(e) for e in tuple(reduced) + tuple(jac_entries)))
    return tidy(kernel), len(reduced)


def _forward(e: sp.Expr, deriv: dict, calls: dict) -> dict[int, sp.Expr]:
    acc: dict[int, sp.Expr] = {}
    for a in sorted(e.free_symbols & deriv.keys(), key=str):
        if not deriv[a]:
            continue
        partial = e.diff(a)
        if partial == 0:
            continue
        partial = partial.xreplace(calls)
        for col, da in deriv[a].items():
            acc[col] = acc.get(col, 0) + partial * da
    return {c: v for c, v in acc.items() if v != 0}


def tidy(kernel: Kernel, prefix: str = "_c") -> Kernel:
    """Share repeated subexpressions across all assignments and outputs; keep dependency order."""
    exprs = [e for _, e in kernel.assignments] + list(kernel.outputs)
    reps, reduced = sp.cse(exprs, symbols=sp.numbered_symbols(prefix, real=True), order="none")
    n = len(kernel.assignments)
    defs = dict(reps)
    defs.update({x: reduced[i] for i, (x, _) in enumerate(kernel.assignments)})
    order = _topological(defs, [x for x, _ in reps] + [x for x, _ in kernel.assignments])
    assignments = tuple((x, defs[x]) for x in order)
    return Kernel(kernel.inputs, drop_dead(assignments, reduced[n:]), tuple(reduced[n:]))


def _topological(defs: dict, preferred: list[sp.Symbol]) -> list[sp.Symbol]:
    """Dependency order of the defined symbols; ties broken by ``preferred`` order."""
    rank = {x: i for i, x in enumerate(preferred)}
    done: set = set()
    order: list = []
    for root in sorted(defs, key=lambda x: rank[x]):
        stack = [(root, False)]
        while stack:
            x, expanded = stack.pop()
            if x in done:
                continue
            if expanded:
                done.add(x)
                order.append(x)
                continue
            stack.append((x, True))
            deps = sorted((d for d in defs[x].free_symbols if d in defs and d not in done),
                          key=lambda d: -rank[d])
            stack.extend((d, False) for d in deps)
    return order


def drop_dead(assignments, outputs) -> tuple:
    live = set().union(*(e.free_symbols for e in outputs)) if outputs else set()
    kept = []
    for x, e in reversed(assignments):
        if x in live:
            kept.append((x, e))
            live |= e.free_symbols
    return tuple(reversed(kept))


# --------------------------------------------------------------------------------------------
# numeric evaluation (Python/NumPy)
# --------------------------------------------------------------------------------------------


class _Printer(NumPyPrinter):
    """NumPy printer that leaves fgc's special functions as calls into a given namespace."""

    def _print_Function(self, expr):
        if isinstance(expr, (special.LieCoefficient, special.SO3LogComponent,
                             *special.GUARD_FUNCTIONS)):
            args = ", ".join(self._print(a) for a in expr.args)
            return f"{type(expr).__name__}({args})"
        return super()._print_Function(expr)


def python_source(kernel: Kernel, name: str = "kernel") -> str:
    """Python source of ``def name(*inputs) -> list of outputs`` for a kernel."""
    printer = _Printer({"fully_qualified_modules": True, "inline": True})
    names = {s: _identifier(s, i) for i, s in enumerate(kernel.inputs)}
    lines = [f"def {name}({', '.join(names[s] for s in kernel.inputs)}):"]
    sub = {s: sp.Symbol(n) for s, n in names.items()}
    for x, e in kernel.assignments:
        lines.append(f"    {x} = {printer.doprint(e.xreplace(sub))}")
    outs = ", ".join(printer.doprint(sp.sympify(e).xreplace(sub)) for e in kernel.outputs)
    lines.append(f"    return [{outs}]")
    return "\n".join(lines) + "\n"


def _identifier(sym: sp.Symbol, i: int) -> str:
    text = str(sym)
    ok = text.isidentifier() and not keyword.iskeyword(text)
    return text if ok else f"_in{i}"


def numeric_function(kernel: Kernel):
    """Compile a kernel to a Python callable over NumPy scalars/arrays.

    The callable raises no NumPy floating-point warning: a 0/0 or an overflow (a direction x / |x|
    at x = 0) gives inf/NaN outputs, which every caller checks and reports naming the
    factor (``require_finite_start``, verify's linearisation checks), instead of an unworded
    ``<fgc kernel>: RuntimeWarning`` on stderr."""
    ns: dict = {"numpy": np, "np": np}
    ns.update(special.numeric_namespace())
    exec(compile(python_source(kernel), "<fgc kernel>", "exec"), ns)  # noqa: S102 - own source
    fn = ns["kernel"]

    def quiet(*inputs):
        with np.errstate(all="ignore"):
            return fn(*inputs)
    return quiet
