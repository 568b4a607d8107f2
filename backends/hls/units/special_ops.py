"""The arithmetic inside fgc's special functions as the HLS kernel prints them.

The printer counts a Lie coefficient (``lie_A`` … ``lie_D1``) or a component of the SO(3)
logarithm as one ``special`` operation (:func:`fgc_backends.cfamily.printer.printed_ops`), which the
operator table prices as one transcendental core. The emitted header defines each as an inline
function whose body Vitis binds inside the caller's pipelined loop: a coefficient's Taylor
series in Horner form (one multiply and one add a term) beside its closed form (printed from
``fgc_backends.cfamily.special``'s kernels: a square root, sines and cosines, divides and a few
products), and ``so3_log`` (kernel.h.jinja) once per rotation for its three components. The
adds, multiplies, divides and square roots of those bodies come on top of the kernel's own
printed counts (the sines, cosines and the arctangent are what the ``special`` operation prices).
The second reader, which reads the bodies in place, found the difference: imu_window's
``factor_cost_0`` holds 477 adds and 560 multiplies an evaluation where the kernel's counts
said 305 and 373.

Both bodies branch: a coefficient is ``if (t < 4) return series; closed form``, ``so3_log``
``if (cos θ >= 0) { …; return; } the symmetric part's axis``. The operators Vitis builds are
every branch's (:func:`printed_counts`, the text's sum); what one evaluation issues through
the ``ALLOCATION``'d operators is the larger branch of each kind (:func:`issued_counts`):
mutually exclusive operations under a control predicate may share one operator in the same
cycle (UG1448, "Mutual Exclusion, Resources, and Predicates"; the predicate, a compare of
``t`` or ``cos θ``, is ready before the branches' first operations, which wait for the same
value). The second reader counts both the same way (``ops`` and ``peak``).
"""

from __future__ import annotations

import functools
from collections import Counter

import sympy as sp

from fgc.compiler.kernel import Kernel
from fgc.frontend.geometry import special
from fgc.ir.program import KernelText
from fgc_backends.cfamily.blocks import cost_outputs_kernel
from fgc_backends.cfamily.printer import kernel_printed_ops

# so3_log's body as kernel.h.jinja prints it, its arctangent apart (both of its branches are
# built): the skew and symmetric parts, cos and sin of the angle, the axis and its norm
SO3_LOG_OPS = {"add": 22, "mul": 28, "div": 7, "sqrt": 3}
# what one so3_log issues, its exclusive branches sharing: before the branch 8 adds, 5
# multiplies and a square root; the skew part's branch 4 multiplies and a divide; the symmetric
# part's 14 adds, 19 multiplies, 6 divides and 2 square roots
SO3_LOG_ISSUED = {"add": 22, "mul": 24, "div": 6, "sqrt": 3}
ARITHMETIC = ("add", "mul", "div", "sqrt")


@functools.lru_cache(maxsize=32)
def coefficient_ops(name: str, exclusive: bool = False) -> tuple[tuple[str, int], ...]:
    """The arithmetic of ``lie_<name>``'s body: its series' Horner terms (a multiply and an add
    a term after the first) and its closed form's operations (sines and cosines left out),
    summed; ``exclusive``: per kind the larger of the two branches (what one call issues)."""
    from fgc_backends.cfamily.special import _closed_form_kernel

    terms = len(special.SERIES[name]) - 1
    closed = dict(kernel_printed_ops(_closed_form_kernel(name)))
    series = {"add": terms, "mul": terms}
    pick = max if exclusive else (lambda a, b: a + b)
    ops = {k: pick(closed.get(k, 0), series.get(k, 0)) for k in ARITHMETIC}
    return tuple(sorted(ops.items()))


def helper_ops(text: KernelText | Kernel, exclusive: bool = False
               ) -> tuple[tuple[str, int], ...]:
    """The special functions' arithmetic that one evaluation of kernel ``text`` runs: each
    Lie coefficient call's body, and one ``so3_log`` per rotation whose components it takes;
    ``exclusive``: each body's branches sharing (the larger of each kind)."""
    return _helper_ops(text.kernel() if isinstance(text, KernelText) else text, exclusive)


@functools.lru_cache(maxsize=256)
def _helper_ops(kernel: Kernel, exclusive: bool) -> tuple[tuple[str, int], ...]:
    total: Counter = Counter()
    rotations = set()
    exprs = [e for _, e in kernel.assignments] + list(kernel.outputs)
    for expr in exprs:
        for node in sp.preorder_traversal(sp.sympify(expr)):
            if isinstance(node, special.LieCoefficient):
                total.update(dict(coefficient_ops(node.coeff_name, exclusive)))
            elif isinstance(node, special.SO3LogComponent):
                rotations.add(node.args)
    for _ in rotations:
        total.update(SO3_LOG_ISSUED if exclusive else SO3_LOG_OPS)
    return tuple(sorted((k, n) for k, n in total.items() if n))


def printed_counts(block, mode: str) -> dict:
    """The operations by kind of block ``block``'s (a ``BlockSpec``) datapath in ``mode``
    ("jacobian": ``factor_<b>``, "cost": ``factor_cost_<b>``) as the HLS kernel prints it: the
    printer's own count of the kernel it prints
    (:func:`fgc_backends.cfamily.printer.kernel_printed_ops`: a division by a constant a
    multiply, a sign no multiply, a power's repeated base once; the
    cost mode's kernel reduced to the members' costs, as printed) and its special functions'
    arithmetic (:func:`helper_ops`). What sizes the factor datapaths' ``ALLOCATION`` limits and
    their II: the second reader counts the same text (``tests/hls/reader/test_printed_ops.py``
    holds the two equal)."""
    return dict(_printed_counts(block.kernel if mode == "jacobian" else block.cost_kernel,
                                mode, block.residual_dim, len(block.members), False))


def issued_counts(block, mode: str) -> dict:
    """What one evaluation of block ``block``'s datapath in ``mode`` issues through its
    ``ALLOCATION``'d operators: :func:`printed_counts` with each special function's exclusive
    branches sharing (per kind the larger: the module's note). What sizes the datapath's II;
    the operators bound at that II are still :func:`printed_counts`' (every branch is built).
    The second reader's ``peak`` count of the same text
    (``tests/hls/reader/test_printed_ops.py``)."""
    return dict(_printed_counts(block.kernel if mode == "jacobian" else block.cost_kernel,
                                mode, block.residual_dim, len(block.members), True))


@functools.lru_cache(maxsize=256)
def _printed_counts(text: KernelText, mode: str, m: int, n: int, exclusive: bool
                    ) -> tuple[tuple[str, int], ...]:
    kernel = text.kernel() if mode == "jacobian" else cost_outputs_kernel(text.kernel(), m, n)
    out = dict(kernel_printed_ops(kernel))
    for kind, k in helper_ops(kernel, exclusive):
        out[kind] = out.get(kind, 0) + k
    return tuple((kind, k) for kind, k in out.items() if k)
