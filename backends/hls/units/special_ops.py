"""The arithmetic inside fgc's special functions as the HLS kernel prints them.

The compiler counts a Lie coefficient (``lie_A`` … ``lie_D1``) or a component of the SO(3)
logarithm as one ``special`` operation (:func:`fgc.compiler.kernel._count_ops`), which the
operator table prices as one transcendental core. The emitted header defines each as an inline
function whose body Vitis binds inside the caller's pipelined loop: a coefficient's Taylor
series in Horner form (one multiply and one add a term) beside its closed form (printed from
``fgc_backends.cfamily.special``'s kernels: a square root, sines and cosines, divides and a few
products), and ``so3_log`` (kernel.h.jinja) once per rotation for its three components. The
adds, multiplies, divides and square roots of those bodies come on top of the kernel's own
counts (the sines, cosines and the arctangent are what the ``special`` operation prices).
The second reader, which reads the bodies in place, found the difference: imu_window's
``factor_cost_0`` holds 477 adds and 560 multiplies an evaluation where the kernel's counts
said 305 and 373.
"""

from __future__ import annotations

import functools
from collections import Counter

import sympy as sp

from fgc.frontend.geometry import special
from fgc.ir.program import KernelText

# so3_log's body as kernel.h.jinja prints it, its arctangent apart (both of its branches are
# built): the skew and symmetric parts, cos and sin of the angle, the axis and its norm
SO3_LOG_OPS = {"add": 22, "mul": 28, "div": 7, "sqrt": 3}
ARITHMETIC = ("add", "mul", "div", "sqrt")


@functools.lru_cache(maxsize=16)
def coefficient_ops(name: str) -> tuple[tuple[str, int], ...]:
    """The arithmetic of ``lie_<name>``'s body: its series' Horner terms (a multiply and an add
    a term after the first) and its closed form's operations (sines and cosines left out)."""
    from fgc.compiler.kernel import _op_counts
    from fgc_backends.cfamily.special import _closed_form_kernel

    terms = len(special.SERIES[name]) - 1
    closed = dict(_op_counts(_closed_form_kernel(name)))
    ops = {k: closed.get(k, 0) for k in ARITHMETIC}
    ops["add"] += terms
    ops["mul"] += terms
    return tuple(sorted(ops.items()))


@functools.lru_cache(maxsize=256)
def helper_ops(text: KernelText) -> tuple[tuple[str, int], ...]:
    """The special functions' arithmetic that one evaluation of kernel ``text`` runs: each
    Lie coefficient call's body, and one ``so3_log`` per rotation whose components it takes."""
    kernel = text.kernel()
    total: Counter = Counter()
    rotations = set()
    exprs = [e for _, e in kernel.assignments] + list(kernel.outputs)
    for expr in exprs:
        for node in sp.preorder_traversal(sp.sympify(expr)):
            if isinstance(node, special.LieCoefficient):
                total.update(dict(coefficient_ops(node.coeff_name)))
            elif isinstance(node, special.SO3LogComponent):
                rotations.add(node.args)
    for _ in rotations:
        total.update(SO3_LOG_OPS)
    return tuple(sorted((k, n) for k, n in total.items() if n))


@functools.lru_cache(maxsize=256)
def negations(text: KernelText) -> int:
    """Products with a -1 coefficient in kernel ``text``: the compiler's count takes -1 as a
    factor (``a - b`` is ``a + (-1)·b``: one multiply), the printer writes a subtraction or a
    sign (``-x``, ``-a*b``): one multiply fewer each."""
    kernel = text.kernel()
    exprs = [e for _, e in kernel.assignments] + list(kernel.outputs)
    return sum(1 for expr in exprs for node in sp.preorder_traversal(sp.sympify(expr))
               if node.is_Mul and node.as_coeff_Mul()[0] == -1)


def with_helpers(counts: dict, text: KernelText) -> dict:
    """``counts`` (a kernel's operation counts by kind) as the kernel is printed: its special
    functions' arithmetic (:func:`helper_ops`) added, its sign flips (:func:`negations`) no
    multiplies."""
    out = dict(counts)
    for kind, n in helper_ops(text):
        out[kind] = out.get(kind, 0) + n
    if "mul" in out:
        out["mul"] = max(0, out["mul"] - negations(text))
    return out
