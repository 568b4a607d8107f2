"""One set of functions for every backend (fgc.frontend.functions): the whitelist prints with both
printers (and so do its derivatives), the emitted C++ defines every wrapper the HLS printer calls,
and a function outside the whitelist is refused at the first trace, naming the factor."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import fgc
from fgc.compile import compile_graph
from fgc.compiler.kernel import Kernel
from fgc.frontend import noise
from fgc.frontend.factors import PriorFactor
from fgc.frontend.functions import DERIVATIVE_FUNCTIONS, FUNCTIONS
from fgc.frontend.geometry import Point2
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import native, sim
from fgc_backends.cfamily.printer import print_kernel
from fgc_backends.sim.printer import SimPrinter

ROOT = Path(__file__).resolve().parents[2]
# the kernel templates (the native backend's; the HLS backend renders them too for now)
TEMPLATES = ROOT / "backends" / "native" / "templates"
X, Y = sp.symbols("x y", real=True)


def _call(f):
    return f(Y, X) if f is sp.atan2 else f(X)


def _kernel(expr) -> Kernel:
    return Kernel((X, Y), (), (expr,))


def _emitted_cpp() -> str:
    """The native kernel's templates and the C-family macros they print the functions from."""
    shared = ROOT / "backends" / "cfamily" / "templates" / "common.jinja"
    return "".join(path.read_text() for path in (TEMPLATES / "kernel.cpp.jinja",
                                                  TEMPLATES / "kernel.h.jinja", shared))


@pytest.mark.parametrize("f", FUNCTIONS + DERIVATIVE_FUNCTIONS, ids=lambda f: f.__name__)
def test_whitelist_prints_in_both_printers(f):
    """Each function, and a whitelisted one's derivatives in both arguments, prints with the
    simulator's and the HLS printer (scalar and lane-wise), and every C++ function called is
    defined in the templates; the simulator's text evaluates to sympy's value."""
    expr = _call(f)
    exprs = [expr]
    if f in FUNCTIONS:  # fgc takes first derivatives only (Jacobians): sign's is not needed
        exprs += [e for e in (sp.diff(expr, X), sp.diff(expr, Y)) if e != 0]
    cpp = _emitted_cpp()
    for e in exprs:
        printed = SimPrinter().kernel(_kernel(e), "k")
        namespace = {"numpy": np}
        exec("def k(x):\n" + "\n".join("    " + line for line in printed.lines), namespace)
        point = {X: 0.4, Y: 0.3}
        got = namespace["k"](np.array([[0.4], [0.3]]))[0, 0]
        assert got == pytest.approx(float(e.subs(point)), rel=1e-12, abs=1e-12)
        for vector in (False, True):
            text = print_kernel(_kernel(e), ("in[0]", "in[1]"), "test", vector=vector).outputs[0]
            for name in re.findall(r"\b(v_fgc_\w+|fgc_\w+)\(", text):
                defined = (f"V {name}(" in cpp or f"T {name}(" in cpp
                           or (name.startswith("v_") and f'"{name[2:]}"' in cpp))
                assert defined, f"{text}: {name} is not defined in the templates"


def _trace(body):
    return fgc.factor(body, name="my_factor").trace()[2]


def test_abs_and_float_half_powers_trace_to_printable_residuals():
    def f(p: Point2, *, m: float):
        return [abs(p.x() - m) + (p.y() ** 2 + 1) ** 0.5 + (p.x() ** 2 + 2) ** -1.5]

    residual = _trace(f)
    powers = [n.exp for n in sp.preorder_traversal(residual[0]) if isinstance(n, sp.Pow)]
    assert all(e.is_Rational for e in powers)  # 0.5 and -1.5 became exact
    syms = sorted(residual.free_symbols, key=str)
    for e in [residual[0]] + [sp.diff(residual[0], s) for s in syms]:  # sign() from abs
        print_kernel(Kernel(tuple(syms), (), (e,)), tuple(f"in[{i}]" for i in range(len(syms))),
                     "test")


@pytest.mark.parametrize("body, word", [
    (lambda p, m: [np.arctan2(p.y(), p.x()) - m], "fgc.atan2"),
    (lambda p, m: [np.sqrt(p.x() ** 2 + 1) - m], "fgc.sqrt"),
    (lambda p, m: [sp.Max(p.x(), m)], "'Max'"),
    (lambda p, m: [p.x() ** 0.3 - m], "power"),
    (lambda p, m: [sp.sinh(p.x()) - m], "fgc.exp"),
])
def test_outside_the_whitelist_is_refused_at_trace(body, word):
    def f(p: Point2, *, m: float):
        return body(p, m)

    with pytest.raises(fgc.DslError) as info:
        _trace(f)
    assert "my_factor" in str(info.value) and word in str(info.value)


def test_functions_work_on_floats_and_symbols():
    assert fgc.sqrt(4.0) == 2.0 and fgc.atan2(1.0, 1.0) == math.atan2(1.0, 1.0)
    assert fgc.hypot(3.0, 4.0) == 5.0 and fgc.tanh(0.0) == 0.0 and fgc.asin(1.0) == math.pi / 2
    assert fgc.sqrt(X) == sp.sqrt(X) and fgc.atan2(Y, X) == sp.atan2(Y, X)
    assert isinstance(fgc.acos(X), sp.acos) and isinstance(fgc.log(X), sp.log)


def test_abs_and_sqrt_factor_runs_on_the_native_backend():
    """A residual with abs(), x ** 0.5 and every trigonometric function builds and runs natively
    and agrees with the simulator (float64, 1e-9 of max(1, |x|))."""

    @fgc.factor
    def odd(p: Point2, *, m: float):
        r = (p.x() ** 2 + 1) ** 0.5 - m
        s = abs(p.y() - 0.5) + fgc.asin(p.x() / 10) + fgc.acos(p.y() / 10) + fgc.tanh(p.x())
        return [r, s + fgc.atan(p.y()) + fgc.exp(p.x() / 10) + fgc.log(p.y() ** 2 + 1)]

    g = fgc.Graph()
    g.add_variable("a", Point2(1.0, 2.0))
    g.add(PriorFactor("a", Point2(1.2, 2.1), noise.isotropic(2, 1.0)))
    g.add(odd("a", m=1.5, noise=noise.isotropic(2, 0.5)))
    program = compile_graph(g, SolverConfig(), name="odd")
    data = problem_data(g, program)
    got = native.run(program, data).values["a"]
    want = sim.run(program, data).storage["a"]
    assert np.max(np.abs(np.asarray(got) - np.asarray(want))) <= 1e-9 * max(
        1.0, float(np.max(np.abs(want))))
