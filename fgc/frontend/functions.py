"""The functions a residual may use, and the check that a traced residual uses no other.

Every function here works on floats (``math``) and on the symbolic values a residual is traced
with (sympy), and every backend prints it and the functions its derivative introduces (``sign``
from ``abs``): the simulator's NumPy printer and the HLS C++ printer
(tests/frontend/test_functions.py prints each with both). :func:`check_residual` runs once per
factor type, right after tracing (:meth:`fgc.frontend.dsl.FactorType.trace`), so a function no
backend can emit is refused there, naming the factor, the function and the alternative, instead
of failing at ``--backend hls``.

Powers: ``x**k`` for integer or half-integer ``k`` with -7 <= k <= 8 (so a Jacobian's
``x**(k-1)`` still prints as multiplies and at most one square root); a float exponent that is
such a number (``x ** 0.5``) is taken as that rational.
"""

from __future__ import annotations

import math
import re

import sympy as sp

from fgc.errors import DslError
from fgc.frontend.geometry import special

__all__ = ["abs_", "acos", "asin", "atan", "atan2", "cos", "exp", "hypot", "log", "sin", "sqrt",
           "tan", "tanh"]


def _symbolic(*xs) -> bool:
    return any(isinstance(x, sp.Basic) for x in xs)


def _unary(name: str, sym, num):
    def f(x):
        return sym(x) if _symbolic(x) else num(float(x))
    f.__name__ = f.__qualname__ = name
    f.__doc__ = (f"``{name}(x)`` on a float (``math.{num.__name__}``) or a symbolic value in a "
                 "residual (sympy).")
    return f


sqrt = _unary("sqrt", sp.sqrt, math.sqrt)
sin = _unary("sin", sp.sin, math.sin)
cos = _unary("cos", sp.cos, math.cos)
tan = _unary("tan", sp.tan, math.tan)
asin = _unary("asin", sp.asin, math.asin)
acos = _unary("acos", sp.acos, math.acos)
atan = _unary("atan", sp.atan, math.atan)
exp = _unary("exp", sp.exp, math.exp)
log = _unary("log", sp.log, math.log)
tanh = _unary("tanh", sp.tanh, math.tanh)
abs_ = _unary("abs", sp.Abs, math.fabs)  # Python's abs() works as well


def atan2(y, x):
    """``atan2(y, x)`` on floats (``math.atan2``) or symbolic values (sympy)."""
    return sp.atan2(y, x) if _symbolic(y, x) else math.atan2(float(y), float(x))


def hypot(x, y):
    """``sqrt(x² + y²)`` on floats (``math.hypot``) or symbolic values, differentiated with
    GTSAM's norm convention at (0, 0) (:class:`~fgc.frontend.geometry.special.VectorNorm`)."""
    return special.VectorNorm(x, y) if _symbolic(x, y) else math.hypot(float(x), float(y))


# The whitelist: sympy function classes a traced residual may contain (besides +, *, powers,
# numbers, symbols and fgc's own special functions), and the ones their derivatives introduce.
FUNCTIONS: tuple[type, ...] = (sp.sin, sp.cos, sp.tan, sp.asin, sp.acos, sp.atan, sp.atan2,
                               sp.exp, sp.log, sp.tanh, sp.Abs)
DERIVATIVE_FUNCTIONS: tuple[type, ...] = (sp.sign,)
SPECIAL: tuple[type, ...] = (special.LieCoefficient, special.SO3LogComponent,
                             *special.GUARD_FUNCTIONS)
MIN_POWER, MAX_POWER = -7, 8

# what to write instead of a function outside the whitelist
_ALTERNATIVES = {
    "Min": "a smooth residual (min/max have no derivative where the arguments meet)",
    "Max": "a smooth residual (min/max have no derivative where the arguments meet)",
    "Heaviside": "a smooth residual (a step has no derivative)",
    "DiracDelta": "a smooth residual",
    "Piecewise": "straight-line math (no branches on variables)",
    "sinh": "(fgc.exp(x) - fgc.exp(-x)) / 2",
    "cosh": "(fgc.exp(x) + fgc.exp(-x)) / 2",
    "cot": "1 / fgc.tan(x)",
    "sec": "1 / fgc.cos(x)",
    "csc": "1 / fgc.sin(x)",
}
_LISTED = ("fgc.sqrt, fgc.sin, fgc.cos, fgc.tan, fgc.asin, fgc.acos, fgc.atan, fgc.atan2, "
           "fgc.exp, fgc.log, fgc.tanh, fgc.hypot, abs(), powers x**k (k integer or half-integer,"
           f" {MIN_POWER} <= k <= {MAX_POWER})")


def _power(factor: str, node: sp.Pow) -> sp.Expr:
    exp = node.exp
    if exp.is_Float:
        rational = sp.Rational(float(exp)).limit_denominator(2)
        if float(rational) == float(exp):
            exp = rational
    ok = exp.is_Rational and exp.q in (1, 2) and MIN_POWER <= exp <= MAX_POWER and exp != 0
    if not ok:
        raise DslError(f"factor '{factor}': the power {node} cannot be emitted by every backend; "
                       f"use an integer or half-integer exponent between {MIN_POWER} and "
                       f"{MAX_POWER} (x**0.5, x**-1.5, fgc.sqrt(x)), or fgc.exp(k * fgc.log(x)) "
                       "for x > 0")
    return node if exp is node.exp else sp.Pow(node.base, exp)


def _norm_of(node: sp.Pow) -> sp.Expr | None:
    """``sqrt(a² + b² + …)`` (two or more squares, ``x ** 0.5`` too) as the norm
    ``vector_norm(a, b, …)``, whose derivative follows GTSAM's convention where all of them are
    0 (a distance between coincident points) instead of 0/0; None for any other power."""
    exp = node.exp
    if not (exp == sp.Rational(1, 2) or (exp.is_Float and float(exp) == 0.5)):
        return None
    terms = sp.Add.make_args(node.base)
    if len(terms) < 2 or not all(isinstance(t, sp.Pow) and t.exp == 2 for t in terms):
        return None
    return special.VectorNorm(*(t.base for t in terms))


def check_expression(factor: str, expr: sp.Expr) -> sp.Expr:
    """``expr`` with float half-integer exponents made exact; :class:`DslError` naming
    ``factor`` if it holds anything outside the whitelist.

    The expression is walked as a DAG, each distinct subexpression once: a traced residual
    shares its subterms (the IMU factor's tree form has millions of nodes, its DAG thousands)."""
    replace: dict = {}
    seen: set = set()
    stack = [expr]
    while stack:
        node = stack.pop()
        if node in seen:
            continue
        seen.add(node)
        _check_node(factor, node, replace)
        stack.extend(a for a in node.args if a not in seen)
    return _rebuild(expr, replace) if replace else expr


def _check_node(factor: str, node: sp.Basic, replace: dict) -> None:
    if isinstance(node, (sp.Add, sp.Mul)) or node.is_Symbol or node.is_Number \
            or isinstance(node, sp.NumberSymbol):
        if node.is_Number and not node.is_finite:
            raise DslError(f"factor '{factor}': the residual holds the constant {node}")
        return
    if isinstance(node, sp.Pow):
        norm = _norm_of(node)
        if norm is not None:
            replace[node] = norm
            return
        new = _power(factor, node)
        if new is not node:
            replace[node] = new
        return
    if isinstance(node, FUNCTIONS + DERIVATIVE_FUNCTIONS + SPECIAL):
        return
    name = type(node).__name__
    alternative = _ALTERNATIVES.get(name, f"one of {_LISTED}")
    raise DslError(f"factor '{factor}': the residual uses '{name}', which not every backend "
                   f"can emit; use {alternative}")


def _rebuild(expr: sp.Basic, replace: dict) -> sp.Basic:
    """``expr.xreplace(replace)`` (outermost matches first), each shared subtree visited once."""
    memo: dict = {}

    def visit(e: sp.Basic) -> sp.Basic:
        out = memo.get(e)
        if out is None:
            if e in replace:
                out = replace[e]
                if out.args:  # the replaced power's base may hold further replacements
                    out = out.func(*(visit(a) for a in out.args))
            elif e.args:
                args = tuple(visit(a) for a in e.args)
                out = e.func(*args) if any(
                    a is not b for a, b in zip(args, e.args, strict=True)) else e
            else:
                out = e
            memo[e] = out
        return out

    return visit(expr)


def check_residual(factor: str, residual: sp.Matrix) -> sp.Matrix:
    """:func:`check_expression` on every entry of a traced residual."""
    return residual.applyfunc(lambda e: check_expression(factor, sp.sympify(e)))


# numpy ufunc names on symbolic values -> the fgc function to use instead
_NUMPY = {"sqrt": "sqrt", "sin": "sin", "cos": "cos", "tan": "tan", "arcsin": "asin",
          "arccos": "acos", "arctan": "atan", "arctan2": "atan2", "exp": "exp", "log": "log",
          "tanh": "tanh", "hypot": "hypot", "absolute": "abs", "fabs": "abs"}
_NO_METHOD = re.compile(r"has no (?:attribute|callable) '?(\w+)'?")


def numpy_on_symbols(factor: str, exc: BaseException) -> DslError | None:
    """The :class:`DslError` for a numpy function applied to a symbolic value (numpy calls a
    method of that name on the object: ``'Add' object has no attribute 'arctan2'``), or None."""
    for e in (exc, exc.__cause__, exc.__context__):
        if e is None:
            continue
        m = _NO_METHOD.search(str(e))
        if m and isinstance(e, (AttributeError, TypeError)):
            name = m.group(1)
            use = _NUMPY.get(name)
            instead = f"fgc.{use}" if use and use != "abs" else "abs()" if use else \
                f"one of {_LISTED}"
            return DslError(f"factor '{factor}': numpy's '{name}' was applied to a symbolic "
                            f"value (residuals are traced with sympy); use {instead}, which works "
                            "on both")
    return None


# math / numpy functions by name (numpy's spellings too) → what to write in a residual instead
_SMOOTH = "a smooth residual (it has no derivative where it jumps or kinks)"
_NO_TEST = "no test on a variable (residuals are straight-line math on the variables)"
_REPLACEMENTS = {
    **{n: f"fgc.{n}(x)" for n in ("sqrt", "sin", "cos", "tan", "asin", "acos", "atan", "exp",
                                  "log", "tanh")},
    "arcsin": "fgc.asin(x)", "arccos": "fgc.acos(x)", "arctan": "fgc.atan(x)",
    "atan2": "fgc.atan2(y, x)", "arctan2": "fgc.atan2(y, x)", "hypot": "fgc.hypot(x, y)",
    "fabs": "abs(x)", "absolute": "abs(x)", "abs": "abs(x)",
    "pow": "x**k (k an integer or half-integer from -7 to 8)",
    "power": "x**k (k an integer or half-integer from -7 to 8)",
    "float_power": "x**k (k an integer or half-integer from -7 to 8)", "square": "x * x",
    "sinh": _ALTERNATIVES["sinh"], "cosh": _ALTERNATIVES["cosh"],
    "asinh": "fgc.log(x + fgc.sqrt(x * x + 1))", "arcsinh": "fgc.log(x + fgc.sqrt(x * x + 1))",
    "acosh": "fgc.log(x + fgc.sqrt(x * x - 1))", "arccosh": "fgc.log(x + fgc.sqrt(x * x - 1))",
    "atanh": "fgc.log((1 + x) / (1 - x)) / 2", "arctanh": "fgc.log((1 + x) / (1 - x)) / 2",
    "log10": "fgc.log(x) / math.log(10)", "log2": "fgc.log(x) / math.log(2)",
    "log1p": "fgc.log(1 + x)", "expm1": "fgc.exp(x) - 1", "exp2": "fgc.exp(x * math.log(2))",
    "degrees": "x * (180 / math.pi)", "rad2deg": "x * (180 / math.pi)",
    "radians": "x * (math.pi / 180)", "deg2rad": "x * (math.pi / 180)",
    "dist": "fgc.sqrt(dx * dx + dy * dy + ...) (fgc.hypot(dx, dy) in 2D)",
    "norm": "fgc.sqrt(x * x + y * y + ...) (fgc.hypot(x, y) in 2D)",
    "cbrt": "fgc.exp(fgc.log(x) / 3) for x > 0 (every backend emits integer and half-integer "
            "powers only)",
    **{n: _SMOOTH for n in ("sign", "copysign", "floor", "ceil", "trunc", "fmod", "remainder",
                            "modf", "maximum", "minimum", "fmax", "fmin", "clip", "round",
                            "rint", "fix", "heaviside", "max", "min")},
    **{n: _NO_TEST for n in ("isfinite", "isnan", "isinf", "isclose", "allclose", "where")},
}
_LIBRARY_FRAMES = ("sympy", "numpy", "fgc.", "mpmath")


def called_function(exc: BaseException):
    """The function whose call, written in the user's code, raised ``exc``, or None.

    The innermost traceback frame outside sympy, numpy and fgc is the user's residual (or a
    helper it calls); the instruction it stopped at is a call whose source span names the
    function (``math.atan2(...)``, ``np.linalg.norm(v)``, or a name imported with ``from math
    import atan2``), resolved in that frame's namespace."""
    import ast
    import builtins
    import linecache

    tb, user = exc.__traceback__, None
    while tb is not None:
        if not tb.tb_frame.f_globals.get("__name__", "").startswith(_LIBRARY_FRAMES):
            user = tb
        tb = tb.tb_next
    if user is None:
        return None
    frame = user.tb_frame
    try:
        line, end, col, end_col = list(frame.f_code.co_positions())[user.tb_lasti // 2]
        lines = [x.encode() for x in linecache.getlines(frame.f_code.co_filename,
                                                        frame.f_globals)[line - 1:end]]
        if line is None or end is None or col is None or end_col is None or not lines:
            return None
        joined = b"".join(lines)  # positions are UTF-8 byte offsets
        text = joined[col:len(joined) - len(lines[-1]) + end_col]
        node = ast.parse(text.decode().strip(), mode="eval").body
    except (IndexError, SyntaxError, UnicodeDecodeError, ValueError, TypeError):
        return None
    if not isinstance(node, ast.Call):
        return None

    def resolve(n):
        if isinstance(n, ast.Name):
            for scope in (frame.f_locals, frame.f_globals, vars(builtins)):
                if n.id in scope:
                    return scope[n.id]
            raise LookupError(n.id)
        if isinstance(n, ast.Attribute):
            return getattr(resolve(n.value), n.attr)
        raise LookupError(type(n).__name__)

    try:
        return resolve(node.func)
    except Exception:  # noqa: BLE001 - an expression we cannot resolve: no better message
        return None


def library_function_error(factor: str, exc: BaseException) -> DslError | None:
    """The :class:`DslError` for a ``math`` or ``numpy`` function called on the symbolic values
    a residual is traced with, naming the function and the ``fgc.`` function (or expression) to
    write instead; None when the failing call is not one of theirs."""
    import numpy as np

    fn = called_function(exc)
    if fn is None:
        return None
    module = getattr(fn, "__module__", None) or ""
    name = getattr(fn, "__name__", "")
    if isinstance(fn, np.ufunc):
        module = "numpy"
    if module == "math":
        shown = f"math.{name}"
    elif module == "numpy" or module.startswith("numpy."):
        sub = module.split(".")[1] if module.count(".") and not module.split(".")[1].startswith(
            "_") else ""
        shown = f"np.{sub + '.' if sub else ''}{name}"
    else:
        return None
    instead = _REPLACEMENTS.get(name, f"one of {_LISTED}")
    tail = (f"write {instead} instead (fgc's functions work on numbers and on symbolic values)"
            if "fgc." in instead or instead.startswith(("x", "abs")) else f"use {instead}")
    return DslError(f"factor '{factor}': {shown}() works on numbers only, not on the symbolic "
                    f"values a residual is traced with; {tail}")
