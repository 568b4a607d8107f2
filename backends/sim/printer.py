"""The simulator's sympy printer: block kernels as NumPy functions over all instances at once.

Only this module knows the emitted program's syntax. A printed kernel takes one array ``x`` of
shape (inputs, instances) and returns ``out`` of shape (outputs, instances), so every operation
of the kernel runs once per block type on whole arrays. Numbers are printed as Python literals,
which NumPy treats as "weak" scalars: a float32 ``x`` keeps every intermediate in float32.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Sequence
from typing import NamedTuple

import sympy as sp
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.precedence import PRECEDENCE

from fgc.compiler.kernel import Kernel, drop_dead
from fgc.errors import FgcError
from fgc.frontend.geometry import special


class PrintError(FgcError):
    """A kernel uses something the simulator's printer cannot express."""


_PLAIN = re.compile(r"[A-Za-z0-9_.:+\- ]*")


class PrintedKernel(NamedTuple):
    """Body lines of ``def <name>(x): ... return out`` and the kernel's sizes."""

    name: str
    lines: tuple[str, ...]
    inputs: int
    outputs: int
    assignments: int


class SimPrinter(NumPyPrinter):
    """NumPy printer for the simulator: fgc's special functions as calls into the runtime,
    dtype-preserving literals, cheap integer powers."""

    def __init__(self) -> None:
        super().__init__({"fully_qualified_modules": True, "inline": True,
                          "allow_unknown_functions": False})

    # -- expressions ---------------------------------------------------------------------
    def _print(self, expr, **kwargs) -> str:
        # Constant subexpressions (sqrt(2), 2*pi) would otherwise print as numpy calls, whose
        # float64 results promote float32 arrays; a Python literal does not.
        if isinstance(expr, sp.Expr) and expr.is_number and not expr.is_Atom:
            return self._literal(expr)
        return super()._print(expr, **kwargs)

    def _literal(self, expr: sp.Expr) -> str:
        value = complex(expr.evalf(30))
        if value.imag != 0:
            raise PrintError(f"complex constant {expr} in a kernel")
        text = repr(float(value.real))
        return f"({text})" if text.startswith("-") else text

    def _print_Float(self, expr) -> str:
        return self._literal(expr)

    def _print_Rational(self, expr) -> str:
        return self._literal(expr)

    def _print_Pow(self, expr, rational=False) -> str:
        base, exp = expr.base, expr.exp
        if exp.is_Integer:
            text = self.parenthesize(base, PRECEDENCE["Pow"])
            n = int(exp)
            if n < 0:
                return f"(1/{text})" if n == -1 else f"(1/{text}**{-n})"
            return f"{text}**{n}"
        if exp == sp.Rational(1, 2):
            return f"numpy.sqrt({self._print(base)})"
        if exp == -sp.Rational(1, 2):
            return f"(1/numpy.sqrt({self._print(base)}))"
        return f"{self.parenthesize(base, PRECEDENCE['Pow'])}**{self._literal(exp)}"

    def _print_Function(self, expr) -> str:
        if isinstance(expr, special.LieCoefficient):
            return f"{type(expr).__name__}({self._print(expr.args[0])})"
        if isinstance(expr, special.SO3LogComponent):
            raise PrintError("so3_log components must be grouped before printing")
        if isinstance(expr, special.GuardedQuotient):
            # a / b where g > t, else f; b is replaced by 1 where the quotient is not taken, so
            # no lane divides by 0
            a, b, g, t, f = (self._print(x) for x in expr.args)
            cond = f"({g} > {t})"
            return f"numpy.where({cond}, {a} / numpy.where({cond}, {b}, 1), {f})"
        if isinstance(expr, special.VectorNorm):
            return self._print(expr.expanded())
        return super()._print_Function(expr)

    def _print_not_supported(self, expr) -> str:
        raise PrintError(f"the simulator cannot print {type(expr).__name__} ({expr})")

    # -- kernels -------------------------------------------------------------------------
    def kernel(self, kernel: Kernel, name: str, outputs: Sequence[int] | None = None
               ) -> PrintedKernel:
        """Print ``kernel`` as the body of ``def name(x)``; ``outputs`` selects (and orders) the
        outputs to compute (default: all). Zero outputs are left at the zeros ``out`` starts
        with."""
        chosen = list(range(len(kernel.outputs)) if outputs is None else outputs)
        exprs = [sp.sympify(kernel.outputs[i]) for i in chosen]
        assignments = drop_dead(kernel.assignments, exprs)
        rename = {s: sp.Symbol(f"a{i}", real=True) for i, s in enumerate(kernel.inputs)}
        rename.update({x: sp.Symbol(f"t{i}", real=True) for i, (x, _) in enumerate(assignments)})
        steps = [(rename[x], e.xreplace(rename)) for x, e in assignments]
        exprs = [e.xreplace(rename) for e in exprs]
        steps, exprs = _group_logs(steps, exprs)
        lines = [f"a{i} = x[{i}]" for i in range(len(kernel.inputs))]
        for target, e in steps:
            lines.append(f"{target} = {self._print(e)}" if isinstance(target, sp.Symbol)
                         else f"{', '.join(map(str, target))} = so3_log("
                              f"{', '.join(self._print(a) for a in e)})")
        lines.append(f"out = numpy.zeros(({len(exprs)}, x.shape[1]), dtype=x.dtype)")
        lines += [f"out[{k}] = {self._print(e)}" for k, e in enumerate(exprs) if e != 0]
        lines.append("return out")
        return PrintedKernel(name, tuple(lines), len(kernel.inputs), len(exprs), len(steps))

    # -- tables --------------------------------------------------------------------------
    def literal(self, value) -> str:
        """A Python literal of nested tuples/lists of ints, floats, bools and strings."""
        if isinstance(value, (list, tuple)):
            items = [self.literal(v) for v in value]
            return "(" + ", ".join(items) + ("," if len(items) == 1 else "") + ")"
        if isinstance(value, bool) or value is None:
            return repr(value)
        if isinstance(value, int):
            return str(value)
        if isinstance(value, float):
            # inf / nan have no literal; float("inf") reads back exactly
            return repr(value) if math.isfinite(value) else f'float("{value!r}")'
        if isinstance(value, str) and value.isidentifier():
            return repr(value)
        raise PrintError(f"no literal for {value!r}")

    @staticmethod
    def json_text(value) -> str:
        """A Python string literal holding ``value`` (a variable key) as JSON text: how user data
        reach the emitted code, decoded by ``json_value`` at run time and never read as code.
        An int, or a string of letters, digits, space and ``_.:+-``, is its JSON text
        (``'"x0"'``, ``'7'``); any other is ``'hex:'`` and the hex digits of its UTF-8 JSON
        text, so that no quote, backslash, newline or non-ASCII character of a user's string
        reaches an emitted file (as the HLS backend's ``names`` rules demand of user text)."""
        text = json.dumps(value, ensure_ascii=False)
        if isinstance(value, int) or (isinstance(value, str) and _PLAIN.fullmatch(value)):
            return repr(text)
        return repr("hex:" + text.encode("utf-8").hex())


def _group_logs(steps: list, exprs: list) -> tuple[list, list]:
    """Compute each distinct SO(3) Log once: ``w0_0, w0_1, w0_2 = so3_log(R…)`` before the first
    assignment that uses one of its components, which then refer to the three symbols."""
    groups: dict[tuple, tuple[sp.Symbol, ...]] = {}
    out: list = []

    def replace(e: sp.Expr) -> sp.Expr:
        atoms = sorted(e.atoms(special.SO3LogComponent), key=sp.default_sort_key)
        mapping = {}
        for atom in atoms:
            if atom.args not in groups:
                g = len(groups)
                groups[atom.args] = tuple(sp.Symbol(f"w{g}_{a}", real=True) for a in range(3))
                out.append((groups[atom.args], atom.args))
            mapping[atom] = groups[atom.args][atom.axis]
        return e.xreplace(mapping) if mapping else e

    for target, e in steps:
        e = replace(e)
        out.append((target, e))
    exprs = [replace(e) for e in exprs]
    return out, exprs
